"""The comparison scripts live in ``comparisons/`` (scripts, not a package): make them importable."""

from __future__ import annotations

import sys
from pathlib import Path

COMPARISONS = Path(__file__).resolve().parents[2] / "comparisons"
if str(COMPARISONS) not in sys.path:
    sys.path.insert(0, str(COMPARISONS))
