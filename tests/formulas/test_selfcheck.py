from __future__ import annotations

from koenig_check.formulas.selfcheck import format_table, run_selfcheck


def test_selfcheck_separates_exact_family_from_paper_recipe() -> None:
    results = {(r.case, r.formula): r for r in run_selfcheck(seed=3)}
    for formula in ["koenig_principal", "alyushin_current", "point_masses"]:
        for case in ["box_spin_z", "gimbal_z_then_x", "random"]:
            assert results[(case, formula)].max_rel_error < 1e-12, (case, formula)
    for formula in [
        "koenig_world",
        "alyushin_paper:rotvec",
        "alyushin_paper:euler_xyz",
        "alyushin_paper:integrated",
    ]:
        assert results[("gimbal_z_then_x", formula)].max_rel_error > 1e-3, formula
        assert results[("tilted_box_one_axis", formula)].max_rel_error < 1e-12, formula
    assert results[("gimbal_z_then_x", "planar")].refused is not None
    assert results[("box_spin_z", "planar")].refused is None


def test_table_marks_agreement_and_refusal() -> None:
    text = format_table(run_selfcheck(seed=0), rtol=1e-9)
    row = next(line for line in text.splitlines() if line.startswith("planar"))
    assert "refused" in row and "=" in row
    row = next(line for line in text.splitlines() if line.startswith("koenig_world"))
    assert "≠" in row
