"""Round-off: differences below a stated threshold are printed as zero."""

from __future__ import annotations

import math

#: Relative errors and absolute differences (J, kg m², kg) below this are rounding in double precision
#: and are printed as 0.  The stored records and JSON keep the computed values.
ROUNDOFF = 1e-12


def shown(value: float, threshold: float = ROUNDOFF) -> float:
    """The value as printed: 0.0 when ``|value| < threshold`` (also turns -0.0 into 0.0).

    Parameters
    ----------
    value : float
    threshold : float

    Returns
    -------
    float
    """
    if isinstance(value, float) and math.isnan(value):
        return value
    return 0.0 if abs(value) < threshold else float(value)


def fmt(value: float, spec: str = ".2e", threshold: float = ROUNDOFF) -> str:
    """Format a number, printing round-off as ``0``.

    Parameters
    ----------
    value : float
    spec : str
        Format of values at or above the threshold.
    threshold : float

    Returns
    -------
    str
    """
    if not math.isfinite(value):
        return str(value)
    value = shown(value, threshold)
    return "0" if value == 0 else format(value, spec)
