"""Which engines a run used: per model under ``--engines all``, and once for the installed engines not named.

Under ``--engines all`` each model runs in the installed engines whose parser reads its format, so a batch of an
MJCF and a URDF runs in different sets: a model that left some out gets a line naming the engines it ran in and
those left out, read from its ``ENGINE_NOT_USED`` findings that carry the format not read (values ``format``).
The installed engines the user did not name are said once for the run, not on every model.
"""

from __future__ import annotations

from collections.abc import Sequence

from koenig_check.engines.registry import label
from koenig_check.findings import Kind
from koenig_check.run.cross_check import CrossCheck


def not_named_line(names: Sequence[str]) -> str:
    """The run's one line on the installed engines it did not run because they were not named, or empty.

    Parameters
    ----------
    names : sequence of str
        :func:`koenig_check.diagnosis.policy.not_named`.

    Returns
    -------
    str
    """
    if not names:
        return ""
    return (
        f"Also installed, not run (not named in --engines): {', '.join(label(n) for n in names)}; "
        "--engines all runs every installed engine that reads each model's format"
    )


def engine_set_lines(check: CrossCheck) -> list[str]:
    """Per model that left installed engines out for their format, the engines it ran in; then the not-named line.

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    list of str
        Empty when every model ran in every engine asked for and none was left out by name.
    """
    lines = []
    for comparison in check.comparisons:
        left = {
            f.engine: f.values["format"]
            for f in comparison.findings
            if f.kind is Kind.ENGINE_NOT_USED and "format" in f.values
        }
        if left:
            formats = "/".join(sorted({str(v).upper() for v in left.values()}))
            ran = ", ".join(label(e) for e in comparison.engines)
            lines.append(
                f"{comparison.model}: engines {ran}; left out {', '.join(label(e) for e in left)} "
                f"(their parsers do not read {formats})"
            )
    named = not_named_line(check.not_named)
    return lines + ([named] if named else [])
