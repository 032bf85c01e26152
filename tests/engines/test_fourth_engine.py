"""A fourth engine is one subpackage: two fake engines, made in tmp_path for one test, reach every part of the checker.

The fake engines are subpackages of ``koenig_check.engines`` (their folder is put on the package's search path for
the test): ``gpu`` wraps the MuJoCo adapter under another name; ``gpu_skewed`` does too, with its rigid-body energy
scaled by 1.01, so that it departs.  Each declares ``SPEC = EngineSpec(...)`` in its ``__init__.py`` and an adapter
derived from :class:`koenig_check.engines.base.Engine`; no file of koenig_check changes.  The test then checks
that the engine is listed, attached by ``--engines`` and ``engines=``, in the terminal table's columns, in the
figures' legends, named by the verdict when it departs, in the export's proof and in the dynamics check.
"""

from __future__ import annotations

import sys
import textwrap
from collections.abc import Iterator
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from matplotlib.colors import to_rgba

import koenig_check
import koenig_check.engines
from koenig_check import findings as findings_module
from koenig_check.cli import main
from koenig_check.engines import registry
from koenig_check.engines.base import Engine
from koenig_check.findings import Kind
from koenig_check.report import figures
from koenig_check.report.content import model_findings
from koenig_check.report.terminal import terminal_table

#: A model on which MuJoCo and Pinocchio agree (so that only the skewed engine departs).
MODEL = "gimbal.xml"
#: The skewed engine's factor on the rigid-body energy.
SKEW = 1.01

_INIT = '''
"""A fake engine for a test: the MuJoCo adapter under another name."""

from koenig_check.engines.specs import EngineSpec

SPEC = EngineSpec(
    name="{name}",
    label="{label}",
    module="numpy",
    extra="{name}",
    attach="koenig_check.engines.{name}.adapter:attach",
    load_alone="koenig_check.engines.{name}.adapter:load_alone",
    color="{color}",
)
'''

_ADAPTER = '''
"""The fake engine's adapter: every answer is MuJoCo's (its own MjData), the rigid energy times {scale}."""

from koenig_check.engines.base import Engine
from koenig_check.engines.energy import EnergyParts
from koenig_check.engines.mujoco.adapter import MujocoEngine


class FakeEngine(Engine):
    engine = "{name}"

    def __init__(self, mj_model, path):
        self.inner = MujocoEngine(mj_model, path)
        self.path = self.inner.path
        self.findings = []
        self.segment_names = self.inner.segment_names
        self.nq, self.nv = self.inner.nq, self.inner.nv
        self._mass, self._inertia = self.inner.mass_properties()

    def segment_states(self, qpos, qvel):
        return self.inner.segment_states(qpos, qvel)

    def point_velocities(self, qpos, qvel, points):
        return self.inner.point_velocities(qpos, qvel, points)

    def kinetic_energy(self, qpos, qvel):
        e = self.inner.kinetic_energy(qpos, qvel)
        return EnergyParts({scale} * e.rigid, e.armature, {scale} * e.rigid + e.armature)

    def sweep(self, qpos, qvel, points=None):
        states, pv, rigid, armature = self.inner.sweep(qpos, qvel, points)
        return states, pv, {scale} * rigid, armature

    def mass_matrix(self, qpos):
        return self.inner.mass_matrix(qpos)

    def inverse_dynamics(self, qpos, qvel, qacc):
        return self.inner.inverse_dynamics(qpos, qvel, qacc)

    def armature_matrix(self, qpos):
        return self.inner.armature_matrix(qpos)

    def armature_forces(self, qpos, qvel, qacc):
        return self.inner.armature_forces(qpos, qvel, qacc)

    def dofs_by_kind(self):
        return self.inner.dofs_by_kind()


def attach(model):
    return FakeEngine(model.mujoco.model, model.source.path), []


def load_alone(source, mj_model):
    return FakeEngine(mj_model, source.path)
'''

#: name -> (label, colour, energy factor)
FAKES = {"gpu": ("GPU", "tab:purple", 1.0), "gpu_skewed": ("GPU-skewed", "tab:brown", SKEW)}


@pytest.fixture
def fourth_engine(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[str]:
    """Two engine subpackages in tmp_path, on ``koenig_check.engines``'s search path for the test."""
    root = tmp_path / "engines"
    for name, (label, color, scale) in FAKES.items():
        (root / name).mkdir(parents=True)
        (root / name / "__init__.py").write_text(textwrap.dedent(_INIT.format(name=name, label=label, color=color)))
        (root / name / "adapter.py").write_text(textwrap.dedent(_ADAPTER.format(name=name, scale=scale)))
    monkeypatch.setattr(koenig_check.engines, "__path__", [*koenig_check.engines.__path__, str(root)])
    yield "gpu"
    for name in FAKES:
        for module in [m for m in sys.modules if m.startswith(f"koenig_check.engines.{name}")]:
            del sys.modules[module]


def test_a_subpackage_is_listed_in_report_order(fourth_engine: str) -> None:
    assert registry.names()[:2] == ("mujoco", "pinocchio")
    optional = registry.optional()  # by name, after the required ones (whatever other engines are installed)
    assert registry.names()[2:] == optional == tuple(sorted(optional)) and {"gpu", "gpu_skewed"} <= set(optional)
    assert registry.ENGINE_NAMES == registry.names() and registry.LABEL["gpu"] == "GPU"
    assert registry.install_hint("gpu") == "pip install 'koenig-check[gpu]'"
    assert "gpu" in findings_module.ENGINES
    from koenig_check.engines.load_options import LoadOptions, parse_engines

    assert parse_engines("gpu,pinocchio,mujoco") == ("mujoco", "pinocchio", "gpu")
    assert LoadOptions(engines=("mujoco", "pinocchio", "gpu")).engines == ("mujoco", "pinocchio", "gpu")


def test_without_the_subpackage_it_is_unknown() -> None:
    assert "gpu" not in registry.names()
    from koenig_check.engines.load_options import parse_engines

    with pytest.raises(ValueError, match="unknown"):
        parse_engines("mujoco,pinocchio,gpu")


def test_an_adapter_implements_the_engine_interface(fourth_engine: str) -> None:
    loaded = koenig_check.engines.load_model(MODEL)
    gpu = loaded.attach("gpu")
    assert isinstance(gpu, Engine) and loaded.engines["gpu"] is gpu


def _model_row(table: str, model: str) -> list[str]:
    return next(line for line in table.splitlines() if line.startswith(model)).split()


def test_attached_by_engines_and_given_a_column_of_its_own(fourth_engine: str) -> None:
    check = koenig_check.compare(MODEL, n_poses=4, formulas=["exact"], engines=("mujoco", "pinocchio", "gpu"))
    comparison = check.comparisons[0]
    assert comparison.engines == ("mujoco", "pinocchio", "gpu") and check.ok
    table = terminal_table(check)
    assert table.startswith("Models: do MuJoCo, Pinocchio and GPU agree?")
    header = next(line for line in table.splitlines() if line.startswith("model "))
    assert header.split()[:7] == ["model", "verdict", "pinocchio", "gap", "gpu", "gap", "exact"]
    # Independent route: the records' exact totals on each engine's states (equal to its energy to rounding).
    value = {
        e: comparison.records.where(formula="exact", scope="total", source=e, reference=e)["value"]
        for e in ("mujoco", "gpu")
    }
    gap = float(np.max(np.abs(value["gpu"] - value["mujoco"]) / np.abs(value["mujoco"])))
    printed = _model_row(table, MODEL)[3]
    assert printed == "0" if gap < 1e-13 else float(printed) == pytest.approx(gap, rel=0.06)


def test_attached_by_the_command_line(fourth_engine: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["compare", MODEL, "--poses", "3", "--formulas", "exact", "--engines", "mujoco,pinocchio,gpu"]
    assert main([*argv, "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert "Models: do MuJoCo, Pinocchio and GPU agree?" in out and "gpu gap" in out


def test_in_the_figures_legends_in_its_colour(
    fourth_engine: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    drawn = []
    save = figures._save
    monkeypatch.setattr(figures, "_save", lambda fig, path, dpi: drawn.append(fig) or save(fig, path, dpi))
    argv = ["compare", MODEL, "--poses", "3", "--formulas", "exact", "--engines", "mujoco,pinocchio,gpu"]
    assert main([*argv, "--out", str(tmp_path / "out")]) == 0
    legends = {}  # legend text -> its marker's colour, in the figures' and the axes' legends
    for fig in drawn:
        for legend in [*fig.legends, *(ax.get_legend() for ax in fig.axes)]:
            if legend is None:
                continue
            for text, handle in zip(legend.get_texts(), legend.legend_handles, strict=True):
                legends[text.get_text()] = to_rgba(handle.get_color()) if hasattr(handle, "get_color") else None
    assert legends["gpu states vs gpu energy"] == to_rgba("tab:purple")  # the error distribution
    gap = [t for t in legends if t.startswith("gpu vs mujoco")]  # the engines' gap per pose
    assert gap and legends[gap[0]] == to_rgba("tab:purple")


def test_a_departing_fourth_engine_is_named_by_the_verdict(fourth_engine: str) -> None:
    engines = ("mujoco", "pinocchio", "gpu", "gpu_skewed")
    check = koenig_check.compare(MODEL, n_poses=4, formulas=["exact"], engines=engines)
    comparison = check.comparisons[0]
    verdicts = [f for f in comparison.findings if f.kind is Kind.VERDICT]
    assert [(f.engine, f.element) for f in verdicts] == [("gpu_skewed", "rigid-body energy")]
    assert verdicts[0].summary.startswith("GPU-skewed departs (MuJoCo, Pinocchio and GPU agree)")
    values = verdicts[0].values
    assert values["gpu_skewed"] == pytest.approx(SKEW * values["mujoco"], rel=1e-12)  # the factor set above
    assert values["gpu"] == pytest.approx(values["mujoco"], rel=1e-12)
    assert not check.ok and "GPU-skewed departs" in check.reason()
    assert _model_row(terminal_table(check), MODEL)[1] == "DISAGREE"
    note = f"four engines: {verdicts[0].message()}"  # four voted: the note says so, not "three engines"
    assert note in comparison.notes
    summaries = [s for s in check.summaries if s.model == comparison.model]
    assert model_findings(comparison, summaries, check.parities[0], 1e-9).engines.endswith(f"; {note}")


def test_the_export_proves_it_reads_the_same_robot(fourth_engine: str, tmp_path: Path) -> None:
    result = koenig_check.export(MODEL, to="urdf", out=tmp_path / "gimbal.urdf", engines=("mujoco", "pinocchio", "gpu"))
    proofs = {p.engine: p for p in result.proof.engines}
    assert set(proofs) == {"mujoco", "pinocchio", "gpu"}
    assert proofs["gpu"].equivalent and proofs["gpu"].mass_matrix < 1e-9
    everything = koenig_check.export(MODEL, to="urdf", out=tmp_path / "all.urdf")  # by default, every engine
    assert {"gpu", "gpu_skewed"} <= {p.engine for p in everything.proof.engines}


def test_the_dynamics_check_has_its_column(fourth_engine: str) -> None:
    from koenig_check.implied_dynamics.markdown import terminal_lines

    result = koenig_check.dynamics(MODEL, n_poses=3, formulas=["exact"], engines=("mujoco", "pinocchio", "gpu"))
    assert list(result.engine_mass) == ["mujoco", "pinocchio", "gpu"]
    # The fake answers with MuJoCo's model: MuJoCo's own mass matrix, built here by mj_fullM.
    import mujoco

    loaded = koenig_check.engines.load_model(MODEL)
    data = mujoco.MjData(loaded.mujoco.model)
    data.qpos[:] = result.qpos[0]
    mujoco.mj_forward(loaded.mujoco.model, data)
    full = np.zeros((loaded.mujoco.nv, loaded.mujoco.nv))
    mujoco.mj_fullM(loaded.mujoco.model, data, full)
    rigid = full - np.diag(loaded.mujoco.model.dof_armature)
    np.testing.assert_allclose(result.engine_mass["gpu"][0], rigid, rtol=1e-12, atol=1e-12 * np.abs(rigid).max())
    assert any(e.engine == "gpu" for e in result.errors)
    lines = terminal_lines(result)
    assert any(line.startswith("engines (mujoco vs gpu)") for line in lines) and "M vs gpu" in lines[1]


def _runs(**rigid: float) -> dict[str, SimpleNamespace]:
    """Engine energies at two poses: the given rigid energy (and twice it), no armature."""
    return {e: SimpleNamespace(rigid=np.array([v, 2 * v]), armature=np.zeros(2)) for e, v in rigid.items()}


@pytest.mark.parametrize(
    ("rigid", "expected"),
    [
        ({"mujoco": 1.0, "pinocchio": 1.0, "drake": 1.2}, [("drake", "Drake departs (MuJoCo and Pinocchio agree)")]),
        ({"mujoco": 1.0, "pinocchio": 1.1, "drake": 1.2}, [("all", "all three engines differ")]),
        (
            {"mujoco": 1.0, "pinocchio": 1.0, "gpu": 1.0, "gpu_skewed": SKEW},
            [("gpu_skewed", "GPU-skewed departs (MuJoCo, Pinocchio and GPU agree)")],
        ),
        (
            {"mujoco": 1.0, "pinocchio": 1.0, "drake": 1.0, "gpu": 2.0, "gpu_skewed": 2.0},
            [
                ("gpu", "GPU departs (MuJoCo, Pinocchio and Drake agree)"),
                ("gpu_skewed", "GPU-skewed departs (MuJoCo, Pinocchio and Drake agree)"),
            ],
        ),
        (
            {"mujoco": 1.0, "pinocchio": 1.0, "gpu": 2.0, "gpu_skewed": 2.0},
            [("all", "no majority of the 4 engines agrees")],
        ),
    ],
)
def test_a_majority_names_the_engines_that_depart(
    fourth_engine: str, rigid: dict[str, float], expected: list[tuple[str, str]]
) -> None:
    from koenig_check.diagnosis.three_way import energy_verdicts

    verdicts = energy_verdicts(_runs(**rigid), [])
    assert [(f.engine, f.element, f.summary) for f in verdicts] == [(e, "rigid-body energy", s) for e, s in expected]
    assert all(f.values == {e: 2 * v for e, v in rigid.items()} for f in verdicts)  # at the pose of largest spread


def test_a_subpackage_without_a_spec_is_refused_by_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from koenig_check.engines import specs

    (tmp_path / "nospec").mkdir()
    (tmp_path / "nospec" / "__init__.py").write_text('"""An engine subpackage that forgot its SPEC."""\n')
    monkeypatch.setattr(koenig_check.engines, "__path__", [*koenig_check.engines.__path__, str(tmp_path)])
    monkeypatch.delitem(sys.modules, "koenig_check.engines.nospec", raising=False)
    with pytest.raises(TypeError, match=r"koenig_check\.engines\.nospec: .*SPEC = EngineSpec"):
        specs.specs()
    sys.modules.pop("koenig_check.engines.nospec", None)
