"""Every NoMovement bullet, every Scenario and every reading of every algorithm option, on a
hand-made configuration where the reading changes the outcome. Expected values are worked out by
hand from the paper's text under that reading (the derivation is in each row's comment).

Snapshots are relative to the observer r at the origin; rad_v = 4, one radius = 1 unless stated.
"""

from __future__ import annotations

from fractions import Fraction as Fr

import pytest

from fatline_verify.rules.paper.algorithm import Band, Case, Rule, classify, free_path, vacancy_blocker
from fatline_verify.rules.registry import decide
from tests.conftest import make_model

A, B, C, D, E, F, G, I = (Band(x) for x in "ABCDEFGI")  # noqa: E741 - the paper's set names


def sets_of(decision, point):
    return {m for c, m in decision.classification if c == point}.pop()


REPAIRED = {
    "uncovered": "search-both",
    "repair_lock": "left-first",
    "repair_stack": "align",
    "repair_approach": "on",
    "repair_step": "unit",
    "repair_clear": "on",
    "repair_edges": "on",
}
"""models/repaired.toml's choices."""

# (id, readings, rad_v, snapshot, expected rule, expected destination, expected case)
CASES = [
    # NoMovement bullets, in the paper's order.
    ("nm1-alone", {}, 4, [], Rule.ALONE, (0, 0), None),
    ("nm2-F", {}, 4, [(-3, 0)], Rule.F_NONEMPTY, (0, 0), None),
    # (-3,3) is upper-left: E under quadrants=lower-right; it blocks although C has a robot.
    ("nm3-EFG", {}, 4, [(-3, 3), (3, 0)], Rule.EFG_NONEMPTY, (0, 0), None),
    ("nm4-only-AI", {}, 4, [(0, 3), (1, -3)], Rule.ONLY_AI, (0, 0), None),
    # Scenario 1: (3,3) in B, R_psi n C empty -> (x_psi, 0).
    ("scenario-1", {}, 4, [(3, 3)], Rule.SCENARIO_1, (3, 0), None),
    # Scenario 2: C robot (3,0), B robot (3,3): search down; (3,-1) is 1 from (3,0), (3,-2) is 2: vacant.
    ("scenario-2", {}, 4, [(3, 0), (3, 3)], Rule.SCENARIO_2, (3, -2), None),
    # Scenario 3 mirrors it: D robot (3,-3): search up to (3,2).
    ("scenario-3", {}, 4, [(3, 0), (3, -3)], Rule.SCENARIO_3, (3, 2), None),
    # Scenario 4, I empty: a lone C robot is an uncovered case (R n B, R n D both empty): y = -rad_v + 1.
    ("scenario-4-I-empty", {}, 4, [(3, 0)], Rule.SCENARIO_4_I_EMPTY, (0, -3), Case.UNCOVERED),
    # Scenario 4, I non-empty: top of I at y=-3, d=3, y_p = -d + 1 = -2.
    ("scenario-4-I-nonempty", {}, 4, [(3, 0), (0, -3)], Rule.SCENARIO_4_I_NONEMPTY, (0, -2), Case.UNCOVERED),
    # quadrants: (-3,3) is D (second quadrant) under literal: psi = -3 and r moves LEFT (Scenario 1).
    ("quadrants=literal Q2 is D", {"quadrants": "literal"}, 4, [(-3, 3)], Rule.SCENARIO_1, (-3, 0), None),
    # (3,-3) is G (fourth quadrant) under literal: r stays; under the default it is D (Scenario 1).
    ("quadrants=literal Q4 is G", {"quadrants": "literal"}, 4, [(3, -3)], Rule.EFG_NONEMPTY, (0, 0), None),
    ("quadrants=lower-right Q4 is D", {}, 4, [(3, -3)], Rule.SCENARIO_1, (3, 0), None),
    # bands: (3/2, 3) meets the strip |X| <= 1 (disc reading: A, r stays) but its centre is outside
    # it (centre reading: B, Scenario 1 to (3/2, 0)).
    ("bands=disc", {}, 4, [(Fr(3, 2), 3)], Rule.ONLY_AI, (0, 0), None),
    ("bands=centre", {"bands": "centre"}, 4, [(Fr(3, 2), 3)], Rule.SCENARIO_1, (Fr(3, 2), 0), None),
    # band_overlap: (3/2,-3/2) meets the I and the C strip.
    # both: C makes psi = 3/2, uncovered -> Scenario 4 with I = {it}: y = -3/2 + 1 = -1/2.
    ("band_overlap=both", {}, 4, [(Fr(3, 2), Fr(-3, 2))], Rule.SCENARIO_4_I_NONEMPTY, (0, Fr(-1, 2)), Case.UNCOVERED),
    # horizontal-first: C only, I empty: y = -rad_v + 1 = -3.
    (
        "band_overlap=horizontal-first",
        {"band_overlap": "horizontal-first"},
        4,
        [(Fr(3, 2), Fr(-3, 2))],
        Rule.SCENARIO_4_I_EMPTY,
        (0, -3),
        Case.UNCOVERED,
    ),
    # vertical-first: I only: NoMovement bullet 4.
    (
        "band_overlap=vertical-first",
        {"band_overlap": "vertical-first"},
        4,
        [(Fr(3, 2), Fr(-3, 2))],
        Rule.ONLY_AI,
        (0, 0),
        None,
    ),
    # psi_right: (3,3) in B: centre-line x=3, touch-line x=2.
    ("psi_right=touch-line", {"psi_right": "touch-line"}, 4, [(3, 3)], Rule.SCENARIO_1, (2, 0), None),
    # r_psi: B (2,3) gives psi = 2; C robot (7/2, 0) is 3/2 from psi: in R_psi under disc (Scenario 2,
    # (2,-1) blocked at squared distance 2, (2,-2) vacant), not under centre (Scenario 1).
    ("r_psi=follows-bands(disc)", {}, 4, [(2, 3), (Fr(7, 2), 0)], Rule.SCENARIO_2, (2, -2), None),
    ("r_psi=centre", {"r_psi": "centre"}, 4, [(2, 3), (Fr(7, 2), 0)], Rule.SCENARIO_1, (2, 0), None),
    ("r_psi=follows-bands(centre)", {"bands": "centre"}, 4, [(2, 3), (Fr(7, 2), 0)], Rule.SCENARIO_1, (2, 0), None),
    (
        "r_psi=disc with bands=centre",
        {"bands": "centre", "r_psi": "disc"},
        4,
        [(2, 3), (Fr(7, 2), 0)],
        Rule.SCENARIO_2,
        (2, -2),
        None,
    ),
    # vacant: (3,-2) is exactly 2 from (3,0). strict: not vacant; (3,-3) is out of view (|p|^2 = 18 > 16);
    # up: (3,1), (3,2) blocked -> Scenario 4 after Scenario 2's search.
    ("vacant=strict", {"vacant": "strict"}, 4, [(3, 0), (3, 3)], Rule.SCENARIO_4_I_EMPTY, (0, -3), Case.SCENARIO_2),
    # search_bound=unbounded: the search goes on to (3,-3).
    (
        "search_bound=unbounded",
        {"vacant": "strict", "search_bound": "unbounded"},
        4,
        [(3, 0), (3, 3)],
        Rule.SCENARIO_2,
        (3, -3),
        None,
    ),
    # search_order, rad_v = 6: C (3,0), B (3,5), I robots (3/2,-5/2), (3/2,-9/2) block (3,-1) ... (3,-5);
    # (3,-6) is out of view. primary-then-opposite: up, (3,1) blocked, (3,2) vacant.
    (
        "search_order=primary-then-opposite",
        {},
        6,
        [(3, 0), (3, 5), (Fr(3, 2), Fr(-5, 2)), (Fr(3, 2), Fr(-9, 2))],
        Rule.SCENARIO_2,
        (3, 2),
        None,
    ),
    # primary-only: Scenario 4 with top of I at -5/2: y = -5/2 + 1 = -3/2.
    (
        "search_order=primary-only",
        {"search_order": "primary-only"},
        6,
        [(3, 0), (3, 5), (Fr(3, 2), Fr(-5, 2)), (Fr(3, 2), Fr(-9, 2))],
        Rule.SCENARIO_4_I_NONEMPTY,
        (0, Fr(-3, 2)),
        Case.SCENARIO_2,
    ),
    # uncovered: a lone C robot.
    ("uncovered=search-both", {"uncovered": "search-both"}, 4, [(3, 0)], Rule.UNCOVERED_SEARCH, (3, -2), None),
    ("uncovered=stay", {"uncovered": "stay"}, 4, [(3, 0)], Rule.UNCOVERED_STAY, (0, 0), Case.UNCOVERED),
    # scenario4_guard=all-three-full: R n B, R n D empty -> no rule applies.
    (
        "scenario4_guard=all-three-full fails",
        {"scenario4_guard": "all-three-full"},
        4,
        [(3, 0)],
        Rule.SCENARIO_4_GUARD_FAILS,
        (0, 0),
        Case.UNCOVERED,
    ),
    # ... and holds when B (2,3), C (3,0), D (2,-3) are all in R_psi (psi = 2).
    (
        "scenario4_guard=all-three-full holds",
        {"scenario4_guard": "all-three-full"},
        4,
        [(3, 0), (2, 3), (2, -3)],
        Rule.SCENARIO_4_I_EMPTY,
        (0, -3),
        Case.UNCOVERED,
    ),
    # scenario4_drop, I non-empty with top at y=-3 (d = 3) and I empty.
    (
        "scenario4_drop=touch",
        {"scenario4_drop": "touch"},
        4,
        [(3, 0), (0, -3)],
        Rule.SCENARIO_4_I_NONEMPTY,
        (0, -1),
        Case.UNCOVERED,
    ),
    # gap: d = 3 - 2 = 1, y_p = -1 + 1 = 0: Scenario 4 fires but r does not move.
    (
        "scenario4_drop=gap",
        {"scenario4_drop": "gap"},
        4,
        [(3, 0), (0, -3)],
        Rule.SCENARIO_4_I_NONEMPTY,
        (0, 0),
        Case.UNCOVERED,
    ),
    (
        "scenario4_drop=proofs I non-empty",
        {"scenario4_drop": "proofs"},
        4,
        [(3, 0), (0, -3)],
        Rule.SCENARIO_4_I_NONEMPTY,
        (0, -1),
        Case.UNCOVERED,
    ),
    (
        "scenario4_drop=proofs I empty",
        {"scenario4_drop": "proofs"},
        4,
        [(3, 0)],
        Rule.SCENARIO_4_I_EMPTY,
        (0, -4),
        Case.UNCOVERED,
    ),
    # scenario4_free_path: I robot (1,-3), drop to (0,-2): the rectangle [-1,1]x[-2,0] is exactly 1 from
    # (1,-3). touching-allowed: free; strict: blocked, r stays.
    (
        "scenario4_free_path=on touching",
        {"scenario4_free_path": "on"},
        4,
        [(3, 0), (1, -3)],
        Rule.SCENARIO_4_I_NONEMPTY,
        (0, -2),
        Case.UNCOVERED,
    ),
    (
        "scenario4_free_path=on strict",
        {"scenario4_free_path": "on", "vacant": "strict"},
        4,
        [(3, 0), (1, -3)],
        Rule.SCENARIO_4_PATH_BLOCKED,
        (0, 0),
        Case.UNCOVERED,
    ),
    # The repairs (not the paper's; fatline_verify/rules/repaired/algorithm.py), each with every repair on.
    ("repair-align", REPAIRED, 4, [(1, 2)], Rule.REPAIR_ALIGN, (1, 0), None),
    ("repair-contract", REPAIRED, 4, [(0, -4)], Rule.REPAIR_CONTRACT, (0, -1), None),
    ("repair-approach", REPAIRED, 4, [(4, 0)], Rule.REPAIR_APPROACH, (1, 0), Case.UNCOVERED),
    ("repair-lock", REPAIRED, 4, [(-1, 3), (3, 1)], Rule.REPAIR_LOCK, (0, 0), None),
    ("repair-step", REPAIRED, 4, [(3, 2)], Rule.SCENARIO_1, (1, 0), None),
    # repair_progress=detour: (0,1) of (0,1) (1,4) (2,0): the search finds (2,-3); right is refused by (2,-1)
    # (clearance), down by (1,3) (the edge), and no height below is reachable: one radius up, a top leg.
    (
        "repair-detour",
        {**REPAIRED, "repair_progress": "detour"},
        4,
        [(1, 3), (2, -1)],
        Rule.REPAIR_DETOUR,
        (0, 1),
        None,
    ),
    (
        "repair-blocked",
        {"uncovered": "search-both", "repair_clear": "on"},
        4,
        [(-1, -3), (2, -1)],
        Rule.REPAIR_BLOCKED,
        (0, 0),
        None,
    ),
]


@pytest.mark.parametrize(
    ("readings", "rad_v", "snapshot", "rule", "destination", "case"), [c[1:] for c in CASES], ids=[c[0] for c in CASES]
)
def test_rule_and_destination(readings, rad_v, snapshot, rule, destination, case):
    decision = decide(snapshot, make_model(rad_v=rad_v, **readings))
    assert decision.rule is rule
    assert decision.destination == destination
    assert decision.case == case
    assert decision.moves == (destination != (0, 0))


def test_every_rule_is_exercised():
    assert {c[4] for c in CASES} == set(Rule)


@pytest.mark.parametrize(
    ("readings", "point", "expected"),
    [
        ({}, (0, 3), {A}),
        ({}, (0, -3), {I}),
        ({}, (3, 0), {C}),
        ({}, (-3, 0), {F}),
        ({}, (3, 3), {B}),
        ({}, (3, -3), {D}),
        ({}, (-3, 3), {E}),
        ({}, (-3, -3), {G}),
        ({"quadrants": "literal"}, (3, 3), {B}),
        ({"quadrants": "literal"}, (-3, 3), {D}),
        ({"quadrants": "literal"}, (-3, -3), {E}),
        ({"quadrants": "literal"}, (3, -3), {G}),
        # disc bands: the strip test is strict (|x| < 2): at |x| = 2 the disc only touches the strip.
        ({}, (2, 3), {B}),
        ({}, (Fr(199, 100), 3), {A}),
        # centre bands: |x| <= 1 is in, boundary included.
        ({"bands": "centre"}, (1, 3), {A}),
        ({"bands": "centre"}, (Fr(101, 100), 3), {B}),
        ({}, (Fr(3, 2), Fr(3, 2)), {A, C}),
        ({"band_overlap": "vertical-first"}, (Fr(3, 2), Fr(3, 2)), {A}),
        ({"band_overlap": "horizontal-first"}, (Fr(3, 2), Fr(3, 2)), {C}),
        ({}, (Fr(-3, 2), Fr(-3, 2)), {I, F}),
    ],
)
def test_classification(readings, point, expected):
    assert classify(point, make_model(**readings)) == frozenset(expected)


def test_decision_records_sets_psi_rpsi_and_candidates():
    decision = decide([(3, 0), (3, 3), (-1, 3)], make_model())
    assert sets_of(decision, (3, 0)) == {C}
    assert sets_of(decision, (3, 3)) == {B}
    assert sets_of(decision, (-1, 3)) == {A}
    assert decision.members(A) == ((-1, 3),)
    assert decision.psi == 3
    assert set(decision.r_psi) == {(3, 0), (3, 3)}
    assert [(c.point, c.vacant, c.blocker) for c in decision.candidates] == [
        ((3, -1), False, (3, 0)),
        ((3, -2), True, None),
    ]


def test_lattice_scale_q2_matches_q1():
    """The same configuration on a finer lattice (q = 2) gives the same move, scaled."""
    coarse = decide([(3, 0), (3, 3)], make_model())
    fine = decide([(6, 0), (6, 6)], make_model(q=2))
    assert fine.rule is coarse.rule
    assert fine.destination == (2 * coarse.destination[0], 2 * coarse.destination[1])


@pytest.mark.parametrize(
    ("shape", "path"),
    [
        ("straight", ((0, 0), (2, -2))),
        ("horizontal-then-vertical", ((0, 0), (2, 0), (2, -2))),
        ("vertical-then-horizontal", ((0, 0), (0, -2), (2, -2))),
    ],
)
def test_path_shapes(shape, path):
    decision = decide([(2, 3), (3, 0)], make_model(path=shape))
    assert decision.rule is Rule.SCENARIO_2 and decision.destination == (2, -2)
    assert decision.path == path


def test_axis_parallel_move_is_one_segment_under_every_shape():
    for shape in ("straight", "horizontal-then-vertical", "vertical-then-horizontal"):
        assert decide([(3, 3)], make_model(path=shape)).path == ((0, 0), (3, 0))


@pytest.mark.parametrize(
    ("readings", "p", "blocked"),
    [
        ({}, (3, -2), False),  # exactly 2 from (3, 0): touching is allowed
        ({"vacant": "strict"}, (3, -2), True),
        ({}, (3, -1), True),
    ],
)
def test_vacancy_tie_at_distance_two(readings, p, blocked):
    assert (vacancy_blocker(p, [(3, 0)], make_model(**readings)) is not None) == blocked


@pytest.mark.parametrize(
    ("readings", "robot", "free"),
    [
        ({}, (1, -3), True),  # exactly one radius below the rectangle's end
        ({"vacant": "strict"}, (1, -3), False),
        ({}, (Fr(1, 2), -1), False),
        ({}, (2, -1), True),  # exactly one radius beside it
        ({"vacant": "strict"}, (2, -1), False),
    ],
)
def test_free_path_boundary(readings, robot, free):
    assert free_path((0, -2), [robot], make_model(**readings)) == free
