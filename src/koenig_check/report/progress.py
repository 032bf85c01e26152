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

#: The bar once a model's pose count is known: tqdm's, with the rate given as :meth:`Progress._rate` writes it.
BAR_FORMAT = "{l_bar}{bar}| {n_fmt}/{total_fmt} [{elapsed}<{remaining}{postfix}]"
#: Columns of the bar on a terminal that reports none (a pseudo-terminal of size 0 x 0).
FALLBACK_COLUMNS = 100

#: Seconds before the bar appears (``KOENIG_CHECK_PROGRESS_DELAY`` overrides it).
DELAY = 2.0


def _columns() -> int | None:
    """:data:`FALLBACK_COLUMNS` on a terminal that reports 0 columns, else None (tqdm follows the width).

    tqdm takes such a terminal's size as it is and then draws nothing (it counts -1 rows).
    """
    try:
        unknown = sys.stderr.isatty() and os.get_terminal_size(sys.stderr.fileno()).columns == 0
    except (OSError, ValueError, AttributeError):  # not a terminal, or a stand-in stream
        return None
    return FALLBACK_COLUMNS if unknown else None


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
        self._drawn = False
        columns = _columns()
        self._bar = tqdm(
            total=None,
            unit=" poses",
            file=sys.stderr,
            mininterval=0.5,
            leave=False,
            ncols=columns,
            nrows=None if columns is None else 24,
            dynamic_ncols=columns is None,
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
        self._bar.bar_format = None  # until the model's count is known: "0 poses [00:00, ?poses/s]"
        self._bar.postfix = None
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
        if not self._bar.disable:  # a disabled bar has no clock
            self._bar.bar_format = BAR_FORMAT
            self._bar.postfix = self._rate()
        self._show()

    def _rate(self) -> str:
        """The current model's poses per second with three significant digits (``45.7k poses/s``)."""
        elapsed = time.time() - self._bar.start_t
        rate = self._bar.n / elapsed if elapsed > 0 else 0.0
        return f"{tqdm.format_sizeof(rate)} poses/s" if rate else "? poses/s"

    def _show(self) -> None:
        """Redraw, once the run has lasted the delay (each chunk: a chunk takes a fraction of a second or more)."""
        if not self._bar.disable and time.monotonic() - self._since >= self._delay:
            self._bar.refresh()
            self._drawn = True

    def __enter__(self) -> Progress:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        if self._drawn:  # erased here: step() restarts tqdm's clock, so its close() thinks a delayed bar never drawn
            self._bar.clear()
        self._bar.close()
