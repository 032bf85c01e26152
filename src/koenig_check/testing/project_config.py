"""The models a project lists for ``pytest --koenig-check``: ``[tool.koenig-check] models = [...]`` in pyproject.toml.

Each entry is a string — a path relative to the pyproject.toml, or any name the command line accepts
(``gimbal``, ``ur5``, ``menagerie:unitree_g1``, ``rd:ur5e_description``) — or an inline table with ``model`` and
any of: a load option (``floating``, ``balance_inertia``, ``repair_inertia``, ``pinocchio_model``, ``xacro_args``,
``engines``: a list, or ``"all"``), ``rtol``, ``poses``, ``seed``, ``dynamics = true`` (also require ``koenig-check
dynamics`` to pass)::

    [tool.koenig-check]
    models = [
        "models/arm.xml",
        "menagerie:unitree_go2",
        { model = "urdf/arm.urdf.xacro", xacro_args = { length = "0.8" }, floating = true, rtol = 1e-8 },
    ]
"""

from __future__ import annotations

import difflib
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from koenig_check.engines.load_options import LoadOptions
from koenig_check.exceptions import one_line

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10: pytest brings tomli
    import tomli as tomllib

#: The table the models are read from.
TABLE = "koenig-check"
#: Keys of an inline table besides the load options.
RUN_KEYS = ("model", "rtol", "poses", "seed", "dynamics")


class ProjectConfigError(ValueError):
    """A ``[tool.koenig-check]`` entry that cannot be read; the message names the file and the entry."""


@dataclass(frozen=True)
class ModelEntry:
    """One model to check, as the project lists it.

    Attributes
    ----------
    model : str
        The name or the absolute path handed to :func:`koenig_check.compare`.
    load : LoadOptions
    rtol : float or None
        ``None``: the command line's default.
    poses : int or None
    seed : int or None
    dynamics : bool
    written : str
        The entry as written in the file, for messages.
    """

    model: str
    load: LoadOptions = field(default_factory=LoadOptions)
    rtol: float | None = None
    poses: int | None = None
    seed: int | None = None
    dynamics: bool = False
    written: str = ""

    def compare_options(self) -> dict[str, Any]:
        """The keywords of :func:`koenig_check.compare` this entry sets (the others keep the CLI's defaults).

        Returns
        -------
        dict
        """
        options: dict[str, Any] = {"load_options": self.load}
        for key, value in (("rtol", self.rtol), ("n_poses", self.poses), ("seed", self.seed)):
            if value is not None:
                options[key] = value
        return options


def read_models(pyproject: Path) -> list[ModelEntry | ProjectConfigError]:
    """Read the models of ``[tool.koenig-check]``, one result per entry (an entry's error does not stop the others).

    Parameters
    ----------
    pyproject : Path

    Returns
    -------
    list of ModelEntry or ProjectConfigError

    Raises
    ------
    ProjectConfigError
        If the file cannot be read or has no ``[tool.koenig-check] models`` list.
    """
    try:
        data = tomllib.loads(pyproject.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as err:
        raise ProjectConfigError(f"{pyproject}: {one_line(err)}") from None
    table = data.get("tool", {}).get(TABLE)
    if not isinstance(table, Mapping) or "models" not in table:
        raise ProjectConfigError(f"{pyproject}: no [tool.{TABLE}] models = [...] to check")
    models = table["models"]
    if not isinstance(models, list):
        raise ProjectConfigError(f"{pyproject}: [tool.{TABLE}] models must be a list, got {type(models).__name__}")
    out: list[ModelEntry | ProjectConfigError] = []
    for k, raw in enumerate(models):
        try:
            out.append(_entry(raw, pyproject.parent))
        except (ProjectConfigError, TypeError, ValueError) as err:
            out.append(ProjectConfigError(f"{pyproject}: [tool.{TABLE}] models[{k}] {raw!r}: {err}"))
    return out


def _entry(raw: Any, base: Path) -> ModelEntry:
    if isinstance(raw, str):
        raw = {"model": raw}
    if not isinstance(raw, Mapping):
        raise ProjectConfigError("expected a string or an inline table with `model`")
    unknown = sorted(set(raw) - set(RUN_KEYS) - set(LoadOptions.names()))
    if unknown:
        keys = [*RUN_KEYS, *LoadOptions.names()]
        close = [m for k in unknown for m in difflib.get_close_matches(k, keys, n=1)]
        hint = f"; did you mean {', '.join(close)}?" if close else ""
        raise ProjectConfigError(f"unknown key(s) {unknown}{hint} (keys are {keys})")
    if not isinstance(raw.get("model"), str) or not raw["model"]:
        raise ProjectConfigError("`model` must be a non-empty string")
    load = {k: v for k, v in raw.items() if k in LoadOptions.names()}
    if isinstance(load.get("pinocchio_model"), str):
        load["pinocchio_model"] = _relative_to(load["pinocchio_model"], base)
    rtol, poses, seed, dyn = (raw.get(k) for k in ("rtol", "poses", "seed", "dynamics"))
    number = isinstance(rtol, int | float) and not isinstance(rtol, bool)
    if rtol is not None and not (number and 0 < rtol < float("inf")):
        raise ProjectConfigError(f"rtol must be a finite number > 0, got {rtol!r}")
    for name, value, low in (("poses", poses, 1), ("seed", seed, 0)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or value < low):
            raise ProjectConfigError(f"{name} must be a whole number >= {low}, got {value!r}")
    if dyn is not None and not isinstance(dyn, bool):
        raise ProjectConfigError(f"dynamics must be true or false, got {dyn!r}")
    return ModelEntry(
        _relative_to(raw["model"], base),
        LoadOptions(**load),
        None if rtol is None else float(rtol),
        poses,
        seed,
        bool(dyn),
        raw["model"],
    )


def _relative_to(model: str, base: Path) -> str:
    """A path relative to the pyproject.toml when it names a file there, else the name as written."""
    candidate = base / model
    return str(candidate) if candidate.exists() and not Path(model).is_absolute() else model
