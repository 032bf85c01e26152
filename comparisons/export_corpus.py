"""Export every dm_control model (to URDF and to portable MJCF) and every example-robot-data URDF (to MJCF).

Each export is proved by ``koenig_check.export`` itself: every engine loads the written file and its rigid
mass matrix and energy at 10 seeded poses are compared with MuJoCo's reading of the original, at 1e-9
relative.  A row says: equivalent (and in which engines), refused (naming the construct the target cannot
hold), or not equivalent (and why).  An original MuJoCo cannot load is listed with MuJoCo's reason, a file
without any body (a fragment) as nothing moves; a
URDF MuJoCo refuses for its inertias is exported with ``--repair-inertia`` (recorded); a model where nothing
moves at a fixed base is exported with ``--floating``.

    python comparisons/export_corpus.py [--models NAME ...] [--out DIR]
"""

from __future__ import annotations

import argparse
import collections
import tempfile
from pathlib import Path

from common import HERE, display_name, dm_control_corpus, erd_corpus, progress, scrub, table

from koenig_check.engines.errors import InertiaError, ModelLoadError, NotFloatableError
from koenig_check.engines.registry import installed, names, spec
from koenig_check.export import ExportRefusedError, export_model
from koenig_check.modelfile.validate import ModelFileError

RTOL = 1e-9


def _export(path: Path, to: str, out: Path) -> tuple[str, str, str, str]:
    """(verdict, engines compared, detail, options used) for one export."""
    options: dict[str, bool] = {}
    for _ in range(3):
        try:
            result = export_model(path, to=to, out=out, rtol=RTOL, **options)
        except ExportRefusedError as err:
            return "refused", "", "; ".join(f"{c.construct}: {c.element}" for c in err.constructs), _words(options)
        except InertiaError as err:
            if options.get("repair_inertia"):
                return "original does not load", "", scrub(str(err)), _words(options)
            options["repair_inertia"] = True
            continue
        except (ModelLoadError, ModelFileError) as err:
            if options.get("floating") and isinstance(err, NotFloatableError) and not err.top_level:
                return "nothing moves", "", "no body: a fragment of a model", _words(options)
            return "original does not load", "", scrub(str(err)), _words(options)
        proof = result.proof
        if "nothing moves" in " ".join(proof.problems) and not options.get("floating"):
            options["floating"] = True
            continue
        compared = ", ".join(e.engine for e in proof.engines if e.compared)
        skipped = "; ".join(scrub(s)[:160] for s in proof.skipped())
        if proof.equivalent:
            detail = f"max {proof.max_relative_difference:.1e}" + (f"; not compared: {skipped}" if skipped else "")
            return "equivalent", compared, detail, _words(options)
        return "not equivalent", compared, scrub("; ".join(proof.reasons()))[:300], _words(options)
    return "not equivalent", "", "nothing moves even with --floating", _words(options)


def _words(options: dict[str, bool]) -> str:
    return " ".join("--" + k.replace("_", "-") for k, v in options.items() if v)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", nargs="+", help="only these file names")
    parser.add_argument("--out", default=str(HERE), help="directory of export_corpus.md")
    args = parser.parse_args()
    jobs = [(p, to) for p in dm_control_corpus() for to in ("urdf", "mjcf")] + [(p, "mjcf") for p in erd_corpus()]
    if args.models:
        jobs = [(p, to) for p, to in jobs if p.name in args.models]
    rows, counts = [], collections.Counter()
    with tempfile.TemporaryDirectory() as tmp:
        for i, (path, to) in enumerate(jobs):
            out = Path(tmp) / f"{i}_{path.stem}.{'urdf' if to == 'urdf' else 'xml'}"
            source = "urdf" if path.suffix == ".urdf" else "mjcf"
            verdict, engines, detail, options = _export(path, to, out)
            counts[(f"{source} → {to}", verdict)] += 1
            rows.append([display_name(path), f"{source} → {to}", verdict, engines, options, detail])
            progress(f"{display_name(path)} → {to}: {verdict}")
    directions = sorted({d for d, _ in counts})
    verdicts = ["equivalent", "refused", "not equivalent", "original does not load", "nothing moves"]
    readers = {to: {n for n in names() if to in spec(n).formats and installed(n)} for to in ("mjcf", "urdf")}
    every = collections.Counter(
        r[1] for r in rows if r[2] == "equivalent" and set(r[3].split(", ")) == readers[r[1].split(" → ")[1]]
    )
    summary = [[d, *(str(counts[(d, v)]) for v in verdicts), str(every[d])] for d in directions]
    columns = ["direction", *verdicts, "equivalent in every engine that reads the target"]
    lines = [
        "# Exports of robot files koenig-check was not developed on",
        "",
        f"`python comparisons/export_corpus.py`: each export proved at {RTOL:g} relative (rigid mass matrix and energy "
        "at 10 seeded poses, each engine's reading of the export against MuJoCo's reading of the original).",
        "",
        *table(columns, summary, "lrrrrrr"),
        "",
        *table(["model", "direction", "verdict", "engines compared", "options", "detail"], rows),
        "",
    ]
    Path(args.out, "export_corpus.md").write_text("\n".join(lines), encoding="utf-8")
    print("\n".join(table(columns, summary, "lrrrrrr")))


if __name__ == "__main__":
    main()
