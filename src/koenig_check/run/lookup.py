"""Looking into a run's results: a short repr, one model's comparison by label, one formula's summary, a table.

:class:`ResultLookup` is the part of :class:`koenig_check.api.CrossCheck` that reads its ``comparisons``,
``summaries``, ``failures`` and ``rtol``; it computes nothing.
"""

from __future__ import annotations

from typing import Any

from koenig_check.engines.specs import reference as reference_engine
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.summaries import FormulaSummary


class ResultLookup:
    """Lookups over ``comparisons``, ``summaries`` and ``failures`` (provided by the class it is mixed into)."""

    comparisons: list[ModelComparison]
    summaries: list[FormulaSummary]
    failures: list[tuple[str, str]]
    rtol: float

    @property
    def ok(self) -> bool:
        """Whether the run passed (defined by the class this is mixed into)."""
        raise NotImplementedError

    def __repr__(self) -> str:
        models = [c.model for c in self.comparisons] + [m for m, _ in self.failures]
        shown = ", ".join(models[:5]) + (f", ... ({len(models)} models)" if len(models) > 5 else "")
        return (
            f"<CrossCheck ok={self.ok} models=[{shown}] summaries={len(self.summaries)} "
            f"failures={len(self.failures)} rtol={self.rtol:g}>"
        )

    def __getitem__(self, model: str) -> ModelComparison:
        """The comparison of one model, by its label (``check["gimbal.xml"]``).

        Raises
        ------
        KeyError
            Naming the models there are (a model that failed to load has no comparison: see :attr:`failures`).
        """
        for comparison in self.comparisons:
            if comparison.model == model:
                return comparison
        failed = dict(self.failures)
        if model in failed:
            raise KeyError(f"{model!r} failed: {failed[model]}")
        raise KeyError(f"no model {model!r}; models: {[c.model for c in self.comparisons]}")

    def summary(
        self, model: str, formula: str, source: str | None = None, reference: str | None = None
    ) -> FormulaSummary:
        """The summary of one formula on one model (``check.summary("gimbal.xml", "koenig_world")``).

        Parameters
        ----------
        model : str
            The model's label.
        formula : str
        source : str, optional
            The engine whose segment states the formula was evaluated on (default: the reference engine, MuJoCo).
        reference : str, optional
            The engine whose own energy it is compared with (default: ``source``).

        Returns
        -------
        FormulaSummary

        Raises
        ------
        KeyError
            When there is no such summary (the message lists what there is for that model).
        """
        source = reference_engine() if source is None else source
        reference = source if reference is None else reference
        for s in self.summaries:
            if (s.model, s.formula, s.source, s.reference) == (model, formula, source, reference):
                return s
        there = sorted({(s.formula, s.source, s.reference) for s in self.summaries if s.model == model})
        raise KeyError(f"no summary of {formula!r} on {model!r} ({source} states, {reference} energy); there: {there}")

    def to_pandas(self) -> Any:
        """The summaries as a ``pandas.DataFrame``, one row per summary (needs pandas).

        Returns
        -------
        pandas.DataFrame
            Columns: the fields of :class:`FormulaSummary`.

        Raises
        ------
        ImportError
            When pandas is not installed (``pip install pandas``).
        """
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("CrossCheck.to_pandas needs pandas: pip install pandas") from None
        from dataclasses import asdict, fields

        columns = [f.name for f in fields(FormulaSummary)]
        return pd.DataFrame([asdict(s) for s in self.summaries], columns=columns)
