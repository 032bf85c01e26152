"""compare(progress=...) gets each model's start and, with an ``advance`` method, every chunk's poses."""

from __future__ import annotations

import koenig_check


class Recorder:
    def __init__(self) -> None:
        self.events: list[tuple] = []

    def __call__(self, label: str) -> None:
        self.events.append(("start", label))

    def advance(self, poses: int, total: int) -> None:
        self.events.append(("advance", poses, total))


def test_chunks_advance_by_their_poses():
    recorder = Recorder()
    koenig_check.compare(["gimbal", "double_pendulum"], n_poses=23, chunk_poses=5, progress=recorder)
    starts = [i for i, e in enumerate(recorder.events) if e[0] == "start"]
    assert [recorder.events[i][1] for i in starts] == ["gimbal", "double_pendulum"]
    for first, stop in zip(starts, [*starts[1:], len(recorder.events)], strict=True):
        chunks = recorder.events[first + 1 : stop]
        assert [c[1] for c in chunks] == [5, 5, 5, 5, 3]  # 23 poses in chunks of 5
        assert {c[2] for c in chunks} == {23}


def test_a_plain_callable_still_gets_the_labels():
    started: list[str] = []
    koenig_check.compare(["gimbal"], n_poses=3, progress=started.append)
    assert started == ["gimbal"]
