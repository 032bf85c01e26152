"""The package's layout: no import cycle between its subpackages, no module over about 400 lines.

Imports are read from the source (every ``import koenig_check...`` and ``from koenig_check... import``, at the
top of a module and inside functions alike: a function-local import that closes a cycle is still one).
"""

from __future__ import annotations

import ast
import itertools
from collections import defaultdict
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "koenig_check"
#: The largest module the layout allows ("no module over about 400 lines").
MOST_LINES = 400
#: Modules that are compatibility shims, not code: the old import paths of moved modules.
SHIMS = {"_moved.py"}


def _home(dotted: str) -> str:
    """The subpackage a dotted module name lives in (``koenig_check.run.poses`` -> ``run``), or ``""``."""
    parts = dotted.split(".")
    if len(parts) > 1 and (PACKAGE / parts[1]).is_dir():
        return parts[1]
    return ""  # a top-level module (exceptions, findings, ...): shared by all, below every subpackage


def import_graph() -> dict[str, dict[str, list[str]]]:
    """Subpackage -> the subpackages it imports from -> the modules that do, read from the source."""
    graph: dict[str, dict[str, list[str]]] = defaultdict(lambda: defaultdict(list))
    for path in PACKAGE.rglob("*.py"):
        relative = path.relative_to(PACKAGE.parent).with_suffix("")
        module = ".".join(relative.parts).removesuffix(".__init__")
        home = _home(module) if len(relative.parts) > 2 else ""
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                targets = [node.module]
            elif isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                continue
            for target in targets:
                if target.startswith("koenig_check.") and home and _home(target) not in ("", home):
                    graph[home][_home(target)].append(module)
    return graph


def cycles(graph: dict[str, dict[str, list[str]]]) -> list[list[str]]:
    """Every elementary cycle's subpackages (found by depth-first search from each subpackage)."""
    found: list[list[str]] = []

    def walk(start: str, node: str, path: list[str]) -> None:
        for nxt in graph.get(node, {}):
            if nxt == start:
                found.append([*path, start])
            elif nxt not in path and nxt > start:  # each cycle once, from its smallest name
                walk(start, nxt, [*path, nxt])

    for start in sorted(graph):
        walk(start, start, [start])
    return found


def described(graph: dict[str, dict[str, list[str]]]) -> list[str]:
    """Each cycle of ``graph`` with the modules that make each of its imports (two at most)."""
    return [
        " -> ".join(cycle)
        + ": "
        + "; ".join(f"{a}->{b} in {sorted(set(graph[a][b]))[:2]}" for a, b in itertools.pairwise(cycle))
        for cycle in cycles(graph)
    ]


def test_the_cycle_finder_finds_a_cycle() -> None:
    """The check below could fail: a hand-made graph with one cycle of three and one edge outside it."""
    graph = {"a": {"b": ["a.x"]}, "b": {"c": ["b.y"]}, "c": {"a": ["c.z"]}, "d": {"a": ["d.w"]}}
    assert cycles(graph) == [["a", "b", "c", "a"]]


def test_no_import_cycle_between_subpackages() -> None:
    graph = import_graph()
    assert graph["cli"] and graph["engines"]  # the graph was read (the CLI and the engines import others)
    assert not cycles(graph), described(graph)


#: The one import from a top-level module into a subpackage below which nothing would close a cycle: a finding
#: checks the engine it names against the engines' specs (engines/specs.py imports nothing of the package).
#: It also asks which cause ids exist (engines/catalogue.py, read when a finding with a cause is built).
ALLOWED_UPWARD = {(".findings", "engines.specs"), (".findings", "engines.catalogue")}


def _node(dotted: str) -> str:
    """A subpackage (``run``), or a top-level module as ``.name`` (``.api``), or ``<package>``."""
    parts = dotted.split(".")
    return _home(dotted) or (f".{parts[1]}" if len(parts) > 1 else "<package>")


def _runtime_imports(tree: ast.AST) -> list[str]:
    """The modules a source imports when run: every import but those under ``if TYPE_CHECKING:``."""
    typing_only = {
        id(inner)
        for node in ast.walk(tree)
        if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"
        for stmt in node.body
        for inner in ast.walk(stmt)
    }
    found = []
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found += [_submodule(node.module, alias.name) for alias in node.names]
        elif isinstance(node, ast.Import):
            found += [alias.name for alias in node.names]
    return [m for m in found if m.startswith("koenig_check.")]


def _submodule(module: str, name: str) -> str:
    """``from module import name``: the module ``module.name`` when it is one, else ``module``."""
    inner = PACKAGE.parent.joinpath(*module.split("."), name)
    return f"{module}.{name}" if inner.with_suffix(".py").is_file() or inner.is_dir() else module


def module_graph() -> dict[str, dict[str, list[str]]]:
    """Like :func:`import_graph`, with each top-level module a node of its own (``.api``, ``.findings``)."""
    graph: dict[str, dict[str, list[str]]] = defaultdict(lambda: defaultdict(list))
    for path in PACKAGE.rglob("*.py"):
        relative = path.relative_to(PACKAGE.parent).with_suffix("")
        module = ".".join(relative.parts).removesuffix(".__init__")
        for target in _runtime_imports(ast.parse(path.read_text(encoding="utf-8"))):
            a, b = _node(module), _node(target)
            if a != b and (a, target.removeprefix("koenig_check.")) not in ALLOWED_UPWARD:
                graph[a][b].append(module)
    return graph


def test_no_import_cycle_through_top_level_modules() -> None:
    """A top-level module is either below the subpackages (exceptions, findings) or above them (api, demo):
    never both, e.g. report importing the API that imports report."""
    graph = module_graph()
    assert graph[".api"]["run"] and graph["cli"][".api"]  # read: the API uses run, the CLI the API
    assert not cycles(graph), described(graph)


def test_the_allowed_upward_import_imports_nothing_of_the_package() -> None:
    """Besides each other and the cause declarations (engines/cause.py, which import nothing of the package)."""
    below = {"koenig_check." + t for _, t in ALLOWED_UPWARD} | {"koenig_check.engines.cause"}
    for target in below:
        relative = target.removeprefix("koenig_check.").replace(".", "/") + ".py"
        source = (PACKAGE / relative).read_text(encoding="utf-8")
        assert set(_runtime_imports(ast.parse(source))) <= below, target


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_over_about_400_lines(path: Path) -> None:
    if path.name in SHIMS:
        pytest.skip("a table of old import paths")
    assert len(path.read_text(encoding="utf-8").splitlines()) <= MOST_LINES
