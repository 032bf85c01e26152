"""``koenig_check.export``: write a model for another engine or format, then prove it is the same robot."""

from __future__ import annotations

import os
from pathlib import Path

from koenig_check.arguments import ArgumentValueError
from koenig_check.engines.load_options import LoadOptions, parse_engines
from koenig_check.engines.mujoco.loader import load_mujoco
from koenig_check.engines.registry import mjcf_mesh_formats, names
from koenig_check.engines.specs import ALL
from koenig_check.export.carried import NotCarried
from koenig_check.export.mjcf_from_urdf import write_mjcf_from_urdf
from koenig_check.export.portable_mjcf import write_portable_mjcf
from koenig_check.export.proof import PROOF_POSES, PROOF_RTOL, prove
from koenig_check.export.result import ExportResult
from koenig_check.export.urdf_writer import write_urdf
from koenig_check.sources.catalogue import resolve_model

#: The formats an export writes.
TARGETS = ("urdf", "mjcf")


def check_export_arguments(
    model: str | os.PathLike[str], to: str, out: str | os.PathLike[str], poses: int, rtol: float
) -> None:
    """Refuse unusable arguments before any work (``ArgumentValueError``, a usage error).

    Parameters
    ----------
    model, to, out, poses, rtol
        As :func:`export_model`.
    """
    if to not in TARGETS:
        raise ArgumentValueError(f"to must be one of {', '.join(TARGETS)}, got {to!r}")
    target = Path(out)
    suffix = {"urdf": ".urdf", "mjcf": ".xml"}[to]
    if target.suffix.lower() != suffix:
        raise ArgumentValueError(f"out {str(out)!r}: a {to.upper()} file is read by its suffix; name it *{suffix}")
    if target.is_dir():
        raise ArgumentValueError(f"out {str(out)!r} is a directory; give the file to write")
    if not target.resolve().parent.is_dir():
        raise ArgumentValueError(f"out {str(out)!r}: its directory does not exist")  # the path named once
    if Path(model).exists() and target.resolve() == Path(model).resolve():
        raise ArgumentValueError(f"out {str(out)!r} is the model file itself")
    if poses < 1:
        raise ArgumentValueError(f"poses must be >= 1, got {poses}")
    if not 0 < rtol < 1:
        raise ArgumentValueError(f"rtol must be in (0, 1), got {rtol}")


def export_model(
    model: str | os.PathLike[str],
    *,
    to: str,
    out: str | os.PathLike[str],
    floating: bool = False,
    repair_inertia: bool = False,
    balance_inertia: bool = False,
    drake_extensions: bool = False,
    poses: int = PROOF_POSES,
    seed: int = 0,
    rtol: float = PROOF_RTOL,
    engines: tuple[str, ...] | str | None = None,
) -> ExportResult:
    """Write ``model`` as URDF or portable MJCF, load it back and compare it with the original.

    Parameters
    ----------
    model : str or path
        A model file, or a name from ``koenig-check models``.
    to : {"urdf", "mjcf"}
        The target format (an MJCF written as MJCF is the portable form).
    out : str or path
        The file to write.
    floating, repair_inertia, balance_inertia : bool
        Load options of the original (:class:`~koenig_check.engines.load_options.LoadOptions`).
    drake_extensions : bool
        URDF: write armature as Drake's ``drake:rotor_inertia``.
    poses, seed, rtol
        The proof's seeded random poses and relative tolerance.
    engines : tuple of str or "all", optional
        Engines the proof uses (those not installed are reported, not run); default: every engine that reads the
        export's format (:func:`koenig_check.export.proof.prove`); ``"all"``: every installed engine that reads
        both files' formats, each asked for.  An MJCF
        for engines without Drake keeps mesh geoms of every format MuJoCo reads (Drake's MJCF parser reads
        ``.obj`` only: with Drake, other meshes are listed as not carried; the inertia is explicit either way).

    Returns
    -------
    ExportResult

    Raises
    ------
    ArgumentValueError
        Bad arguments, before any work.
    koenig_check.export.carried.ExportRefusedError
        The target cannot hold the robot (a ball joint in URDF), naming the joints.
    koenig_check.engines.ModelLoadError
        MuJoCo cannot load the original.
    """
    check_export_arguments(model, to, out, poses, rtol)
    if isinstance(engines, str):
        engines = parse_engines(engines)  # "all", or "mujoco,pinocchio,newton"
    options = LoadOptions(floating=floating, repair_inertia=repair_inertia, balance_inertia=balance_inertia)
    source = resolve_model(model)
    mj_model, findings, body_findings = load_mujoco(
        source, floating=floating, balance_inertia=balance_inertia, repair_inertia=repair_inertia
    )
    name = source.path.stem
    mesh_formats = mjcf_mesh_formats(names() if engines in (None, (ALL,)) else engines)  # the proof's readers
    not_carried: list[NotCarried]
    if to == "urdf":
        text, not_carried = write_urdf(
            mj_model, out, robot_name=name, drake_extensions=drake_extensions, model_dir=source.path.parent
        )
    elif source.format == "urdf":
        text, not_carried = write_mjcf_from_urdf(
            mj_model,
            findings,
            body_findings,
            out,
            model_name=name,
            model_dir=source.path.parent,
            mesh_formats=mesh_formats,
        )
    else:
        text, not_carried = write_portable_mjcf(
            mj_model, out, model_name=name, model_dir=source.path.parent, mesh_formats=mesh_formats
        )
    Path(out).write_text(text, encoding="utf-8")
    proof = prove(source.path, out, options, poses=poses, seed=seed, rtol=rtol, engines=engines)
    floating_base = any(n.construct == "floating base" for n in not_carried)
    return ExportResult(Path(out), to, tuple(not_carried), proof, floating_base)
