"""The certified rule set (``fatline_verify/rules/certified/``, issue 32): its golden verdicts, one
decision per rule, the soundness of the regions its safety argument rests on, the lattice argument for
movers that do not see each other, random rounds beyond the window, and the corpus under it."""

from __future__ import annotations

import itertools
import json
from collections import Counter
from dataclasses import replace
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from fatline_verify.check.checker import check
from fatline_verify.errors import FatlineError
from fatline_verify.lemmas.properties import SAFETY, Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.model.geometry import dist2, path_point_dist2, segment_segment_dist2
from fatline_verify.model.swarm import is_connected
from fatline_verify.repair.against import GONE_ON_ITS_ROUNDS, corpus_against
from fatline_verify.rules import registry
from fatline_verify.rules.certified.algorithm import LABELS, decide, region
from fatline_verify.schedulers.round import decide_all, play_round, snapshot
from fatline_verify.trace.traces import load_trace, replay, run_to_json

ROOT = Path(__file__).resolve().parent.parent
CORPUS = sorted((ROOT / "reports" / "traces").glob("*.json"))
MODEL = load_model("certified")


def certified(q: int = 1, scheduler: str = "ssync"):
    model = MODEL.with_q(q)
    return model if scheduler == "ssync" else replace(model, options=model.options.with_(scheduler=scheduler))


def verdicts(result) -> dict[tuple[str, int], str]:
    return {(r.lemma.value, r.robots): r.verdict.value for r in result.results}


# --- the rule set is registered as its own -------------------------------------------------------


def test_the_model_names_the_certified_rule_set_without_a_prover_encoding():
    rule_set = registry.get("certified")
    assert MODEL.rules == "certified" and rule_set.prover is None and not rule_set.options
    assert set(rule_set.labels) == set(LABELS)


def test_prove_takes_the_certified_rule_set_by_its_move_family():
    """No case encoding of its own (prover=None): fatline prove decides its move family's obligations
    (tests/test_certified_family.py) and nothing else (no liveness declared, no rma-fixed or approach rows)."""
    from fatline_verify.prove.smt.family import FamilySpec
    from fatline_verify.prove.tasks import ViewsSpec, encoding_name, tasks_for

    tasks = tasks_for(MODEL)
    assert encoding_name(MODEL) == "family"
    assert tasks and all(isinstance(t, FamilySpec | ViewsSpec) for t in tasks)


# --- golden verdicts -----------------------------------------------------------------------------


@pytest.mark.parametrize("q", [1, 2])
def test_every_lemma_holds_for_2_and_3_robots_and_nothing_escapes(q):
    """The small bounds (seconds): 2 and 3 robots in the 9x9 window, explored within 20x20."""
    result = check(certified(q), (2, 3), (9, 9), bound=(20, 20))
    assert set(verdicts(result).values()) == {Verdict.HOLDS_WITHIN_BOUNDS.value}
    assert all(s.escaped == 0 and not s.truncated for s in result.stats)


@pytest.mark.slow
@pytest.mark.parametrize(("q", "robots", "live_up_to"), [(1, (2, 5), 4), (2, (2, 4), 3)])
@pytest.mark.parametrize("scheduler", ["ssync", "centralized", "fsync"])
def test_the_full_bounds(q, robots, live_up_to, scheduler):
    """2..5 robots at q = 1, 2..4 at q = 2 (9x9, bound 20x20): safety holds throughout and nothing
    escapes; every lemma holds up to 4 robots (q = 1) and 3 (q = 2); at the largest count liveness
    fails by reachable deadlocks, none of them an initial configuration (README, "A live rule set?")."""
    result = check(certified(q, scheduler), robots, (9, 9), bound=(20, 20))
    got = verdicts(result)
    assert all(s.escaped == 0 and not s.truncated for s in result.stats)
    for (lemma, n), verdict in got.items():
        live = n <= live_up_to or Lemma(lemma) in SAFETY
        assert verdict == (Verdict.HOLDS_WITHIN_BOUNDS.value if live else Verdict.VIOLATED.value), (lemma, n)
    for r in result.results:
        if r.verdict is Verdict.VIOLATED:
            assert r.witness is not None and r.witness_rounds  # replayed; none starts stuck


# --- one decision per rule (q = 1 unless said; the robot at the origin, what it sees relative) ----

CASES = [
    (1, (), "alone", (0, 0)),
    # a robot 3 right and 2 up: one radius right, toward the greatest x it sees
    (1, ((3, 2),), "right", (1, 0)),
    # (2, 1) is in the way of a step right: one unit right and down
    (1, ((2, 1),), "down-right", (1, -1)),
    # (2, -1) is in the way right and down-right: right and up
    (1, ((2, -1),), "up-right", (1, 1)),
    # (2, 1) ahead within two radii of its height blocks every step right; (-3, -2), the robot on the
    # left, is stuck (its moves meet r): r falls, still seeing (2, 1)
    (1, ((-3, -2), (2, 1)), "fall", (0, -1)),
    # sees nothing right; (-2, -3) is more than two radii below on the left: down toward it
    (1, ((-2, -3), (-2, -1)), "close-in", (0, -1)),
    (2, ((-1, -6),), "close-in", (0, -1)),
    # sees nothing right, the robot below on its vertical 4 radii down: down to 3
    (1, ((0, -4),), "contract-down", (0, -1)),
    # sees only its vertical, the robot above 4 radii up: up to 2 (it parks)
    (1, ((0, 4),), "contract-up", (0, 1)),
    # sees nothing right; (-1, 2), up on the left, would meet r stepping right: r makes room
    (1, ((-1, 2),), "make-room", (0, -1)),
    # (-3, -1) may move (right), and nothing r could do clears every move it may make
    (1, ((-3, -1),), "lock", (0, 0)),
    # only the robot 3 below on its vertical: nothing to do (3 is the contraction's gap)
    (1, ((0, -3),), "blocked", (0, 0)),
]


@pytest.mark.parametrize(("q", "seen", "rule", "step"), CASES, ids=lambda v: v if isinstance(v, str) else None)
def test_each_rule_on_a_hand_case(q, seen, rule, step):
    decision = decide(seen, certified(q))
    assert (decision.rule, decision.destination) == (rule, step)
    assert decision.path == (((0, 0), step) if step != (0, 0) else ((0, 0),))


def test_every_rule_has_a_hand_case():
    assert {rule for _, _, rule, _ in CASES} == set(LABELS)


def test_a_robot_that_sees_nothing_right_of_it_never_moves_sideways():
    """It may be on the right-most vertical: every decision on snapshots without a robot right of the
    observer keeps x (rma-fixed at any size)."""
    model = certified(1)
    view = [(x, y) for x in range(-4, 1) for y in range(-4, 5) if 4 <= x * x + y * y <= 16]
    for k in (1, 2):
        for seen in itertools.combinations(view, k):
            if k == 2 and (seen[0][0] - seen[1][0]) ** 2 + (seen[0][1] - seen[1][1]) ** 2 < 4:
                continue
            assert decide(seen, model).destination[0] == 0, seen


# --- random swarms: the region is sound, rounds are safe (beyond the window) ---------------------


@st.composite
def swarms(draw):
    """A connected swarm of 2-6 robots at least two radii apart on the lattice q = 1 or 2, grown one
    robot at a time within view of an earlier one, and a non-empty set of robots to activate."""
    q = draw(st.sampled_from([1, 2]))
    model = certified(q)
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
    active = draw(st.lists(st.integers(0, len(state) - 1), min_size=1, max_size=len(state), unique=True))
    return q, tuple(state), active


@settings(max_examples=300, deadline=None)
@given(swarms())
def test_every_decision_is_in_every_observer_s_region_of_it(case):
    """The safety argument rests on :func:`region`: what a robot estimates another might do is a
    superset of what that robot's rules give it. Every pair of robots that see each other, any swarm."""
    q, state, _ = case
    model = certified(q)
    decisions = decide_all(state, model)
    for i, j in itertools.permutations(range(len(state)), 2):
        seen = snapshot(state, i, model)
        c = (state[j][0] - state[i][0], state[j][1] - state[i][1])
        if c not in seen:
            continue
        end = (c[0] + decisions[j].destination[0], c[1] + decisions[j].destination[1])
        assert end == c or end in [e for _, e in region(c, seen, model)], (state, i, j, decisions[j].rule)


@settings(max_examples=300, deadline=None)
@given(swarms())
def test_every_decision_keeps_the_moves_the_argument_allows(case):
    """Right never past the greatest x seen, never left, never sideways without a robot right of it;
    at most one radius along an axis or one lattice unit along each; clear of every robot seen."""
    q, state, _ = case
    model = certified(q)
    rho = model.radius
    for i, d in decide_all(state, model).items():
        seen = snapshot(state, i, model)
        dx, dy = d.destination
        right = max([0, *(c[0] for c in seen)])
        assert 0 <= dx <= min(rho, right) and abs(dy) <= rho
        assert not (dx and dy) or (dx, abs(dy)) == (1, 1)
        if d.moves:
            assert all(path_point_dist2(d.path, c) >= model.contact2 for c in seen)


ROUNDS: list[int] = []


@settings(max_examples=400, deadline=None)
@given(swarms())
def test_a_round_never_collides_or_disconnects_and_keeps_the_rma(case):
    """Any swarm (not only the checker's, not only in its window), any activation: no collision, no
    split, no move past or off the right-most vertical."""
    q, state, active = case
    model = certified(q)
    assume(len(state) > 1)
    assert is_connected(state, model)
    result = play_round(state, active, model)
    assert not result.violations, (state, active, result.violations)
    ROUNDS.append(sum(result.decisions[i].moves for i in active))


def test_the_random_rounds_moved_robots_and_several_at_once():
    if not ROUNDS:
        pytest.skip("run with the property test")
    assert sum(m > 0 for m in ROUNDS) > len(ROUNDS) // 4
    assert any(m > 1 for m in ROUNDS)


def test_off_the_lattice_two_movers_out_of_view_collide():
    """The argument for movers out of view holds on the lattice only: at quarter radii (off the lattice
    q = 1) r0 contracts up and r1, out of its view, steps down-right into it; r2 keeps r0 from being alone.
    The configuration is a legal start (connected, discs apart), and the executable model plays the round."""
    model = certified(1)
    state = ((Fraction(0), Fraction(0)), (Fraction(-5, 2), Fraction(13, 4)), (Fraction(0), Fraction(29, 8)))
    assert is_connected(state, model) and not model.sees(dist2(state[0], state[1]))
    result = play_round(state, (0, 1), model)
    assert [d.rule for d in (result.decisions[0], result.decisions[1])] == ["contract-up", "down-right"]
    assert {v.lemma for v in result.violations} == {Lemma.NO_COLLISION}


def test_two_movers_that_do_not_see_each_other_never_meet_on_the_unit_lattice():
    """The argument for movers more than rad_v apart at q = 1, where a diagonal step is sqrt(2) radii
    long: every pair of steps the rules make, from every offset out of view (squared distance 17 to
    40: farther is out of reach), keeps the two paths at least two radii apart (touching allowed)."""
    model = certified(1)
    steps = [(0, 0), (1, 0), (1, 1), (1, -1), (0, -1), (0, 1)]
    closest = min(
        segment_segment_dist2((0, 0), a, (dx, dy), (dx + b[0], dy + b[1]))
        for dx in range(-7, 8)
        for dy in range(-7, 8)
        if not model.sees(dx * dx + dy * dy)
        for a in steps
        for b in steps
    )
    assert closest == model.contact2


# --- the corpus under the certified rules --------------------------------------------------------


def test_every_corpus_counterexample_is_gone_on_its_own_rounds():
    """Each counterexample of the shipped corpus replayed under certified (`fatline replay --model`):
    its lemma is no longer violated. What remains is the prover's refinement connectivity-edge (an
    edge lost while the swarm stays connected, which the certified rules allow: they bridge edges),
    and ASYNC traces, which play under certified with scheduler = async (two no longer play: the
    robot they move first stays under certified)."""
    rounds, events = certified(), certified(scheduler="async")
    tally: Counter[str] = Counter()
    for path in CORPUS:
        doc = load_trace(path)
        if _points(doc):
            continue  # a published algorithm's point robots: no configuration of the certified rules' discs
        recorded = (doc.get("violation") or {}).get("property")
        asynchronous = any("event" in r for r in doc["rounds"])
        try:
            again = run_to_json(replay(doc, events if asynchronous else rounds), focus=recorded)
        except FatlineError:
            assert asynchronous, path.name
            tally["not playable"] += 1
            continue
        still = (again["violation"] or {}).get("property")
        if recorded is None:
            tally["no violation recorded"] += 1
        elif still is None:
            tally["gone"] += 1
        else:
            assert still == recorded == "connectivity-edge", path.name
            tally["connectivity-edge"] += 1
    # every trace gone but the 23 edge refinements and the 2 ASYNC traces (the corpus grows with fatline report)
    discs = [p for p in CORPUS if not _points(load_trace(p))]
    assert tally == {"gone": len(discs) - 25, "connectivity-edge": 23, "not playable": 2}, tally


def _points(doc: dict) -> bool:
    """Whether a trace is of point robots (a rule set declaring ``robots="points"``)."""
    from fatline_verify.model.config import model_from_mapping
    from fatline_verify.rules import registry

    return registry.of(model_from_mapping(doc["model"], default_name="trace")).robots == "points"


@pytest.mark.slow
def test_every_corpus_configuration_explored_under_the_certified_rules():
    """Every activation from each counterexample's initial configuration, under its own scheduler
    (fatline_verify/repair/against.py): the lemma holds within bounds or is gone on its own rounds,
    except two ASYNC configurations of 4 robots: the certified rules are not ASYNC-safe."""
    rows = corpus_against(MODEL, ROOT / "reports" / "traces")
    counts = Counter(r.verdict for r in rows)
    assert counts == {Verdict.HOLDS_WITHIN_BOUNDS.value: 293, GONE_ON_ITS_ROUNDS: 90, Verdict.VIOLATED.value: 2}
    assert {(r.scheduler, r.robots) for r in rows if r.verdict == Verdict.VIOLATED.value} == {("async", 4)}


def test_the_certified_report_holds_every_lemma_at_its_bounds():
    data = json.loads((ROOT / "reports" / "certified" / "check.json").read_text())
    assert {row["verdict"] for row in data["lemmas"]} == {Verdict.HOLDS_WITHIN_BOUNDS.value}
