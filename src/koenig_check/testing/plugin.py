"""``pytest --koenig-check``: every model of the project's ``[tool.koenig-check]`` is one test item.

Registered through the ``pytest11`` entry point and off unless ``--koenig-check`` is given.  The models are
read from the pyproject.toml of the run (pytest's ``inipath`` when it is one, else ``rootdir/pyproject.toml``;
see :mod:`koenig_check.testing.project_config`).  An item's id is the model's label in reports, it passes exactly when
``koenig-check compare`` would exit 0 (and ``koenig-check dynamics`` too with ``dynamics = true``), and its
failure reads like the command line's verdict: the root causes first, no frame of koenig-check's own code.  An
optional engine that is not installed (Drake) skips the item with the reason.  ``--koenig-check-report DIR``
writes the usual report directory for every model checked in the run.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

if TYPE_CHECKING:
    from koenig_check.api import CrossCheck
    from koenig_check.testing.project_config import ModelEntry, ProjectConfigError


@dataclass
class _Run:
    """What the session keeps: the report directory asked for and every model's check."""

    report: Path | None = None
    checks: list[CrossCheck] = field(default_factory=list)


_RUN = pytest.StashKey[_Run]()


class ModelCheckError(AssertionError):
    """A model's check failed; the message is the verdict."""


def pytest_addoption(parser: pytest.Parser) -> None:
    """Add ``--koenig-check`` and ``--koenig-check-report DIR``.

    Parameters
    ----------
    parser : pytest.Parser
    """
    group = parser.getgroup("koenig-check", "kinetic-energy parity of the models in [tool.koenig-check]")
    group.addoption(
        "--koenig-check",
        action="store_true",
        default=False,
        help="check every model of [tool.koenig-check] models in pyproject.toml, one test item each",
    )
    group.addoption(
        "--koenig-check-report",
        metavar="DIR",
        default=None,
        help="write koenig-check's report directory for the models checked in this run",
    )


def pytest_configure(config: pytest.Config) -> None:
    """Register the marker; refuse an unusable report directory before any test runs.

    Parameters
    ----------
    config : pytest.Config
    """
    config.addinivalue_line("markers", "koenig_check: a model of [tool.koenig-check] checked by koenig-check")
    if not config.getoption("koenig_check"):
        return
    run = _Run()
    report = config.getoption("koenig_check_report")
    if report:
        from koenig_check.arguments import ArgumentValueError
        from koenig_check.report.output_dir import check_out_dir

        try:
            run.report = check_out_dir(Path(report))
        except ArgumentValueError as err:
            raise pytest.UsageError(str(err).replace("--out", "--koenig-check-report")) from None
    config.stash[_RUN] = run


def project_file(config: pytest.Config) -> Path | None:
    """The pyproject.toml the models are read from.

    Parameters
    ----------
    config : pytest.Config

    Returns
    -------
    Path or None
    """
    if config.inipath is not None and config.inipath.name == "pyproject.toml":
        return config.inipath
    candidate = config.rootpath / "pyproject.toml"
    return candidate if candidate.is_file() else None


def pytest_collect_file(file_path: Path, parent: pytest.Collector) -> pytest.Collector | None:
    """Collect the project's pyproject.toml when pytest walks over it (``pytest --koenig-check pyproject.toml``).

    Parameters
    ----------
    file_path : Path
    parent : pytest.Collector

    Returns
    -------
    ModelsFile or None
    """
    config = parent.config
    if _RUN not in config.stash or file_path != project_file(config):
        return None
    return ModelsFile.from_parent(parent, path=file_path)


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(session: pytest.Session, config: pytest.Config, items: list[pytest.Item]) -> None:
    """Add the models when pytest did not walk over the pyproject.toml (``testpaths``, explicit test files).

    Runs before ``-k`` and ``-m`` select items, so both apply to the models too.

    Parameters
    ----------
    session : pytest.Session
    config : pytest.Config
    items : list of pytest.Item
    """
    if _RUN not in config.stash or any(isinstance(item, ModelItem) for item in items):
        return  # not asked for, or collected already (pytest walked over the pyproject.toml)
    path = project_file(config)
    if path is None:
        raise pytest.UsageError("--koenig-check: no pyproject.toml in the rootdir to read [tool.koenig-check] from")
    items.extend(ModelsFile.from_parent(session, path=path).collect())


class ModelsFile(pytest.File):
    """The pyproject.toml: one item per model of ``[tool.koenig-check] models``."""

    def collect(self) -> Iterator[pytest.Item]:
        """One :class:`ModelItem` per entry; an entry that cannot be read is an item that fails with why.

        Yields
        ------
        pytest.Item
        """
        from koenig_check.run.labels import unique_labels
        from koenig_check.testing.project_config import ProjectConfigError, read_models

        try:
            entries = read_models(self.path)
        except ProjectConfigError as err:
            yield ModelItem.from_parent(self, name="[tool.koenig-check]", entry=err)
            return
        # Labels as one run over every model gives them: two files with one name are told apart by their path.
        base = unique_labels([e.model for e in entries if not isinstance(e, ProjectConfigError)])
        seen: dict[str, int] = {}
        for k, entry in enumerate(entries):
            if isinstance(entry, ProjectConfigError):
                name = f"models[{k}]"
            else:
                name = base.pop(0)
                if entry.load.xacro_args and name.endswith(".xacro"):
                    name += " [" + ", ".join(f"{k}={v}" for k, v in entry.load.xacro_args) + "]"
                if entry.load.floating:
                    name += " (floating)"
            seen[name] = seen.get(name, 0) + 1
            yield ModelItem.from_parent(self, name=name if seen[name] == 1 else f"{name} #{seen[name]}", entry=entry)


class ModelItem(pytest.Item):
    """One model: passes exactly when ``koenig-check compare`` (and ``dynamics`` when asked) would exit 0."""

    def __init__(self, *, entry: ModelEntry | ProjectConfigError, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.entry = entry
        self.add_marker("koenig_check")

    def runtest(self) -> None:
        """Check the model; raise :class:`ModelCheckError` with the verdict, or skip for a missing engine."""
        __tracebackhide__ = True
        from koenig_check import compare, dynamics
        from koenig_check.exceptions import EngineUnavailableError
        from koenig_check.sources import ModelSourceError
        from koenig_check.testing.failure_text import verdict_lines

        entry = self.entry
        if isinstance(entry, Exception):
            raise ModelCheckError(str(entry))
        run = self.config.stash[_RUN]
        records = "totals" if run.report else "none"
        try:
            check = compare({self.name: entry.model}, records=records, **entry.compare_options())  # the run's label
        except EngineUnavailableError as err:
            pytest.skip(str(err))
        except ModelSourceError as err:
            raise ModelCheckError(f"{self.name}: {err}") from None
        run.checks.append(check)
        lines = verdict_lines(check)
        if entry.dynamics and check.ok:
            options: dict[str, Any] = {
                **entry.load.as_overrides(),
                **({"seed": entry.seed} if entry.seed is not None else {}),
            }
            result = dynamics(entry.model, **options)
            if not result.ok:
                lines.append(f"{self.name}: koenig-check dynamics would exit 1: {result.reason()}")
        if lines:
            raise ModelCheckError("\n".join(lines))

    def repr_failure(self, excinfo: pytest.ExceptionInfo[BaseException], style: Any = None) -> str | Any:
        """The verdict alone for a failed check; pytest's usual report for anything else.

        Parameters
        ----------
        excinfo : pytest.ExceptionInfo
        style : str, optional

        Returns
        -------
        str or TerminalRepr
        """
        if isinstance(excinfo.value, ModelCheckError):
            return str(excinfo.value)
        return super().repr_failure(excinfo, style=style)

    def reportinfo(self) -> tuple[Path, int | None, str]:
        """Where the item comes from: the pyproject.toml and the model's label.

        Returns
        -------
        (Path, None, str)
        """
        return self.path, None, f"koenig-check {self.name}"


def pytest_sessionfinish(session: pytest.Session) -> None:
    """Write the report of every model checked, when ``--koenig-check-report DIR`` was given.

    Parameters
    ----------
    session : pytest.Session
    """
    run = session.config.stash.get(_RUN, None)
    if run is None or run.report is None or not run.checks:
        return
    from koenig_check.report import write_report
    from koenig_check.report.output_dir import clean_out_dir, finish_out_dir

    clean_out_dir(run.report)
    written = finish_out_dir(run.report, write_report(run.report, merged(run.checks)))
    session.config.stash[_RUN].checks = []
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None:
        reporter.write_line(f"koenig-check report: {run.report} ({len(written)} files)")


def merged(checks: list[CrossCheck]) -> CrossCheck:
    """One check of every model of the run, as one ``koenig-check compare`` of them all would give.

    Parameters
    ----------
    checks : list of CrossCheck

    Returns
    -------
    CrossCheck
        The tolerance is the models' own when they share one, else the default.
    """
    from koenig_check.api import CrossCheck
    from koenig_check.run.stats import DEFAULT_RTOL

    tolerances = {c.rtol for c in checks}
    out = CrossCheck(rtol=tolerances.pop() if len(tolerances) == 1 else DEFAULT_RTOL)
    for check in checks:
        out.comparisons += check.comparisons
        out.summaries += check.summaries
        out.agreements += check.agreements
        out.failures += check.failures
        out.settings.update(check.settings)
    return out
