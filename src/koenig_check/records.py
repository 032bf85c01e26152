"""A tidy table of comparison records, stored column by column."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

#: The columns of every record, in order.
RECORD_FIELDS = (
    "model",
    "pose",
    "formula",
    "source",
    "reference",
    "scope",
    "value",
    "reference_value",
    "abs_error",
    "rel_error",
    "signed_error",
)
_TEXT = frozenset({"model", "pose", "formula", "source", "reference", "scope"})


@dataclass(frozen=True)
class RecordTable:
    """Tidy records: one row per (model, pose, formula, source, reference, scope).

    Columns are numpy arrays of equal length: text columns are numpy unicode arrays, numbers
    float.  Iterating yields one ``dict`` per row.

    Attributes
    ----------
    columns : dict of str to ndarray
        Keyed by :data:`RECORD_FIELDS`.
    """

    columns: dict[str, np.ndarray] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not self.columns:
            object.__setattr__(
                self,
                "columns",
                {k: np.empty(0, dtype=str if k in _TEXT else float) for k in RECORD_FIELDS},
            )
        lengths = {len(v) for v in self.columns.values()}
        if set(self.columns) != set(RECORD_FIELDS) or len(lengths) > 1:
            raise ValueError(f"RecordTable needs equal-length columns {RECORD_FIELDS}")

    def __len__(self) -> int:
        return len(self.columns["model"])

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]

    def __iter__(self) -> Iterator[dict[str, Any]]:
        lists = [self.columns[k].tolist() for k in RECORD_FIELDS]
        for row in zip(*lists, strict=True):
            yield dict(zip(RECORD_FIELDS, row, strict=True))

    def rows(self) -> list[list[Any]]:
        """Every row as a list in the order of :data:`RECORD_FIELDS`.

        Returns
        -------
        list of list
        """
        return [list(r) for r in zip(*(self.columns[k].tolist() for k in RECORD_FIELDS), strict=True)]

    def mask(self, **equals: str) -> np.ndarray:
        """Boolean mask of the rows whose text columns equal the given values.

        Parameters
        ----------
        **equals : str
            Column name to required value.

        Returns
        -------
        ndarray of bool
        """
        keep = np.ones(len(self), dtype=bool)
        for name, value in equals.items():
            keep &= self.columns[name] == value
        return keep

    def where(self, mask: np.ndarray | None = None, **equals: str) -> RecordTable:
        """The rows selected by a mask and/or equalities.

        Parameters
        ----------
        mask : ndarray of bool, optional
        **equals : str

        Returns
        -------
        RecordTable
        """
        keep = self.mask(**equals)
        if mask is not None:
            keep &= mask
        return RecordTable({k: v[keep] for k, v in self.columns.items()})

    @staticmethod
    def concat(tables: Iterable[RecordTable]) -> RecordTable:
        """Stack several tables.

        Parameters
        ----------
        tables : iterable of RecordTable

        Returns
        -------
        RecordTable
        """
        tables = [t for t in tables if len(t)]
        if not tables:
            return RecordTable()
        return RecordTable({k: np.concatenate([t.columns[k] for t in tables]) for k in RECORD_FIELDS})
