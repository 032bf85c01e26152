"""The result of :func:`koenig_check.compare` over one or several models: whether it is ok, and why not."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from koenig_check.diagnosis import model_reason, reason
from koenig_check.findings import Finding
from koenig_check.gravity.words import reason_words
from koenig_check.line_width import closed_cut
from koenig_check.run import summaries
from koenig_check.run.comparison import ModelComparison, records_for
from koenig_check.run.lookup import ResultLookup
from koenig_check.run.records import RecordTable
from koenig_check.run.stats import DEFAULT_RTOL
from koenig_check.run.summaries import EngineAgreement, FormulaSummary


@dataclass(repr=False)
class CrossCheck(ResultLookup):
    """Result of :func:`compare` over one or several models.

    ``check["gimbal.xml"]`` is that model's :class:`ModelComparison`, ``check.summary(model, formula,
    source, reference)`` one :class:`FormulaSummary`, ``check.to_pandas()`` the summaries as a table.

    Attributes
    ----------
    comparisons : list of ModelComparison
    summaries : list of FormulaSummary
    agreements : list of EngineAgreement
    failures : list of (str, str)
        Models that could not be compared, with a one-line reason each (the engine's whole reason).
    failure_lines : dict of str to str
        Per failed model, its reason in one sentence of at most 200 characters (:meth:`reasons`).
    failure_parts : dict of str to dict
        Per failed model, what its whole message is made of (:func:`koenig_check.diagnosis.message.error_parts`:
        the message, the refusing engine's own words, the hint), for the lines after its reason (:meth:`messages`).
    failure_causes : dict of str to tuple of Finding
        Per failed model, the root causes found for its failure (each carries its catalogue id, ``cause``); a
        model whose joints cannot be paired because one parser ignores a construct of the file is a disagreement
        (:meth:`disagrees`), not an error.
    rtol : float
    settings : dict
        Per model label, the pose settings of its run (``pose_kind``, ``n_poses``, ``seed``,
        ``velocity_scale``, ``duration``), for the report's captions.
    not_named : tuple of str
        The installed optional engines the run left out because the user did not name them
        (:func:`koenig_check.diagnosis.policy.not_named`): said once for the run, not on each model.
    """

    comparisons: list[ModelComparison] = field(default_factory=list)
    summaries: list[FormulaSummary] = field(default_factory=list)
    agreements: list[EngineAgreement] = field(default_factory=list)
    failures: list[tuple[str, str]] = field(default_factory=list)
    failure_lines: dict[str, str] = field(default_factory=dict)
    failure_parts: dict[str, dict[str, Any]] = field(default_factory=dict)
    failure_causes: dict[str, tuple[Finding, ...]] = field(default_factory=dict)
    rtol: float = DEFAULT_RTOL
    settings: dict[str, dict[str, Any]] = field(default_factory=dict)
    not_named: tuple[str, ...] = ()

    @property
    def records(self) -> RecordTable:
        """All tidy records of all models (iterate for dicts, index by column name for arrays)."""
        return records_for(self.comparisons)

    @property
    def ok(self) -> bool:
        """True when every model loaded and the engines agree with each other and with ``exact``.

        With Drake consulted, an engine that departs from the other two (a ``VERDICT`` finding) counts, and so does
        an engine the user named that could not check a model (``ENGINE_UNABLE``: the check asked for was not made),
        and so does a gravity difference (the same robot in the same world: :mod:`koenig_check.gravity`).
        """
        verdicts = any(f.kind in reason.LEADING_KINDS for c in self.comparisons for f in c.findings)
        gravity = all(c.gravity is None or c.gravity.agrees for c in self.comparisons)
        return not self.failures and all(p.agrees for p in self.agreements) and not verdicts and gravity

    def add(self, comparison: ModelComparison) -> EngineAgreement:
        """Record one model's comparison with its summaries and the engines' agreement.

        Parameters
        ----------
        comparison : ModelComparison

        Returns
        -------
        EngineAgreement
            The agreement just recorded.
        """
        self.comparisons.append(comparison)
        self.summaries += summaries.summarize(comparison, self.rtol)
        agreement = summaries.engine_agreement(comparison, self.rtol)
        self.agreements.append(agreement)
        return agreement

    def reasons(self, cli: bool = False) -> list[str]:
        """Why :attr:`ok` is False, one sentence per failing model (empty when it is True).

        A model that could not be checked gives its error and at most three root causes (:attr:`failure_lines`;
        the engine's whole reason is in :attr:`failures`); a disagreeing model gives the check asked for and not
        made or the engine that departs, the gap, and at most three root causes, the most important first,
        or, where only gravity differs, the gravity gap and its cause, within 200 characters (the details are in
        ``koenig-check parity``, ``summary.md`` and the report).

        Parameters
        ----------
        cli : bool
            Options named as the command line spells them (``--rtol 1e-06``), else as the API does (``rtol=1e-06``).

        Returns
        -------
        list of str
        """
        lines = [(m, self.failure_lines.get(m, r)) for m, r in self.failures]
        parts = [r if r.startswith(f"{m}: ") else f"{m}: {r}" for m, r in lines]  # once, not twice
        for comparison, agreement in zip(self.comparisons, self.agreements, strict=True):
            why = self.model_reason(comparison, agreement, cli)
            if why is not None:
                text = why.line()
                unused = reason.engine_usage(comparison.findings)
                if (
                    not reason.lead_line(comparison.findings)
                    and unused
                    and len(text) + len(unused) + 2 <= reason.REASON_WIDTH
                ):
                    text += f"; {unused}"
                parts.append(text)
            elif comparison.gravity is not None and not comparison.gravity.agrees:  # else said in the details
                parts.append(closed_cut(f"{agreement.model}: {reason_words(comparison.gravity)}", reason.REASON_WIDTH))
        return parts

    def model_reason(
        self, comparison: ModelComparison, agreement: EngineAgreement, cli: bool = False
    ) -> model_reason.Reason | None:
        """Why one model fails (None when it does not): the one reason both :meth:`reasons` and the verdict table show.

        Parameters
        ----------
        comparison : ModelComparison
        agreement : EngineAgreement
            Its engines' agreement.
        cli : bool
            Options named as the command line spells them.

        Returns
        -------
        koenig_check.diagnosis.model_reason.Reason or None
        """
        if not reason.lead_line(comparison.findings) and agreement.agrees:
            return None
        gap = summaries.gap_words(comparison, self.rtol, cli) if not agreement.agrees else ""
        return model_reason.model_reason(agreement.model, comparison.findings, gap)

    def disagrees(self, model: str) -> bool:
        """Whether a model that could not be compared is a disagreement: its engines built different mechanisms.

        True when its joints cannot be paired and a root cause that changes the energy explains it (a construct one
        parser ignores: ``<attach>``, ``<include>``, ``<frame>``...); False for an error (a file an engine refuses).

        Parameters
        ----------
        model : str
            The model's label.

        Returns
        -------
        bool
        """
        parts = self.failure_parts.get(model, {})
        causes = self.failure_causes.get(model, ())
        return bool(parts.get("unpaired")) and any(c.root_cause and c.affects_energy for c in causes)

    def messages(self, cli: bool = False, width: int = 200) -> list[str]:
        """Why :attr:`ok` is False, one message per failing model: its reason, then the whole of it indented.

        The first line of each is the model's reason (:meth:`reasons`, at most 200 characters); the lines after it,
        indented, give what that line leaves out, never cut: the rest of the error's message, the refusing
        engine's own words and the hint (a model that could not be compared), or each check asked for and not
        made, whole (a model compared).

        Parameters
        ----------
        cli : bool
            Options named as the command line spells them.
        width : int
            The longest line after the first (a longer one is folded at words, never cut).

        Returns
        -------
        list of str
            One string per failing model, its lines joined by newlines (the first without a prefix).
        """
        from koenig_check.diagnosis.message import detail_lines, finding_lines

        out = []
        lines = self.reasons(cli)
        for (model, _), line in zip(self.failures, lines, strict=False):
            parts = self.failure_parts.get(model)
            out.append("\n".join([line, *(detail_lines(parts, line, cli=cli, width=width) if parts else [])]))
        compared = lines[len(self.failures) :]
        failing = [c for c, a in zip(self.comparisons, self.agreements, strict=True) if _fails(c, a)]
        for comparison, line in zip(failing, compared, strict=True):
            out.append("\n".join([line, *finding_lines(comparison.findings, line, width)]))
        return out

    def reason(self) -> str:
        """One line saying why :attr:`ok` is False (empty when it is True): :meth:`reasons` joined."""
        return "; ".join(self.reasons())


def _fails(comparison: ModelComparison, agreement: EngineAgreement) -> bool:
    """Whether a compared model has a reason in :meth:`CrossCheck.reasons` (as that method decides): gravity too."""
    gravity = comparison.gravity is not None and not comparison.gravity.agrees
    return bool(reason.lead_line(comparison.findings)) or not agreement.agrees or gravity
