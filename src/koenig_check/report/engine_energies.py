"""Each engine's rigid-body energy per pose, read back from the records a run kept or streamed.

The records hold, for every formula, state source and reference engine, the reference engine's own energy
(``reference_value``).  The rows of ``exact`` on MuJoCo's states, totals, hold every engine's energy once per
pose: that is all the engine-gap figure needs, so a run whose records were streamed to a file keeps these rows
only (one per pose and engine), never the whole table.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pyarrow as pa

from koenig_check.run.records import RecordTable
from koenig_check.run.stats import relative_error

#: The state source whose ``exact`` rows carry the engines' energies (every run has MuJoCo's states).
SOURCE = "mujoco"


def energy_rows(records: RecordTable) -> RecordTable:
    """The rows that carry each engine's own energy per pose: ``exact``, totals, on MuJoCo's states.

    Parameters
    ----------
    records : RecordTable

    Returns
    -------
    RecordTable
    """
    if not len(records):
        return records
    return records.where(formula="exact", scope="total", source=SOURCE)


@dataclass(frozen=True)
class EngineEnergies:
    """One model's rigid-body energy per pose and engine, in pose order.

    Attributes
    ----------
    poses : list of str
        Pose labels.
    energy : dict of str to ndarray
        Engine name to its energy at each pose (J).
    """

    poses: list[str]
    energy: dict[str, np.ndarray]

    def gap(self, engine: str, reference: str = "mujoco") -> np.ndarray:
        """``|E_engine − E_reference| / |E_reference|`` per pose.

        Parameters
        ----------
        engine, reference : str

        Returns
        -------
        ndarray
        """
        return np.abs(relative_error(self.energy[engine], self.energy[reference]))


def engine_energies(
    rows: RecordTable, model: str, engines: tuple[str, ...], n_poses: int, skip: int = 0
) -> EngineEnergies | None:
    """Each engine's energy per pose for one model, from energy rows (:func:`energy_rows`).

    Parameters
    ----------
    rows : RecordTable
        Energy rows of one or several models.
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
        None when the rows do not hold every engine's energy for the model.
    """
    if not len(rows) or "mujoco" not in engines:
        return None
    mine = rows.where(model=model)
    energy: dict[str, np.ndarray] = {}
    poses: list[str] = []
    for engine in engines:
        one = mine.where(reference=engine)
        values = np.asarray(one["reference_value"], dtype=float)
        if values.size < skip + n_poses or n_poses <= 0:
            return None
        energy[engine] = values[skip : skip + n_poses]
        if engine == "mujoco":
            poses = [str(p) for p in one["pose"][skip : skip + n_poses]]
    return EngineEnergies(poses, energy)


def concat_rows(tables: list[pa.Table]) -> RecordTable:
    """Energy rows collected chunk by chunk, as one table.

    Parameters
    ----------
    tables : list of pyarrow.Table

    Returns
    -------
    RecordTable
    """
    return RecordTable.concat(RecordTable(t) for t in tables)
