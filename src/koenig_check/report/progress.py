"""Progress bars on standard error for work longer than a second (tqdm)."""

from __future__ import annotations

import sys
from types import TracebackType

from tqdm import tqdm


class Progress:
    """A progress bar over ``total`` items, advanced by :meth:`step` as each item starts.

    Parameters
    ----------
    total : int
    unit : str
        What is counted (``"models"``).
    """

    def __init__(self, total: int, unit: str) -> None:
        self._bar = tqdm(
            total=total,
            unit=f" {unit}",
            file=sys.stderr,
            mininterval=0.5,
            leave=False,
            dynamic_ncols=True,
            disable=None,  # shown on a terminal only: no bar residue in logs and pipes
        )
        self._started = False

    def step(self, label: str) -> None:
        """Mark the previous item done and show the one starting.

        Parameters
        ----------
        label : str
        """
        if self._started:
            self._bar.update(1)
        self._started = True
        self._bar.set_description_str(label[:40])

    def __enter__(self) -> Progress:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        if self._started and exc_type is None:
            self._bar.update(1)
        self._bar.close()
