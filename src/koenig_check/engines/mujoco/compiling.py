"""Compiling an ``MjSpec``: meshes MuJoCo refuses dropped one by one, inertia it refuses repaired or refused.

A refusal is an :class:`~koenig_check.engines.errors.InertiaError` or
:class:`~koenig_check.engines.errors.ModelLoadError` whose one-line message names the file and the element;
MuJoCo's warnings become findings, and each body repaired a ``REPAIR`` finding.
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Iterator
from contextlib import contextmanager

import mujoco
import numpy as np

from koenig_check.engines.errors import InertiaError, ModelLoadError
from koenig_check.engines.mujoco.inertia_repair import Repair, repair_body
from koenig_check.engines.mujoco.mass_changes import BodyFinding
from koenig_check.engines.mujoco.meshes import drop_mesh, inertia_only, mass_geoms, mass_mesh_error
from koenig_check.findings import Finding, Kind
from koenig_check.roundoff import relative_zeros
from koenig_check.segments import check_physical_inertia, principal_moments
from koenig_check.sources.catalogue import ModelSource

_ELEMENT = re.compile(r"Element name '([^']*)'")
#: MuJoCo's element line: its name, its index among the elements of its type, the line of the file.
_ELEMENT_AT = re.compile(r"Element name '([^']*)', id (\d+)(?:, line (\d+))?")
#: Compilations tried per body under repair (the balance margin grows tenfold each time).
MAX_REPAIR_TRIES = 3
#: What a refusal says would load the file.
REPAIR_HINT = "--repair-inertia (repair_inertia=True) loads it with the smallest change MuJoCo accepts, recorded"


def _warning(message: str) -> Finding:
    return Finding(Kind.LOAD, "mujoco", "model", f"compiler warning: {message}")


@contextmanager
def captured_warnings(notes: list[Finding]) -> Iterator[None]:
    """Route MuJoCo's warnings (printed and written to MUJOCO_LOG.TXT by default) into the findings.

    Parameters
    ----------
    notes : list of Finding
        Receives one ``LOAD`` finding per distinct warning when the block ends.
    """
    previous = mujoco.get_mju_user_warning()
    seen: list[str] = []
    mujoco.set_mju_user_warning(seen.append)
    try:
        yield
    finally:
        mujoco.set_mju_user_warning(previous)
        notes.extend(_warning(m) for m in dict.fromkeys(seen))


def mujoco_reason(exc: BaseException) -> str:
    """MuJoCo's message on one line, without its ``Error:``: every line joined with '; ' (element and line kept).

    Unlike :func:`koenig_check.exceptions.one_line`, the lines stay apart (``; ``): :func:`compile_spec` reads the
    refusal before ``; Element name``.

    Parameters
    ----------
    exc : BaseException
        What MuJoCo raised.

    Returns
    -------
    str
    """
    text = str(exc).strip()
    if text.startswith("Error:"):
        text = text[len("Error:") :].strip()
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return "; ".join(lines) if lines else type(exc).__name__


def _moments_text(inertia: np.ndarray) -> str:
    return relative_zeros(principal_moments(inertia))


def _inertia_error(
    source: ModelSource, element: str, message: str, file_inertia: dict[str, tuple[float, np.ndarray]]
) -> InertiaError:
    what = "link" if source.format == "urdf" else "body"
    head = f"{source.path}: {what} {element!r}: MuJoCo rejects its inertia ({message})"
    if element in file_inertia:
        mass, inertia = file_inertia[element]
        reason = check_physical_inertia(mass, inertia)
        if reason is None:
            reason = f"principal moments {_moments_text(inertia)}, MuJoCo requires them strictly positive"
        head += f"; {reason}"
    head += f"; {REPAIR_HINT}"
    if "A + B >= C" in message:
        head += " (or --balance-inertia, balance_inertia=True: MuJoCo's balanceinertia)"
    error = InertiaError(head)
    error.hint = "--repair-inertia (repair_inertia=True) loads it with the smallest change MuJoCo accepts, recorded" + (
        "; or --balance-inertia (balance_inertia=True): MuJoCo's balanceinertia" if "A + B >= C" in message else ""
    )
    error.brief = (  # one line: the link, MuJoCo's reason, what loads it (the moments are in the message)
        f"{source.path}: {what} {element!r}: MuJoCo rejects its inertia ({_refusal(message)}); "
        "--repair-inertia loads it with the smallest change MuJoCo accepts"
    )
    return error


def repair_finding(repair: Repair, message: str, what: str) -> Finding:
    """The ``REPAIR`` finding of a body repaired so that MuJoCo accepts it.

    Parameters
    ----------
    repair : Repair
        The body and its mass and moments before and after.
    message : str
        MuJoCo's refusal (its first line).
    what : str
        ``"link"`` (URDF) or ``"body"`` (MJCF).

    Returns
    -------
    Finding
    """
    return Finding(
        Kind.REPAIR,
        "mujoco",
        f"{what} {repair.body}",
        "inertia changed so that MuJoCo accepts it (mass and principal moments raised to MuJoCo's bounds and "
        "balanced, A + B >= C); Pinocchio keeps the file's values",
        {
            "mass before": repair.mass[0],
            "mass after": repair.mass[1],
            "moments before": list(repair.moments[0]),
            "moments after": list(repair.moments[1]),
            "max moment change": repair.max_change,
            "refused for": _refusal(message),
        },
        affects_energy=True,
        root_cause=True,
        brief="inertia changed so that MuJoCo accepts it",
        tag=what,
    )


def _refusal(message: str) -> str:
    """MuJoCo's reason without the element and line it names (the finding names the link)."""
    return message.split("; Element name")[0].removeprefix("error ").strip()


def refused_geom(spec: mujoco.MjSpec, exc: BaseException, what: str = "body") -> str | None:
    """The geom a MuJoCo refusal is about, as the user finds it in the file; ``None`` when it is about no geom.

    MuJoCo names the element by its name and its index among all geoms (``"... in geom; Element name '', id 3,
    line 12"``): an unnamed geom's name is empty, so its body and place among the body's geoms name it.

    Parameters
    ----------
    spec : mujoco.MjSpec
        The spec MuJoCo compiled (its geoms in MuJoCo's order).
    exc : BaseException
        What MuJoCo raised.
    what : str
        ``"body"`` (MJCF) or ``"link"`` (URDF).

    Returns
    -------
    str or None
        ``"body 'arm', geom #2 (unnamed, line 12)"`` or ``"body 'arm', geom 'rod' (line 12)"``.
    """
    text = str(exc)
    head = text.split("Element name")[0].strip()
    match = _ELEMENT_AT.search(text)
    if not head.endswith(" in geom") or match is None:
        return None
    name, index, line = match.group(1), int(match.group(2)), match.group(3)
    geoms = list(spec.geoms)
    geom = geoms[index] if index < len(geoms) and geoms[index].name == name else None
    if geom is None and name:
        geom = next((g for g in geoms if g.name == name), None)
    if geom is None:
        return None
    body = geom.parent
    place = next(k for k, g in enumerate(body.geoms, start=1) if g == geom)
    notes = ([] if name else ["unnamed"]) + ([f"line {line}"] if line else [])
    label = (f"geom {name!r}" if name else f"geom #{place}") + (f" ({', '.join(notes)})" if notes else "")
    return f"{what} {body.name!r}, {label}"


def _fusions(spec: mujoco.MjSpec) -> list[tuple[str, str]]:
    """(static body, the moving body it is fused into) for every static body under a moving one."""
    out = []
    for body in spec.bodies:
        carrier = body
        while carrier is not None and carrier.name != "world" and not list(carrier.joints):
            carrier = carrier.parent
        if body != carrier and carrier is not None and carrier.name != "world":
            out.append((body.name, carrier.name))
    return out


def fusion_refusal(pairs: list[tuple[str, str]], what: str, message: str) -> str:
    """MuJoCo's refusal of a fused inertia, naming the static bodies and the bodies they fuse into.

    Parameters
    ----------
    pairs : list of (str, str)
        Each static body and the moving body it is fused into (read before compiling: a failed compilation
        leaves the spec unreadable).
    what : str
        ``"link"`` or ``"body"``.
    message : str
        MuJoCo's reason (it names no body).

    Returns
    -------
    str
    """
    named = ", ".join(f"{child!r} into {parent!r}" for child, parent in pairs[:4])
    named += f" and {len(pairs) - 4} more" if len(pairs) > 4 else ""  # counted, never "…"
    where = f": {named}" if pairs else ""
    return f"MuJoCo rejects the inertia of static {what}s fused into their parent ({_refusal(message)}){where}"


def unfused_finding(pairs: list[tuple[str, str]], what: str, message: str) -> Finding:
    """The ``LOAD`` finding of a model compiled without ``fusestatic`` because a fused inertia was refused.

    Parameters
    ----------
    pairs : list of (str, str)
        Each static body and the moving body it would have been fused into.
    what : str
    message : str
        MuJoCo's refusal.

    Returns
    -------
    Finding
    """
    return Finding(
        Kind.LOAD,
        "mujoco",
        "compiler fusestatic",
        f"static {what}s kept apart (fusestatic off): MuJoCo refused the inertia of the fused {what}s, "
        f"{_refusal(message)}; the mass and inertia of each segment are the same",
        {"fusions": [f"{child} into {parent}" for child, parent in pairs]},
    )


def compile_spec(
    spec: mujoco.MjSpec,
    source: ModelSource,
    notes: list[Finding],
    file_inertia: dict[str, tuple[float, np.ndarray]],
    repair: bool = False,
) -> tuple[mujoco.MjModel, list[str], list[BodyFinding]]:
    """Compile, dropping meshes MuJoCo refuses one by one; raise clear errors otherwise.

    With ``repair``, a body whose mass or inertia MuJoCo refuses is repaired in ``spec``
    (:func:`~koenig_check.engines.mujoco.inertia_repair.repair_body`) and a copy compiled again (a failed
    compilation leaves the spec's static bodies fused).

    Parameters
    ----------
    spec : mujoco.MjSpec
    source : ModelSource
        The file (named in the errors).
    notes : list of Finding
        Receives the compiler's warnings and the meshes dropped.
    file_inertia : dict of str to (float, ndarray)
        Each body's mass and inertia as the file declares them.
    repair : bool

    Returns
    -------
    model : mujoco.MjModel
    refused : list of str
        The meshes dropped on the way.
    repairs : list of (str, Finding)
        A ``REPAIR`` finding per body repaired.

    Raises
    ------
    InertiaError, ModelLoadError
    """
    refused: list[str] = []
    reasons: list[str] = []
    files: list[str] = []
    losers: list[str] = []
    repairs: dict[str, tuple[Repair, str]] = {}
    tries: dict[str, int] = {}
    what = "link" if source.format == "urdf" else "body"
    fusions = _fusions(spec)
    while True:
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                model = (spec.copy() if repair else spec).compile()
            notes.extend(_warning(str(w.message)) for w in caught)
        except ValueError as exc:
            message = mujoco_reason(exc)
            match = _ELEMENT.search(str(exc))
            element = match.group(1) if match else ""
            mesh = next(
                (m for m in spec.meshes if (element and m.name == element) or (m.file and m.file in str(exc))),
                None,
            )
            if mesh is not None:
                geoms = mass_geoms(spec, mesh)
                if geoms:  # dropped, its body would have no mass: MuJoCo's refusal of the mesh is the reason
                    raise mass_mesh_error(source.path, mesh, f"refused by MuJoCo ({message})", geoms) from exc
                refused.append(mesh.name)
                reasons.append(message)
                files.append(mesh.file)
                losers += drop_mesh(spec, mesh)
                continue
            geom = refused_geom(spec, exc, what)
            if geom is not None:  # a geom's own value (a negative mass or density): no body repair changes it
                raise ModelLoadError(f"{source.path}: {geom}: MuJoCo rejects it ({_refusal(message)})") from exc
            if "fusing static body inertias" in message and spec.compiler.fusestatic:
                if not repair:  # MuJoCo names no body: the static links and the links they would fuse into
                    raise InertiaError(
                        f"{source.path}: {fusion_refusal(fusions, what, message)}; {REPAIR_HINT}"
                    ) from exc
                spec.compiler.fusestatic = False  # each body then stands alone: the one refused is named, repaired
                notes.append(unfused_finding(fusions, what, message))
                continue
            if "inertia" in message or "mass" in message:
                body = spec.body(element) if element else None
                if repair and body is not None and tries.get(element, 0) < MAX_REPAIR_TRIES:
                    tries[element] = tries.get(element, 0) + 1
                    done = repair_body(body, margin=8.0 * 10 ** (tries[element] - 1))
                    first = repairs.get(element)
                    if first is not None:  # a second pass: before = the file's values
                        done = Repair(
                            done.body, (first[0].mass[0], done.mass[1]), (first[0].moments[0], done.moments[1])
                        )
                    repairs[element] = (done, first[1] if first else message)
                    continue
                if "moving bodies" in message:
                    raise InertiaError(
                        f"{source.path}: {what} {element!r}: MuJoCo rejects a moving body without mass or "
                        f"inertia ({message}); Pinocchio accepts it; {REPAIR_HINT}"
                    ) from exc
                raise _inertia_error(source, element, message, file_inertia) from exc
            where = f" at element {element!r}" if element else ""
            raise ModelLoadError(f"{source.path}: MuJoCo cannot compile the model{where}: {message}") from exc
        if refused:
            notes.append(inertia_only(spec, "MuJoCo refused to compile them: " + "; ".join(reasons), files, losers))
        return model, refused, [(n, repair_finding(r, m, what)) for n, (r, m) in repairs.items()]
