"""What a failing check says, as the command line's verdict does: the root causes first, then the symptoms."""

from __future__ import annotations

from typing import TYPE_CHECKING

from koenig_check.findings import Kind

if TYPE_CHECKING:
    from koenig_check.api import CrossCheck


def verdict_lines(check: CrossCheck) -> list[str]:
    """Why ``koenig-check compare`` would exit 1, model by model: root cause, three-engine verdicts, the gap, gravity.

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    list of str
        Empty when :attr:`CrossCheck.ok`.
    """
    from koenig_check.diagnosis.reason import cause_lines, rounding_hint
    from koenig_check.gravity.words import verdict_line
    from koenig_check.line_width import fold

    lines = []
    for (label, _), message in zip(check.failures, check.messages(width=FAILURE_WIDTH), strict=False):
        first, *rest = message.split("\n")  # its reason, then the engine's own words and the hint, indented
        lines += [f"{label}: failed: {first.removeprefix(f'{label}: ')}", *rest]
    for comparison, parity in zip(check.comparisons, check.agreements, strict=True):
        verdicts = [f for f in comparison.findings if f.kind is Kind.VERDICT]
        unmade = [f for f in comparison.findings if f.kind is Kind.ENGINE_UNABLE]  # a check asked for, not made
        gravity = comparison.gravity
        gravity_off = gravity is not None and not gravity.agrees
        if parity.agrees and not verdicts and not unmade and not gravity_off:
            continue
        lines.append(f"{parity.model}: MuJoCo and Pinocchio {'agree' if parity.agrees else 'disagree'}")
        # Beside the kinetic verdict, where gravity has a cause of its own (a cause the kinetic lines already
        # name, a mass read differently, is not said twice) or is the only disagreement.
        own = gravity is not None and any(f.root_cause for f in gravity.explanations)
        if gravity is not None and gravity_off and (own or (parity.agrees and not verdicts)):
            lines.append(f"  {verdict_line(gravity)}")
        lines += [f"  root cause: {cause}" for cause in cause_lines(comparison.findings)]  # one a line
        lines += [f"  three engines: {f.message()}" for f in verdicts]
        if not parity.agrees:
            lines.append(f"  engines: {'; '.join(parity.symptoms)}")  # the cause is the root-cause line above
            hint = rounding_hint(parity.rigid_max_rel, check.rtol)
            if hint and parity.gap == hint:  # the gap alone, at a written file's rounding: the option for it
                lines.append(f"  {hint}")
        lines += [f"  {f.message()}" for f in unmade]
    return [part for line in lines for part in fold(line, FAILURE_WIDTH)]


#: The longest line of a failure's text: pytest writes it after a prefix of up to 8 characters (``E       ``).
FAILURE_WIDTH = 192
