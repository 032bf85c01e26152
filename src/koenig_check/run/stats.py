"""Mergeable summaries: what a chunk of poses contributes to a model's verdict, merged chunk by chunk.

Every statistic here is computed from arrays (never from record text) and merges exactly: the
maximum and its first location, counts of over- and under-estimates, the engines' agreement.  The
median is exact up to :data:`EXACT_LIMIT` values per group (the values themselves are kept and
``numpy.median`` is taken at the end); beyond that, the values are binned on a fixed logarithmic
grid of :data:`BINS_PER_DECADE` bins per decade and the median is read from the bin counts, which
bounds its relative error by ``10**(0.5 / BINS_PER_DECADE) − 1`` (0.058 %).  Both forms give the
same result whatever the chunking and merge order: the exact values form the same multiset, and
each value falls in the same bin.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: Default relative tolerance for "agrees".
DEFAULT_RTOL = 1e-9

#: Values kept exactly per group before the quantile sketch switches to bins.
EXACT_LIMIT = 1 << 14
#: Logarithmic bins per decade of the quantile sketch (relative error of a quantile ≤ 0.058 %).
BINS_PER_DECADE = 2000
#: The binned range, decades: values below 10**LOG_MIN count as 0, at or above 10**LOG_MAX as inf.
LOG_MIN, LOG_MAX = -20, 20
_NBINS = (LOG_MAX - LOG_MIN) * BINS_PER_DECADE


def relative_error(value: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """Signed relative error ``(value − reference)/|reference|``; 0/0 is 0 and x/0 is ±inf.

    Parameters
    ----------
    value, reference : ndarray

    Returns
    -------
    ndarray
    """
    diff = np.asarray(value, dtype=float) - np.asarray(reference, dtype=float)
    ref = np.abs(np.asarray(reference, dtype=float))
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = diff / ref
    return np.where(ref > 0, rel, np.where(diff == 0, 0.0, np.copysign(np.inf, diff)))


def absolute_relative_error(difference: np.ndarray, magnitude: np.ndarray) -> np.ndarray:
    """``|relative_error|`` from ``value − reference`` and ``|reference|`` already at hand, in fewer passes.

    Equal to ``np.abs(relative_error(value, reference))`` element for element: ``|d| / |r|`` where
    ``|r| > 0``; elsewhere (``r`` zero or NaN) 0 where ``d == 0`` and ``inf`` otherwise.

    Parameters
    ----------
    difference : ndarray
        ``value − reference``.
    magnitude : ndarray
        ``|reference|``.

    Returns
    -------
    ndarray
        A new array.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.divide(difference, magnitude)
    np.abs(rel, out=rel)
    undefined = ~(magnitude > 0)
    if undefined.any():
        rel[undefined] = np.where(difference[undefined] == 0, 0.0, np.inf)
    return rel


class QuantileSketch:
    """Quantiles of non-negative values (relative errors), exact while small, binned beyond.

    See the module docstring for the bound on the binned form.
    """

    def __init__(self) -> None:
        self.n = 0
        self.nan = 0
        self._values: list[np.ndarray] | None = []
        self._counts: np.ndarray | tuple[np.ndarray, np.ndarray] | None = None  # dense, or (bins, counts)

    @property
    def exact(self) -> bool:
        """True while every value is kept."""
        return self._values is not None

    @staticmethod
    def _bins(x: np.ndarray) -> np.ndarray:
        with np.errstate(divide="ignore"):
            pos = np.floor((np.log10(x) - LOG_MIN) * BINS_PER_DECADE)
        pos = np.where(x >= 10.0**LOG_MAX, _NBINS + 1, pos)
        return np.clip(np.where(x < 10.0**LOG_MIN, 0, pos + 1), 0, _NBINS + 1).astype(np.int64)

    def _to_bins(self) -> None:
        counts = np.zeros(_NBINS + 2, dtype=np.int64)
        for v in self._values or []:
            self._count_into(counts, v)
        self._values, self._counts = None, counts

    @classmethod
    def _count_into(cls, counts: np.ndarray, values: np.ndarray) -> None:
        np.add.at(counts, cls._bins(values), 1)  # unbuffered: repeated bins all count

    def add(self, values: np.ndarray, copy: bool = True) -> None:
        """Add values.

        Parameters
        ----------
        values : ndarray
            Non-negative numbers (``inf`` allowed; NaN counted apart and makes every quantile NaN).
        copy : bool
            Keep a copy of ``values`` (False: the caller hands them over and will not change them).
        """
        values = np.asarray(values, dtype=float).ravel()
        bad = np.isnan(values)
        if bad.any():
            self.nan += int(bad.sum())
            values, copy = values[~bad], False
        self.n += values.size
        if self._values is not None:
            self._values.append(values.copy() if copy else values)
            if self.n > EXACT_LIMIT:
                self._to_bins()
        else:
            self._count_into(self._dense(), values)

    def compact(self) -> None:
        """Keep only the occupied bins (a finished model's sketch: memory follows the spread of its values)."""
        if isinstance(self._counts, np.ndarray):
            occupied = np.flatnonzero(self._counts)
            self._counts = (occupied, self._counts[occupied])

    def _dense(self) -> np.ndarray:
        if isinstance(self._counts, tuple):
            dense = np.zeros(_NBINS + 2, dtype=np.int64)
            dense[self._counts[0]] = self._counts[1]
            self._counts = dense
        if self._counts is None:
            raise RuntimeError("QuantileSketch: no bin counts while every value is still kept")
        return self._counts

    def merge(self, other: QuantileSketch) -> None:
        """Add every value of another sketch.

        Parameters
        ----------
        other : QuantileSketch
        """
        self.nan += other.nan
        self.n += other.n
        if self._values is not None and other._values is not None and self.n <= EXACT_LIMIT:
            self._values += other._values
            return
        if self._values is not None:
            self._to_bins()
        counts = self._dense()
        if other._values is not None:
            for v in other._values:
                self._count_into(counts, v)
        elif isinstance(other._counts, tuple):
            np.add.at(counts, other._counts[0], other._counts[1])
        else:
            counts += other._counts

    def _bin_value(self, k: int) -> float:
        if k == 0:
            return 0.0
        if k == _NBINS + 1:
            return float("inf")
        return float(10.0 ** (LOG_MIN + (k - 0.5) / BINS_PER_DECADE))

    def quantile(self, q: float) -> float:
        """The ``q`` quantile (linear between order statistics, as ``numpy.quantile``; bins: centres).

        Parameters
        ----------
        q : float
            In [0, 1].

        Returns
        -------
        float
        """
        if self.nan or self.n == 0:
            return float("nan")
        if self._values is not None:
            return float(np.quantile(np.concatenate(self._values), q))
        pos = q * (self.n - 1)
        lo, hi = int(np.floor(pos)), int(np.ceil(pos))
        cum = np.cumsum(self._dense())
        a = self._bin_value(int(np.searchsorted(cum, lo + 1)))
        b = self._bin_value(int(np.searchsorted(cum, hi + 1)))
        return a if a == b else a + (b - a) * (pos - lo)

    def median(self) -> float:
        """The median (exact while every value is kept: ``numpy.median``).

        Returns
        -------
        float
        """
        if self._values is not None and not self.nan and self.n:
            return float(np.median(np.concatenate(self._values)))
        return self.quantile(0.5)


@dataclass
class Extreme:
    """The largest value seen and where it was first seen (ties keep the earlier one)."""

    value: float = -np.inf
    where: str = ""
    extra: tuple = ()

    def offer(self, values: np.ndarray, labels, extra: tuple[np.ndarray, ...] = ()) -> None:
        """Offer a batch; keep its first maximum if larger than the current one.

        Parameters
        ----------
        values : ndarray, shape (n,)
        labels : callable or sequence
            ``labels(k)`` or ``labels[k]``: where value ``k`` comes from.
        extra : tuple of ndarray
            Arrays whose entries at the maximum are kept along.
        """
        if values.size == 0:
            return
        k = int(np.argmax(values))
        v = float(values[k])
        if v > self.value or (np.isnan(v) and not np.isnan(self.value)):
            self.value = v
            self.where = labels(k) if callable(labels) else str(labels[k])
            self.extra = tuple(float(np.ravel(e)[k]) for e in extra)

    def merge(self, other: Extreme) -> None:
        """Keep the larger of two extremes; on a tie, this (earlier) one.

        Parameters
        ----------
        other : Extreme
        """
        if other.value > self.value or (np.isnan(other.value) and not np.isnan(self.value)):
            self.value, self.where, self.extra = other.value, other.where, other.extra


@dataclass
class GroupStats:
    """One formula, state source and reference engine: totals over the poses of a model."""

    n: int = 0
    over: int = 0
    under: int = 0
    worst: Extreme = field(default_factory=Extreme)
    sketch: QuantileSketch = field(default_factory=QuantileSketch)

    def add(self, value: np.ndarray, reference: np.ndarray, rtol: float, pose_labels) -> None:
        """Add one chunk's totals.

        Parameters
        ----------
        value, reference : ndarray, shape (P,)
        rtol : float
        pose_labels : sequence or callable
        """
        signed = value - reference
        magnitude = np.abs(reference)
        rel = absolute_relative_error(signed, magnitude)
        scale = rtol * magnitude
        self.n += value.size
        self.over += int(np.count_nonzero(signed > scale))
        self.under += int(np.count_nonzero(signed < -scale))
        self.worst.offer(rel, pose_labels)
        self.sketch.add(rel, copy=False)

    def merge(self, other: GroupStats) -> None:
        """Merge a later chunk's statistics.

        Parameters
        ----------
        other : GroupStats
        """
        self.n += other.n
        self.over += other.over
        self.under += other.under
        self.worst.merge(other.worst)
        self.sketch.merge(other.sketch)


@dataclass
class AgreementStats:
    """The engines' agreement with each other and each with ``exact`` on its own states."""

    rigid: Extreme = field(default_factory=Extreme)  # extra: (MuJoCo, Pinocchio) rigid energies
    armature: Extreme = field(default_factory=Extreme)  # extra: (MuJoCo, Pinocchio) armature energies
    armature_scaled: float = -np.inf
    self_rel: dict[str, float] = field(default_factory=dict)
    gaps: dict[str, Extreme] = field(default_factory=dict)  # engine to its rigid energy's largest gap to MuJoCo's

    def merge(self, other: AgreementStats) -> None:
        """Merge a later chunk's statistics.

        Parameters
        ----------
        other : AgreementStats
        """
        self.rigid.merge(other.rigid)
        self.armature.merge(other.armature)
        self.armature_scaled = max(self.armature_scaled, other.armature_scaled)
        for k, v in other.self_rel.items():
            self.self_rel[k] = max(self.self_rel.get(k, -np.inf), v)
        for k, gap in other.gaps.items():
            self.gaps.setdefault(k, Extreme()).merge(gap)


@dataclass
class ModelStats:
    """Everything a model's summaries and the engines' agreement need, mergeable chunk by chunk.

    Attributes
    ----------
    rtol : float
        Tolerance of the over/under counts.
    n_poses : int
    groups : dict
        ``(formula, source, reference)`` to :class:`GroupStats`.
    worst_segments : dict
        ``(formula, source)`` to the largest per-segment absolute error against ``exact`` on the
        same states (:class:`Extreme`, located as ``"segment @ pose"``).
    agreement : AgreementStats
        The engines' energies against each other (not the import parity of :mod:`koenig_check.diagnosis`).
    refusals : dict
        ``(formula, source)`` to the first refusal's reason.
    """

    rtol: float
    n_poses: int = 0
    groups: dict[tuple[str, str, str], GroupStats] = field(default_factory=dict)
    worst_segments: dict[tuple[str, str], Extreme] = field(default_factory=dict)
    agreement: AgreementStats = field(default_factory=AgreementStats)
    refusals: dict[tuple[str, str], str] = field(default_factory=dict)

    def group(self, key: tuple[str, str, str]) -> GroupStats:
        """The statistics of one group, created on first use.

        Parameters
        ----------
        key : (formula, source, reference)

        Returns
        -------
        GroupStats
        """
        if key not in self.groups:
            self.groups[key] = GroupStats()
        return self.groups[key]

    def merge(self, other: ModelStats) -> None:
        """Merge the statistics of the next chunk (chunks are merged in pose order).

        Parameters
        ----------
        other : ModelStats
        """
        if other.rtol != self.rtol:
            raise ValueError(f"cannot merge statistics at rtol {self.rtol:g} and {other.rtol:g}")
        self.n_poses += other.n_poses
        for key, g in other.groups.items():
            self.group(key).merge(g)
        for segment_key, w in other.worst_segments.items():
            self.worst_segments.setdefault(segment_key, Extreme()).merge(w)
        self.agreement.merge(other.agreement)
        for refusal_key, reason in other.refusals.items():
            self.refusals.setdefault(refusal_key, reason)

    def compact(self) -> None:
        """Shrink the binned sketches of a finished model to their occupied bins."""
        for g in self.groups.values():
            g.sketch.compact()

    def kept_groups(self) -> dict[tuple[str, str, str], GroupStats]:
        """The groups of formulas that did not refuse on that source in any chunk.

        Returns
        -------
        dict
        """
        return {k: g for k, g in self.groups.items() if (k[0], k[1]) not in self.refusals}
