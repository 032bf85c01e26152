"""``pytest --koenig-check`` with entries that name each new engine, one that cannot read the format, and ``all``.

Each engine passes on a URDF the project ships where it agrees with MuJoCo and Pinocchio, and fails, with its own
reason, on a model it cannot check: Newton's inertia validation changes a foot's point mass (a parser limit), and
PyBullet and iDynTree cannot read an MJCF.  ``engines = "all"`` runs each model in the installed engines that read
its format: an MJCF passes without PyBullet and iDynTree, which are left out, not failed; a URDF is checked by them.
"""

from __future__ import annotations

import shutil

import pytest

from koenig_check.causes import cause, fixture_path
from koenig_check.engines import resolve_model
from koenig_check.engines.registry import installed, label
from named_engines import named

#: Per new engine, a model it cannot check and the words its failure opens with.
CANNOT_CHECK = {
    "newton": (fixture_path(cause("newton.any.inertia-validation")), "foot.urdf", "cannot check this model"),
    "pybullet": (resolve_model("double_pendulum.xml").path, "pendulum.xml", "asked for (--engines) but it could not"),
    "idyntree": (resolve_model("double_pendulum.xml").path, "pendulum.xml", "asked for (--engines) but it could not"),
}


@pytest.fixture(autouse=True)
def _cache(tmp_path, monkeypatch):
    monkeypatch.setenv("KOENIG_CHECK_CACHE", str(tmp_path / "koenig-check-cache"))


def _run(pytester: pytest.Pytester, files: dict[str, object], engines: str) -> pytest.RunResult:
    (pytester.path / "models").mkdir()
    for name, path in files.items():
        shutil.copy(path, pytester.path / "models" / name)  # installed or editable alike
    entries = [f'{{ model = "models/{name}", engines = {engines}, poses = 2 }}' for name in files]
    pytester.makepyprojecttoml("[tool.koenig-check]\nmodels = [\n" + ",\n".join(entries) + "\n]\n")
    return pytester.runpytest_subprocess("--koenig-check", "-v", "-p", "no:cacheprovider")


@pytest.mark.parametrize("engine", [named(e) for e in CANNOT_CHECK])
def test_an_entry_naming_the_engine_passes_where_it_agrees_and_fails_with_its_reason(
    pytester: pytest.Pytester, engine: str
) -> None:
    path, name, words = CANNOT_CHECK[engine]
    files = {"serial7.urdf": resolve_model("serial7.urdf").path, name: path}
    result = _run(pytester, files, f'["mujoco", "pinocchio", "{engine}"]')
    result.assert_outcomes(passed=1, failed=1)
    result.stdout.fnmatch_lines(["*serial7.urdf PASSED*", f"*{label(engine)} {words}*"])


@pytest.mark.skipif(not installed("pybullet"), reason="PyBullet absent")
def test_all_passes_an_mjcf_and_a_urdf_each_in_the_engines_that_read_it(pytester: pytest.Pytester) -> None:
    """PyBullet, asked for by ``all`` on a URDF, gives the camera link without <inertial> 1 kg: that entry fails,
    naming it; on the MJCFs it is left out, and they pass."""
    files = {name: resolve_model(name).path for name in ("serial7.urdf", "serial7.xml", "double_pendulum.xml")}
    files["camera.urdf"] = fixture_path(cause("pybullet.urdf.link-without-inertial"))
    result = _run(pytester, files, '"all"')
    result.assert_outcomes(passed=3, failed=1)
    result.stdout.fnmatch_lines(["*camera.urdf FAILED*", "*PyBullet cannot check this model*(links: camera)*"])
