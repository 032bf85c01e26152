"""The import parity report for the terminal: root causes, then one row per segment and per dof."""

from __future__ import annotations

from koenig_check.diagnosis.import_parity import ParityReport
from koenig_check.report.line_width import fold_text, hanging
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
    lines = [f"Import parity of {model or report.model} (relative tolerance {report.rtol:g})"]
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
        f"{'segment':28s} {'mass MuJoCo':>13s} {'mass Pin.':>13s} {'|ΔCOM| m':>10s} {'|ΔI|_F':>10s} "
        f"{'|Δanchor| m':>11s}  principal moments MuJoCo / Pinocchio   verdict",
    ]
    for s in report.segments:
        pm = (
            " ".join(f"{v:.4g}" for v in s.principal_moments[0])
            + " / "
            + " ".join(f"{v:.4g}" for v in s.principal_moments[1])
        )
        verdict = "same" if not s.causes else "DIFFERS: " + ", ".join(s.causes)
        cells = (
            f"{s.name[:28]:28s} {s.mass[0]:13.6g} {s.mass[1]:13.6g} {s.com_distance:10.2e} "
            f"{s.inertia_frobenius:10.2e} {s.pole_distance:11.2e}  {pm:38s} "
        )
        lines += hanging(cells, verdict)
    lines += [
        "",
        f"{'dof':24s} {'armature MuJoCo':>16s} {'armature Pin.':>14s} {'|ΔJacobian|':>12s}  verdict",
    ]
    for d in report.dofs:
        verdict = "same" if not d.causes else "DIFFERS: " + ", ".join(d.causes)
        cells = (
            f"{d.joint[:24]:24s} {shown(d.armature[0]):16.6g} {shown(d.armature[1]):14.6g} "
            f"{d.jacobian_difference:12.2e}  "
        )
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
    lines.append("\nverdict: " + ("no import difference" if report.clean else report.headline(brief=True)))
    return fold_text("\n".join(lines))
