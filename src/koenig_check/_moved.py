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
        module = importlib.import_module(MOVED[spec.name])
        # The import system next sets module.__spec__ to the old name's spec: keep the module's own, which
        # exec_module puts back (else importlib.reload of the new module would be a silent no-op).
        spec.loader_state = module.__spec__
        return module

    def exec_module(self, module: ModuleType) -> None:
        """Nothing to run (the new module ran when it was imported): give the module back its own spec."""
        own = getattr(module.__spec__, "loader_state", None)
        if isinstance(own, importlib.machinery.ModuleSpec):
            module.__spec__ = own


def install() -> None:
    """Let the old names of :data:`MOVED` be imported (once per process)."""
    if not any(isinstance(f, _MovedModules) for f in sys.meta_path):
        sys.meta_path.append(_MovedModules())
