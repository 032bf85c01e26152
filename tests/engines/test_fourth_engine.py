"""A fourth engine is one subpackage: two fake engines, made in tmp_path for one test, reach every part of the checker.

The fake engines are subpackages of ``koenig_check.engines`` (their folder is put on the package's search path for
the test): ``gpu`` wraps the MuJoCo adapter under another name; ``gpu_skewed`` does too, with its rigid-body energy
scaled by 1.01, so that it departs.  Each declares ``SPEC = EngineSpec(...)`` in its ``__init__.py`` and an adapter
derived from :class:`koenig_check.engines.base.Engine`; no file of koenig_check changes.  The test then checks
that the engine is listed, attached by ``--engines`` and ``engines=``, in the terminal table's columns, in the
figures' legends, named by the verdict when it departs, in the export's proof and in the dynamics check.

``gpu`` has traps of its own, declared in its subpackage only: its MJCF parser drops ``<geom mass>`` (density ×
volume instead, cause ``gpu.mjcf.geom-mass``) and ignores joint armature (``gpu.mjcf.joint-armature``, which it
declares a parser limit in ``limits.py``), each with a fixture in ``gpu/fixtures/``; it breaks no tie.  Its
verdict, the ranking of its causes, its abstention and its hint are checked through compare, parity and the
one-line reason (the tests at the end).
"""

from __future__ import annotations

import importlib
import json
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

_TRAPS = '''
"""The fake engine's MJCF parser: it drops <geom mass> (density × volume) and ignores joint armature."""

import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.canonical import segment_of_body
from koenig_check.findings import Finding, Kind

GEOM_MASS = "gpu.mjcf.geom-mass"
ARMATURE = "gpu.mjcf.joint-armature"


def read_text(path):
    """The file as this parser reads it, or None where it reads it as written (an MJCF file without the traps)."""
    root = ET.parse(path).getroot()
    changed = False
    for world in root.iter("worldbody"):
        for element, attribute in (("geom", "mass"), ("joint", "armature")):
            for e in world.iter(element):
                changed = e.attrib.pop(attribute, None) is not None or changed
    return ET.tostring(root, encoding="unicode") if changed else None


def read(path, mj_model):
    """The parser's model of a file: MuJoCo's own where no trap is in it."""
    text = read_text(path)
    return mj_model if text is None else mujoco.MjModel.from_xml_string(text)


def in_a_file(path):
    """The file as this parser reads it, written to a temporary file (the file itself where nothing changes)."""
    text = read_text(path)
    if text is None:
        return Path(path)
    out = Path(tempfile.mkdtemp()) / Path(path).name
    out.write_text(text)
    return out


def findings(mj_model, own):
    """The traps the file springs: one root cause per body whose mass changed, per joint whose armature went."""
    seg = segment_of_body(mj_model)
    out = []
    for b in range(1, mj_model.nbody):
        written, read_ = float(mj_model.body_mass[b]), float(own.body_mass[b])
        if not np.isclose(written, read_, rtol=1e-12, atol=0.0):
            body = mj_model.body(b).name
            out.append(Finding(
                Kind.MASS, "gpu", f"body {body}", "GPU's MJCF parser drops the geoms' mass: density × volume",
                {"mujoco": written, "gpu": read_}, affects_energy=True, root_cause=True,
                segments=(seg[body],) if seg.get(body) else (), cause=GEOM_MASS, tag="body",
            ))
    for j in range(mj_model.njnt):
        dof = int(mj_model.jnt_dofadr[j])
        if mj_model.dof_armature[dof] and not own.dof_armature[dof]:
            joint = mj_model.joint(j).name
            out.append(Finding(
                Kind.ARMATURE, "gpu", f"joint {joint}", "GPU's MJCF parser ignores the joint's armature",
                {"mujoco": [float(mj_model.dof_armature[dof])], "gpu": [0.0]}, affects_energy=True,
                root_cause=True, segments=(joint,), cause=ARMATURE, tag="joint",
            ))
    return out
'''

_CAUSES = '''
"""The constructs the fake engine's MJCF parser reads differently (MuJoCo and Pinocchio read them as written)."""

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.gpu.traps import in_a_file
from koenig_check.engines.mujoco.causes import measure as _mujoco_measure

CAUSES = (
    Cause(
        id="gpu.mjcf.geom-mass",
        construct="<geom mass>",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written"),
            Reading("pinocchio", "as written"),
            Reading("gpu", "differently", "drops the mass: density × volume of the geom"),
        ),
        quantities=("mass", "inertia"),
        brief="geom mass dropped by GPU",
        hint="give the body an <inertial>",
        fixture="geom_mass.xml",
    ),
    Cause(
        id="gpu.mjcf.joint-armature",
        construct="<joint armature>",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written"),
            Reading("pinocchio", "as written"),
            Reading("gpu", "differently", "ignores it: no rotor inertia"),
        ),
        quantities=("armature",),
        brief="joint armature ignored by GPU",
        hint="check the model without GPU",
        fixture="joint_armature.xml",
    ),
)


def measure(path):
    """The fake's reading of a file: MuJoCo's measurement of the file as this parser reads it."""
    return _mujoco_measure(in_a_file(path))
'''

_LIMITS = '''
"""What the fake engine's parser does not read: a model with joint armature is another robot in it."""

from koenig_check.engines.limit import ParserLimit

LIMITS = (ParserLimit("ignores armature", cause="gpu.mjcf.joint-armature"),)
'''

#: The fake's fixtures: a geom's written mass (MuJoCo: 2 kg; density × volume: 1000 × 0.2³ = 8 kg) and an armature.
_FIXTURES = {
    "geom_mass.xml": """<mujoco model="geom_mass">
  <worldbody>
    <body name="arm"><joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom type="box" size="0.1 0.1 0.1" pos="0.3 0 0" mass="2"/></body>
  </worldbody>
</mujoco>
""",
    "joint_armature.xml": """<mujoco model="joint_armature">
  <worldbody>
    <body name="wheel" pos="1 0 0"><joint name="spin" type="hinge" axis="0 0 1" armature="0.05"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.2 0.3 0.4"/></body>
  </worldbody>
</mujoco>
""",
}

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

#: The trapped engine's attach: its parser's own model of the file, and the traps it springs as findings.
_TRAPPED_ATTACH = """

def attach(model):
    from koenig_check.engines.gpu import traps

    own = traps.read(model.source.path, model.mujoco.model)
    return FakeEngine(own, model.source.path), traps.findings(model.mujoco.model, own)
"""

#: name -> (label, colour, energy factor)
FAKES = {"gpu": ("GPU", "tab:purple", 1.0), "gpu_skewed": ("GPU-skewed", "tab:brown", SKEW)}


@pytest.fixture
def fourth_engine(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[str]:
    """Two engine subpackages in tmp_path, on ``koenig_check.engines``'s search path for the test."""
    root = tmp_path / "engines"
    for name, (label, color, scale) in FAKES.items():
        (root / name).mkdir(parents=True)
        (root / name / "__init__.py").write_text(textwrap.dedent(_INIT.format(name=name, label=label, color=color)))
        adapter = textwrap.dedent(_ADAPTER.format(name=name, scale=scale))
        if name == "gpu":  # the trapped one: its parser's model, its causes, its limits, its fixtures
            adapter += _TRAPPED_ATTACH
            for module, text in (("traps", _TRAPS), ("causes", _CAUSES), ("limits", _LIMITS)):
                (root / name / f"{module}.py").write_text(textwrap.dedent(text))
            (root / name / "fixtures").mkdir()
            for fixture, text in _FIXTURES.items():
                (root / name / "fixtures" / fixture).write_text(text)
        (root / name / "adapter.py").write_text(adapter)
    monkeypatch.setattr(koenig_check.engines, "__path__", [*koenig_check.engines.__path__, str(root)])
    yield "gpu"
    for name in FAKES:
        for module in [m for m in sys.modules if m.startswith(f"koenig_check.engines.{name}")]:
            del sys.modules[module]


def test_a_subpackage_is_listed_in_report_order(fourth_engine: str) -> None:
    assert registry.names()[:2] == ("mujoco", "pinocchio")
    fakes = [n for n in registry.names() if n in FAKES]  # the optional engines sort by name, fakes among them
    assert fakes == ["gpu", "gpu_skewed"] and [n for n in registry.optional() if n in FAKES] == fakes
    assert list(registry.optional()) == sorted(registry.optional())
    assert registry.LABEL["gpu"] == "GPU"
    assert registry.install_hint("gpu") == "pip install 'koenig-check[gpu]'"
    assert "gpu" in findings_module.concerned()
    from koenig_check.engines.load_options import LoadOptions, parse_engines

    assert parse_engines("gpu,pinocchio,mujoco") == ("mujoco", "pinocchio", "gpu")
    assert LoadOptions(engines=("mujoco", "pinocchio", "gpu")).engines == ("mujoco", "pinocchio", "gpu")


def test_without_the_subpackage_it_is_unknown() -> None:
    from koenig_check.causes import catalogue

    assert "gpu" not in registry.names()
    assert not [c for c in catalogue() if c.engine == "gpu"]  # its causes come and go with it (the catalogue too)
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
    assert model_findings(comparison, summaries, check.agreements[0], 1e-9).engines.endswith(f"; {note}")


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


# --- The trapped engine: its causes, verdict, ranking, abstention and hint, through the whole pipeline ------------

#: The trapped engine's causes (declared in its own causes.py, with fixtures in its own fixtures/).
GEOM_MASS, ARMATURE = "gpu.mjcf.geom-mass", "gpu.mjcf.joint-armature"
#: The engines named in the trap's tests.
TRAPPED = ("mujoco", "pinocchio", "gpu")
#: Two geom masses on two bodies, the smaller change first in the file: body small, 1.5 kg written and
#: 1000 kg/m³ × 0.1³ m³ = 1 kg read by GPU (0.5 kg); body big, 2 kg written and 1000 × 0.2³ = 8 kg read (6 kg).
TWO_GEOM_MASSES = """<mujoco model="two_geom_masses">
  <worldbody>
    <body name="small"><joint name="j1" type="hinge" axis="0 1 0"/>
      <geom type="box" size="0.05 0.05 0.05" pos="0.2 0 0" mass="1.5"/>
      <body name="big" pos="0.4 0 0"><joint name="j2" type="hinge" axis="0 1 0"/>
        <geom type="box" size="0.1 0.1 0.1" pos="0.3 0 0" mass="2"/></body></body>
  </worldbody>
</mujoco>
"""


def _fixture(cause_id: str) -> Path:
    from koenig_check.causes import cause, fixture_path

    return fixture_path(cause(cause_id))


def test_its_causes_are_catalogued_with_fixtures_in_its_subpackage(
    fourth_engine: str, capsys: pytest.CaptureFixture[str]
) -> None:
    from koenig_check.causes import catalogue

    assert {c.id for c in catalogue() if c.engine == "gpu"} == {GEOM_MASS, ARMATURE}
    for cause_id in (GEOM_MASS, ARMATURE):
        path = _fixture(cause_id)
        assert path.is_file() and path.parent.parent.name == "gpu"  # engines/gpu/fixtures/
    assert main(["causes", "--engine", "gpu", "--json"]) == 0
    assert {c["id"] for c in json.loads(capsys.readouterr().out)} >= {GEOM_MASS, ARMATURE}


@pytest.mark.parametrize("cause_id", [GEOM_MASS, ARMATURE])
def test_its_fixtures_are_read_as_declared(fourth_engine: str, cause_id: str) -> None:
    """Re-measured: GPU's reading departs from MuJoCo's in the declared quantities, Pinocchio's does not."""
    from koenig_check.causes import cause
    from koenig_check.engines.measurement import differences, fields

    path, declared = _fixture(cause_id), fields(cause(cause_id).quantities)
    mj, pin, gpu = (importlib.import_module(f"koenig_check.engines.{e}.causes").measure(path) for e in TRAPPED)
    assert differences(gpu, mj, 1e-9) & declared and not differences(pin, mj, 1e-9) & declared
    if cause_id == GEOM_MASS:  # by hand: 2 kg written; a 0.2 m cube of density 1000 kg/m³ weighs 8 kg
        assert mj.mass == pytest.approx(2.0, rel=1e-12) and gpu.mass == pytest.approx(8.0, rel=1e-12)
    else:
        assert mj.armature == {"spin": pytest.approx(0.05, rel=1e-12)} and gpu.armature == {}


def test_its_trap_makes_it_depart_with_its_cause_named(fourth_engine: str, capsys: pytest.CaptureFixture[str]) -> None:
    path = _fixture(GEOM_MASS)
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=TRAPPED)
    comparison = check.comparisons[0]
    (energy,) = [f for f in comparison.findings if f.kind is Kind.VERDICT and f.element == "rigid-body energy"]
    assert energy.engine == "gpu" and energy.summary.startswith("GPU departs (MuJoCo and Pinocchio agree)")
    # By hand: one hinge, a cube (side 0.2 m) 0.3 m off the axis: I = m (0.2²/6 + 0.3²) is linear in m, 8/2 = 4.
    assert energy.values["gpu"] == pytest.approx(4 * energy.values["mujoco"], rel=1e-12)
    (found,) = [f for f in comparison.findings if f.cause == GEOM_MASS]
    assert found.engine == "gpu" and found.element == "body arm" and found.root_cause
    assert check.reason().startswith("geom_mass.xml: GPU departs; root cause: body arm: ")
    argv = ["compare", str(path), "--poses", "4", "--formulas", "exact", "--engines", ",".join(TRAPPED)]
    assert main(argv) == 1
    assert "geom_mass.xml: GPU departs; root cause: body arm" in capsys.readouterr().err


def test_its_causes_are_ranked_by_their_effect(fourth_engine: str, tmp_path: Path) -> None:
    from koenig_check.diagnosis.reason import ordered_causes

    path = tmp_path / "two_geom_masses.xml"
    path.write_text(TWO_GEOM_MASSES)
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=TRAPPED)
    findings = check.comparisons[0].findings
    assert [f.element for f in findings if f.cause == GEOM_MASS] == ["body small", "body big"]  # the file's order
    assert [f.element for f in ordered_causes(findings) if f.cause == GEOM_MASS] == ["body big", "body small"]
    reason = check.reason()
    assert "GPU departs" in reason and reason.index("big") < reason.index("small")  # 6 kg before 0.5 kg


def test_it_does_not_vote_where_its_parser_misreads_and_names_the_others_in_its_hint(
    fourth_engine: str, capsys: pytest.CaptureFixture[str]
) -> None:
    path = _fixture(ARMATURE)
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=TRAPPED)
    findings = check.comparisons[0].findings
    assert not check.ok and not [f for f in findings if f.kind is Kind.VERDICT]
    (unable,) = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.engine == "gpu" and unable.segments == ("spin",)
    assert check.reason() == (
        "joint_armature.xml: GPU cannot check this model: its MJCF parser ignores armature (joints: spin); "
        "without GPU: --engines mujoco,pinocchio"
    )
    both = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=(*TRAPPED, "gpu_skewed"))
    (unable,) = [f for f in both.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.hint == "without GPU: --engines mujoco,pinocchio,gpu_skewed"  # the other engines asked stay
    assert main(["parity", str(path), "--engines", ",".join(TRAPPED)]) == 1
    out, err = capsys.readouterr()
    assert err.startswith("koenig-check: joint_armature.xml: GPU cannot check this model: its MJCF parser ignores")
    assert "gpu: joint spin: GPU's MJCF parser ignores the joint's armature" in out


def test_it_breaks_no_tie_unless_it_declares_so(fourth_engine: str) -> None:
    """By default only a declared tie-breaker (Drake) is consulted where MuJoCo and Pinocchio disagree."""
    path = _fixture("pinocchio.mjcf.class-geom-mass")
    comparison = koenig_check.compare(path, n_poses=4, formulas=["exact"]).comparisons[0]
    assert [f for f in comparison.findings if f.kind is Kind.MASS and f.engine == "pinocchio"]  # they disagree
    assert "gpu" not in comparison.engines and "gpu_skewed" not in comparison.engines
    # not named and no tie-breaker: no note on each model (a run that names engines says the others once)
    assert not [f for f in comparison.findings if f.kind is Kind.ENGINE_NOT_USED and f.engine.startswith("gpu")]
    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.run.poses import random_pose_range

    model = koenig_check.engines.load_model(path)
    poses = random_pose_range(model.mujoco.model, 0, 4, 0, 1.0)
    consulted = diagnose(model, disagree=True, qpos=poses.qpos, qvel=poses.qvel).engines
    assert "gpu" not in consulted and ("drake" in consulted) == registry.installed("drake")


def test_a_reading_another_engines_cause_declares_for_it_is_acted_on(
    fourth_engine: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The route is keyed on the catalogue, not on an engine: declare that GPU ignores settotalmass (a reading of
    Pinocchio's cause) and GPU's finding carries that id and GPU abstains, asked for, on the cause's quantities."""
    import dataclasses

    from koenig_check.causes import catalogue, cause, fixture_path
    from koenig_check.engines import catalogue as module
    from koenig_check.engines.cause import Reading

    c = cause("pinocchio.mjcf.settotalmass")
    path = fixture_path(c)
    before = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=TRAPPED).comparisons[0].findings
    assert not [f for f in before if f.engine == "gpu" and (f.cause or f.kind is Kind.ENGINE_UNABLE)]
    declared = dataclasses.replace(c, readings=(*c.readings, Reading("gpu", "differently", "ignores the option")))
    every = catalogue()
    monkeypatch.setattr(module, "catalogue", lambda: tuple(declared if x.id == c.id else x for x in every))
    findings = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=TRAPPED).comparisons[0].findings
    (gpu,) = [f for f in findings if f.engine == "gpu" and f.cause == c.id]
    assert gpu.root_cause and gpu.element == "compiler settotalmass"
    (unable,) = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.engine == "gpu" and unable.values["causes"] == (c.id,)
    assert unable.values["quantities"] == ("mass", "inertia")
    assert not [f for f in findings if f.kind is Kind.VERDICT]
