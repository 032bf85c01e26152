"""A cause found on the file that the catalogue says another attached engine reads differently too.

A cause is declared once, by the engine that departs (``pinocchio.mjcf.replicate``); its readings say how each
other engine measured reads the same construct (Drake skips ``<replicate>`` too).  The always-loaded engines'
detection finds the construct on the user's file; each attached optional engine whose declared reading of it
is ``"differently"`` or ``"refuses"`` (for its installed version, :func:`~koenig_check.engines.catalogue.applies`)
then gets a finding of its own carrying the same id: it was given another robot than the file's, so it does not
vote (:mod:`koenig_check.diagnosis.engine_limits`).  Everything said is rendered from the declaration; nothing
here names an engine.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from koenig_check.engines.catalogue import applies, cause
from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.registry import label, names, optional
from koenig_check.findings import Finding


def departing_reading(cause_id: str, engine: str) -> tuple[Cause, Reading] | None:
    """The cause and an engine's declared reading of it, when the engine misreads it and is not the cause's own.

    Parameters
    ----------
    cause_id : str
    engine : str

    Returns
    -------
    (Cause, Reading) or None
        None when the engine is the one the id names (its own detection says it), reads the construct as
        written, has no declared reading, or its installed version is outside the reading's versions.
    """
    c = cause(cause_id)
    if engine == c.engine:
        return None
    try:
        reading = c.reading(engine)
    except KeyError:
        return None
    if reading.reads == "as written" or not applies(cause_id, engine):
        return None
    return c, reading


def cross_readings(findings: Sequence[Finding], engines: Iterable[str], fmt: str | None = None) -> list[Finding]:
    """The findings of attached optional engines that misread a cause the always-loaded engines found.

    Parameters
    ----------
    findings : sequence of Finding
        What is known about the model; its root causes with a cause id, found by an engine that is not optional
        (or by the file: ``"both"``, ``"file"``), are looked up in the catalogue.
    engines : iterable of str
        The engines attached to the model (the optional ones among them are considered).
    fmt : str, optional
        The file's format (``"mjcf"``, ``"urdf"``): a cause declared for other formats is left alone.  Without
        it (a file that could not be loaded), the found causes are taken to be of the file's format.

    Returns
    -------
    list of Finding
        Per (engine, found cause): a copy of the found cause's finding for the engine (same kind, element, id and
        segments, the values without the other engines' readings), its summary the engine's declared reading; one
        per element the cause was found on; none where the engine's own detection already gave a finding of that
        id or a catalogued finding on that element.
    """
    extra = [e for e in engines if e in optional()]
    own = {(f.engine, f.element) for f in findings if f.cause} | {(f.engine, f.cause) for f in findings if f.cause}
    added: set[tuple[str, str, str]] = set()
    every = set(names())
    out: list[Finding] = []
    for f in findings:
        if not (f.cause and f.root_cause) or f.engine in optional():
            continue
        for engine in extra:
            found = departing_reading(f.cause, engine)
            if found is None or {(engine, f.cause), (engine, f.element)} & own or (engine, f.element, f.cause) in added:
                continue
            c, reading = found
            if fmt is not None and fmt not in c.formats:
                continue
            added.add((engine, f.element, f.cause))
            parser = f"{label(engine)}'s {fmt.upper()} parser" if fmt else f"{label(engine)}'s parser"
            verb = "refused" if reading.reads == "refuses" else "read differently"
            out.append(
                Finding(
                    f.kind,
                    engine,
                    f.element,
                    f"{c.construct} {verb} by {parser}: {reading.how}",
                    values={k: v for k, v in f.values.items() if k not in every},
                    affects_energy=f.affects_energy,
                    root_cause=True,
                    segments=f.segments,
                    hint=c.hint,
                    cause=c.id,
                    tag=f.tag,
                )
            )
    return out
