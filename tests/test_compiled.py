"""The compiled engine against the fast engine: expansions field by field, keys against decode + expand +
canonical + encode, random readings and states, whole explorations, errors, and its caches."""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from fatline_verify.check.compiled import CompiledEngine, HashTable, KeyExpansion, distinct
from fatline_verify.check.engines import engine_for
from fatline_verify.check.fast import FastEngine
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.lemmas.properties import Lemma
from fatline_verify.model.config import load_model
from fatline_verify.model.lattice import KeyCodec, canonical
from fatline_verify.model.options import CATALOGUE
from fatline_verify.rules.paper.algorithm import Decision, Rule, decide
from fatline_verify.schedulers.systems import system_for
from tests.conftest import make_model
from tests.test_checker_seeded import MUTANTS, toy
from tests.test_explore import FIELDS, READINGS

EXPANSION = ["enabled", "goal", "src", "action", "after", "flags", "exact"]
KEYED = ["enabled", "goal", "src", "action", "key", "flags", "fits", "exact"]
IDS = [",".join(f"{k}={v}" for k, v in r.items()) or "default" for r in READINGS]


def assert_same_expansion(model, states):
    system = system_for(model)
    a = FastEngine(system).expand(states)
    b = CompiledEngine(system).expand(states)
    for f in EXPANSION:
        x, y = getattr(a, f), getattr(b, f)
        assert x.dtype == y.dtype and x.shape == y.shape and np.array_equal(x, y), f
    return a


def composed(engine, keys, codec):
    """What ``expand_keys`` must equal: decode, expand, canonicalise, bound check, encode."""
    ex = engine.expand(codec.decode(keys))
    canon, _ = canonical(ex.after)
    fits = codec.fits(canon)
    key = np.zeros(len(canon), dtype=np.int64)
    if fits.any():
        key[fits] = codec.encode(canon[fits])
    return KeyExpansion(ex.enabled, ex.goal, ex.src, ex.action, key, ex.flags, fits, ex.exact)


def assert_same_keys(a, b):
    for f in KEYED:
        x, y = getattr(a, f), getattr(b, f)
        assert x.dtype == y.dtype and x.shape == y.shape and np.array_equal(x, y), f


def successors(model, states, levels):
    """Canonical states reached from ``states`` in up to ``levels`` rounds, violating ones included
    (colliding, disconnected and RMA-crossing states are expanded too)."""
    engine = FastEngine(system_for(model))
    seen = [states]
    for _ in range(levels):
        canon, _ = canonical(engine.expand(states).after)
        states = np.unique(canon, axis=0)
        seen.append(states)
    return np.unique(np.concatenate(seen), axis=0)


# --- expand ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("readings", READINGS, ids=IDS)
def test_expand_equals_fast_engine(readings):
    model = make_model(**readings)
    for n in (2, 3):
        assert_same_expansion(model, initial_array(n, (6, 6), model))


@pytest.mark.parametrize("readings", [{}, {"scheduler": "centralized", "goal": "any-line"}, READINGS[6]])
def test_expand_equals_fast_engine_for_four_robots(readings):
    model = make_model(**readings)
    ex = assert_same_expansion(model, initial_array(4, (6, 6), model))
    assert ex.flags.any()  # some step violates a lemma, so the flags are compared in earnest


@pytest.mark.parametrize("readings", [{}, {"goal": "line-meets-discs", "timing": "lockstep"}])
def test_expand_equals_fast_engine_beyond_initial_states(readings):
    """Reached states (two rounds on, violating steps included): colliding, disconnected, crossed."""
    model = make_model(**readings)
    ex = assert_same_expansion(model, successors(model, initial_array(3, (5, 5), model), 2))
    for lemma_bit in (1, 2):  # (the RMA bit: under the planted defects below)
        assert (ex.flags & lemma_bit).any()


@pytest.mark.parametrize("mutant", list(MUTANTS), ids=str)
def test_expand_equals_fast_engine_under_planted_defects(mutant):
    """The seeded-bug algorithms collide, disconnect and cross the RMA on purpose (L-shaped paths)."""
    model = replace(make_model(path="vertical-then-horizontal"), algorithm=toy(MUTANTS[mutant]))
    ex = assert_same_expansion(model, successors(model, initial_array(3, (6, 6), model), 2))
    if isinstance(mutant, Lemma) and mutant.flag:
        assert (ex.flags & mutant.flag).any()


@pytest.mark.parametrize("n", [1, 2, 5, 7, 8])
def test_expand_every_robot_count(n):
    column = np.array([[[0, 3 * k] for k in range(n)]], dtype=np.int64)
    spread = np.array([[[2 * (k % 3), 3 * (k // 3)] for k in range(n)]], dtype=np.int64)
    codec = KeyCodec(n, (8, 8))
    keys = codec.encode(canonical(spread)[0])
    for scheduler in ("ssync", "fsync", "centralized"):
        model = make_model(scheduler=scheduler)
        assert_same_expansion(model, np.concatenate([column, spread]))
        system = system_for(model)
        want = composed(FastEngine(system), keys, codec)
        assert_same_keys(want, CompiledEngine(system).expand_keys(keys, codec))
    assert_same_expansion(model, np.zeros((0, n, 2), dtype=np.int64))


def test_expand_with_a_larger_view_radius():
    for model in (make_model(q=2), make_model(q=2, visibility="any-part", contact="strict")):
        states = initial_array(3, (9, 9), model)
        assert_same_expansion(model, states[:: max(1, len(states) // 300)])


# --- expand_keys ----------------------------------------------------------------------------------
@pytest.mark.parametrize("readings", [{}, {"scheduler": "fsync"}, {"path": "horizontal-then-vertical"}])
def test_expand_keys_equals_decode_expand_canonical_encode(readings):
    model = make_model(**readings)
    system = system_for(model)
    fast, comp = FastEngine(system), CompiledEngine(system)
    for n, bound in [(3, (6, 6)), (3, (20, 20)), (4, (6, 6)), (4, (7, 5))]:
        codec = KeyCodec(n, bound)
        initial = initial_array(n, (5, 5), model)
        initial = initial[codec.fits(initial)]
        keys = codec.encode(initial)
        want = composed(fast, keys, codec)
        got = comp.expand_keys(keys, codec)
        assert_same_keys(want, got)
        if bound == (6, 6):
            assert not want.fits.all() and want.fits.any()  # successors outgrow the window


def test_expand_keys_on_an_empty_batch():
    model = make_model()
    codec = KeyCodec(3, (6, 6))
    got = CompiledEngine(system_for(model)).expand_keys(np.zeros(0, dtype=np.int64), codec)
    assert_same_keys(composed(FastEngine(system_for(model)), np.zeros(0, dtype=np.int64), codec), got)


# --- random readings and states -------------------------------------------------------------------
def readings() -> st.SearchStrategy[dict[str, str]]:
    table = {
        name: st.sampled_from(sorted(spec.readings)) for name, spec in CATALOGUE.items() if spec.only_under is None
    }
    table["scheduler"] = st.sampled_from(["ssync", "fsync", "centralized"])
    return st.fixed_dictionaries(table)


@st.composite
def batches(draw):
    """1 to 4 states of 1 to 8 robots at distinct points of a small window (any distances: overlapping,
    disconnected, collinear)."""
    n = draw(st.integers(1, 8))
    window = draw(st.integers(max(2, n), 8))
    cells = [(x, y) for x in range(window) for y in range(window)]
    count = draw(st.integers(1, 4))
    states = [draw(st.permutations(cells))[:n] for _ in range(count)]
    return np.array(states, dtype=np.int64).reshape(-1, n, 2)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(readings(), st.sampled_from([1, 2]), batches())
def test_random_readings_and_states(opts, q, states):
    model = make_model(q=q, **opts)
    try:
        FastEngine(system_for(model)).expand(states)
    except ValueError:
        event("the fast engine refuses")
        with pytest.raises(ValueError):
            CompiledEngine(system_for(model)).expand(states)
        return
    event(f"{states.shape[1]} robots")
    assert_same_expansion(model, states)
    canon, _ = canonical(states)
    codec = KeyCodec(states.shape[1], (8, 8))
    keys = codec.encode(canon)
    system = system_for(model)
    assert_same_keys(composed(FastEngine(system), keys, codec), CompiledEngine(system).expand_keys(keys, codec))


# --- whole explorations ---------------------------------------------------------------------------
@pytest.mark.parametrize("readings", [{}, {"scheduler": "centralized"}, {"timing": "lockstep", "goal": "any-line"}])
def test_explore_equals_fast_engine(readings):
    model = make_model(**readings)
    system = system_for(model)
    for n, w in [(2, 6), (3, 6)]:
        init = system.initial(initial_array(n, (w, w), model))
        a = explore(system, init, (w, w), engine_for(system, "fast"))
        b = explore(system, init, (w, w), CompiledEngine(system))
        assert b.engine == "compiled"
        for f in FIELDS:
            assert np.array_equal(getattr(a, f), getattr(b, f)), f


@pytest.mark.slow
@pytest.mark.parametrize("readings", READINGS, ids=IDS)
def test_explore_equals_fast_engine_every_reading(readings):
    model = make_model(**readings)
    system = system_for(model)
    for n, w in [(2, 7), (3, 7), (4, 6)]:
        init = system.initial(initial_array(n, (w, w), model))
        a = explore(system, init, (w, w), engine_for(system, "fast"))
        b = explore(system, init, (w, w), CompiledEngine(system))
        for f in FIELDS:
            assert np.array_equal(getattr(a, f), getattr(b, f)), f


@pytest.mark.slow
def test_expand_keys_over_a_whole_state_space():
    """Five robots of the SPIN anchor's reading in a 20x20 bound, level by level."""
    model = load_model("paper")
    system = system_for(model)
    fast, comp = FastEngine(system), CompiledEngine(system)
    codec = KeyCodec(5, (20, 20))
    frontier = distinct(codec.encode(initial_array(5, (7, 7), model)))
    visited = frontier
    while len(frontier):
        got = comp.expand_keys(frontier, codec)
        assert_same_keys(composed(fast, frontier, codec), got)
        nxt = distinct(got.key[got.fits & (got.flags == 0)])
        nxt = nxt[~np.isin(nxt, visited)]
        visited = np.sort(np.concatenate([visited, nxt]))
        frontier = nxt


# --- errors ---------------------------------------------------------------------------------------
def test_off_lattice_decisions_hand_the_search_to_the_scalar_engine():
    """The packed engines refuse a rational destination (they pack lattice moves); the checker then searches
    that robot count with the scalar engine, and every engine asked gives the scalar engine's verdicts."""
    from fatline_verify.check.checker import CheckPlan, check_robots
    from fatline_verify.check.offlattice import OffLattice

    def half(snapshot, model):
        if not any(x >= 3 for x, _ in snapshot):
            return Decision(Rule.ALONE, (0, 0), ((0, 0),), ())
        return Decision(Rule.SCENARIO_1, (Fraction(1, 2), 0), ((0, 0), (Fraction(1, 2), 0)), ())

    model = replace(make_model(), algorithm=half)
    states = initial_array(2, (5, 5), model)
    with pytest.raises(OffLattice, match="off the lattice: the fast engine packs lattice moves only"):
        FastEngine(system_for(model)).expand(states)
    with pytest.raises(OffLattice, match="off the lattice: the compiled engine packs lattice moves only"):
        CompiledEngine(system_for(model)).expand(states)
    got = {}
    for engine in ("scalar", "fast", "compiled"):
        stats, results = check_robots(CheckPlan.of(model, robots=(2, 2), window=(5, 5), engine=engine), 2)
        assert stats.engine == "scalar" and stats.asked == ("" if engine == "scalar" else engine)
        assert stats.off_lattice > 0
        got[engine] = [(r.lemma, r.verdict, r.reason) for r in results]
    assert got["scalar"] == got["fast"] == got["compiled"]


def test_offsets_beyond_the_pair_packing_are_refused():
    model = make_model()
    states = np.array([[[0, 0], [200, 0]]], dtype=np.int64)
    with pytest.raises(ValueError, match="127 lattice units"):
        FastEngine(system_for(model)).expand(states)
    with pytest.raises(ValueError, match="127 lattice units"):
        CompiledEngine(system_for(model)).expand(states)
    edge = np.array([[[0, 0], [127, 0]], [[128, 0], [0, 0]]], dtype=np.int64)  # -128 packs, +127 packs
    assert_same_expansion(model, edge)


def test_snapshots_beyond_63_bits_are_refused():
    model = make_model(q=3)  # a 25x25 view: 10 bits a cell, 7 cells for 8 robots
    states = np.array([[[0, 3 * k] for k in range(8)]], dtype=np.int64)
    with pytest.raises(ValueError, match="63 bits"):
        FastEngine(system_for(model)).expand(states)
    with pytest.raises(ValueError, match="63 bits"):
        CompiledEngine(system_for(model)).expand(states)


# --- caches ---------------------------------------------------------------------------------------
def test_cache_hits_do_not_ask_the_model_again():
    calls = []

    def counting(snapshot, model):
        calls.append(snapshot)
        return decide(snapshot, model)

    model = replace(make_model(), algorithm=counting)
    engine = CompiledEngine(system_for(model))
    states = initial_array(4, (5, 5), model)
    first = engine.expand(states)
    asked, pairs = len(calls), len(engine.pairs)
    assert asked == len(engine.decisions) and len({tuple(s) for s in calls}) == asked  # each snapshot once
    again = engine.expand(states)
    assert len(calls) == asked and len(engine.pairs) == pairs
    for f in EXPANSION:
        assert np.array_equal(getattr(first, f), getattr(again, f)), f


def test_hash_table_grows_and_keeps_every_row():
    from fatline_verify.check.hashtable import find as _find

    table = HashTable(2, capacity=4)
    rng = np.random.default_rng(1)
    keys = np.unique(rng.integers(0, 1 << 62, size=5000))
    for chunk in np.array_split(keys, 7):
        table.insert(chunk, np.stack([chunk % 97, chunk % 89], axis=1))
    assert len(table) == len(keys) and 2 * len(keys) <= len(table.keys)
    for key in [*keys[::50].tolist(), 0, 5]:
        slot = _find(table.slots, table.shift, key)
        if key in (0, 5):
            assert slot == -1
        else:
            assert table.vals[slot].tolist() == [key % 97, key % 89]


def test_goal_and_connectivity_kernels_equal_the_array_code():
    """The per-state kernels against :func:`goal_positions` and :func:`connected_within`, on small
    windows where collinear, coincident and disconnected states are common."""
    from fatline_verify.check.compiled_common import GOALS, at_goal, connected
    from fatline_verify.model.lattice import connected_within, goal_positions

    rng = np.random.default_rng(7)
    scratch = np.zeros(8, dtype=np.int64)
    for n in range(1, 9):
        states = rng.integers(0, 4, size=(300, n, 2)).astype(np.int64)
        for goal, kind in GOALS.items():
            for width in (1, 2, 4):
                want = goal_positions(states, goal, width)
                assert [at_goal(s, kind, width) for s in states] == want.tolist()
        for view2 in (1, 2, 4, 9):
            want = connected_within(states, view2)
            assert [connected(s, view2, scratch) for s in states] == want.tolist()
