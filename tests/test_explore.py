"""The exploration: initial configurations three ways, engines against each other, keys, witnesses."""

from __future__ import annotations

import json

import numpy as np
import pytest

from fatline_verify.check.checker import check
from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import count_by_brute_force, initial_array, initial_configurations
from fatline_verify.check.search import explore
from fatline_verify.model.config import load_model
from fatline_verify.model.lattice import KeyCodec, canonical
from fatline_verify.schedulers.systems import system_for
from fatline_verify.trace.traces import check_replay
from tests.conftest import make_model


@pytest.mark.parametrize(
    ("n", "w", "readings"), [(2, 5, {}), (3, 5, {}), (3, 6, {"visibility": "any-part"}), (4, 5, {})]
)
def test_initial_configurations_three_ways(n, w, readings):
    model = make_model(**readings)
    redelmeier = list(initial_configurations(n, (w, w), model))
    assert len(redelmeier) == len(set(redelmeier))
    vectorised = {tuple(map(tuple, s.tolist())) for s in initial_array(n, (w, w), model)}
    assert set(redelmeier) == vectorised
    assert len(vectorised) == count_by_brute_force(n, (w, w), model)


def test_initial_configurations_are_canonical_and_valid():
    model = make_model()
    from fatline_verify.model.swarm import initial_problems

    for s in initial_array(3, (6, 6), model):
        state = tuple(map(tuple, s.tolist()))
        assert min(p[0] for p in state) == 0 and min(p[1] for p in state) == 0
        assert list(state) == sorted(state)
        assert initial_problems(state, model) == []


def test_key_codec_round_trip_and_canonical_form():
    codec = KeyCodec(3, (9, 9))
    states = np.array([[[5, 5], [2, 7], [8, 5]], [[0, 0], [3, 0], [0, 3]]])
    canon, order = canonical(states)
    assert canon[0].tolist() == [[0, 2], [3, 0], [6, 0]]  # shifted by (2, 5), sorted by (x, y)
    assert order[0].tolist() == [1, 0, 2]
    assert np.array_equal(codec.decode(codec.encode(canon)), canon)


FIELDS = [
    "keys",
    "parent",
    "parent_action",
    "depth",
    "enabled",
    "goal",
    "edge_src",
    "edge_dst",
    "edge_action",
    "edge_flags",
    "edge_fits",
    "edge_exact",
]

READINGS = [
    {},
    {"scheduler": "fsync"},
    {"scheduler": "centralized"},
    {"timing": "lockstep"},
    {"contact": "strict", "vacant": "strict"},
    {"path": "horizontal-then-vertical"},
    {"path": "vertical-then-horizontal", "timing": "lockstep"},
    {"quadrants": "literal", "goal": "any-line"},
    {"goal": "line-meets-discs"},
    {"uncovered": "search-both", "scenario4_drop": "touch"},
    {"uncovered": "stay", "scenario4_guard": "all-three-full"},
    {"visibility": "any-part", "bands": "centre"},
    {"psi_right": "touch-line", "scenario4_free_path": "on"},
    {"search_bound": "unbounded", "scenario4_drop": "proofs"},
]


@pytest.mark.parametrize(
    "readings", READINGS, ids=[",".join(f"{k}={v}" for k, v in r.items()) or "default" for r in READINGS]
)
def test_fast_engine_equals_scalar_engine(readings):
    model = make_model(**readings)
    for n, w in [(2, 6), (3, 6)]:
        system = system_for(model)
        init = system.initial(initial_array(n, (w, w), model))
        a = explore(system, init, (w, w), engine_for(system, "scalar"))
        b = explore(system, init, (w, w), engine_for(system, "fast"))
        for f in FIELDS:
            assert np.array_equal(getattr(a, f), getattr(b, f)), f


def test_engines_agree_on_verdicts_and_witness_lengths_for_four_robots():
    model = load_model("paper")
    fast = check(model, (4, 4), (6, 6), engine="fast")
    scalar = check(model, (4, 4), (6, 6), engine="scalar")
    assert [(r.lemma, r.verdict, r.witness_rounds) for r in fast.results] == [
        (r.lemma, r.verdict, r.witness_rounds) for r in scalar.results
    ]
    assert fast.stats[0].states == scalar.stats[0].states


def test_after_violation_continue_explores_more():
    model = load_model("paper")
    stop = check(model, (3, 3), (6, 6))
    cont = check(model, (3, 3), (6, 6), after_violation="continue")
    assert cont.stats[0].states > stop.stats[0].states
    assert cont.stats[0].violating_only == 0


def test_every_witness_is_shortest_and_replays():
    model = load_model("paper")
    result = check(model, (2, 3), (7, 7))
    for r in result.results:
        if r.witness is not None:
            check_replay(json.loads(json.dumps(r.witness)), model)
            assert r.witness_rounds == len(r.witness["rounds"])
    # The 2-robot connectivity witness: one robot drops out of view in the first round.
    conn = next(r for r in result.results if r.lemma.value == "connectivity" and r.robots == 2)
    assert conn.witness_rounds == 1


def test_max_states_makes_liveness_inconclusive():
    model = load_model("paper")
    result = check(model, (3, 3), (7, 7), max_states=10)
    assert result.stats[0].truncated
    verdicts = {r.lemma.value: r.verdict.value for r in result.results}
    assert verdicts["rma-fixed"] == "INCONCLUSIVE"  # no violation seen, but the search was cut short


@pytest.mark.parametrize("readings", [{}, {"timing": "lockstep", "path": "vertical-then-horizontal"}])
def test_collision_words_equal_the_general_table(readings):
    """The 64-bit collision words (n <= 6) and the general (m, 2^n) table used beyond agree."""
    model = make_model(**readings)
    engine = engine_for(system_for(model), "fast")
    states = initial_array(4, (6, 6), model)
    dest, corner = engine._destinations(states)
    words = engine._collision_words(states, dest, corner)
    table = engine._collisions_by_mask(states, dest, corner)
    bits = ((words[:, None] >> np.arange(16, dtype=np.uint64)[None, :]) & np.uint64(1)).astype(bool)
    assert np.array_equal(bits, table)
    assert table.any()  # some activation set collides, so the comparison is not vacuous
