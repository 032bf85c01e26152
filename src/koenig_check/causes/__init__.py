"""The catalogue of parser differences: each cause declared once (in its engine's subpackage), listed, carried by id.

``koenig-check causes`` prints it, ``docs/causes.md`` is generated from it (:func:`markdown`), and every finding a
cause explains carries its :attr:`Cause.id`.
"""

from koenig_check.causes.listing import markdown, select, table
from koenig_check.engines.catalogue import applies, catalogue, cause, fixture_path, installed_version, twin_path
from koenig_check.engines.cause import FORMATS, QUANTITIES, READS, Cause, Reading

__all__ = [
    "FORMATS",
    "QUANTITIES",
    "READS",
    "Cause",
    "Reading",
    "applies",
    "catalogue",
    "cause",
    "fixture_path",
    "installed_version",
    "markdown",
    "select",
    "table",
    "twin_path",
]
