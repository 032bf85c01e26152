"""Memory: a finished run holds no model, so a process that checks many files one after the other holds one
model at a time (the corpus tests held the last model of each compare, ~0.5 GB for dm_control's fruitfly)."""

from __future__ import annotations

import gc
import weakref


def test_a_finished_compare_holds_no_model(monkeypatch) -> None:
    import koenig_check.engines

    kept: list[weakref.ref] = []
    load_model = koenig_check.engines.load_model

    def watched(*args, **kwargs):
        model = load_model(*args, **kwargs)
        kept.append(weakref.ref(model.mujoco))
        return model

    monkeypatch.setattr(koenig_check.engines, "load_model", watched)
    check = koenig_check.compare(["serial7.urdf", "gimbal.xml"], n_poses=4)
    assert check.ok, check.reason()
    gc.collect()
    assert len({id(ref) for ref in kept}) >= 2 and all(ref() is None for ref in kept), "a model outlived its run"
