"""The collector's pauses: start-up objects frozen out of it, later garbage still collected,
every collection counted by generation."""

from __future__ import annotations

import gc
import weakref

from deploy.compute.gc_pauses import GcPauses


class _Node:
    def __init__(self) -> None:
        self.other: _Node | None = None


def _cycle() -> weakref.ref[_Node]:
    a, b = _Node(), _Node()
    a.other, b.other = b, a
    return weakref.ref(a)


def test_start_freezes_what_exists_and_later_cycles_are_still_collected() -> None:
    pauses = GcPauses()
    before = _cycle()  # garbage already: start's collection frees it before freezing
    kept = _Node()
    pauses.start()
    try:
        assert before() is None
        assert gc.get_freeze_count() > 0
        assert gc.is_tracked(kept)
        after = _cycle()
        gc.collect(0)
        assert after() is None  # the young generation is collected as before: no leak
        gc.collect(1)
        summary = pauses.summary()
        assert summary["gen0"]["collections"] >= 1
        assert summary["gen1"]["collections"] >= 1
        assert summary["gen0"]["max_ms"] >= 0.0
    finally:
        pauses.stop()
    assert gc.get_freeze_count() == 0  # handed back: the next run starts from the same state
    assert pauses._callback not in gc.callbacks
    counted = pauses.summary()["gen0"]["collections"]
    gc.collect(0)
    assert pauses.summary()["gen0"]["collections"] == counted  # no longer counting


def test_stop_without_start_and_double_start_are_harmless() -> None:
    pauses = GcPauses()
    pauses.stop()
    pauses.start(freeze=False)
    pauses.start(freeze=False)
    try:
        assert gc.callbacks.count(pauses._callback) == 1
        assert gc.get_freeze_count() == 0
    finally:
        pauses.stop()
