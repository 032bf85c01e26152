"""The constructs Drake's parsers read differently from the file, and Drake's own reading of a fixture."""

from __future__ import annotations

from pathlib import Path

from koenig_check.engines.cause import Cause
from koenig_check.engines.measurement import Measurement

#: The Drake release these readings were measured on.
MEASURED = "1.51.1"

CAUSES: tuple[Cause, ...] = ()


def measure(path: Path) -> Measurement:
    """Drake's reading of a model file: ``Parser.AddModels``, ``CalcMassMatrix`` at the default context.

    Parameters
    ----------
    path : pathlib.Path

    Returns
    -------
    Measurement

    Raises
    ------
    Exception
        Drake refuses the file (its own exception).
    """
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import MultibodyPlant
    from pydrake.multibody.tree import BodyIndex

    plant = MultibodyPlant(0.0)
    Parser(plant).AddModels(path)
    plant.Finalize()
    context = plant.CreateDefaultContext()
    full = plant.CalcMassMatrix(context)
    joints = [plant.get_joint(i) for i in plant.GetJointIndices()]
    moving = [j for j in joints if j.num_velocities() > 0]
    one_dof = {j.name(): j.velocity_start() for j in moving if j.num_velocities() == 1}
    welded = {b.index() for b in plant.GetBodiesWeldedTo(plant.world_body())}
    bodies = [plant.get_body(BodyIndex(i)) for i in range(plant.num_bodies())]
    armature: dict[str, float] = {}
    for a in (plant.get_joint_actuator(i) for i in plant.GetJointActuatorIndices()):
        reflected = float(a.default_reflected_inertia())
        if reflected and a.joint().name() in one_dof:
            armature[a.joint().name()] = reflected
    return Measurement(
        joints=tuple(sorted(j.name() for j in moving)),
        mass=float(sum(b.default_mass() for b in bodies if b.index() not in welded)),
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=tuple(float(g) for g in plant.gravity_field().gravity_vector()),
        armature=armature,
    )
