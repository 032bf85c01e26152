"""Old import paths of modules that moved, kept working for now.

A module that moves adds one line to :data:`MOVED` (old dotted name -> new dotted name); importing the old
name then gives the new module itself (the same object, so patching either name patches both).  A module
split in several adds one line to :data:`SPLIT` (old name -> the new modules): the old name then gives a
module whose names are looked up in the new ones, in order.
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
    "koenig_check.engines.mujoco_engine": "koenig_check.engines.mujoco.adapter",
    "koenig_check.engines.mujoco_loader": "koenig_check.engines.mujoco.loader",
    "koenig_check.engines.inertia_repair": "koenig_check.engines.mujoco.inertia_repair",
    "koenig_check.engines.pinocchio_engine": "koenig_check.engines.pinocchio.adapter",
    "koenig_check.engines.pinocchio_loader": "koenig_check.engines.pinocchio.loader",
    "koenig_check.engines.state_map": "koenig_check.engines.pinocchio.state_map",
    "koenig_check.engines.drake_loader": "koenig_check.engines.drake.loader",
    "koenig_check.engines.drake_state_map": "koenig_check.engines.drake.state_map",
    "koenig_check.engines.drake_inertia": "koenig_check.engines.drake.inertia",
    "koenig_check.parity": "koenig_check.diagnosis.import_parity",
    "koenig_check.pipeline": "koenig_check.run.pipeline",
    "koenig_check.poses": "koenig_check.run.poses",
    "koenig_check.pose_file": "koenig_check.run.pose_file",
    "koenig_check.records": "koenig_check.run.records",
    "koenig_check.stats": "koenig_check.run.stats",
    "koenig_check.figures": "koenig_check.report.figures",
    "koenig_check.output_dir": "koenig_check.report.output_dir",
    "koenig_check.progress": "koenig_check.report.progress",
    "koenig_check.report_content": "koenig_check.report.content",
    "koenig_check.report_html": "koenig_check.report.html",
    "koenig_check.verdict": "koenig_check.report.terminal",
    "koenig_check.report.line_width": "koenig_check.line_width",
    "koenig_check.validate": "koenig_check.modelfile.validate",
    "koenig_check.pytest_plugin": "koenig_check.testing.plugin",
    "koenig_check.project_config": "koenig_check.testing.project_config",
    "koenig_check.failure_text": "koenig_check.testing.failure_text",
    "koenig_check.implied_dynamics.drake_column": "koenig_check.implied_dynamics.engine_columns",
    "koenig_check.export.cli_export": "koenig_check.cli.export",
}


#: Old module name -> the modules it was split into.
SPLIT: dict[str, tuple[str, ...]] = {
    "koenig_check.engines.sources": (
        "koenig_check.sources.catalogue",
        "koenig_check.sources.model_names",
        "koenig_check.sources.uris",
    ),
    "koenig_check.engines.drake_engine": ("koenig_check.engines.drake.adapter", "koenig_check.engines.drake.building"),
    "koenig_check.causes": (
        "koenig_check.diagnosis.pair_causes",
        "koenig_check.diagnosis.root_frame",
        "koenig_check.engines.parser_traps",
        "koenig_check.engines.canonical",
        "koenig_check.modelfile.mjcf",
    ),
    "koenig_check.tiebreak": (
        "koenig_check.diagnosis.three_way",
        "koenig_check.diagnosis.reason",
        "koenig_check.engines.registry",
        "koenig_check.engines.drake.attach",
        "koenig_check.exceptions",
    ),
    "koenig_check.grid": (
        "koenig_check.run.comparison",
        "koenig_check.run.chunks",
        "koenig_check.run.engine_runs",
        "koenig_check.run.summaries",
        "koenig_check.run.stats",
        "koenig_check.run.records",
        "koenig_check.diagnosis.reason",
    ),
}


class _SplitModule(ModuleType):
    """An old module name whose names now live in several modules."""

    def __init__(self, name: str, homes: tuple[str, ...]) -> None:
        super().__init__(name, f"Moved: the names of {name} now live in {', '.join(homes)}.")
        self._homes = homes

    def __getattr__(self, attr: str) -> object:
        for home in self._homes:
            module = importlib.import_module(home)
            if hasattr(module, attr):
                return getattr(module, attr)
        raise AttributeError(f"module {self.__name__!r} has no attribute {attr!r} (moved to {', '.join(self._homes)})")


class _MovedModules(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old module name and loads it as the module it moved to."""

    def find_spec(
        self, fullname: str, path: object = None, target: object = None
    ) -> importlib.machinery.ModuleSpec | None:
        """A spec for an old name of :data:`MOVED`, else None (the other finders look)."""
        if fullname not in MOVED and fullname not in SPLIT:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        """The module the old name moved to."""
        if spec.name in SPLIT:
            return _SplitModule(spec.name, SPLIT[spec.name])
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
