"""The documentation site: ``mkdocs build --strict`` (warnings fail it), generated pages, offline, 1280 px.

The site is built in this process from ``mkdocs.yml`` into a temporary folder, as ``mkdocs build --strict``
does; a warning (a broken link, a missing reference, a stale generated page) aborts the build and fails the
test.  The generated pages are checked to follow the code: an option added to the parser appears on the CLI
page; a catalogue page that no longer matches ``python -m koenig_check.causes`` fails the build.
"""

from __future__ import annotations

import argparse
import importlib
import logging
import re
import shutil
from html.parser import HTMLParser
from pathlib import Path
from typing import ClassVar

import pytest

mkdocs_config = pytest.importorskip("mkdocs.config", reason="the docs extra: pip install '.[docs]'")
from mkdocs.commands.build import build  # noqa: E402
from mkdocs.exceptions import Abort  # noqa: E402

cli_main = importlib.import_module("koenig_check.cli.main")  # the module (koenig_check.cli.main is the function)

ROOT = Path(__file__).resolve().parents[2]


def build_site(site: Path, docs_dir: Path | None = None) -> Path:
    """``mkdocs build --strict`` into ``site`` (optionally from another copy of ``docs/``); return the folder."""
    overrides = {"site_dir": str(site), "strict": True}
    if docs_dir is not None:
        overrides["docs_dir"] = str(docs_dir)
    config = mkdocs_config.load_config(str(ROOT / "mkdocs.yml"), **overrides)
    build(config)
    return site


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return build_site(tmp_path_factory.mktemp("site"))


def test_every_page_of_the_nav_is_built_and_opens_from_index_html(site: Path) -> None:
    nav = re.findall(r"^\s*-\s+(?:[^:\n]+:\s+)?([\w/.-]+\.md)\s*$", (ROOT / "mkdocs.yml").read_text(), re.M)
    assert len(nav) >= 20
    for page in nav:
        built = site / page.replace("README.md", "index.html").replace(".md", ".html")
        assert built.is_file(), page
    index = (site / "index.html").read_text(encoding="utf-8")
    assert 'href="getting-started.html"' in index  # use_directory_urls: false, so file:// links open a file


class _Resources(HTMLParser):
    """Every URL a page loads by itself (scripts, stylesheets, images, frames), not the links a reader follows."""

    LOADING: ClassVar[dict[str, str]] = {
        "script": "src",
        "img": "src",
        "iframe": "src",
        "link": "href",
        "source": "src",
    }

    def __init__(self) -> None:
        super().__init__()
        self.loaded: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        name = self.LOADING.get(tag)
        if name and a.get(name) and not (tag == "link" and a.get("rel") in ("canonical", "alternate")):
            self.loaded.append(a[name] or "")


def test_the_site_loads_nothing_from_the_network(site: Path) -> None:
    pages = sorted(site.rglob("*.html"))
    assert pages
    for page in pages:
        parser = _Resources()
        parser.feed(page.read_text(encoding="utf-8"))
        external = [u for u in parser.loaded if re.match(r"(https?:)?//", u)]
        assert not external, (page.name, external)
    for css in site.rglob("*.css"):
        assert not re.search(r"@import\s+url\(\s*['\"]?https?:", css.read_text(encoding="utf-8")), css.name
    assert (site / "assets" / "javascripts" / "iframe-worker-shim.js").is_file()  # search from file://


def test_the_cli_page_holds_every_command_and_option(site: Path) -> None:
    page = (site / "cli.html").read_text(encoding="utf-8")
    parser = cli_main.build_parser()
    from koenig_check.cli.reference import _commands

    for name, _, sub in _commands(parser):
        assert f'id="{name}"' in page, name
        for action in sub._actions:
            for flag in action.option_strings if action.help != argparse.SUPPRESS else ():  # as --help shows
                assert flag in page, (name, flag)


def test_an_option_added_to_the_parser_appears_on_the_built_page(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    original = cli_main.build_parser

    def with_an_option():  # type: ignore[no-untyped-def]
        parser = original()
        from koenig_check.cli.reference import _commands

        compare = next(sub for name, _, sub in _commands(parser) if name == "compare")
        compare.add_argument("--frobnicate-joints", metavar="K", help="a test option: %(default)s", default=7)
        return parser

    monkeypatch.setattr(cli_main, "build_parser", with_an_option)
    page = (build_site(tmp_path / "site") / "cli.html").read_text(encoding="utf-8")
    assert "--frobnicate-joints K" in page and "a test option: 7" in page


def test_a_stale_catalogue_page_fails_the_build(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    docs = tmp_path / "docs"
    shutil.copytree(ROOT / "docs", docs)
    page = docs / "causes.md"
    page.write_text(page.read_text(encoding="utf-8").replace("| mjcf |", "| mjcf, urdf |", 1), encoding="utf-8")
    with caplog.at_level(logging.WARNING), pytest.raises(Abort):
        build_site(tmp_path / "site", docs_dir=docs)
    assert any("docs/causes.md is stale" in r.getMessage() for r in caplog.records)


def test_a_broken_link_fails_the_build(tmp_path: Path) -> None:
    docs = tmp_path / "docs"
    shutil.copytree(ROOT / "docs", docs)
    page = docs / "scale.md"
    page.write_text(page.read_text(encoding="utf-8") + "\n[gone](no_such_page.md)\n", encoding="utf-8")
    with pytest.raises(Abort):
        build_site(tmp_path / "site", docs_dir=docs)
