"""The import parity report for the terminal: root causes, then one row per segment and per dof."""

from __future__ import annotations

from koenig_check.diagnosis.import_parity import ParityReport
from koenig_check.line_width import fold_text, hanging
from koenig_check.roundoff import ROUNDOFF, shown, side_by_side


def format_parity(report: ParityReport, model: str = "") -> str:
    """Render a parity report for the terminal, every line within 200 characters.

    A long cause is folded onto indented continuation lines; a row's long verdict continues under its column.

    Parameters
    ----------
    report : ParityReport
    model : str
        The model as the user named it (default: the report's path).

    Returns
    -------
    str
    """
    from koenig_check.diagnosis.reason import rounding_hint

    lines = [f"Import parity of {model or report.model} (relative tolerance {report.rtol:g})"]
    # a segment as the user wrote it: its link or body, and the joint that moves it
    names = {s.name: report.label(s.name).removeprefix("segment ") for s in report.segments}
    width = min(max([28, *map(len, names.values())]), _NAME_WIDTH)
    if report.causes:
        lines.append("\nroot causes:")
        for c in report.causes:
            effect = "changes the kinetic energy" if c.affects_energy else "no effect on the kinetic energy"
            lines.append(f"  - [{c.kind.value}, {effect}] {c.message()}")
        lines.append("")
    mujoco, pinocchio, whole = side_by_side([*report.total_mass, report.model_mass])  # the same digits each
    lines += [
        f"moving mass: MuJoCo {mujoco} kg, Pinocchio {pinocchio} kg "
        f"(the whole model in Pinocchio: {whole} kg, static bodies included)",
        f"mass matrices differ by at most {report.mass_matrix_max_rel:.2e} relative",
        "",
        f"{'segment':{width}s} {'mass MuJoCo':>13s} {'mass Pin.':>13s} {'|ΔCOM| m':>10s} {'|ΔI|_F':>10s} "
        f"{'|Δanchor| m':>11s}  principal moments MuJoCo / Pinocchio   verdict",
    ]
    for s in report.segments:
        pm = (
            " ".join(f"{v:.4g}" for v in s.principal_moments[0])
            + " / "
            + " ".join(f"{v:.4g}" for v in s.principal_moments[1])
        )
        verdict = "same" if not s.causes else "DIFFERS: " + _sized(s.causes, s.relative)
        cells = (
            f"{names[s.name][:width]:{width}s} {s.mass[0]:13.6g} {s.mass[1]:13.6g} {s.com_distance:10.2e} "
            f"{s.inertia_frobenius:10.2e} {s.pole_distance:11.2e}  {pm:38s} "
        )
        lines += hanging(cells, verdict)
    lines += [
        "",
        f"{'dof':24s} {'armature MuJoCo':>16s} {'armature Pin.':>14s} {'|ΔJacobian|':>12s}  verdict",
    ]
    for d in report.dofs:
        verdict = "same" if not d.causes else "DIFFERS: " + _sized(d.causes, d.relative)
        if d.missing:  # no Jacobian of its own segment in one engine: say which, never print nan
            verdict = f"Jacobian not compared: {d.missing}" + ("" if not d.causes else f"; {verdict}")
        jacobian = "—" if d.missing else f"{d.jacobian_difference:.2e}"
        cells = f"{d.joint[:24]:24s} {shown(d.armature[0]):16.6g} {shown(d.armature[1]):14.6g} {jacobian:>12s}  "
        lines += hanging(cells, verdict)
    lines.append(f"(armature values below {ROUNDOFF:g} kg m² are rounding, printed as 0)")
    if report.only_in_mujoco:
        lines.append(f"\nsegments only in MuJoCo: {report.only_in_mujoco}")
    if report.only_in_pinocchio:
        lines.append(f"segments only in Pinocchio: {report.only_in_pinocchio}")
    if report.massless_in_pinocchio:
        lines.append(f"segments massless in Pinocchio: {report.massless_in_pinocchio}")
    if report.massless_in_mujoco:
        lines.append(f"segments massless in MuJoCo: {report.massless_in_mujoco}")
    if report.findings:
        lines.append("\nfindings:")
        lines += [f"  - {f}" for f in report.findings]
    hint = "" if report.clean else rounding_hint(report.largest_relative(), report.rtol, cli=True)
    verdict = "no import difference" if report.clean else hint or report.headline(brief=True)
    lines.append(f"\nverdict: {verdict}")
    return fold_text("\n".join(lines))


#: The widest segment column (a longer link and joint name is cut).
_NAME_WIDTH = 48


def _sized(causes: tuple[str, ...], relative: dict[str, float]) -> str:
    """The differing quantities, each with its relative size: values equal to the printed digits still differ."""
    return ", ".join(f"{c} ({relative[c]:.2g} relative)" if c in relative else c for c in causes)
