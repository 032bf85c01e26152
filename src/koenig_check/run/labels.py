"""Model labels of a run: unique, so that two files with one name never share records, summaries or rows."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path


def _is_file(model: str | os.PathLike[str]) -> bool:
    return bool(Path(str(model)).suffix) and not str(model).startswith(("menagerie:", "rd:"))


def unique_labels(
    models: Sequence[str | os.PathLike[str]], floating: bool = False, xacro_args: Sequence[tuple[str, str]] = ()
) -> list[str]:
    """One label per model of a run: the file name, or the shortest path suffix that tells it apart.

    ``a/robot.xml`` and ``b/robot.xml`` are labelled ``a/robot.xml`` and ``b/robot.xml``; a file given alone
    is labelled by its name; a model name (``ur5``, ``menagerie:unitree_g1``, ``rd:ur5e``) is its own label.
    The arguments of a xacro file follow its label (``arm.urdf.xacro [length=0.8]``).  The same file given
    twice gets ``#2``, ``#3``... after its label.  ``(floating)`` follows the label of a floating-base run.

    Parameters
    ----------
    models : sequence of str or path
        Model files or names, as the user gave them.
    floating : bool
    xacro_args : sequence of (str, str)
        The ``$(arg)`` values given for xacro files.

    Returns
    -------
    list of str
        In the order of ``models``, all different.
    """
    parts = [Path(os.path.abspath(str(m))).parts if _is_file(m) else (str(m),) for m in models]
    labels = []
    for k, mine in enumerate(parts):
        others = [p for j, p in enumerate(parts) if j != k and p != mine]
        depth = 1
        while depth < len(mine) and any(p[-depth:] == mine[-depth:] for p in others):
            depth += 1
        label = "/".join(mine[-depth:])
        if xacro_args and label.endswith(".xacro"):  # the arguments make another robot of the same file
            label += " [" + ", ".join(f"{k}={v}" for k, v in xacro_args) + "]"
        labels.append(label)
    seen: dict[str, int] = {}
    out = []
    for label in labels:
        seen[label] = seen.get(label, 0) + 1
        text = label if seen[label] == 1 else f"{label}#{seen[label]}"
        out.append(f"{text} (floating)" if floating else text)
    return out
