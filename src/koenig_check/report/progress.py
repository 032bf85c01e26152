"""A progress bar on standard error over the poses of each model, and over the models (tqdm).

The bar is drawn only when standard error is a terminal (never into a log or a pipe), not with ``--quiet``,
and only once a run has lasted :data:`DELAY` seconds, so that a short run prints nothing but its verdict.
"""

from __future__ import annotations

import os
import sys
import time
from types import TracebackType

from tqdm import tqdm

#: Seconds before the bar appears (``KOENIG_CHECK_PROGRESS_DELAY`` overrides it).
DELAY = 2.0


def _delay() -> float:
    text = os.environ.get("KOENIG_CHECK_PROGRESS_DELAY")
    try:
        return max(float(text), 0.0) if text else DELAY
    except ValueError:
        return DELAY


class Progress:
    """A progress bar over the poses of the model being compared, labelled with the model and its rank.

    Call it (or :meth:`step`) with a model's label as the model starts; :meth:`advance` after each chunk of
    poses.  Pass it as ``progress=`` to :func:`koenig_check.compare`, which does both.

    Parameters
    ----------
    total : int
        The number of models.
    unit : str
        What the models are called in the label (``"models"``).
    quiet : bool
        Draw nothing (``--quiet``).
    """

    def __init__(self, total: int, unit: str = "models", *, quiet: bool = False) -> None:
        self._delay = _delay()
        self._since = time.monotonic()
        self._bar = tqdm(
            total=None,
            unit=" poses",
            file=sys.stderr,
            mininterval=0.5,
            leave=False,
            dynamic_ncols=True,
            delay=self._delay,
            disable=True if quiet else None,  # None: shown on a terminal only, no residue in logs and pipes
        )
        self._models = total
        self._unit = unit
        self._started = 0

    def step(self, label: str) -> None:
        """Show the model starting; the pose count starts again from zero.

        Parameters
        ----------
        label : str
        """
        self._started += 1
        rank = f"{self._started}/{self._models} {self._unit}: " if self._models > 1 else ""
        self._bar.set_description_str(f"{rank}{label[:40]}", refresh=False)
        self._bar.n = self._bar.last_print_n = 0
        self._bar.total = None
        self._bar.start_t = self._bar.last_print_t = time.time()  # the rate is the model's own
        self._show()

    __call__ = step

    def advance(self, poses: int, total: int) -> None:
        """Count a chunk of poses of the current model.

        Parameters
        ----------
        poses : int
            Poses just compared.
        total : int
            The model's poses.
        """
        self._bar.total = total
        self._bar.n += poses
        self._show()

    def _show(self) -> None:
        """Redraw, once the run has lasted the delay (each chunk: a chunk takes a fraction of a second or more)."""
        if not self._bar.disable and time.monotonic() - self._since >= self._delay:
            self._bar.refresh()

    def __enter__(self) -> Progress:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self._bar.close()
