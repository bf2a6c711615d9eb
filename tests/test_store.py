"""The compact store: per-level summaries against every transition, levels on disk against in memory."""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest

from fatline_verify.check import checker
from fatline_verify.check.checker import check, check_to_json, initial_keys_for
from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore, explore_keys
from fatline_verify.check.shard import FLAG_BITS, fold_summaries, summarise
from fatline_verify.lemmas.properties import SAFETY
from fatline_verify.model.config import load_model
from fatline_verify.schedulers.systems import system_for
from tests.conftest import make_model

STATE_COLUMNS = ("keys", "parent", "parent_action", "depth", "expanded", "enabled", "goal", "summary")


def _explore(model, n, w, engine="compiled", **options):
    system = system_for(model)
    init = system.initial(initial_array(n, (w, w), model))
    return explore(system, init, (w, w), engine_for(system, engine), **options)


@pytest.mark.parametrize("after_violation", ["stop", "continue"])
@pytest.mark.parametrize("readings", [{}, {"scheduler": "fsync"}, {"uncovered": "search-both"}])
def test_summary_equals_the_transitions_it_folds(readings, after_violation):
    """Counts and least violating transitions, folded batch by batch (7 states a batch), equal those
    read off every transition recomputed at once."""
    ex = _explore(make_model(**readings), 3, 6, batch=7, after_violation=after_violation)
    src, dst, action, flags, fits, exact = ex.transitions(np.arange(ex.n_expanded))
    assert ex.n_transitions == len(src) > 0
    assert ex.escaped == int((~fits).sum())
    assert ex.off_lattice == int((~exact).sum())
    core = np.bitwise_or.reduce([lemma.flag for lemma in SAFETY])
    assert ex.violating_only == int(((dst < 0) & fits & ((flags & core) != 0)).sum())
    seen_violation = False
    for bit in range(FLAG_BITS):
        hits = np.flatnonzero(flags & (1 << bit))
        want = None
        if len(hits):
            first = hits[np.lexsort((action[hits], src[hits]))[0]]
            want = (int(src[first]), int(action[first]))
            seen_violation = True
        assert ex.least_violating(1 << bit) == want, bit
    assert seen_violation  # the readings above violate some lemma at n = 3


def test_fold_summaries_takes_the_least_transition_whatever_the_order():
    rng = np.random.default_rng(7)
    src = np.sort(rng.integers(0, 50, 400))
    action = rng.integers(1, 8, 400)
    order = np.lexsort((action, src))
    src, action = src[order], action[order]
    flags = rng.integers(0, 256, 400).astype(np.uint8)
    fits, exact = rng.random(400) < 0.9, rng.random(400) < 0.95
    whole = summarise(src, action, flags, fits, exact, "stop")
    parts = [summarise(src[a:b], action[a:b], flags[a:b], fits[a:b], exact[a:b], "stop") for a, b in
             [(0, 90), (90, 91), (91, 300), (300, 400)]]  # fmt: skip
    assert np.array_equal(fold_summaries(parts[::-1]), whole)
    assert np.array_equal(fold_summaries(parts), whole)


def test_levels_on_disk_give_the_same_exploration():
    model = load_model("paper")
    memory = _explore(model, 4, 6)
    disk = _explore(model, 4, 6, on_disk=True)
    assert disk.on_disk and not memory.on_disk
    assert isinstance(disk.keys, np.memmap) and not isinstance(memory.keys, np.memmap)
    for name in STATE_COLUMNS:
        assert np.array_equal(getattr(memory, name), getattr(disk, name)), name
    assert np.array_equal(memory.edge_dst, disk.edge_dst)


def test_max_memory_moves_levels_to_disk_with_the_same_results():
    """Budgets from generous to tight: each either finishes with the in-memory search's result (on disk
    where the budget says so) or stops at the memory bound, its levels on disk; some budget finishes
    only on disk. (A search from 20 initial states, past violations, whose levels grow: from all initial
    states the first level is the largest, and a budget it fits fits the rest in memory.)"""
    system = system_for(load_model("paper"))
    codec = system.codec(4, (9, 9))
    every = initial_keys_for(system, 4, (9, 9), codec)
    start = every[:: len(every) // 20][:20]

    def run(**options):
        return explore_keys(system, 4, start, (9, 9), "compiled", after_violation="continue", **options)

    reference = run()
    assert list(reference.level_sizes[:4]) == sorted(reference.level_sizes[:4])  # growing levels
    finished_on_disk = truncated = 0
    for budget in np.geomspace(2**16, 2**12, 30).astype(int).tolist():
        got = run(max_bytes=budget)
        if got.truncated:
            assert got.on_disk  # the levels went to disk before the search gave up
            truncated += 1
            continue
        for name in STATE_COLUMNS:
            assert np.array_equal(getattr(reference, name), getattr(got, name)), (budget, name)
        finished_on_disk += got.on_disk
    assert finished_on_disk and truncated


def test_check_json_and_witnesses_are_the_same_in_memory_and_on_disk(monkeypatch):
    """Every verdict, count and witness of a check, its levels on disk, equals the in-memory check's."""
    model = load_model("paper")
    memory = check(model, (3, 4), (6, 6))
    monkeypatch.setattr(checker, "explore_keys", partial(explore_keys, on_disk=True))
    disk = check(model, (3, 4), (6, 6))

    def strip(result):
        doc = check_to_json(result, {})
        for s in doc["searches"]:
            s.pop("seconds")
        return doc

    assert strip(memory) == strip(disk)
    assert [r.witness for r in memory.results] == [r.witness for r in disk.results]
    assert any(r.witness for r in disk.results)


def test_the_store_keeps_few_bytes_a_state():
    """Key 8, parent 4, action 4, enabled 1, goal 1: no transition columns held."""
    ex = _explore(load_model("paper"), 4, 7)
    assert ex.nbytes == 18 * ex.n_states
    assert "edges" not in ex._cache  # nothing recomputed them yet


def test_kept_answers_give_the_same_check_and_are_read_again(tmp_path, monkeypatch):
    """A check with the model's answers kept by an earlier run equals one that asks the model; the
    engine then asks nothing new; a file that does not match its digest is ignored."""
    from fatline_verify.check import answers, compiled

    model = load_model("paper")
    fresh = check(model, (4, 4), (6, 6))
    monkeypatch.setenv(answers.ENV, str(tmp_path / "answers"))
    first = check(model, (4, 4), (6, 6))
    (kept,) = (tmp_path / "answers").glob("*.npz")
    asked = []
    original = compiled.CompiledEngine._learn_decisions
    monkeypatch.setattr(
        compiled.CompiledEngine, "_learn_decisions", lambda self, k, n: (asked.append(len(k)), original(self, k, n))
    )
    second = check(model, (4, 4), (6, 6))
    assert not asked  # every decision came from the kept file
    for got in (first, second):
        assert [(r.lemma, r.verdict, r.reason, r.witness) for r in got.results] == [
            (r.lemma, r.verdict, r.reason, r.witness) for r in fresh.results
        ]
    data = bytearray(kept.read_bytes())
    data[-10] ^= 1
    kept.write_bytes(bytes(data))
    assert answers.load_answers(kept) is None
    third = check(model, (4, 4), (6, 6))
    assert asked and [r.verdict for r in third.results] == [r.verdict for r in fresh.results]


@pytest.mark.parametrize("engine", ["compiled", "fast"])
def test_ranked_keys_give_the_same_search_as_packed_keys(engine, monkeypatch):
    """Keys past 63 bits are ranks of the sorted cell codes, in the packed keys' order: a search with
    ranked keys where packed ones would do gives the same ids, parents, states, summaries and verdicts."""
    from fatline_verify.model.lattice import KeyCodec, RankedCodec
    from fatline_verify.schedulers import rounds

    model = load_model("paper")
    packed = check(model, (4, 4), (6, 6), engine=engine, bound=(8, 8))
    a = _explore(model, 4, 7, engine)
    assert type(a.codec) is KeyCodec
    monkeypatch.setattr(rounds, "key_codec", RankedCodec)
    b = _explore(model, 4, 7, engine)
    ranked = check(model, (4, 4), (6, 6), engine=engine, bound=(8, 8))
    assert isinstance(b.codec, RankedCodec) and not np.array_equal(a.keys, b.keys)
    for name in ("parent", "parent_action", "level_sizes", "enabled", "goal", "summary", "states"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert [(r.lemma, r.verdict, r.reason, r.witness) for r in packed.results] == [
        (r.lemma, r.verdict, r.reason, r.witness) for r in ranked.results
    ]


def test_eight_robots_in_a_20x20_bound_rank_into_54_bits():
    from fatline_verify.model.lattice import RankedCodec

    codec = system_for(load_model("paper")).codec(8, (20, 20))
    assert isinstance(codec, RankedCodec) and (int(codec.cum[0, -1]) - 1).bit_length() == 54
    rng = np.random.default_rng(3)
    states = np.sort(np.stack([rng.integers(0, 20, (2000, 8)), rng.integers(0, 20, (2000, 8))], -1), axis=1)
    states[:, :, 0] -= states[:, :, 0].min(axis=1, keepdims=True)
    states[:, :, 1] -= states[:, :, 1].min(axis=1, keepdims=True)
    keys = codec.encode(states)
    back = codec.decode(keys)
    assert np.array_equal(codec.encode(back), keys)
    codes = lambda s: np.sort(s[..., 0] * 20 + s[..., 1], axis=1)  # noqa: E731
    assert np.array_equal(codes(back), codes(states))
    # the order of the codes, read as one 72-bit number, is the order of the keys
    as_int = [int("".join(f"{c:09b}" for c in row), 2) for row in codes(states).tolist()]
    assert np.array_equal(np.argsort(keys, kind="stable"), sorted(range(len(as_int)), key=lambda i: (as_int[i], i)))
