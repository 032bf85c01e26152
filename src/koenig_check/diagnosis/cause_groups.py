"""Root causes said once: the same cause found on several elements is one cause naming them all.

A repair of four links, a fusestatic drop on two feet, five root bodies Pinocchio does not read: each is one root
cause (one thing to fix in the file or one option), found on several elements.  A reason counts and names causes,
not the elements they were found on.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from koenig_check.findings import Finding, shown_names, value_text

#: The plural of an element's tag (``body ball``, ``body peg`` -> ``bodies ball, peg``).
_PLURAL = {"body": "bodies", "class": "classes", "mesh": "meshes", "compiler": "compiler"}
#: Names listed in a group's element before "(+N more)".
SHOWN_ELEMENTS = 4
#: Joints listed in a cause that loses them before "(+N more)".
SHOWN_JOINTS = 6


def brief_form(f: Finding) -> str:
    """A finding in a few words: its cause's brief form (:attr:`~koenig_check.causes.Cause.brief`), else its own.

    A finding without a cause gives its :attr:`~koenig_check.findings.Finding.brief`, else its summary.

    Parameters
    ----------
    f : Finding

    Returns
    -------
    str
    """
    if f.cause:
        from koenig_check.engines.cross_readings import departing_reading

        found = departing_reading(f.cause, f.engine)  # another engine's cause, misread by this one too
        if found is not None:
            return f"{found[0].construct} read differently ({found[1].how})"
        from koenig_check.engines.catalogue import cause

        return cause(f.cause).brief
    return f.brief or f.summary


def element_words(f: Finding) -> str:
    """A finding's element, one that lists several names by the first and how many more.

    The names are the finding's values under the plural of its :attr:`~koenig_check.findings.Finding.tag`
    (``geom`` -> ``geoms``, ``segment`` -> ``segments``), never read back from the element's text.

    Parameters
    ----------
    f : Finding

    Returns
    -------
    str
    """
    names = _names(f)
    if len(names) > 1:
        return f"{f.tag} {names[0]} (+{len(names) - 1} more)"
    return f.element


def _plural(tag: str) -> str:
    return _PLURAL.get(tag, tag + "s")


def _names(f: Finding) -> list[str]:
    """The names a finding's values list under the plural of its tag (empty without a tag or a list)."""
    names = f.values.get(_plural(f.tag), ()) if f.tag else ()
    if isinstance(names, (tuple, list)) and all(isinstance(n, str) for n in names):
        return list(names)
    return []


def lost_joints(f: Finding) -> list[str]:
    """The joints a finding's engine lacks because of its cause: its ``joints`` when the cause loses joints.

    Parameters
    ----------
    f : Finding

    Returns
    -------
    list of str
    """
    if not f.cause:
        return []
    from koenig_check.engines.catalogue import cause

    if not cause(f.cause).loses_joints:
        return []
    return [j for j in f.values.get("joints", ()) if isinstance(j, str)]


@dataclass(frozen=True)
class CauseGroup:
    """One cause: findings of the same kind, engine, summary and hint, on one element or several.

    Attributes
    ----------
    findings : tuple of Finding
        In the order the causes were ranked; the first is the most important.
    """

    findings: tuple[Finding, ...]

    @property
    def root_cause(self) -> bool:
        """Whether it is a root cause (a per-segment symptom is not)."""
        return self.findings[0].root_cause

    def elements(self, shown: int = SHOWN_ELEMENTS) -> str:
        """The elements concerned: ``link base``, ``links link_3.0, link_7.0, link_11.0, link_15.0``.

        Parameters
        ----------
        shown : int
            How many are named before "(+N more)".

        Returns
        -------
        str
        """
        if len(self.findings) == 1:
            return element_words(self.findings[0])
        tags = {f.tag for f in self.findings}
        single = all(f.tag and len(_names(f)) <= 1 for f in self.findings)  # each names one element
        if len(tags) == 1 and single:
            names = [f.name for f in self.findings]
            return f"{_plural(tags.pop())} {shown_names(names, shown)}"
        return shown_names([element_words(f) for f in self.findings], shown)

    def lost_joints(self) -> list[str]:
        """The joints the engine concerned does not read because of this cause (:func:`lost_joints`)."""
        joints: list[str] = []
        for f in self.findings:
            joints += [j for j in lost_joints(f) if j not in joints]
        return joints

    def short(self, joints: bool = True, brief: bool = False, shown: int = SHOWN_ELEMENTS) -> str:
        """The cause in a few words: its elements, its brief form (:func:`brief_form`), and the joints it loses.

        Parameters
        ----------
        joints : bool
            Name the joints it loses (False: a message before it names them).
        brief : bool
            Without the joints it loses, for a line that cannot hold more.
        shown : int
            How many elements are named before "(+N more)".

        Returns
        -------
        str
        """
        text = f"{self.elements(shown)}: {brief_form(self.findings[0])}"
        lost = self.lost_joints() if joints and not brief else []
        if lost:
            from koenig_check.engines.registry import label

            which = "joint" if len(lost) == 1 else "joints"
            text += f", so {label(self.findings[0].engine)} lacks {which} {shown_names(lost, SHOWN_JOINTS)}"
        return text

    def message(self) -> str:
        """The cause in full: engine, elements, summary, the values the elements share, and the hint.

        One finding gives its own :meth:`Finding.message`; several give the values equal on all of them (the
        values of each are in ``koenig-check parity`` and the report), and the cause's brief form (:func:`brief_form`)
        for a catalogued cause (its findings may say it of different elements: two default classes), else the
        summary they share.  The hint is theirs when they share it, else the cause's.

        Returns
        -------
        str
        """
        first = self.findings[0]
        if len(self.findings) == 1:
            return first.message()
        text = f"{first.engine}: {self.elements()}: {brief_form(first) if first.cause else first.summary}"
        shared = {k: v for k, v in first.values.items() if all(f.values.get(k) == v for f in self.findings)}
        texts = {k: value_text(v) for k, v in shared.items()}
        shown = {k: t for k, t in texts.items() if t}
        if shown:
            text += " (" + ", ".join(f"{k} {v}" for k, v in shown.items()) + ")"
        lost = self.lost_joints()
        if lost:
            text += f"; lacks joints {shown_names(lost, SHOWN_JOINTS)}"
        hint = first.hint if all(f.hint == first.hint for f in self.findings) else _cause_hint(first)
        if hint:
            text += f"; {hint}"
        return text


def _cause_hint(f: Finding) -> str:
    from koenig_check.engines.catalogue import cause

    return cause(f.cause).hint if f.cause else f.hint


def _key(f: Finding) -> tuple[str, ...]:
    """What makes two root causes one: the same cause on the same engine; without a cause, the same finding's words."""
    return ("cause", f.cause, f.engine) if f.cause else ("kind", f.kind.value, f.engine, f.summary, f.hint)


def cause_groups(causes: Iterable[Finding]) -> list[CauseGroup]:
    """Causes ranked most important first, the same cause on several elements made one (root causes only).

    Parameters
    ----------
    causes : iterable of Finding
        Ranked, e.g. by :func:`koenig_check.diagnosis.reason.ordered_causes`.

    Returns
    -------
    list of CauseGroup
        In the order of each cause's first finding; a per-segment symptom stays a cause of its own (its values
        rank it).
    """
    groups: dict[object, list[Finding]] = {}
    for i, f in enumerate(causes):
        key: object = _key(f) if f.root_cause else i
        groups.setdefault(key, []).append(f)
    return [CauseGroup(tuple(found)) for found in groups.values()]


def more_causes(rest: Sequence[CauseGroup]) -> str:
    """``and 2 more root causes`` for the causes not named (empty when none).

    Parameters
    ----------
    rest : sequence of CauseGroup

    Returns
    -------
    str
    """
    if not rest:
        return ""
    noun = "root cause" if all(g.root_cause for g in rest) else "cause"
    return f"and {len(rest)} more {noun}{'s' if len(rest) > 1 else ''}"
