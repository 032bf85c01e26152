"""How a worker process gets its model (``WorkerModel``): one name, one meaning (the former name is gone)."""

from __future__ import annotations

import importlib
import inspect
import pkgutil

import koenig_check
from koenig_check.engines.load_options import LoadOptions


def test_worker_model_is_the_run_s_model_and_has_no_former_name() -> None:
    from koenig_check.run import chunk_tasks, pipeline
    from koenig_check.sources.catalogue import ModelSource as FileSource

    assert chunk_tasks.WorkerModel.__name__ == "WorkerModel"
    assert not hasattr(chunk_tasks, "ModelSource") and not hasattr(pipeline, "ModelSource")
    assert pipeline.WorkerModel is chunk_tasks.WorkerModel
    assert FileSource is not chunk_tasks.WorkerModel  # where a file comes from: another thing, its own name
    a = chunk_tasks.WorkerModel("gimbal.xml", LoadOptions(floating=True))
    assert a == chunk_tasks.WorkerModel("gimbal.xml", LoadOptions(floating=True)) and hash(a) == hash(
        chunk_tasks.WorkerModel("gimbal.xml", LoadOptions(floating=True))
    )  # a process loads each once: it keys the models it keeps


def test_no_two_classes_of_the_package_share_a_name() -> None:
    """One meaning per word: a class name names one class (an alias of a former name is the same class)."""
    homes: dict[str, set[str]] = {}
    for info in pkgutil.walk_packages(koenig_check.__path__, "koenig_check."):
        if info.name.endswith("__main__"):  # running it would run the command line
            continue
        module = importlib.import_module(info.name)
        for obj in vars(module).values():
            if inspect.isclass(obj) and obj.__module__ == module.__name__:
                homes.setdefault(obj.__name__, set()).add(f"{obj.__module__}.{obj.__qualname__}")
    shared = {name: sorted(where) for name, where in homes.items() if len(where) > 1}
    assert not shared, shared
