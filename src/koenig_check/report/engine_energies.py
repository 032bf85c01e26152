"""Each engine's rigid-body energy per pose, read back from the records a run kept or streamed.

The records hold, for every formula, state source and reference engine, the reference engine's own energy
(``reference_value``).  The rows of ``exact`` on MuJoCo's states, totals, hold every engine's energy once per
pose: that is all the engine-gap figure needs, so a run whose records were streamed to a file keeps only these
values (one number per pose and engine, and the pose labels as stored), never the whole table.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pyarrow as pa

from koenig_check.engines.specs import reference
from koenig_check.run.records import RecordTable
from koenig_check.run.stats import relative_error

#: The state source whose ``exact`` rows carry the engines' energies: the reference engine's (every run has
#: MuJoCo's states).
SOURCE = reference()


@dataclass(frozen=True)
class EnergyChunk:
    """One model's engine energies from one block of records, in pose order.

    Attributes
    ----------
    model : str
    poses : pyarrow.ChunkedArray
        Pose labels, as the records store them (dictionary-coded).
    energy : dict of str to ndarray
        Engine name to its energy at each pose (J).
    """

    model: str
    poses: pa.ChunkedArray
    energy: dict[str, np.ndarray]


def energy_chunks(records: RecordTable) -> list[EnergyChunk]:
    """Each engine's energy per pose, per model, from records: ``exact``, totals, on MuJoCo's states.

    Parameters
    ----------
    records : RecordTable

    Returns
    -------
    list of EnergyChunk
        One per model in the records.
    """
    if not len(records):
        return []
    totals = records.where(formula="exact", scope="total", source=SOURCE)
    out = []
    # RecordTable's masks, not pyarrow.compute with a scalar (which imports pandas when it is installed).
    for model in totals.table.column("model").unique().to_pylist():
        mine = totals.where(model=model)
        energy = {
            str(e): mine.where(reference=e)["reference_value"]
            for e in mine.table.column("reference").unique().to_pylist()
        }
        poses = mine.where(reference=SOURCE).table.column("pose")
        out.append(EnergyChunk(str(model), poses, energy))
    return out


@dataclass(frozen=True)
class EngineEnergies:
    """One model's rigid-body energy per pose and engine, in pose order.

    Attributes
    ----------
    poses : pyarrow.ChunkedArray
        Pose labels (:meth:`label` gives one as text).
    energy : dict of str to ndarray
        Engine name to its energy at each pose (J).
    """

    poses: pa.ChunkedArray
    energy: dict[str, np.ndarray]

    def label(self, k: int) -> str:
        """The label of pose ``k``.

        Parameters
        ----------
        k : int

        Returns
        -------
        str
        """
        return str(self.poses[k].as_py())

    def gap(self, engine: str, reference: str = SOURCE) -> np.ndarray:
        """``|E_engine − E_reference| / |E_reference|`` per pose.

        Parameters
        ----------
        engine : str
        reference : str
            Default: the reference engine (MuJoCo).

        Returns
        -------
        ndarray
        """
        return np.abs(relative_error(self.energy[engine], self.energy[reference]))


def engine_energies(
    chunks: Sequence[EnergyChunk], model: str, engines: tuple[str, ...], n_poses: int, skip: int = 0
) -> EngineEnergies | None:
    """Each engine's energy per pose for one model run, from energy chunks (:func:`energy_chunks`).

    Parameters
    ----------
    chunks : sequence of EnergyChunk
        In run order, of one or several models.
    model : str
        The model's label.
    engines : tuple of str
        The engines of the model's run.
    n_poses : int
        The run's poses.
    skip : int
        Poses of an earlier run under the same label to pass over (runs are kept in run order).

    Returns
    -------
    EngineEnergies or None
        None when the chunks do not hold every engine's energy at each of the run's poses.
    """
    mine = [c for c in chunks if c.model == model]
    if not mine or SOURCE not in engines or n_poses <= 0 or any(set(engines) - set(c.energy) for c in mine):
        return None
    energy = {e: np.concatenate([c.energy[e] for c in mine])[skip : skip + n_poses] for e in engines}
    if any(v.size != n_poses for v in energy.values()):
        return None
    poses = pa.chunked_array([a for c in mine for a in c.poses.chunks], type=mine[0].poses.type)
    return EngineEnergies(poses.slice(skip, n_poses), energy)
