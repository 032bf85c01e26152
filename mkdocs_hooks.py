"""MkDocs hooks of the documentation site: pages generated from the code at build time, never copied by hand.

- ``cli.md``: the command-line reference, from the argument parser (:mod:`koenig_check.cli.reference`).
- ``comparisons/``: the committed outputs of ``comparisons/`` (their Markdown and figures), as they are.
- Search works from ``site/index.html`` without a server: Material's ``offline`` plugin runs the search worker in an
  iframe (the npm package ``iframe-worker``), which it would load from a CDN; the shim is taken from the npm
  registry once (``npm pack``) into a cache and served from the site itself, so the pages load nothing from
  the network.
- ``causes.md`` is committed (``python -m koenig_check.causes > docs/causes.md``); a stale one is a warning,
  which ``mkdocs build --strict`` turns into a failed build.
"""

from __future__ import annotations

import logging
import os
import shutil
import subprocess
import tarfile
import tempfile
from pathlib import Path
from typing import Any

from mkdocs.structure.files import File, Files

ROOT = Path(__file__).resolve().parent
#: The generated pages' and figures' folder in the site, and the extensions taken from comparisons/.
COMPARISONS = "comparisons"
_TAKEN = (".md", ".png")
log = logging.getLogger("mkdocs.plugins.koenig_check")
#: The search worker's shim: the npm package, its file, and where the site serves it.
SHIM_PACKAGE = "iframe-worker@1.0.4"
SHIM_FILE = "package/shim/index.js"
SHIM_URI = "assets/javascripts/iframe-worker-shim.js"


def _shim() -> Path | None:
    """The iframe-worker shim: ``$KOENIG_CHECK_IFRAME_WORKER``, else the cache, else ``npm pack`` into the cache."""
    given = os.environ.get("KOENIG_CHECK_IFRAME_WORKER")
    if given:
        return Path(given)
    cache = Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "koenig-check-docs"
    shim = cache / SHIM_PACKAGE.replace("@", "-") / "shim.js"
    if shim.is_file():
        return shim
    npm = shutil.which("npm")
    if npm is None:
        return None
    with tempfile.TemporaryDirectory() as tmp:
        done = subprocess.run([npm, "pack", SHIM_PACKAGE], cwd=tmp, capture_output=True, text=True, check=False)
        packed = sorted(Path(tmp).glob("*.tgz"))
        if done.returncode != 0 or not packed:
            log.info("npm pack %s failed: %s", SHIM_PACKAGE, done.stderr.strip())
            return None
        with tarfile.open(packed[0]) as archive:
            member = archive.extractfile(SHIM_FILE)
            if member is None:
                return None
            shim.parent.mkdir(parents=True, exist_ok=True)
            shim.write_bytes(member.read())
    return shim


def on_config(config: Any) -> Any:
    """Serve the search worker's shim from the site instead of the CDN the offline plugin names."""
    external = [p for p in config.extra.get("polyfills", []) if "iframe-worker" in str(p)]
    if external:
        config.extra["polyfills"] = [p for p in config.extra["polyfills"] if p not in external] + [SHIM_URI]
    return config


def generated_pages() -> dict[str, str]:
    """The pages written from the code: site path -> Markdown.

    Returns
    -------
    dict of str to str
    """
    from koenig_check.cli.reference import markdown

    return {"cli.md": markdown()}


def on_files(files: Files, config: Any) -> Files:
    """Add the generated pages and the committed outputs of ``comparisons/``; warn when causes.md is stale."""
    for uri, text in generated_pages().items():
        files.append(File.generated(config, uri, content=text))
    for path in sorted((ROOT / COMPARISONS).iterdir()):
        if path.suffix in _TAKEN:
            files.append(File.generated(config, f"{COMPARISONS}/{path.name}", abs_src_path=str(path)))
    if any(SHIM_URI == str(p) for p in config.extra.get("polyfills", [])):
        shim = _shim()
        if shim is None:
            log.warning("no %s for offline search: install npm, or set KOENIG_CHECK_IFRAME_WORKER", SHIM_PACKAGE)
        else:
            files.append(File.generated(config, SHIM_URI, abs_src_path=str(shim)))
    from koenig_check.causes.listing import markdown as causes_page

    page = Path(config["docs_dir"]) / "causes.md"
    if page.read_text(encoding="utf-8") != causes_page():
        log.warning("docs/causes.md is stale: python -m koenig_check.causes > docs/causes.md")
    return files
