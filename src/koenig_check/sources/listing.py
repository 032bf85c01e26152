"""``koenig-check models --menagerie``: Menagerie's robots, by category, as lines of at most 100 columns."""

from __future__ import annotations

import textwrap

from koenig_check.sources.menagerie import PREFIX, menagerie_file, menagerie_robots, menagerie_where

#: Width of the listing.
WIDTH = 100


def menagerie_lines(paths: bool = False) -> list[str]:
    """The listing: a header, then one row per robot (name, category, default model, other entries).

    Parameters
    ----------
    paths : bool
        Add each local robot's default model file (robots that would need a download show none).

    Returns
    -------
    list of str

    Raises
    ------
    koenig_check.sources.ModelSourceError
        If ``mujoco-menagerie`` is not installed.
    """
    robots = menagerie_robots()  # first: the one-line error when the extra is missing
    import mujoco_menagerie as mm

    local = sum(r.local for r in robots)
    head = (
        f"{len(robots)} MuJoCo Menagerie robots (mujoco-menagerie {mm.__version__}, Menagerie commit "
        f"{mm.commit()[:12]}); {local} here without a download; read from {menagerie_where()}. "
        f"Type {PREFIX}NAME for the robot alone (its default model) or {PREFIX}NAME:ENTRY for another entry "
        "point (a scene includes the robot: Pinocchio does not read <include>)."
    )
    lines = textwrap.wrap(head, WIDTH, break_on_hyphens=False)
    width = max(len(r.name) for r in robots) if robots else 4
    category_width = max((len(r.category) for r in robots), default=8)
    model_width = max((len(r.default_model) for r in robots), default=7)
    header = f"{'NAME':{width}s} {'CATEGORY':{category_width}s} {'MODEL':{model_width}s} LOCAL OTHER ENTRIES"
    lines.append(header)
    for r in robots:
        prefix = f"{r.name:{width}s} {r.category:{category_width}s} {r.default_model:{model_width}s} "
        prefix += f"{'yes' if r.local else 'no':5s} "
        rows, row = [], ""
        for entry in r.other_entries:  # wrapped under their column, within WIDTH columns
            if row and len(prefix) + len(row) + len(entry) + 3 > WIDTH:  # ", " and a closing ","
                rows.append(row + ",")
                row = ""
            row = f"{row}, {entry}" if row else entry
        for k, text in enumerate([*rows, row]):
            lines.append(((prefix if k == 0 else " " * len(prefix)) + text).rstrip())
        if paths and r.local:
            lines.append(f"{'':{width}s} {menagerie_file(PREFIX + r.name)}")
    return lines
