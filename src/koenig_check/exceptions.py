"""Every exception koenig-check raises on purpose: the root :class:`KoenigCheckError` and its subclasses.

Each message is one line naming the file (or the argument) and the element concerned; the refusing engine's own
words, whole and as it wrote them, are :attr:`KoenigCheckError.engine_texts` (the lines printed after the
message's first line: :mod:`koenig_check.diagnosis.message`).  Values a caller needs are attributes, not text to
parse: the root causes of a load failure are
:attr:`KoenigCheckError.causes` (typed :class:`~koenig_check.findings.Finding` records), the joints
that cannot be paired are :attr:`JointMismatch.only_in_mujoco` and its siblings.

The modules that raise these errors import them from here and keep their old names
(``koenig_check.engines.errors.ModelLoadError``, ``koenig_check.modelfile.validate.ModelFileError``, …).

Hierarchy::

    KoenigCheckError
    ├── ArgumentValueError (ValueError), ArgumentTypeError (TypeError)   usage errors
    ├── ModelFileError (ValueError)                                      the file cannot be read as MJCF/URDF
    ├── ModelLoadError (ValueError)                                      an engine cannot load the file
    │   └── InertiaError, CoupledJointsError, NoMovingSegmentError (an engine's own load error, such as
    │       DrakeLoadError, lives in its subpackage: koenig_check.engines.drake.loader)
    ├── JointMismatch (ValueError)                                       the engines' joints cannot be paired
    ├── EngineUnavailableError (ValueError)                              an optional engine asked for, unusable
    ├── PoseFileError (ValueError), RecordFileError (ValueError)         input files of a run
    ├── NotPlaneParallelError (ValueError)                               eq. (16) on a motion not in a plane
    └── PathDependentError                                               a formula's energy needs the path
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from koenig_check.findings import Finding

__all__ = [
    "ArgumentTypeError",
    "ArgumentValueError",
    "CoupledJointsError",
    "EngineUnavailableError",
    "InertiaError",
    "JointMismatch",
    "KoenigCheckError",
    "ModelFileError",
    "ModelLoadError",
    "NoMassError",
    "NoMovingSegmentError",
    "NotFloatableError",
    "NotPlaneParallelError",
    "PathDependentError",
    "PoseFileError",
    "RecordFileError",
]


class KoenigCheckError(Exception):
    """Root of every exception koenig-check raises on purpose.

    Messages are one line naming the file and the element concerned.

    Attributes
    ----------
    causes : tuple of Finding
        The root causes found for this error (a construct of the file one engine's parser reads
        differently, a model without a joint), set by :meth:`attach_causes`; empty when none was found
        or none was looked for.
    head : str
        The message before the root causes were appended to it (empty when none were).
    brief : str
        A shorter message for a one-line display (empty: the message itself is short enough), set where an
        engine's reason is long; the whole message stays ``str(err)``.
    engine_texts : tuple of (str, str)
        The refusing engine's own words, whole and as it wrote them (its label, its text), set by
        :func:`quote_engine`; empty when no engine refused (the error is koenig-check's own).
    hint : str
        What would load or fix the model (an option, a change to the file), or empty.
    """

    causes: tuple[Finding, ...] = ()
    head: str = ""
    brief: str = ""
    engine_texts: tuple[tuple[str, str], ...] = ()
    hint: str = ""

    def attach_causes(self, causes: Iterable[Finding], *, in_message: bool = True) -> None:
        """Record the root causes of this error and, when asked and there are any, end the message with them.

        Parameters
        ----------
        causes : iterable of Finding
            The root causes (possibly none).
        in_message : bool
            Append ``"; root cause: <cause>; <cause>…"`` to the one-line message when there are causes.
        """
        self.causes = tuple(causes)
        if in_message and self.causes and self.args:
            self.head = str(self.args[0])
            found = "; ".join(c.message() for c in self.causes)
            self.args = (f"{self.args[0]}; root cause: {found}", *self.args[1:])


# ------------------------------------------------------------------------------------------ usage errors
class ArgumentValueError(KoenigCheckError, ValueError):
    """An argument with a value the tool cannot use (a usage error)."""


class ArgumentTypeError(KoenigCheckError, TypeError):
    """A keyword the function does not take, or an argument of the wrong type (a usage error)."""


# --------------------------------------------------------------------------------- model files and loading
class ModelFileError(KoenigCheckError, ValueError):
    """A model file cannot be read as MJCF or URDF; the message names the file and the element."""


class ModelLoadError(KoenigCheckError, ValueError):
    """A model file cannot be loaded by one engine; the message names the file and the element."""


class NotFloatableError(ModelLoadError):
    """``floating`` asked for a model whose root already moves, or that has no single root.

    Parameters
    ----------
    message : str
        Names the file and the top-level bodies.
    top_level : sequence of str
        The file's top-level bodies (links): none, several, or one that already has joints.
    """

    def __init__(self, message: str, top_level: Sequence[str] = ()) -> None:
        super().__init__(message)
        self.top_level = tuple(top_level)


class InertiaError(ModelLoadError):
    """MuJoCo rejects a link's mass or inertia; the message names the link and the reason."""


class CoupledJointsError(ModelLoadError):
    """The model couples joints (mimic, equality constraints) or closes loops; the message names them."""


class NoMovingSegmentError(ModelLoadError):
    """The model has no joint: nothing moves, there is no kinetic energy to compare.

    Attributes
    ----------
    advice : str
        What would make it move (``--floating`` for one top-level body, else a joint); empty when not known.
    """

    advice: str = ""


class NoMassError(ModelLoadError):
    """Nothing that moves has mass (at most round-off, e.g. MuJoCo's minimum masses of a repair).

    Parameters
    ----------
    message : str
        One line naming the file and the massless moving links.
    links : tuple of str
        The moving links (bodies) without mass.
    """

    def __init__(self, message: str, links: tuple[str, ...] = ()) -> None:
        super().__init__(message)
        self.links = tuple(links)

    def __reduce__(self) -> tuple[Any, ...]:
        return (type(self), (self.args[0] if self.args else "", self.links))


class JointMismatch(KoenigCheckError, ValueError):  # noqa: N818 - the name the design uses
    """The joints of the MuJoCo model and the Pinocchio model cannot be paired by name.

    Parameters
    ----------
    path : str
        The model file.
    only_in_mujoco : list of str
        Canonical (MuJoCo) joint names with no Pinocchio counterpart.
    only_in_pinocchio : list of str
        Pinocchio joint names with no MuJoCo counterpart.
    kind_mismatch : list of str
        Joints present in both engines whose types are incompatible, as ``"name: mujoco-kind vs pin-kind"``.
    """

    def __init__(
        self,
        path: str,
        only_in_mujoco: list[str],
        only_in_pinocchio: list[str],
        kind_mismatch: list[str] | None = None,
    ) -> None:
        self.path = path
        self.only_in_mujoco = list(only_in_mujoco)
        self.only_in_pinocchio = list(only_in_pinocchio)
        self.kind_mismatch = list(kind_mismatch or [])
        named = (
            ("only in MuJoCo", self.only_in_mujoco),
            ("only in Pinocchio", self.only_in_pinocchio),
            ("of incompatible types", self.kind_mismatch),
        )
        parts = [f"{what.removeprefix('of ')}: {', '.join(names)}" for what, names in named if names]
        super().__init__(f"{path}: joints do not match between the engines ({'; '.join(parts)})")
        shown = [f"joints {what} ({_first_names(names)})" for what, names in named if names]  # a few names each
        self.brief = f"{path}: {'; '.join(shown)}"

    def __reduce__(self) -> tuple[Any, ...]:
        """Rebuild from the fields, not from the message (a worker process sends the error back pickled)."""
        return (type(self), (self.path, self.only_in_mujoco, self.only_in_pinocchio, self.kind_mismatch), self.__dict__)


class EngineUnavailableError(KoenigCheckError, ValueError):
    """An engine was asked for but cannot run: not installed, or it cannot check the model.

    Parameters
    ----------
    message : str
        One line naming the engine (and the file, when the engine refused it) with the engine's own reason.
    engine : str
        The engine's name.
    """

    def __init__(self, message: str, engine: str = "") -> None:
        super().__init__(message)
        self.engine = engine

    def __reduce__(self) -> tuple[Any, ...]:
        return (type(self), (self.args[0] if self.args else "", self.engine))


# ------------------------------------------------------------------------------------------ inputs of a run
class PoseFileError(KoenigCheckError, ValueError):
    """A pose file cannot be used; the message names the file, the row and the column."""


class RecordFileError(KoenigCheckError, ValueError):
    """A file read as records is not a record file."""


# ---------------------------------------------------------------------------------------------- formulas
class NotPlaneParallelError(KoenigCheckError, ValueError):
    """Raised when eq. (16) is asked for a motion that is not plane-parallel."""


class PathDependentError(KoenigCheckError):
    """Raised when a formula's energy depends on the path, not on the state ``(q, q̇)``."""


def _first_names(names: list[str], shown: int = 6) -> str:
    """``a, b, c`` and, past ``shown`` names, how many more."""
    more = f" (+{len(names) - shown} more)" if len(names) > shown else ""
    return ", ".join(names[:shown]) + more


def quote_engine(err: BaseException, engine: str, text: str | None = None) -> None:
    """Record on ``err`` the engine's own words: ``text``, else the engine's exception ``err`` was raised from.

    Nothing is recorded when the error already quotes an engine, or when it was raised from none (the text of an
    exception koenig-check raised itself is not an engine's).

    Parameters
    ----------
    err : BaseException
        A :class:`KoenigCheckError` (anything else is left alone).
    engine : str
        The engine's label (``"MuJoCo"``).
    text : str, optional
        The engine's whole text (its exception's, with what its parser printed); by default the text of the
        exception ``err`` was raised from.
    """
    if not isinstance(err, KoenigCheckError) or err.engine_texts:
        return
    cause = err.__cause__
    if text is None and (cause is None or isinstance(cause, KoenigCheckError)):
        return
    words = (text if text is not None else str(cause)).strip()
    if words:
        err.engine_texts = ((engine, words),)


def one_line(err: BaseException) -> str:
    """A one-line description of an exception: its message with every run of white space made one space.

    Engines' messages span lines (MuJoCo's parser, Pinocchio's C++ source locations); a reason is one line.
    An exception without a message gives its type's name.

    Parameters
    ----------
    err : BaseException

    Returns
    -------
    str
    """
    return without_build_location(" ".join(str(err).split())) or type(err).__name__


#: Where a C++ check of Drake failed in Drake's build tree (``Failure at bazel-out/.../file.h:2896 in F(): ``).
_BUILD_LOCATION = re.compile(r"Failure at \S+:\d+ in (?=\S+\(\): )")


def without_build_location(text: str) -> str:
    """An engine's message without the source location of the C++ check that failed, its reason kept whole.

    ``Failure at bazel-out/k8-opt/.../multibody_plant.h:2896 in SetPositions(): condition 'q.size() ==
    num_positions()' failed.`` becomes ``SetPositions(): condition 'q.size() == num_positions()' failed.``

    Parameters
    ----------
    text : str

    Returns
    -------
    str
    """
    return _BUILD_LOCATION.sub("", text)
