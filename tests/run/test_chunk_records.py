"""A chunk's record table (codes reused between chunks of one layout) equals the records written out one by one."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.run.chunks import _chunk_table
from koenig_check.run.records import RecordTable

FORMULAS = ["exact", "koenig", "planar"]
SOURCES = ["mujoco", "pinocchio"]
REFERENCES = ["mujoco", "pinocchio", "exact@mujoco", "exact@pinocchio"]
SCOPES = ["total", "hip", "knee", "ankle"]


def _blocks(P: int, seed: int, segments: bool) -> list:
    """Blocks as evaluate_chunk builds them: totals per (formula, source, reference), then per-segment values."""
    rng = np.random.default_rng(seed)
    blocks = []
    for f in range(len(FORMULAS)):
        for s in range(len(SOURCES)):
            for r in range(len(SOURCES)):
                blocks.append((f, s, r, None, rng.standard_normal(P), rng.standard_normal(P)))
            if segments:
                seg = np.array([1, 2, 3], dtype=np.int64)
                blocks.append((f, s, 2 + s, seg, rng.standard_normal((P, 3)), rng.standard_normal((P, 3))))
    return blocks


def _one_by_one(label: str, ids: list[str], blocks: list, names: tuple = ()) -> list[tuple]:
    """The records in pose order, written out with Python loops (the independent route)."""
    formulas, sources, references, scopes_of = names or (FORMULAS, SOURCES, REFERENCES, SCOPES)
    rows = []
    for p, pose in enumerate(ids):
        for f, s, r, seg, value, ref in blocks:
            scopes = [0] if seg is None else list(seg)
            for k, scope in enumerate(scopes):
                v, rv = (value[p], ref[p]) if seg is None else (value[p, k], ref[p, k])
                rows.append((label, pose, formulas[f], sources[s], references[r], scopes_of[scope], v, rv))
    return rows


@pytest.mark.parametrize("segments", [False, True], ids=["totals", "segments"])
def test_chunk_tables_equal_records_written_one_by_one(segments: bool) -> None:
    # Three chunks of one layout, then a shorter last chunk, then the first layout again: the codes are
    # built once per layout and reused, the values and pose names are each chunk's own.
    for k, P in enumerate([5, 5, 5, 2, 5]):
        ids = [f"pose{k}.{p}" for p in range(P)]
        blocks = _blocks(P, seed=k, segments=segments)
        table = RecordTable(_chunk_table("m", ids, P, blocks, FORMULAS, SOURCES, REFERENCES, SCOPES))
        fields = ("model", "pose", "formula", "source", "reference", "scope", "value", "reference_value")
        got = [tuple(row[f] for f in fields) for row in table]
        assert got == _one_by_one("m", ids, blocks), f"chunk {k}"


def test_records_of_a_chunk_are_each_formula_evaluated_alone_on_the_engine_states() -> None:
    """Every formula's per-segment and total records (exact included, now taken from the reference array) equal
    the formula evaluated alone on that engine's states, and every per-segment reference equals exact alone."""
    from pathlib import Path

    from koenig_check.engines import load_model
    from koenig_check.formulas import FORMULAS
    from koenig_check.run.chunks import evaluate_chunk
    from koenig_check.run.engine_runs import run_engine
    from koenig_check.run.poses import random_poses

    pair = load_model(Path(__file__).resolve().parents[2] / "models" / "double_pendulum.xml")
    poses = random_poses(pair.mujoco.model, 6, seed=3)
    runs = {e.engine: run_engine(e, poses) for e in (pair.mujoco, pair.pinocchio)}
    names = [n for n in FORMULAS if "integrated" not in n]
    table = evaluate_chunk("m", poses, runs, names, records="segments").records
    records = RecordTable(table)
    for source, run in runs.items():
        exact = FORMULAS["exact"](run.states)
        for name in names:
            if name == "point_masses":
                alone = FORMULAS[name].func(run.states, point_velocities=run.point_velocities)
            else:
                alone = FORMULAS[name](run.states)
            for k, segment in enumerate(run.states.names):
                rows = records.where(formula=name, source=source, scope=segment)
                np.testing.assert_array_equal(rows["value"], alone[:, k], err_msg=f"{name}@{source} {segment}")
                np.testing.assert_array_equal(rows["reference_value"], exact[:, k], err_msg=f"{name}@{source}")
            totals = records.where(formula=name, source=source, scope="total", reference=source)
            np.testing.assert_array_equal(totals["value"], alone.sum(axis=1), err_msg=f"{name}@{source} total")


def test_chunk_tables_of_one_layout_carry_each_models_label_and_names() -> None:
    """Chunks of two models with one layout (pose count and blocks): each table has its own label and names.

    The columns but the values and pose names are built once per layout and reused: the model's label and
    the formula, source, reference and scope names must be part of what they are reused for.
    """
    P, fields = 4, ("model", "pose", "formula", "source", "reference", "scope", "value", "reference_value")
    blocks = _blocks(P, seed=1, segments=True)
    first = (FORMULAS, SOURCES, REFERENCES, SCOPES)
    second = (["exact", "koenig_world", "planar"], ["pinocchio", "mujoco"], REFERENCES[::-1], ["total", "a", "b", "c"])
    for label, names in (("m", first), ("n", first), ("n", second), ("m", first)):
        ids = [f"{label}.{p}" for p in range(P)]
        table = RecordTable(_chunk_table(label, ids, P, blocks, *(list(n) for n in names)))
        got = [tuple(row[f] for f in fields) for row in table]
        assert got == _one_by_one(label, ids, blocks, names), (label, names[0])
