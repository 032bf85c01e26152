"""Constructs of an MJCF file that Pinocchio's (and Drake's) MJCF parsers read differently from MuJoCo, from the file.

Each is one :class:`~koenig_check.findings.Finding` with ``root_cause=True``: a ``<frame>`` skipped with
everything inside (for any engine whose catalogue declares it), and :func:`file_causes`, every cause the file
alone shows, gathered from the modules where each engine declares its own (Pinocchio's ``<include>``, root
bodies, bare bodies, ``<attach>``: :mod:`koenig_check.engines.pinocchio.file_traps` and its neighbours); and the
decorator that makes a load failure carry them.  What Pinocchio 4.1's ``buildModelFromMJCF`` does was verified on
small files (``tests/models/causes/``): see :mod:`koenig_check.diagnosis.pair_causes` for the causes read from both
engines' loaded models.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import Any, TypeVar, cast

import mujoco

from koenig_check.engines.canonical import segment_of_body
from koenig_check.engines.catalogue import cause
from koenig_check.engines.pinocchio.attached_models import attach_causes
from koenig_check.engines.pinocchio.bare_bodies import bare_body_causes
from koenig_check.engines.pinocchio.file_traps import FRAME, about_z, include_causes, planar_cause, root_body_causes
from koenig_check.engines.registry import label
from koenig_check.engines.replicates import replicate_causes
from koenig_check.engines.unit_axes import axisangle_causes
from koenig_check.exceptions import (
    CoupledJointsError,
    InertiaError,
    JointMismatch,
    ModelLoadError,
    NoMovingSegmentError,
)
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.mjcf import frames, includes, read_mjcf
from koenig_check.modelfile.urdf_links import planar_axes

F = TypeVar("F", bound=Callable[..., Any])


def frame_causes(root: ET.Element, seg_of: dict[str, str], engine: str) -> list[Finding]:
    """The ``<frame>`` elements an engine's MJCF parser does not read, with what they hold.

    MuJoCo resolves a ``<frame>`` at compile time (its pose moves every child); Pinocchio 4.1's and
    Drake's MJCF parsers skip the element and everything inside it: its bodies (with their joints) and
    the geoms it adds to the enclosing body, whose mass and inertia the segment then lacks.

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The MJCF document.
    seg_of : dict of str to str
        Body name to the segment (joint) that moves it, from MuJoCo's compiled model.
    engine : str
        The engine whose parser skips ``<frame>``.

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause per outermost frame that holds a body or a geom, an instance of
        :func:`frame_cause`; none for an engine the catalogue does not say skips ``<frame>``.
    """
    cause_id = frame_cause(engine)
    if not cause_id:
        return []
    parser = f"{label(engine)}'s"
    out = []
    for fr in frames(root):
        if not fr.bodies and not fr.geoms:
            continue
        held = [f"{len(fr.bodies)} bodies", f"{len(fr.joints)} joints"] if fr.bodies else []
        if fr.geoms:
            held.append(f"{fr.geoms} geoms of body {fr.enclosing}" if fr.enclosing else f"{fr.geoms} world geoms")
        moved = tuple(dict.fromkeys(seg_of[b] for b in (*fr.bodies, fr.enclosing or "") if seg_of.get(b)))
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                engine,
                f"frame {fr.label} in {fr.where}",
                f"<frame> not read by {parser} MJCF parser: what it holds is missing ({', '.join(held)})",
                values={"bodies": fr.bodies, "joints": fr.joints, "geoms": fr.geoms},
                affects_energy=bool(fr.joints or moved),
                root_cause=True,
                segments=moved or fr.joints,
                hint="give the bodies and geoms inside it the frame's pose and remove the <frame> "
                "(MuJoCo resolves it at compile time)",
                cause=cause_id,
                tag="frame",
            )
        )
    return out


def frame_cause(engine: str) -> str:
    """The id of the cause "``<frame>`` not read by this engine's MJCF parser", or empty when none is declared.

    Parameters
    ----------
    engine : str

    Returns
    -------
    str
    """
    from koenig_check.engines.catalogue import catalogue

    cause_id = f"{engine}.mjcf.frame"
    return cause_id if any(c.id == cause_id for c in catalogue()) else ""


def file_causes(path: str | os.PathLike[str], mj_model: mujoco.MjModel | None = None) -> list[Finding]:
    """Root causes visible in the file alone: ignored ``<include>`` and ``<frame>``, the root bodies Pinocchio skips.

    Used when Pinocchio cannot load the file or its joints cannot be paired with MuJoCo's, and for every
    model loaded in both engines.

    Parameters
    ----------
    path : str or path
        An MJCF file (anything else gives no cause).
    mj_model : mujoco.MjModel, optional
        MuJoCo's compiled model of the file: tells which included bodies move (a jointless subtree
        included in a moving body carries mass of that segment).

    Returns
    -------
    list of Finding
    """
    path = Path(path)
    root = read_mjcf(path)
    if root is None:
        return []
    seg_of = {} if mj_model is None else segment_of_body(mj_model)
    world_bodies = [b for w in root.findall("worldbody") for b in w.findall("body")]
    out = include_causes(includes(root, path.parent), seg_of, bool(world_bodies))
    out += frame_causes(root, seg_of, cause(FRAME).engine)
    out += attach_causes(root, path.parent, mj_model)
    out += bare_body_causes(root, seg_of)
    out += axisangle_causes(root, seg_of)
    out += replicate_causes(root, seg_of)
    out += root_body_causes(world_bodies)
    return out


def moving_advice(mj_model: Any, urdf: bool) -> str:
    """What would make a model without joints move: ``--floating`` for one top-level body, else a joint.

    A URDF has one root link, which ``--floating`` frees (MuJoCo fuses it into the world when it is static).

    Parameters
    ----------
    mj_model : mujoco.MjModel
    urdf : bool
        Whether the file is a URDF.

    Returns
    -------
    str
    """
    if urdf:
        return "--floating, floating=True, gives the root link a free joint"
    roots = [mj_model.body(i).name or f"#{i}" for i in range(1, mj_model.nbody) if mj_model.body_parentid[i] == 0]
    if len(roots) == 1:
        return "--floating, floating=True, gives the root body a free joint"
    if not roots:
        return "the <worldbody> holds no <body>"
    shown = ", ".join(roots[:3]) + (f" and {len(roots) - 3} more" if len(roots) > 3 else "")
    return f"{len(roots)} top-level bodies ({shown}): --floating frees one only; give each that moves a joint"


def nothing_moves(path: str | os.PathLike[str], has_body: bool = True, advice: str = "") -> Finding:
    """The finding for a model without a joint: nothing to compare, not an engine error.

    Parameters
    ----------
    path : str or path
    has_body : bool
        Whether the model has a body that ``--floating`` could set free.
    advice : str
        What would make it move (:func:`moving_advice`); by default ``--floating``.

    Returns
    -------
    Finding
    """
    return Finding(
        Kind.NOTHING_MOVES,
        "file",
        "model",
        "no joint: nothing moves, so there is no kinetic energy to compare (not an engine error)"
        + ("" if has_body else "; the <worldbody> holds no <body>"),
        values={"file": str(path)},
        root_cause=True,
        hint=(advice or "--floating (floating=True) gives the root body a free joint") if has_body else "",
        brief="no joint: nothing moves, so there is no kinetic energy to compare",
    )


def explain_load_failures(load: F) -> F:
    """Decorate a loader so that its load errors carry the file's root causes.

    The error keeps its type; ``err.causes`` (:attr:`~koenig_check.exceptions.KoenigCheckError.causes`) is
    the tuple of root causes (possibly empty) and, when there are any, the one-line message ends with them.
    A model without a joint gets :func:`nothing_moves`.

    Parameters
    ----------
    load : callable
        ``load_model(path_or_name, ...)``.

    Returns
    -------
    callable
    """

    @wraps(load)
    def wrapper(path_or_name: Any, *args: Any, **kwargs: Any) -> Any:
        try:
            return load(path_or_name, *args, **kwargs)
        except NoMovingSegmentError as err:
            err.attach_causes([nothing_moves(getattr(err, "path", path_or_name), advice=err.advice)], in_message=False)
            raise
        except (CoupledJointsError, InertiaError) as err:  # MuJoCo's refusal or the file's couplings
            err.attach_causes([])
            raise
        except (ModelLoadError, JointMismatch) as err:
            err.attach_causes(_file_causes_of(path_or_name, kwargs.get("fmt")))
            raise

    return cast("F", wrapper)


def _file_causes_of(path_or_name: Any, fmt: str | None) -> list[Finding]:
    from koenig_check.sources.catalogue import resolve_model

    try:
        source = resolve_model(path_or_name, fmt)
    except Exception:  # the original error says what is wrong with the name
        return []
    if source.format == "urdf":
        return [planar_cause(name, axis) for name, axis in planar_axes(source.path).items() if not about_z(axis)]
    if source.format != "mjcf":
        return []
    try:
        model = mujoco.MjModel.from_xml_path(str(source.path))
    except Exception:  # MuJoCo refuses the file itself: Pinocchio's reading of it is not the cause
        return []
    if model.njnt == 0:  # e.g. a <worldbody> without a <body>: Pinocchio fails, but nothing moves anyway
        return [nothing_moves(source.path, has_body=model.nbody > 1, advice=moving_advice(model, urdf=False))]
    return file_causes(source.path, model)
