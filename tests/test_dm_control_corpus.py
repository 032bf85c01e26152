"""The models shipped with dm_control, as a corpus: every file loads or is refused with one line naming it;
where both engines load and every joint maps, the verdict matches an independent check (energies from the
engines' own mass matrices) and a disagreement carries a root cause or a per-segment reason."""

from __future__ import annotations

from pathlib import Path

import pytest
from common import dm_control_corpus, dm_control_root

import koenig_check
from independent_energy import engines_agree
from koenig_check.diagnosis.cause_groups import cause_groups
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.engines import load_model
from koenig_check.findings import Kind, KoenigCheckError
from process_memory import release_memory

pytest.importorskip("dm_control")
ROOT = dm_control_root()
CORPUS = dm_control_corpus()


@pytest.fixture(autouse=True)
def _release_memory_after_each_model():
    """The corpus's largest models (fruitfly, dog: thousands of meshes) one after the other would hold GBs."""
    yield
    release_memory()


def test_corpus_is_found() -> None:
    assert len(CORPUS) >= 30


@pytest.mark.parametrize("path", CORPUS, ids=[str(p.relative_to(ROOT)) for p in CORPUS])
def test_verdict_or_whole_refusal(path: Path) -> None:
    check = koenig_check.compare(path, n_poses=2, formulas=["exact"])
    try:
        pair = load_model(path)
    except KoenigCheckError as err:
        ((_label, reason),) = check.failures
        assert "\n" not in reason and path.name in reason, reason
        assert str(err).split()[0] in reason
        assert not reason.rstrip().endswith(".cpp"), f"the engine's reason is cut to its first line: {reason}"
        return
    independent = engines_agree(pair)
    if independent is None:
        pytest.skip("engines differ by between 1e-9 and 1e-6 relative: no clear independent verdict")
    gravity = check.comparisons[0].gravity
    gravity_off = gravity is not None and not gravity.agrees  # the gravity verdict: tests/gravity
    kinetic_ok = all(p.agrees for p in check.agreements) and not any(
        f.kind in (Kind.VERDICT, Kind.ENGINE_UNABLE) for f in check.comparisons[0].findings
    )
    assert (check.ok if not gravity_off else kinetic_ok) == independent, check.reason()
    if gravity_off:  # a gravity difference is never unexplained on dm_control's files: a cause or a mass reading
        assert gravity is not None and not check.ok
        assert all(f.root_cause or f.cause or "explained by" in f.values for f in gravity.explanations)
    report = import_parity(pair)
    if independent:  # no cause that changes the energy on a model whose engines agree
        assert not [c.message() for c in report.causes if c.affects_energy]
    else:
        reason = check.reason()
        causes = [c for c in report.causes if c.affects_energy]
        assert len(reason) <= 186 and "\n" not in reason, reason  # one sentence: koenig-check: <it> fits 200
        if causes:
            first = cause_groups(causes)[0]  # the same cause on several elements is one
            assert first.short() in reason  # the one-line reason leads with the root cause
        else:
            assert not report.clean


def _dm(rel: str) -> Path:
    return ROOT / rel


def test_cartpole_pole_mass_from_class() -> None:
    report = import_parity(load_model(_dm("suite/cartpole.xml")))
    (cause,) = [c for c in report.causes if c.kind is Kind.MASS]
    assert cause.values["class"] == "pole" and cause.values["mujoco"] == pytest.approx(0.1)
    assert cause.values["pinocchio"] == pytest.approx(6.74, abs=0.01)


def test_rodent_joint_positions_from_classes() -> None:
    pair = load_model(_dm("locomotion/walkers/assets/rodent.xml"))
    report = import_parity(pair)
    assert report.total_mass[0] == pytest.approx(report.total_mass[1], rel=1e-12)
    anchors = [c for c in report.causes if c.kind is Kind.ANCHOR]
    assert anchors and {c.values["class"] for c in anchors} == {"lumbar"}
    assert engines_agree(pair) is False


def test_fruitfly_segments_are_massless_in_pinocchio_not_missing() -> None:
    report = import_parity(load_model(_dm("locomotion/walkers/assets/fruitfly_v2/fruitfly.xml")))
    (massless,) = [c for c in report.causes if c.kind is Kind.SEGMENTS]
    assert massless.engine == "pinocchio" and massless.values["pinocchio"] == 0.0 and massless.values["mujoco"] > 0
    assert report.massless_in_pinocchio and not report.only_in_mujoco
    assert set(report.massless_in_pinocchio) <= set(massless.segments)


def test_humanoid_capsules_are_read_as_capsules() -> None:
    report = import_parity(load_model(_dm("suite/humanoid.xml")))
    inertial = [f for f in report.findings if "<inertial>" in f]
    assert inertial and not any("sphere" in f for f in inertial if "torso" in f), inertial
    assert any("capsule" in f for f in inertial)


def test_cheetah_settotalmass_is_named() -> None:
    report = import_parity(load_model(_dm("suite/cheetah.xml")))
    (cause,) = [c for c in report.causes if c.kind is Kind.COMPILER]
    assert (cause.engine, cause.element) == ("pinocchio", "compiler settotalmass")  # the engine that ignores it
    assert cause.values["mujoco"] == pytest.approx(14.0) and cause.values["pinocchio"] > 14.0
    assert report.headline().startswith("root cause: " + cause.message())


def test_a_worldbody_without_a_body_is_nothing_to_compare() -> None:
    with pytest.raises(KoenigCheckError) as info:
        load_model(_dm("mujoco/testing/assets/sphere.xml"))
    (cause,) = info.value.causes
    assert cause.kind is Kind.NOTHING_MOVES and not cause.affects_energy and cause.hint == ""
