"""Newton's attach reads the file once: every ``finalize`` option and ``collapse_fixed_joints`` measured on it come
from the one parsed builder, and each is the model Newton builds from the file loaded again with that option."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("newton", reason="Newton (the optional extra [newton]) is not installed: its tests are skipped")

from koenig_check.causes import cause, fixture_path
from koenig_check.engines import load_model
from koenig_check.engines.newton import causes as ids
from koenig_check.engines.newton import loader
from koenig_check.engines.newton.departures import effect_poses, mass_matrices


def _arrays(model) -> list[np.ndarray]:
    return [a.numpy() for a in (model.body_mass, model.body_inertia, model.body_com, model.joint_X_p, model.joint_type)]


@pytest.mark.parametrize(
    ("options", "finalize"),
    [({}, {"skip_validation_inertia": True}), ({"collapse_fixed_joints": True}, None)],
    ids=["skip-validation", "collapse"],
)
def test_a_variant_of_the_parsed_builder_is_newtons_own_load_with_the_option(options, finalize) -> None:
    path = fixture_path(cause(ids.COLLAPSE))  # welded links, and an inertia finalize() does not change
    robot, _ = loader.parse(path, "urdf", False)
    mine, _ = loader.finalized(robot, path, finalize=finalize, collapse=bool(options))
    theirs, _ = loader.build(path, "urdf", False, finalize=finalize, options=options or None)
    for a, b in zip(_arrays(mine), _arrays(theirs), strict=True):
        assert np.array_equal(a, b)
    rows = effect_poses(theirs)
    assert np.array_equal(mass_matrices(mine, rows), mass_matrices(theirs, rows))


def test_finalize_leaves_the_builder_as_it_was() -> None:
    path = fixture_path(cause(ids.VALIDATION))  # a point mass: finalize() replaces its zero inertia
    robot, _ = loader.parse(path, "urdf", False)
    first, _ = loader.finalized(robot, path)
    loader.finalized(robot, path, finalize={"skip_validation_inertia": True})
    again, _ = loader.finalized(robot, path)
    for a, b in zip(_arrays(first), _arrays(again), strict=True):
        assert np.array_equal(a, b)


@pytest.mark.parametrize(("fixture", "parses"), [(ids.COLLAPSE, 1), (ids.FLOATING_FALSE, 2)])
def test_attach_parses_the_file_once(monkeypatch: pytest.MonkeyPatch, fixture: str, parses: int) -> None:
    """Once per attach; an MJCF twice, ``floating=False`` being a parser option (the engine's replicas aside)."""
    calls = []
    parse = loader.parse

    def counted(*args, **kwargs):
        calls.append(args[0])
        return parse(*args, **kwargs)

    monkeypatch.setattr(loader, "parse", counted)
    pair = load_model(str(fixture_path(cause(fixture))))
    assert pair.attach("newton") is not None or pair.refusal("newton") is not None
    assert len(calls) == parses
