"""The parity table's columns hold each engine's own value, and a differing segment or dof says DIFFERS.

Expected values are read from the engines' own models (MuJoCo's ``body_mass`` and ``dof_armature``, Pinocchio's
``inertias`` and ``armature``), not from the parity report.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.engines import load_model
from koenig_check.report.parity_table import format_parity

CAUSES = Path(__file__).parents[1] / "models" / "causes"


def _rows(text: str, header: str) -> list[list[str]]:
    """The whitespace-split rows of a table, from its header line to the first blank line."""
    lines = text.splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith(header))
    rows = []
    for line in lines[start + 1 :]:
        if not line.strip() or line.startswith("("):
            break
        rows.append(line.split())
    return rows


def _masses(loaded) -> tuple[list[float], list[float]]:
    mj, pin = loaded.mujoco.model, loaded.pinocchio.model
    return (
        [float(mj.body_mass[b]) for b in range(1, mj.nbody) if mj.body_weldid[b] != 0],
        [float(pin.inertias[i].mass) for i in range(1, pin.njoints)],
    )


def test_segment_rows_give_mujocos_mass_then_pinocchios() -> None:
    """class_mass: MuJoCo gives the pole its class mass 0.1 kg, Pinocchio density × volume."""
    loaded = load_model(CAUSES / "class_mass.xml")
    text = format_parity(import_parity(loaded))
    mj_masses, pin_masses = _masses(loaded)
    rows = _rows(text, "segment ")
    differing = 0
    for row in rows:
        # "body NAME (joint J)  m_mj  m_pin ..."; the masses follow the closing bracket of the label
        k = next(i for i, cell in enumerate(row) if cell.endswith(")"))
        m_mj, m_pin = float(row[k + 1]), float(row[k + 2])
        assert any(abs(m_mj - m) <= 1e-5 * m for m in mj_masses), (row, mj_masses)
        assert any(abs(m_pin - m) <= 1e-5 * m for m in pin_masses), (row, pin_masses)
        if abs(m_mj - m_pin) > 1e-5 * max(m_mj, m_pin):
            differing += 1
            assert "DIFFERS:" in row, row
    assert differing == 1  # the pole


def test_dof_rows_give_mujocos_armature_then_pinocchios() -> None:
    """MuJoCo from armature_chain.xml (armature on every joint), Pinocchio from its URDF twin (no armature)."""
    loaded = load_model("armature_chain.xml", pinocchio_model="armature_chain.urdf")
    text = format_parity(import_parity(loaded))
    mj = loaded.mujoco.model
    pin = loaded.pinocchio.model
    rows = _rows(text, "dof ")
    assert [r[0] for r in rows] == [mj.joint(j).name for j in range(mj.njnt)]
    for j, row in enumerate(rows):
        want_mj = float(mj.dof_armature[mj.jnt_dofadr[j]])
        want_pin = float(np.asarray(pin.armature)[pin.joints[pin.getJointId(row[0])].idx_v])
        assert float(row[1]) == pytest.approx(want_mj, rel=1e-5)
        assert float(row[2]) == pytest.approx(want_pin, abs=1e-12)
        assert want_mj > 0 and "DIFFERS:" in row, row


_BODY = """<mujoco model="one">
  <worldbody>
    <body name="arm">
      <joint name="hinge" type="hinge" axis="0 0 1"/>
      <inertial pos="{x} 0 0" mass="2" diaginertia="0.01 0.02 0.03"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_a_segment_with_one_difference_says_differs(tmp_path: Path) -> None:
    """Only the centre of mass moved (0.1 m -> 0.3 m): one cause, and the row still says DIFFERS."""
    (tmp_path / "a.xml").write_text(_BODY.format(x=0.1))
    (tmp_path / "b.xml").write_text(_BODY.format(x=0.3))
    loaded = load_model(tmp_path / "a.xml", pinocchio_model=str(tmp_path / "b.xml"))
    com_mj = loaded.mujoco.model.body_ipos[1]
    com_pin = loaded.pinocchio.model.inertias[1].lever
    assert np.linalg.norm(com_mj - com_pin) == pytest.approx(0.2)  # the engines' own reading of the two files
    text = format_parity(import_parity(loaded))
    (row,) = _rows(text, "segment ")
    verdict = " ".join(row[row.index("DIFFERS:") :]) if "DIFFERS:" in row else row[-1]
    assert verdict.startswith("DIFFERS:"), text
