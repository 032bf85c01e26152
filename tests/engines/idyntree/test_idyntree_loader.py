"""iDynTree's loader on files it cannot take: an XML declaration of another version than 1.x crashes it.

Measured on iDynTree 15.1: ``ModelLoader.loadModelFromFile`` on ``<?xml version="0.0" ?>`` (pybullet_data's
minitaur.urdf, quadruped.urdf, bike.urdf) prints ``Unsupported version '0.0'`` and the process dies of a segmentation
fault, taking the batch's other models with it. Without the check in the loader these tests crash the test process.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

import koenig_check
from koenig_check.engines.catalogue import cause, fixture_path
from koenig_check.findings import Kind

pytest.importorskip("idyntree")

from koenig_check.engines.idyntree.loader import IDynTreeXmlVersionError, load_idyntree

FIXTURE = fixture_path(cause("idyntree.urdf.xml-version"))


def _with_version(tmp_path: Path, version: str) -> Path:
    text = FIXTURE.read_text().replace('<?xml version="0.0" ?>', f'<?xml version="{version}" ?>', 1)
    path = tmp_path / f"v{version}.urdf"
    path.write_text(text)
    return path


@pytest.mark.parametrize("version", ["0.0", "2.0"])
def test_a_version_that_crashes_idyntree_is_refused_in_one_line(tmp_path: Path, version: str) -> None:
    path = _with_version(tmp_path, version)
    with pytest.raises(IDynTreeXmlVersionError) as caught:
        load_idyntree(path)
    first, *rest = str(caught.value).splitlines()
    assert len(first) <= 200 and first.startswith(f'{path}: <?xml version="{version}"?>')
    assert rest == [f"    [ERROR] XMLParser :: [Parsing] : Unsupported version '{version}'"]


@pytest.mark.parametrize("version", ["1.0", "1.1"])
def test_a_version_idyntree_reads_is_given_to_it(tmp_path: Path, version: str) -> None:
    model = load_idyntree(_with_version(tmp_path, version))
    assert model.getNrOfDOFs() == 1 and model.getLink(model.getLinkIndex("arm")).getInertia().getMass() == 1.5


def test_pybullet_datas_minitaur_is_refused_with_its_cause_and_the_batch_goes_on() -> None:
    """A real file (pybullet_data ships with pybullet, in the [test] extra): iDynTree abstains, the rest is checked."""
    pybullet_data = pytest.importorskip("pybullet_data")
    minitaur = os.path.join(pybullet_data.getDataPath(), "quadruped", "minitaur.urdf")
    engines = ("mujoco", "pinocchio", "idyntree")
    check = koenig_check.compare([minitaur, "serial7.urdf"], n_poses=2, formulas=["exact"], engines=engines)
    first, second = check.comparisons
    refusals = [f for f in first.findings if f.kind == Kind.ENGINE_NOT_USED and f.engine == "idyntree"]
    assert [f.cause for f in refusals] == ["idyntree.urdf.xml-version"]
    assert first.engines == ("mujoco", "pinocchio") and second.engines == engines
