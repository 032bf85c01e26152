"""Old import paths of modules that moved, kept working for now.

A module that moves adds one line to :data:`MOVED` (old dotted name -> new dotted name); importing the old
name then gives the new module itself (the same object, so patching either name patches both).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import sys
from types import ModuleType

#: Old module name -> the module it moved to.
MOVED: dict[str, str] = {
    "koenig_check.figures": "koenig_check.report.figures",
    "koenig_check.output_dir": "koenig_check.report.output_dir",
    "koenig_check.progress": "koenig_check.report.progress",
    "koenig_check.report_content": "koenig_check.report.content",
    "koenig_check.report_html": "koenig_check.report.html",
    "koenig_check.verdict": "koenig_check.report.terminal",
}


class _MovedModules(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old module name and loads it as the module it moved to."""

    def find_spec(
        self, fullname: str, path: object = None, target: object = None
    ) -> importlib.machinery.ModuleSpec | None:
        """A spec for an old name of :data:`MOVED`, else None (the other finders look)."""
        if fullname not in MOVED:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        """The module the old name moved to."""
        return importlib.import_module(MOVED[spec.name])

    def exec_module(self, module: ModuleType) -> None:
        """Nothing: the new module was executed when it was imported."""


def install() -> None:
    """Let the old names of :data:`MOVED` be imported (once per process)."""
    if not any(isinstance(f, _MovedModules) for f in sys.meta_path):
        sys.meta_path.append(_MovedModules())
