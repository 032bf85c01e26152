"""The gravity verdict of one model: every engine's gravity terms against MuJoCo's, and why they differ."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines import registry
from koenig_check.findings import Finding
from koenig_check.gravity.attribution import gravity_findings, springs
from koenig_check.gravity.readings import GravityReading, read_gravity
from koenig_check.roundoff import ROUNDOFF


@dataclass(frozen=True)
class Gap:
    """The largest difference of one engine's gravity quantity from the reference's.

    Attributes
    ----------
    engine : str
    quantity : {"g(q)", "dV"}
        ``g(q)`` or the potential-energy difference ``V(q) - V(q_ref)`` of gravity.
    relative : float
        ``|difference|`` at the worst entry over the reference's largest magnitude (the engine's, when the
        reference's is zero); 0 when the difference is round-off (at most ``ROUNDOFF`` times that magnitude, or
        ``ROUNDOFF`` itself below 1: a horizontal motion, where g(q) and dV are zero).
    absolute : float
        The signed difference (engine minus reference) at the worst entry.
    pose : int
        Index of the worst pose.
    dof : int
        Canonical dof of the worst entry (-1 for ``dV``).
    """

    engine: str
    quantity: str
    relative: float
    absolute: float
    pose: int
    dof: int = -1


def gap(engine: str, quantity: str, reference: np.ndarray, value: np.ndarray) -> Gap:
    """The worst entry of ``value - reference``, with its relative size.

    Parameters
    ----------
    engine, quantity : str
    reference, value : ndarray, shape (P,) or (P, nv)

    Returns
    -------
    Gap
    """
    ref = np.asarray(reference, dtype=float).reshape(reference.shape[0], -1)
    val = np.asarray(value, dtype=float).reshape(ref.shape)
    diff = val - ref
    if diff.size == 0:
        return Gap(engine, quantity, 0.0, 0.0, 0)
    pose, dof = np.unravel_index(int(np.argmax(np.abs(diff))), diff.shape)
    scale = float(np.abs(ref).max()) or float(np.abs(val).max())
    size = abs(float(diff[pose, dof]))
    rounding = size <= ROUNDOFF * max(1.0, scale)  # the project's round-off (1e-12): a motion gravity cannot see
    relative = size / scale if scale > 0 and not rounding else 0.0
    return Gap(engine, quantity, relative, float(diff[pose, dof]), int(pose), int(dof) if ref.shape[1] > 1 else -1)


@dataclass
class GravityParity:
    """Every engine's gravity terms on one model, compared with MuJoCo's.

    Attributes
    ----------
    readings : dict of str to GravityReading
    gaps : list of Gap
        Per engine other than the reference: ``g(q)`` and ``dV``.
    findings : list of Finding
        Why they differ (catalogued causes with ids, or a mass cause named once), and notes (URDF's
        default gravity, springs kept apart).
    explanations : list of Finding
        Those of :attr:`findings` that say why an engine differs, one per engine beyond tolerance.
    rtol : float
    left_out : dict of str to str
        Engines that could not report their gravity terms, and why.
    """

    readings: dict[str, GravityReading]
    gaps: list[Gap] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)
    explanations: list[Finding] = field(default_factory=list)
    rtol: float = 1e-9
    left_out: dict[str, str] = field(default_factory=dict)

    @property
    def agrees(self) -> bool:
        """Whether every engine's ``g(q)`` and ``dV`` are within ``rtol`` of the reference's."""
        return all(g.relative <= self.rtol for g in self.gaps)

    @property
    def worst(self) -> Gap | None:
        """The largest gap, or None without a second engine."""
        return max(self.gaps, key=lambda g: g.relative, default=None)

    def vectors(self) -> dict[str, tuple[float, ...]]:
        """Each engine's gravity vector as read from the file."""
        return {e: tuple(float(x) + 0.0 for x in r.vector) for e, r in self.readings.items()}

    def as_dict(self) -> dict[str, Any]:
        """A JSON-ready record of the verdict.

        Returns
        -------
        dict
        """
        return {
            "agrees": self.agrees,
            "rtol": self.rtol,
            "vectors": {e: list(v) for e, v in self.vectors().items()},
            "gaps": [vars(g) for g in self.gaps],
            "springs": {e: float(np.abs(r.dv_springs).max(initial=0.0)) for e, r in self.readings.items()},
            "left_out": dict(self.left_out),
            "findings": [f.as_dict() for f in self.findings],
        }


def gravity_parity(
    loaded: Any, qpos: np.ndarray, findings: list[Finding], rtol: float = 1e-9, engines: list[str] | None = None
) -> GravityParity:
    """Compare every loaded engine's gravity terms with MuJoCo's at ``qpos``, and name why they differ.

    Parameters
    ----------
    loaded : koenig_check.engines.LoadedModel
        Its ``engines`` (name to adapter) take part; ``mujoco`` is the reference.
    qpos : ndarray, shape (P, nq)
        Canonical positions (the run's poses).
    findings : list of Finding
        What is already known about the model (a mass cause there explains a ``g(q)`` difference).
    rtol : float
    engines : list of str, optional
        The engines that take part (default: every loaded one); the others are left out, and said so.

    Returns
    -------
    GravityParity
    """
    qref = np.asarray(loaded.mujoco.model.qpos0, dtype=float)
    readings: dict[str, GravityReading] = {}
    left_out: dict[str, str] = {}
    for name, engine in loaded.engines.items():
        if engine is None:
            continue
        if engines is not None and name not in engines:
            left_out[name] = "given another robot (see its findings): its gravity terms are not compared"
            continue
        try:
            readings[name] = read_gravity(engine, qpos, qref)
        except NotImplementedError as exc:
            left_out[name] = str(exc)
    reference = registry.reference()  # every model is loaded in it; it reads MJCF as written
    ref = readings[reference]
    gaps = []
    for name, r in readings.items():
        if name != reference:
            gaps += [gap(name, "g(q)", ref.g, r.g), gap(name, "dV", ref.dv_gravity, r.dv_gravity)]
    parity = GravityParity(readings, gaps, rtol=rtol, left_out=left_out)
    fmt = "urdf" if Path(loaded.path).suffix.lower() == ".urdf" else "mjcf"
    found = gravity_findings(parity, loaded.mujoco.model, str(loaded.path), fmt, findings)
    parity.explanations = [f for f in found if f.engine != "file"]  # URDF's note explains nothing
    parity.findings = found + springs(parity)
    return parity
