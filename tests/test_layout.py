"""The package's layout: no import cycle between its subpackages, no module over about 400 lines, at most twelve
modules directly in the package, no former name kept.

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
#: The most modules directly in the package (the rest live in subpackages, one job each).
MOST_TOP_LEVEL = 12


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
    assert len(path.read_text(encoding="utf-8").splitlines()) <= MOST_LINES


def test_at_most_twelve_modules_directly_in_the_package() -> None:
    top = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert "__init__.py" in top  # the package was read
    assert len(top) <= MOST_TOP_LEVEL, top


def aliases(source: str) -> list[str]:
    """The former names a module keeps: a module-level ``Old = New`` of a class or function it defines or imports,
    and a module ``__getattr__`` outside a package's ``__init__`` (names served on demand: old tables)."""
    tree = ast.parse(source)
    defined = {
        node.name for node in tree.body if isinstance(node, ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef)
    }
    imported = {
        (alias.asname or alias.name).split(".")[0]
        for node in tree.body
        if isinstance(node, ast.Import | ast.ImportFrom)
        for alias in node.names
    }
    found = []
    for node in tree.body:
        value = node.value.id if isinstance(node, ast.Assign) and isinstance(node.value, ast.Name) else ""
        if value in defined or (value in imported and not value.isupper()):  # a constant's new name is no alias
            found += [f"{t.id} = {value}" for t in node.targets if isinstance(t, ast.Name)]  # type: ignore[attr-defined]
        if isinstance(node, ast.FunctionDef) and node.name == "__getattr__":
            found.append("__getattr__")
    return found


def test_the_alias_finder_finds_aliases() -> None:
    """The check below could fail: a former name of a class, of an imported function, and a module __getattr__."""
    source = (
        "from x import TOL, f\nclass New: ...\nOld = New\nold_f = f\nLIMIT = 3\nCOPY = LIMIT\nNO = TOL\n"
        "def __getattr__(name): ...\n"
    )
    assert aliases(source) == ["Old = New", "old_f = f", "__getattr__"]


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_former_name_is_kept(path: Path) -> None:
    """No alias of a renamed class or function and no shim of old import paths: they went with 0.1 (CHANGELOG.md).
    A package's ``__init__`` may import its names on first use (``koenig_check.compare``): not a former name."""
    found = aliases(path.read_text(encoding="utf-8"))
    if path.name == "__init__.py":
        found = [a for a in found if a != "__getattr__"]
    assert not found, found
    assert path.name != "_moved.py"


# --- No engine decides behaviour by its name outside its own subpackage -------------------------------------------

#: Where a module may name an engine other than its own, and why (module relative to the package -> names).
#: Everything else fails: a new engine is one subpackage, and no code outside it and the registry says its name.
#: Docstrings are not code and are not read; comments are not in the syntax tree.
ENGINE_NAMES_ALLOWED: dict[str, frozenset[str]] = {
    # The MJCF root element is <mujoco>: a tag of the file format, not the engine (modelfile.mjcf.ROOT_TAG).
    "modelfile/mjcf.py": frozenset({"mujoco"}),
    "modelfile/validate.py": frozenset({"mujoco"}),
    "export/portable_mjcf.py": frozenset({"mujoco"}),
    # MuJoCo applies the compiler options it reads (modelfile is below engines: no registry there).
    "modelfile/compiler.py": frozenset({"mujoco"}),
    # A cause's readings name each engine it was measured in: declared data, one Reading per engine.
    "engines/pinocchio/causes.py": frozenset({"mujoco", "drake", "newton"}),
    "engines/newton/causes.py": frozenset({"mujoco", "pinocchio", "drake"}),
    "engines/pybullet/causes.py": frozenset({"mujoco", "pinocchio", "idyntree"}),
    "engines/idyntree/causes.py": frozenset({"mujoco", "pinocchio", "pybullet", "drake", "newton"}),
    "engines/drake/causes.py": frozenset({"mujoco", "pinocchio"}),
    "engines/mujoco/causes.py": frozenset({"pinocchio", "drake"}),
}


def _docstrings(tree: ast.AST) -> set[int]:
    """The ids of the docstring constants of a module, its classes and functions."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                found.add(id(first.value))
    return found


def engine_literals(package: Path, engines: tuple[str, ...]) -> dict[str, dict[str, list[int]]]:
    """Module (relative to ``package``) -> engine name -> the lines where a string constant is exactly that name,
    outside the engine's own subpackage (``engines/<name>/``), ``engines/registry.py`` and docstrings."""
    found: dict[str, dict[str, list[int]]] = defaultdict(lambda: defaultdict(list))
    for path in sorted(package.rglob("*.py")):
        module = path.relative_to(package).as_posix()
        if module == "engines/registry.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        skip = _docstrings(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and node.value in engines and id(node) not in skip:
                if not module.startswith(f"engines/{node.value}/"):
                    found[module][node.value].append(node.lineno)
    return found


def _unallowed(found: dict[str, dict[str, list[int]]]) -> list[str]:
    return [
        f"{module}:{lines[0]}: {name!r}"
        for module, by_name in sorted(found.items())
        for name, lines in sorted(by_name.items())
        if name not in ENGINE_NAMES_ALLOWED.get(module, frozenset())
    ]


def test_the_engine_literal_finder_finds_one(tmp_path: Path) -> None:
    """The check below could fail: a module outside an engine's subpackage that compares with its name."""
    (tmp_path / "engines" / "drake").mkdir(parents=True)
    (tmp_path / "engines" / "drake" / "own.py").write_text('NAME = "drake"\n')
    (tmp_path / "engines" / "registry.py").write_text('ORDER = ("drake",)\n')
    (tmp_path / "policy.py").write_text('"""drake in a docstring."""\n\n\ndef f(e):\n    return e == "drake"\n')
    assert engine_literals(tmp_path, ("drake", "mujoco")) == {"policy.py": {"drake": [5]}}


def test_no_engine_name_decides_anything_outside_its_subpackage() -> None:
    from koenig_check.engines.specs import names

    found = engine_literals(PACKAGE, names())
    assert "modelfile/mjcf.py" in found  # read: an allowed site is seen
    assert not _unallowed(found), "engine names outside their subpackage (use the registry or the spec):\n" + "\n".join(
        _unallowed(found)
    )


def test_every_allowed_engine_name_is_still_there() -> None:
    """The allowances only shrink: one that no code uses any more is taken off the list."""
    from koenig_check.engines.specs import names

    found = engine_literals(PACKAGE, names())
    stale = {m: sorted(n - set(found.get(m, {}))) for m, n in ENGINE_NAMES_ALLOWED.items() if n - set(found.get(m, {}))}
    assert not stale, f"remove from ENGINE_NAMES_ALLOWED: {stale}"


#: Methods that read a finding's words (a split, a prefix test, a search).
_TEXT_METHODS = {"split", "rsplit", "partition", "rpartition", "startswith", "endswith", "removeprefix", "find"}
#: Where a finding's words are still read (debt: listed so that it only shrinks).  The ENGINE_UNABLE finding reuses
#: the reason of the ENGINE_NOT_USED one it follows, without its head; an export's refusal names each construct
#: without its parenthesis (an unread construct's element, not a finding's).
FINDING_TEXT_ALLOWED = {"diagnosis/policy.py": 1, "cli/export.py": 1}


def finding_text_reads(root: Path) -> dict[str, int]:
    """Module -> how many times it splits, prefix-tests or searches a finding's ``element`` or ``summary``."""
    found: dict[str, int] = {}
    for path in sorted(root.rglob("*.py")):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            read = isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            read = read and node.func.attr in _TEXT_METHODS and _is_finding_text(node.func.value)
            contains = isinstance(node, ast.Compare) and any(isinstance(o, (ast.In, ast.NotIn)) for o in node.ops)
            contains = contains and any(_is_finding_text(c) for c in node.comparators)
            if read or contains or (isinstance(node, ast.Call) and _is_regex_on_finding_text(node)):
                module = path.relative_to(root).as_posix()
                found[module] = found.get(module, 0) + 1
    return found


def _is_finding_text(node: ast.AST) -> bool:
    """``x.element`` or ``x.summary`` of another object (a class's own attribute of that name is its business)."""
    own = isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "self"
    return isinstance(node, ast.Attribute) and node.attr in ("element", "summary") and not own


def _is_regex_on_finding_text(node: ast.Call) -> bool:
    func = node.func
    regex = isinstance(func, ast.Attribute) and func.attr in ("match", "search", "fullmatch", "findall", "sub")
    return regex and any(_is_finding_text(a) for a in node.args)


def test_the_finding_text_finder_finds_each_form(tmp_path: Path) -> None:
    """The check below could fail: a split, a prefix test, a substring test and a regex on a finding's words."""
    (tmp_path / "m.py").write_text(
        "import re\n\n\ndef f(x):\n    a = x.element.partition(' ')\n    b = x.summary.startswith('a')\n"
        "    c = 'mass' in x.summary\n    d = re.search('a', x.element)\n    e = x.element == 'model'\n"
    )
    assert finding_text_reads(tmp_path) == {"m.py": 4}  # an equality with a whole element is no parsing


def test_no_finding_text_is_parsed_in_the_package() -> None:
    """Grouping, shortening and matching read kinds, cause ids, values and Finding.tag, never a finding's words."""
    found = finding_text_reads(PACKAGE)
    assert found == FINDING_TEXT_ALLOWED, "a finding's element or summary read as text (use its tag, cause, values)"
