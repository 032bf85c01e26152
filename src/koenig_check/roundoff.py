"""Round-off: differences below a stated threshold are printed as zero."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

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


def relative_zeros(values: Iterable[float], spec: str = ".6g", threshold: float = ROUNDOFF) -> str:
    """Numbers of one kind (a body's principal moments), those below ``threshold`` times the largest as ``0``.

    An inertia written rotated comes back with moments such as ``-1.99283e-22, 8.51804e-23, 3e-06``: the two
    first are round-off of the rotation, zeros at the scale of the third.

    Parameters
    ----------
    values : iterable of float
    spec : str
        Format of the others.
    threshold : float
        Relative to the largest magnitude.

    Returns
    -------
    str
        The values joined by ``", "``.
    """
    items = [float(v) for v in values]
    scale = max((abs(v) for v in items if math.isfinite(v)), default=0.0)
    return ", ".join(fmt(v, spec, threshold * scale) if scale > 0 else fmt(v, spec) for v in items)


#: Fewest and most significant digits :func:`side_by_side` prints.
SIDE_BY_SIDE_DIGITS = (6, 12)


def side_by_side(values: Sequence[float]) -> list[str]:
    """Numbers compared with each other (MuJoCo's and Pinocchio's, before and after), with the same digits.

    Each is printed with the same number of significant digits: 6, or as many as make the values that differ
    print differently, up to 12 (beyond, the difference is round-off): ``0.0096`` and ``0.00960001``, not
    ``0.0096`` twice; ``2.92866`` and ``5.53996``, not ``2.928662`` and ``5.53996438``.

    Parameters
    ----------
    values : sequence of float

    Returns
    -------
    list of str
    """
    low, high = SIDE_BY_SIDE_DIGITS
    distinct = len({float(v) for v in values})
    digits = low
    while digits < high and len({format(float(v), f".{digits}g") for v in values}) < distinct:
        digits += 1
    return [format(float(v), f".{digits}g") for v in values]
