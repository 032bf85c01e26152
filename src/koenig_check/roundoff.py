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


def distinct(a: float, b: float, least: int = 6) -> tuple[str, str]:
    """Two values with the fewest significant digits (at least ``least``) that show them different.

    Values that differ look different (``0.21942`` and ``0.219420244``, not ``0.21942`` twice); equal values
    are printed with ``least`` digits.

    Parameters
    ----------
    a, b : float
    least : int

    Returns
    -------
    (str, str)
    """
    for digits in range(least, 18):
        x, y = f"{a:.{digits}g}", f"{b:.{digits}g}"
        if x != y or a == b:
            break
    return x, y
