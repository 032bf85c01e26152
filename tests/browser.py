"""Headless Chromium for the tests that look at a page as a reader does (report.html, the documentation site).

Skipped, with the reason, where Chromium is not installed; CI installs it and sets
``KOENIG_CHECK_REQUIRE_CHROMIUM=1``, which turns the skip into a failure.
"""

from __future__ import annotations

import html
import json
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest

WINDOW = 1280
CHROMIUM = next((p for p in map(shutil.which, ("chromium", "chromium-browser", "google-chrome")) if p), None)


def require_chromium() -> None:
    """Skip the calling test module when Chromium is missing, unless CI requires it."""
    if CHROMIUM is None and os.environ.get("KOENIG_CHECK_REQUIRE_CHROMIUM") != "1":
        pytest.skip(
            "Chromium is not installed (apt-get install chromium): the page is not measured at 1280 px",
            allow_module_level=True,
        )


def chromium(page: Path, *args: str, height: int = 1000) -> str:
    """Run headless Chromium on a local page with a 1280 px wide window; return what it prints."""
    assert CHROMIUM is not None, "KOENIG_CHECK_REQUIRE_CHROMIUM=1 and Chromium is not installed"
    with tempfile.TemporaryDirectory() as profile:
        flags = [
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            f"--user-data-dir={profile}",
            f"--window-size={WINDOW},{height}",
            "--force-device-scale-factor=1",
        ]
        done = subprocess.run(
            [CHROMIUM, *flags, *args, page.as_uri()], capture_output=True, text=True, timeout=120, check=False
        )
    assert done.returncode == 0, done.stderr[-2000:]
    return done.stdout


def measure(page: Path, script: str, *, height: int = 1000, budget_ms: int = 10000) -> dict:
    """Open ``page`` with ``script`` added before ``</body>``; the script writes JSON into ``<pre id="measured">``.

    The page is copied beside itself (``measured-<name>``), so that its relative links still resolve.
    """
    copy = page.with_name("measured-" + page.name)
    copy.write_text(page.read_text(encoding="utf-8").replace("</body>", script + "</body>"), encoding="utf-8")
    dom = chromium(copy, "--dump-dom", f"--virtual-time-budget={budget_ms}", height=height)
    found = re.search(r'<pre id="measured" hidden="">(.*?)</pre>', dom, re.S)
    assert found, "the measuring script did not run"
    return json.loads(html.unescape(found.group(1)))
