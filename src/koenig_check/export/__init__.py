"""Export: write a model for another engine or format, and prove that it is the same robot.

``export_model`` (``koenig_check.export(...)``, ``koenig-check export``) writes MJCF → URDF
(:mod:`.urdf_writer`), MJCF → portable MJCF (:mod:`.portable_mjcf`) or URDF → MJCF (:mod:`.mjcf_from_urdf`)
from MuJoCo's compiled model, lists what the target cannot hold (:mod:`.carried`), and proves the result
(:mod:`.proof`): every engine's own mass matrix and energy of both files at the same states.
"""

import inspect
import sys
import types
from typing import Any

from koenig_check.export.api import TARGETS, export_model
from koenig_check.export.carried import ExportRefusedError, NotCarried
from koenig_check.export.proof import prove
from koenig_check.export.result import EngineProof, ExportResult, Proof, SegmentDifference

__all__ = [
    "TARGETS",
    "EngineProof",
    "ExportRefusedError",
    "ExportResult",
    "NotCarried",
    "Proof",
    "SegmentDifference",
    "export_model",
    "prove",
]


class _CallableModule(types.ModuleType):
    """The package, callable as ``koenig_check.export(...)``.

    Importing a submodule makes the import system set ``koenig_check.export`` to this package, over the
    function of the same name in ``koenig_check/__init__.py``; calling the package calls that function.
    """

    def __call__(self, *args: Any, **kwargs: Any) -> ExportResult:
        return export_model(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
__signature__ = inspect.signature(export_model)
