"""Drake attached to a model already loaded in MuJoCo and Pinocchio, with the constructs its parser misreads."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from koenig_check.engines.armature_readings import armature_differences
from koenig_check.engines.base import Engine
from koenig_check.engines.registry import not_used
from koenig_check.exceptions import one_line
from koenig_check.findings import Finding, Kind


def attach(model: Any) -> tuple[Engine | None, list[Finding]]:
    """Load a model's file in Drake, paired with MuJoCo's joints.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel

    Returns
    -------
    engine : DrakeEngine or None
        None when Drake cannot check this model.
    findings : list of Finding
        Drake's load findings, the armature Drake's parser does not read and the ``<frame>`` elements it
        skips; or one ``ENGINE_NOT_USED`` finding with Drake's whole reason on one line.
    """
    from koenig_check.engines.drake.building import load_drake_engine
    from koenig_check.engines.drake.loader import DrakeLoadError

    if model.options.pinocchio_model is not None:
        return None, [not_used("drake", "Pinocchio was given another file (--pinocchio-model)")]
    from koenig_check.engines.drake.failures import failed_check

    try:
        engine = load_drake_engine(model.source, model.mujoco.model)
    except SystemExit as exit_:  # a failed C++ check of Drake's: its reason, not the end of the run
        reason = failed_check(exit_)
        if reason is None:
            raise
        return None, [_refusal(model, f"Drake cannot load the model: {reason}")]
    except DrakeLoadError as err:  # Drake's reason; the model's row and label already name the file
        return None, [_refusal(model, one_line(err).removeprefix(f"{model.source.path}: "))]
    except ImportError as err:  # installed but not importable
        return None, [not_used("drake", f"pydrake cannot be imported: {one_line(err)}")]
    return engine, list(engine.findings) + armature_findings(model, engine) + _file_causes(model)


def _refusal(model: Any, reason: str) -> Finding:
    """Drake's refusal, with the catalogued cause whose construct the file shows (read from the file, not the text)."""
    from dataclasses import replace

    from koenig_check.engines.refusals import refusal_cause

    return replace(not_used("drake", reason), cause=refusal_cause("drake", model.source.path, model.source.format))


def _file_causes(model: Any) -> list[Finding]:
    """The constructs of an MJCF file that Drake's parser skips: ``<frame>``, inline meshes (measured on 1.51)."""
    from koenig_check.engines.canonical import segment_of_body
    from koenig_check.engines.drake.inline_meshes import inline_mesh_causes
    from koenig_check.engines.parser_traps import frame_causes
    from koenig_check.modelfile.mjcf import read_mjcf

    if model.source.format != "mjcf":
        return []
    path = Path(str(model.source.path))
    root = read_mjcf(path)
    frames = [] if root is None else frame_causes(root, segment_of_body(model.mujoco.model), engine="drake")
    return frames + inline_mesh_causes(path, model.mujoco.model)


def armature_findings(model: Any, drake: Any) -> list[Finding]:
    """Joints whose armature MuJoCo has but Drake's model lacks (Drake's MJCF parser reads it where a motor drives).

    Which joints differ is read by :func:`koenig_check.engines.armature_readings.armature_differences`, the same
    for any engine; what the difference means is Drake's, said here.

    Parameters
    ----------
    model : LoadedModel
    drake : DrakeEngine

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause naming the joints, when any.
    """
    differences = armature_differences(model, drake)  # the engine-independent part, read the same for any engine
    joints, extension = differences.missing, differences.added
    out = []
    if extension:
        out.append(
            Finding(
                Kind.ARMATURE,
                "drake",
                "actuators of joints " + ", ".join(extension),
                "reflected inertia (rotor inertia × gear ratio², Drake's URDF/MJCF actuator data) that MuJoCo's "
                "armature does not match",
                {
                    "joints": extension,
                    "drake": [differences.engine[j] for j in extension],
                },
                affects_energy=True,
                root_cause=True,
                segments=tuple(extension),
                cause="drake.urdf.reflected-inertia" if model.source.format == "urdf" else "",
            )
        )
    if not joints or model.source.format != "mjcf":
        return out
    return [
        *out,
        Finding(
            Kind.IGNORED_CONSTRUCT,
            "drake",
            "joint armature",
            "Drake's MJCF parser does not read the armature of a joint no motor drives (a driven joint's it "
            "reads as the motor's reflected inertia, rotor inertia × gear ratio²)",
            {
                "joints": joints,
                "mujoco armature": [differences.mujoco[j] for j in joints],
            },
            affects_energy=True,
            root_cause=True,
            segments=tuple(joints),
            cause="drake.mjcf.unactuated-armature",
            tag="joint",
        ),
    ]
