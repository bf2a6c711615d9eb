"""The named repairs (``fatline_verify/rules/repaired/algorithm.py``): each does what its docstring says, the paper's
models are untouched by their existence, and the repaired rule set keeps the safety lemmas on every
round of random swarms (beyond the checker's window)."""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from fatline_verify.model.config import load_model, model_to_mapping, shipped_models
from fatline_verify.model.geometry import path_point_dist2
from fatline_verify.model.options import CATALOGUE, Options
from fatline_verify.model.swarm import is_connected
from fatline_verify.rules.paper.algorithm import Rule, paper_decide
from fatline_verify.rules.registry import decide
from fatline_verify.rules.repaired.algorithm import Leg, allowed, leg_of
from fatline_verify.schedulers.round import play_round
from fatline_verify.schedulers.round import snapshot as view_of
from tests.conftest import make_model

REPAIRED = {name: str(spec.enum(list(spec.readings)[1])) for name, spec in CATALOGUE.items() if spec.repair}
"""Every repair on (each has one reading besides ``off``)."""


def repaired(q: int = 1, **more: str):
    return make_model(q=q, uncovered="search-both", **{**REPAIRED, **more})


def test_every_repair_is_off_by_default_and_left_out_of_the_paper_s_models():
    assert REPAIRED and all(str(getattr(Options(), name)) == "off" for name in REPAIRED)
    for path in shipped_models():
        model = load_model(path)
        keys = set(model_to_mapping(model)["options"])
        assert bool(keys & set(REPAIRED)) == model.options.repaired == (path.stem == "repaired")
    assert set(Options().with_(repair_step="unit").as_dict()) - set(Options().as_dict()) == {"repair_step"}


def test_the_paper_s_decisions_do_not_change():
    model = make_model()
    for snapshot in [((4, 0),), ((0, 3), (3, 0)), ((-1, 3), (3, 0)), ((1, 2),)]:
        assert decide(snapshot, model) == paper_decide(snapshot, model)


def test_the_lock_holds_a_robot_that_sees_one_strictly_left():
    snapshot = ((-1, 3), (3, 1))  # (-1, 3) is in A (not E: |x| < 2), so the paper moves r
    assert paper_decide(snapshot, repaired()).moves
    assert decide(snapshot, repaired()).rule is Rule.REPAIR_LOCK


def test_a_step_is_one_radius_along_one_axis():
    for q in (1, 2):
        model = repaired(q)
        far = paper_decide(((3 * q, 2 * q),), model)  # Scenario 1: to the foot of psi_right
        assert far.rule is Rule.SCENARIO_1 and far.destination == (3 * q, 0)
        got = decide(((3 * q, 2 * q),), model)
        assert got.rule is Rule.SCENARIO_1 and got.destination == (q, 0) and got.path == ((0, 0), (q, 0))


def test_a_leg_through_a_visible_robot_is_refused():
    model = repaired(repair_lock="off", repair_step="off", repair_edges="off")
    snapshot = ((-1, -3), (2, -1))  # the search finds (2, -3); the straight path passes sqrt(2) from (2, -1)
    paper = paper_decide(snapshot, model)
    assert paper.rule is Rule.UNCOVERED_SEARCH and paper.destination == (2, -3)
    assert decide(snapshot, model).rule is Rule.REPAIR_BLOCKED
    assert decide(((3, 2),), model).destination == (3, 0)  # Scenario 1 with nothing in the way: as the paper


def test_the_scenario_4_drop_that_loses_the_other_robot_becomes_an_approach():
    # Two robots 4 apart on a horizontal: the paper drops r by rad_v - 1 = 3 and the edge is lost.
    paper, fixed = make_model(uncovered="search-both"), repaired()
    state = ((0, 0), (4, 0))
    before = play_round(state, [0], paper)
    assert before.decisions[0].destination == (0, -3) and not is_connected(before.after, paper)
    after = play_round(state, [0], fixed)
    assert after.decisions[0].rule is Rule.REPAIR_APPROACH and after.decisions[0].destination == (1, 0)
    assert not after.violations


def test_robots_in_each_other_s_bands_align_instead_of_deadlocking():
    state = ((0, 0), (1, 2))  # each sees only A or I: the paper's NoMovement, and no line
    assert paper_decide(((1, 2),), make_model()).rule is Rule.ONLY_AI
    got = decide(((1, 2),), repaired())
    assert got.rule is Rule.REPAIR_ALIGN and got.destination == (1, 0)
    assert not play_round(state, [0, 1], repaired()).violations


def test_a_stack_contracts_from_the_top_and_the_bottom():
    assert decide(((0, -4),), repaired()).destination == (0, -1)  # the top comes down
    assert decide(((0, 4),), repaired()).destination == (0, 1)  # the bottom goes up, 3 short of the other
    assert not decide(((0, 3),), repaired()).moves  # 3 apart: the bottom waits for the top


def test_the_prover_proves_the_repaired_collision_lemma_for_every_swarm_size(capsys, tmp_path):
    """``fatline prove repaired``: its move family's leg obligations and the views row come out PROVED, exit 0."""
    from fatline_verify.cli import main

    assert main(["prove", "repaired", "--lemma", "no-collision", "--out", str(tmp_path / "p"), "-q"]) == 0
    out = capsys.readouterr().out
    assert "no-collision: 10 obligations: 10 PROVED" in out and "no-collision: PROVED" in out
    assert len(list((tmp_path / "p" / "repaired" / "no-collision").glob("*.smt2"))) == 9


@st.composite
def swarms(draw):
    """A connected swarm of 2-6 non-overlapping robots on the lattice q = 1 or 2, grown one robot at a
    time within view of an earlier one, and a non-empty set of robots to activate."""
    q = draw(st.sampled_from([1, 2]))
    model = repaired(q)
    near = [
        (x, y)
        for x in range(-model.view, model.view + 1)
        for y in range(-model.view, model.view + 1)
        if model.contact2 <= x * x + y * y and model.sees(x * x + y * y)
    ]
    state = [(0, 0)]
    for _ in range(draw(st.integers(1, 5))):
        base = draw(st.sampled_from(state))
        dx, dy = draw(st.sampled_from(near))
        new = (base[0] + dx, base[1] + dy)
        if all((new[0] - a) ** 2 + (new[1] - b) ** 2 >= model.contact2 for a, b in state):
            state.append(new)
    n = len(state)
    active = draw(st.lists(st.integers(0, n - 1), min_size=1, max_size=n, unique=True))
    return q, tuple(state), active


@pytest.mark.parametrize("progress", ["detour", "corner"])
@settings(max_examples=400, deadline=None)
@given(swarms())
def test_a_repaired_round_never_collides_or_disconnects_and_keeps_the_rma(progress, case):
    """The safety argument of repairs.py on any swarm (not only initial ones, not only in the window):
    discs apart and the graph connected before, then after any activation neither a collision, nor a
    split, nor a move past the right-most axis. Corner legs (not proved) are held to the same test."""
    q, state, active = case
    model = repaired(q, repair_progress=progress)
    assume(len(state) > 1)
    assert is_connected(state, model)
    result = play_round(state, active, model)
    assert not result.violations, (state, active, result.violations)
    MOVED.append(sum(result.decisions[i].moves for i in active))


MOVED: list[int] = []
"""Movers per round the property test played (the next test checks the property was exercised)."""


def test_the_random_rounds_moved_robots_and_several_at_once():
    if not MOVED:
        pytest.skip("run with the property test")
    assert sum(m > 0 for m in MOVED) > len(MOVED) // 4
    assert any(m > 1 for m in MOVED)


def test_the_detour_moves_the_blocked_robot_of_the_three_robot_deadlock():
    """``repair_progress = detour``: in (0, 1) (1, 4) (2, 0) the only unlocked robot, (0, 1), has its
    leg right refused by clearance with (2, 0) and its leg down by the edge to (1, 4); without the
    option it stays (a deadlock), with it it takes one radius up (a top leg), and the round is safe."""
    state = ((0, 1), (1, 4), (2, 0))
    before = play_round(state, [0], repaired(repair_progress="off"))
    assert before.decisions[0].rule is Rule.REPAIR_BLOCKED
    after = play_round(state, [0], repaired())
    assert after.decisions[0].rule is Rule.REPAIR_DETOUR and after.decisions[0].destination == (0, 1)
    assert not after.violations


def test_the_detour_needs_the_repairs_its_legs_rest_on():
    snapshot = ((1, 3), (2, -1))
    assert decide(snapshot, repaired()).rule is Rule.REPAIR_DETOUR
    assert decide(snapshot, repaired(repair_edges="off")).rule is not Rule.REPAIR_DETOUR


SQUARE = ((0, 0), (0, 4), (4, 0), (4, 4))
"""Side ``rad_v``: each robot on the left vertical holds an edge of length ``rad_v`` up or down its
vertical and one to the right; every one-axis leg lengthens one of them."""


def test_the_square_of_side_rad_v_deadlocks_with_one_axis_legs_and_a_corner_leg_moves_it():
    stuck = play_round(SQUARE, [0, 1, 2, 3], repaired())
    assert not any(d.moves for d in stuck.decisions.values())
    moved = play_round(SQUARE, [0, 1, 2, 3], repaired(repair_progress="corner"))
    movers = {i: d for i, d in moved.decisions.items() if d.moves}
    assert movers and all(state[0] == 0 for state in (SQUARE[i] for i in movers))
    top = movers[1]
    assert top.rule is Rule.REPAIR_DETOUR and top.destination == (1, -1)
    assert leg_of(top.destination, view_of(SQUARE, 1, repaired())) is Leg.TOP_CORNER
    assert not moved.violations


def test_a_corner_leg_is_refused_where_a_robot_on_r_s_vertical_moving_right_would_meet_it():
    """At q = 4, the top (0, 0) with (0, -11/4) below it: its corner leg to (1, -1) clears the robot
    at rest (distance sqrt(65)/4 > 2), not the robot's own move right to (1, -11/4) (7/4 < 2)."""
    model = repaired(4, repair_progress="corner", repair_edges="off")
    below, end = (0, -11), (4, -4)
    assert path_point_dist2(((0, 0), end), below) >= model.contact2
    assert not allowed(end, ((0, 0), end), (below,), model)
    assert allowed(end, ((0, 0), end), ((0, -13),), model)  # 9/4 from the move right
