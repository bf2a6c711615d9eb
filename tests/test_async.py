"""ASYNC: the transition system of the paper's theorem (events, K-step moves, stale snapshots)."""

from __future__ import annotations

import json
from dataclasses import replace
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.check.checker import check
from fatline_verify.check.engines import engine_for
from fatline_verify.check.initial import initial_array
from fatline_verify.check.search import explore
from fatline_verify.errors import InvalidInput
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import Model, load_model
from fatline_verify.model.options import Scheduler
from fatline_verify.rules.paper.algorithm import Rule
from fatline_verify.schedulers.asynchronous import AsyncCodec, async_canonical, current_positions
from fatline_verify.schedulers.systems import system_for
from fatline_verify.trace.simulate import Outcome, parse_schedule, play_schedule
from fatline_verify.trace.traces import check_replay, load_trace, run_to_json, validate, write_trace

ROOT = Path(__file__).resolve().parent.parent


def asynchronous(model: Model, K: int = 2, **options: str) -> Model:
    return replace(
        model,
        options=model.options.with_(scheduler="async", **options),
        parameters=replace(model.parameters, async_steps=K),
    )


def play(model: Model, init: tuple[tuple[int, int], ...], schedule: str):
    return play_schedule(init, model, parse_schedule(schedule, len(init), Scheduler.ASYNC, model))


# --- inclusion: every synchronous execution is an asynchronous one --------------------------------------


def _idle_keys(ex, K: int) -> set[tuple[int, ...]]:
    """Canonical positions (in base units) of the explored states where no robot is moving."""
    st = ex.states
    idle = (st[..., 0] == st[..., 2]).all(axis=1) & (st[..., 1] == st[..., 3]).all(axis=1)
    out = set()
    for row in st[idle]:
        pos = row[:, :2]
        assert (pos % K == 0).all()
        out.add(tuple(sorted(map(tuple, (pos // K).tolist()))))
    return out


@pytest.mark.parametrize("K", [1, 2])
@pytest.mark.parametrize("scheduler", ["ssync", "centralized"])
def test_synchronous_states_are_reachable_asynchronously(K, scheduler):
    """For every 3-robot initial configuration of the 6x6 window: each state a violation-free prefix of
    rounds reaches is reached by ASYNC (all active robots look, then move one after the other). ASYNC
    is explored in a larger window, steps past a violation included, since a serialisation of a clean
    round may pass through states that are not clean (a robot briefly out of view) or wider."""
    base = load_model("paper")
    sync = replace(base, options=base.options.with_(scheduler=scheduler))
    init = initial_array(3, (6, 6), base)
    s_sys = system_for(sync)
    s_ex = explore(s_sys, s_sys.initial(init), (6, 6), engine_for(s_sys, "fast"), after_violation="stop")
    a_sys = system_for(asynchronous(base, K))
    a_ex = explore(a_sys, a_sys.initial(init), (12, 12), engine_for(a_sys, "fast"), after_violation="continue")
    sync_states = {tuple(sorted(map(tuple, row.tolist()))) for row in s_ex.states}
    missing = sync_states - _idle_keys(a_ex, K)
    assert len(sync_states) > len(init)  # the synchronous search went somewhere
    assert not missing, f"{len(missing)} synchronous states never reached asynchronously, e.g. {sorted(missing)[:3]}"


# --- K = 1 vs K = 2: a robot seen halfway --------------------------------------------------------------------

HALFWAY = ((0, 0), (1, 2), (4, 0))
"""Robot 1 sees robot 0 in D and robot 2 in B: Scenario 1 to the foot of psi_right, (4, 2)."""


def test_a_robot_seen_halfway_only_when_moves_take_two_steps():
    two = asynchronous(load_model("paper"), K=2)
    run = play(two, HALFWAY, "L1;M1;L0")
    halfway = run.rounds[1].after[1]
    assert halfway == (Fraction(5, 2), 2)
    look = run.rounds[2].decisions[0]
    assert look.rule is Rule.SCENARIO_2  # robot 0 decides on robot 1 at (5/2, 2)
    assert look.destination == (Fraction(5, 2), -2)
    # With atomic moves the same events show robot 1 at its destination, and robot 0 decides as at the start.
    one = asynchronous(load_model("paper"), K=1)
    run1 = play(one, HALFWAY, "L1;M1;L0")
    assert run1.rounds[1].after[1] == (4, 2)
    assert run1.rounds[2].decisions[0].rule is Rule.SCENARIO_4_I_EMPTY
    assert play(one, HALFWAY, "L0").rounds[0].decisions[0].destination == (0, -3)
    # K = 2 states hold the halfway point; no K = 1 state can.
    two_states = explore_states(two, HALFWAY)
    one_states = explore_states(one, HALFWAY)
    assert any((5, 4) in {tuple(p) for p in row} for row in two_states)  # (5/2, 2) on the 2-fine lattice
    assert len(two_states) > len(one_states)


def explore_states(model: Model, init) -> list[np.ndarray]:
    system = system_for(model)
    arr = system.initial(np.array([init], dtype=np.int64))
    canon, _ = system.canonical(arr)
    ex = explore(system, canon, (9, 9), engine_for(system, "scalar"), max_states=100_000)
    return [system.array_positions(ex.states[i : i + 1])[0] + 0 for i in range(ex.n_states)]


# --- a stale snapshot collides ----------------------------------------------------------------------------------

STALE = ((0, 0), (2, 4), (4, 0), (5, 3))
"""Robot 1 heads straight down to (2, 1); robot 0 looks while robot 1 is halfway, at (2, 5/2)."""


def test_a_stale_snapshot_collision_replays(tmp_path):
    """Robot 0 decides on robot 1 halfway (Scenario 1, to (2, 0)); robot 1 arrives at (2, 1); robot 0's
    first step comes within 2 of robot 1 where it is now. Found by the checker at n = 4 (K = 2); no
    stale-snapshot collision exists for 3 robots in 8 events."""
    model = asynchronous(load_model("paper"), K=2)
    run = play(model, STALE, "L1;M1;L0;M1;M0")
    assert run.outcome is Outcome.VIOLATION
    last = run.rounds[-1]
    (hit,) = [v for v in last.violations if v.lemma is Lemma.NO_COLLISION]
    assert hit.robots == (0, 1) and hit.closest_dist2 == 2 < model.contact2
    looked = run.rounds[2]
    assert looked.decisions[0].rule is Rule.SCENARIO_1 and looked.decisions[0].destination == (2, 0)
    assert looked.target[0].seen[1] == (2, Fraction(5, 2))  # robot 0 decided on robot 1 halfway ...
    assert last.before[1] == (2, 1)  # ... and collides with it where it is now
    doc = json.loads(json.dumps(run_to_json(run)))
    path = tmp_path / "stale.json"
    write_trace(doc, path)
    again = check_replay(load_trace(path))
    assert again.outcome is Outcome.VIOLATION
    assert doc["rounds"][3]["moving"][0]["seen"][1] == [2, "5/2"]


def test_the_stale_decision_is_taken_on_no_view_but_the_halfway_one():
    model = asynchronous(load_model("paper"), K=2)
    before = play(model, STALE, "L0").rounds[0].decisions[0]
    after = play(model, STALE, "L1;M1;M1;L0").rounds[3].decisions[0]
    assert before.rule is after.rule is Rule.SCENARIO_4_I_EMPTY
    assert before.destination == after.destination == (0, -3)
    atomic = play(asynchronous(load_model("paper"), K=1), STALE, "L1;M1;L0").rounds[2].decisions[0]
    assert atomic.destination == (0, -3)  # with atomic moves robot 0 never sees robot 1 halfway


# --- events, motion, traces --------------------------------------------------------------------------------------


def test_non_rigid_moves_may_end_early_and_rigid_ones_not():
    paper = load_model("paper")
    loose = asynchronous(paper, K=2, motion="non-rigid")
    run = play(loose, HALFWAY, "L1;M1;S1;L1")
    assert run.rounds[2].after[1] == (Fraction(5, 2), 2)
    assert not run.rounds[2].target[1].moving
    check_replay(json.loads(json.dumps(run_to_json(run))), loose)
    with pytest.raises(InvalidInput, match="S<i> needs motion=non-rigid"):
        parse_schedule("L1;M1;S1", 3, Scheduler.ASYNC, asynchronous(paper, K=2))
    with pytest.raises(InvalidInput, match="after at least one step"):
        play(loose, HALFWAY, "L1;S1")


def test_async_traces_are_version_2_and_version_1_traces_still_replay():
    model = asynchronous(load_model("paper"))
    doc = run_to_json(play(model, HALFWAY, "L1;M1;L0;M0"))
    validate(doc)
    assert doc["version"] == 2 and doc["rounds"][0]["event"] == "look"
    assert doc["model"]["parameters"]["async_steps"] == 2 and doc["model"]["options"]["motion"] == "rigid"
    fixtures = sorted((ROOT / "tests" / "fixtures" / "traces-v1").glob("*.json"))
    assert len(fixtures) > 100
    for path in fixtures:
        old = load_trace(path)
        assert old["version"] == 1
        check_replay(old)


def test_a_round_trace_does_not_replay_as_events():
    from fatline_verify.errors import InvalidTrace

    fixture = next((ROOT / "tests" / "fixtures" / "traces-v1").glob("paper-check-connectivity-n2.json"))
    doc = load_trace(fixture)
    with pytest.raises(InvalidTrace, match="a round, but model paper has scheduler=async, which plays events"):
        check_replay(doc, asynchronous(load_model("paper")))


def test_round_options_leave_no_trace_of_async_settings():
    doc = load_model("paper")
    from fatline_verify.model.config import model_to_mapping

    mapping = model_to_mapping(doc)
    assert "async_steps" not in mapping["parameters"] and "motion" not in mapping["options"]


# --- array form -------------------------------------------------------------------------------------------------


@pytest.mark.parametrize(("n", "window", "K"), [(3, (7, 7), 2), (5, (9, 9), 2), (4, (9, 9), 3)])
def test_async_keys_round_trip_and_sort_like_the_states(n, window, K):
    rng = np.random.default_rng(n * 10 + K)
    wf, hf = (window[0] - 1) * K + 1, (window[1] - 1) * K + 1
    m = 400
    states = np.zeros((m, n, 6), dtype=np.int64)
    states[..., 0] = rng.integers(0, wf, (m, n))
    states[..., 1] = rng.integers(0, hf, (m, n))
    states[..., 2] = rng.integers(0, wf, (m, n))
    states[..., 3] = rng.integers(0, hf, (m, n))
    states[..., 4] = rng.integers(0, 3, (m, n))
    states[..., 5] = rng.integers(0, K, (m, n))
    canon, _ = async_canonical(states)
    codec = AsyncCodec(n, window, K)
    assert codec.fits(canon).all()
    keys = codec.encode(canon)
    assert np.array_equal(codec.decode(keys), canon)
    order = np.argsort(keys, kind="stable")
    as_tuples = [tuple(canon[i].ravel().tolist()) for i in range(m)]
    assert [as_tuples[i] for i in order] == sorted(as_tuples)


def test_current_positions_follow_l_shaped_paths_by_arc_length():
    # start (0,0), end (4,2) on the 2-fine lattice, horizontal first: length 6, k = 1 of 2 -> 3 along x.
    st = np.array([[[0, 0, 4, 2, 1, 1]]], dtype=np.int64)
    pos, exact = current_positions(st, 2)
    assert pos[0, 0].tolist() == [3, 0] and exact.all()
    st = np.array([[[0, 0, 4, 2, 2, 1]]], dtype=np.int64)  # vertical first: 2 up, then 1 along x
    pos, _ = current_positions(st, 2)
    assert pos[0, 0].tolist() == [1, 2]
    st = np.array([[[0, 0, 1, 0, 0, 1]]], dtype=np.int64)  # straight, 1/2 of one fine unit: off the lattice
    _, exact = current_positions(st, 2)
    assert not exact.any()


# --- the checker speaks ASYNC ---------------------------------------------------------------------------------


def test_check_gives_async_verdicts_with_replayed_witnesses():
    model = asynchronous(load_model("paper"))
    result = check(model, (2, 3), (7, 7))
    verdicts = {(r.lemma, r.robots): r.verdict for r in result.results}
    assert verdicts[(Lemma.NO_COLLISION, 3)] is Verdict.VIOLATED
    for r in result.results:
        if r.witness is not None:
            assert r.witness["version"] == 2
            assert all("event" in step for step in r.witness["rounds"])
            check_replay(json.loads(json.dumps(r.witness)), model)
    assert result.stats[1].states > check(load_model("paper"), (3, 3), (7, 7)).stats[0].states


def test_the_shipped_stale_snapshot_trace_replays_under_paper_async_and_not_under_paper():
    from fatline_verify.errors import InvalidTrace

    path = ROOT / "tests" / "fixtures" / "async" / "paper-async-stale-snapshot-collision-n4.json"
    doc = load_trace(path)
    run = check_replay(doc)
    assert run.outcome is Outcome.VIOLATION and doc["violation"]["property"] == Lemma.NO_COLLISION
    assert check_replay(doc, load_model("paper-async")).outcome is Outcome.VIOLATION
    with pytest.raises(InvalidTrace, match="which plays rounds; expected a model with scheduler=async"):
        check_replay(doc, load_model("paper"))
