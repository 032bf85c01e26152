"""One home for every exception: the old import paths, the declared root causes, pickling."""

from __future__ import annotations

import importlib
import pickle
from pathlib import Path

import pytest

from koenig_check import exceptions
from koenig_check.engines import load_model
from koenig_check.exceptions import JointMismatch, KoenigCheckError, ModelLoadError
from koenig_check.findings import Finding, Kind

CAUSES = Path(__file__).resolve().parent / "models" / "causes"

#: Where each exception was defined before it moved to koenig_check.exceptions.
OLD_HOMES = {
    "KoenigCheckError": "koenig_check.findings",
    "ArgumentValueError": "koenig_check.arguments",
    "ArgumentTypeError": "koenig_check.arguments",
    "ModelLoadError": "koenig_check.engines.errors",
    "InertiaError": "koenig_check.engines.errors",
    "CoupledJointsError": "koenig_check.engines.errors",
    "NoMovingSegmentError": "koenig_check.engines.errors",
    "JointMismatch": "koenig_check.engines.errors",
    "ModelFileError": "koenig_check.modelfile.validate",
    "PoseFileError": "koenig_check.run.pose_file",
    "RecordFileError": "koenig_check.run.records",
    "NotPlaneParallelError": "koenig_check.formulas.planar",
    "PathDependentError": "koenig_check.implied_dynamics.energy",
}


#: Exceptions born in koenig_check.exceptions (no old home).
NEW = {"NoMassError", "EngineUnavailableError", "NotFloatableError"}


def _cause(element: str) -> Finding:
    return Finding(Kind.IGNORED_CONSTRUCT, "pinocchio", element, "ignored by Pinocchio", root_cause=True)


def test_every_exception_lives_in_one_module() -> None:
    defined = {
        name
        for name, obj in vars(exceptions).items()
        if isinstance(obj, type) and issubclass(obj, BaseException) and obj.__module__ == exceptions.__name__
    }
    assert defined == set(OLD_HOMES) | NEW == set(exceptions.__all__)


@pytest.mark.parametrize("name", sorted(OLD_HOMES))
def test_the_old_import_path_gives_the_same_class(name: str) -> None:
    cls = getattr(exceptions, name)
    assert getattr(importlib.import_module(OLD_HOMES[name]), name) is cls
    assert issubclass(cls, KoenigCheckError)


def test_causes_are_declared_empty_until_attached() -> None:
    err = ModelLoadError("robot.xml: link base: refused")
    assert err.causes == ()
    err.attach_causes([])
    assert err.causes == () and str(err) == "robot.xml: link base: refused"


def test_attached_causes_end_the_one_line_message() -> None:
    err = ModelLoadError("robot.xml: link base: refused")
    first, second = _cause("include arm.xml"), _cause("frame f")
    err.attach_causes(iter([first, second]))
    assert err.causes == (first, second)
    assert str(err) == f"robot.xml: link base: refused; root cause: {first.message()}; {second.message()}"
    assert "\n" not in str(err)


def test_causes_kept_out_of_the_message_when_asked() -> None:
    err = ModelLoadError("robot.xml: nothing moves")
    err.attach_causes([_cause("model")], in_message=False)
    assert len(err.causes) == 1 and str(err) == "robot.xml: nothing moves"


def test_a_load_failure_carries_its_file_causes() -> None:
    # An <include> Pinocchio's MJCF parser ignores: the load fails, the cause is attached as data.
    with pytest.raises(KoenigCheckError) as info:
        load_model(CAUSES / "include_in_body.xml")
    assert isinstance(info.value.causes, tuple) and info.value.causes
    assert all(isinstance(c, Finding) for c in info.value.causes)
    assert "root cause: " in str(info.value)


@pytest.mark.parametrize("name", sorted(OLD_HOMES))
def test_every_exception_survives_pickling(name: str) -> None:
    # A worker process (--jobs, Dask) sends its error back pickled: type, message and fields.  (A Finding
    # holds a read-only mapping, which does not pickle, so errors with causes attached stay in-process.)
    cls = getattr(exceptions, name)
    err = cls("robot.xml", ["hip"], ["hip_pin"], ["knee: hinge vs prismatic"]) if cls is JointMismatch else cls("m: x")
    back = pickle.loads(pickle.dumps(err))
    assert type(back) is cls and str(back) == str(err) and back.causes == ()
    if cls is JointMismatch:
        assert (back.path, back.only_in_mujoco, back.only_in_pinocchio, back.kind_mismatch) == (
            "robot.xml",
            ["hip"],
            ["hip_pin"],
            ["knee: hinge vs prismatic"],
        )


def test_drakes_failed_condition_is_kept_whole_without_its_build_location() -> None:
    """Drake's own message, from Drake: the condition and the function stay, the bazel-out path goes."""
    pydrake_plant = pytest.importorskip("pydrake.multibody.plant")
    import numpy as np

    plant = pydrake_plant.MultibodyPlant(0.0)
    plant.Finalize()
    with pytest.raises(SystemExit) as info:  # pydrake's way of failing a C++ check
        plant.SetPositions(plant.CreateDefaultContext(), np.zeros(3))
    raw = str(info.value)
    assert raw.startswith("Failure at ") and ".h:" in raw  # what Drake says, location first
    text = exceptions.one_line(info.value)
    assert text == "SetPositions(): condition 'q.size() == num_positions()' failed."
    assert exceptions.one_line(ValueError("Failure at the gate")) == "Failure at the gate"  # not a location


def test_an_engines_own_load_error_lives_in_its_subpackage() -> None:
    """Drake's load error is Drake's (engines/drake/loader.py), a ModelLoadError that survives pickling; the
    top-level module names no engine's exception."""
    pytest.importorskip("pydrake")
    from koenig_check.engines.drake.loader import DrakeLoadError

    assert not hasattr(exceptions, "DrakeLoadError")
    assert issubclass(DrakeLoadError, ModelLoadError) and DrakeLoadError.__module__.startswith("koenig_check.engines.")
    back = pickle.loads(pickle.dumps(DrakeLoadError("m.xml: Drake cannot load the file: x")))
    assert type(back) is DrakeLoadError and str(back) == "m.xml: Drake cannot load the file: x"
