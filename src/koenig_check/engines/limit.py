"""What an engine's parser is known not to read, declared as data: a :class:`ParserLimit`.

An engine subpackage declares its limits in ``engines/<name>/limits.py`` as ``LIMITS = (ParserLimit(...), ...)``
(:func:`limits` collects them).  A finding of the engine that a limit matches shows that the engine was given
another robot than the file's: it does not vote (:mod:`koenig_check.diagnosis.engine_limits`).  A limit matches a
finding by the catalogued cause the finding carries (:attr:`ParserLimit.cause`), or by its kind and a test on
its values (:attr:`ParserLimit.when`), never by its text.
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from koenig_check.engines.specs import ENGINES_PACKAGE, reference
from koenig_check.findings import Finding, Kind


@dataclass(frozen=True)
class ParserLimit:
    """A construct an engine's parser does not read as the file says, and how the engine's findings show it.

    Parameters
    ----------
    says : str
        What the parser does, after "its MJCF parser" (``"ignores armature"``).
    names : str
        What the names listed after it are (``"joints"``, ``"links"``).
    kind : Kind, optional
        The kind of the engine's finding that shows it.
    cause : str
        The id of the catalogued cause that shows it (a finding carrying it matches, whatever its kind).
    when : callable, optional
        ``when(finding, mj_model) -> bool``: whether a finding of that kind shows the limit on this model
        (None: always).
    """

    says: str
    names: str = "joints"
    kind: Kind | None = None
    cause: str = ""
    when: Callable[[Finding, Any], bool] | None = None

    def __post_init__(self) -> None:
        if self.kind is None and not self.cause:
            raise ValueError(f"parser limit {self.says!r}: declare the kind or the cause that shows it")

    def shown_by(self, finding: Finding, mj_model: Any) -> bool:
        """Whether a finding of the engine shows this limit on a model.

        Parameters
        ----------
        finding : Finding
        mj_model : mujoco.MjModel
            MuJoCo's compiled model (the reference reading of the file).

        Returns
        -------
        bool
        """
        if self.cause and finding.cause == self.cause:
            return self.when is None or self.when(finding, mj_model)
        if self.kind is None or finding.kind is not self.kind:
            return False
        return self.when is None or self.when(finding, mj_model)


def limits(engine: str) -> tuple[ParserLimit, ...]:
    """The limits an engine's subpackage declares (``engines/<name>/limits.py``), or none.

    Parameters
    ----------
    engine : str

    Returns
    -------
    tuple of ParserLimit
    """
    module = f"{ENGINES_PACKAGE}.{engine}.limits"
    if importlib.util.find_spec(module) is None:
        return ()
    declared: tuple[ParserLimit, ...] = importlib.import_module(module).LIMITS
    return declared


def one_of_several_joints(finding: Finding, mj_model: Any) -> bool:
    """Whether the finding's element is a joint of a body with several joints (in MuJoCo's reading).

    Parameters
    ----------
    finding : Finding
        Its element is ``"joint <name>"``.
    mj_model : mujoco.MjModel

    Returns
    -------
    bool
    """
    import mujoco

    tag, _, name = finding.element.partition(" ")
    if tag != "joint":
        return False
    k = mujoco.mj_name2id(mj_model, mujoco.mjtObj.mjOBJ_JOINT, name)
    if k < 0:
        return False
    body = int(mj_model.jnt_bodyid[k])
    return int(mj_model.body_jntnum[body]) > 1


def none_where_reference_has(finding: Finding, mj_model: Any) -> bool:
    """Whether the finding's values give the engine none of a quantity the reference engine has some of.

    Parameters
    ----------
    finding : Finding
        Its values carry the engine's and the reference engine's values by engine name.
    mj_model : mujoco.MjModel
        Unused (the values are the finding's).

    Returns
    -------
    bool
    """
    values, ref = finding.values, reference()
    if finding.engine not in values or ref not in values:
        return False
    own = np.asarray(values[finding.engine], dtype=float)
    return bool(np.all(own == 0)) and bool(np.any(np.asarray(values[ref], dtype=float) != 0))
