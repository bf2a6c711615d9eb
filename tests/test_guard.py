"""The memory guard (fatline_verify/check/guard.py): a level runs when its real figures fit the budget,
not when a presumed or sampled rate says so; the search's allocations stay within the budget; levels
move to disk only when the real figures ask for it; the held bytes count each buffer once."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

from fatline_verify.check import guard
from fatline_verify.check.checker import initial_keys_for
from fatline_verify.check.engines import engine_for
from fatline_verify.check.search import LocalShards, explore_keys
from fatline_verify.check.shard import Shard
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.systems import system_for

STATE_COLUMNS = ("keys", "parent", "parent_action", "enabled", "goal", "level_sizes", "summary")
BATCH = 2000
"""Small batches, so that the level's own columns, not a batch's temporaries, decide what fits."""


@pytest.fixture(scope="module")
def every_start():
    """n = 5 on the paper's model from every initial configuration in 9x9 (its first level is the
    largest), one engine kept warm across runs (its caches are not the search's), and the reference
    search without a budget."""
    system = system_for(load_model("paper"))
    codec = system.codec(5, (9, 9))
    start = initial_keys_for(system, 5, (9, 9), codec)
    engine = engine_for(system, "compiled")

    def run(**options):
        return explore_keys(system, 5, start, (9, 9), engine, max_states=None, batch=BATCH, **options)

    reference = run()
    pool = LocalShards([Shard(system, 5, (9, 9), engine)])
    pool.shards[0].seed(start, start, np.arange(len(start)))
    rates = guard.measure(pool, [start], start, np.arange(len(start)))
    held = len(start) * (8 + 4 + 4 + 8)  # keys, parents, actions, frontier ids (the shard's keys are the level's)
    sampled = guard.projected(held, len(start), rates, len(start), codec.dtype.itemsize)
    return run, reference, sampled, rates


def _same(a, b) -> bool:
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in STATE_COLUMNS)


def test_a_level_its_sample_prices_above_the_budget_runs_when_its_real_figures_fit(every_start):
    """The sample's rates are upper bounds (fewer successors coincide in a sample than in the level):
    the first level, priced by them above the budget, still runs, in memory, and equals the free search."""
    run, reference, sampled, rates = every_start
    assert rates.measured and rates.new <= rates.candidates
    assert reference.level_sizes[1] < rates.new * reference.level_sizes[0]  # the sample over-counts the level
    got = run(max_bytes=int(sampled * 0.7))
    assert not got.truncated and not got.on_disk
    assert _same(got, reference)


def test_the_search_allocates_within_the_budget_and_finishes_identically_or_stops(every_start):
    """For budgets from above the sampled projection down to a third of it, what the search allocates
    (numpy's arrays, traced) stays within the budget; each run equals the free search or stops at the
    memory bound naming more than it had."""
    run, reference, sampled, _ = every_start
    finished = stopped = 0
    for share in (1.2, 0.8, 0.6, 0.5, 0.4, 0.3):
        budget = int(sampled * share)
        tracemalloc.start()
        try:
            got = run(max_bytes=budget)
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
        assert peak <= budget, (share, peak, budget)
        if got.truncated:
            assert got.limit.value == "max-memory" and got.needed_bytes > budget
            stopped += 1
        else:
            assert _same(got, reference), share
            finished += 1
    assert finished and stopped


def test_the_watch_spills_once_then_stops_with_the_level_extrapolated():
    spills: list[int] = []

    def spill() -> int:
        spills.append(1)
        return 10_000

    watch = guard.Watch(room=2_000, frontier=100, visited=50, key=8, spill=spill)
    assert watch.fits(10, 0)  # nothing gathered: the fixed part fits
    assert watch.fits(10, 100) and spills == [1] and watch.room == 12_000  # 100 * 81 > 2000: the levels spill
    assert not watch.fits(50, 1_000) and spills == [1]  # once only
    whole = 2_000  # 1000 candidates from 50 of 100 states, over the whole frontier
    assert watch.needed == max(guard.expansion_bytes(100, whole, 8), guard.merge_bytes(100, whole, whole, 50, 8))


def test_held_bytes_count_each_buffer_once_and_no_memory_map(tmp_path):
    a = np.zeros(1000, dtype=np.int64)
    b = np.zeros(10, dtype=np.int32)
    mapped = np.memmap(tmp_path / "m.bin", dtype=np.int64, mode="w+", shape=(500,))
    assert guard.held_bytes([a, a, np.asarray(a), b]) == 8000 + 40
    assert guard.held_bytes([a[:100], a]) == 800 + 8000  # a view is its own bytes
    assert guard.held_bytes([mapped, np.asarray(mapped), mapped[:10]]) == 0


def test_the_sample_is_evenly_spaced_and_bounded():
    assert guard.sample_size(10) == 10
    assert guard.sample_size(114_341_098) == guard.SAMPLE_MIN + 114_341_098 // guard.SAMPLE_SHARE
