"""The what-if legs' obligations (``fatline prove repaired --with left,corner``): every condition they
assert holds on the legs ``reach``'s family allows (random swarms), a proved pair and a violated pair
whose counterexample is replayed here by the family's own tests, and the command's rows kept apart
from the shipped obligations."""

from __future__ import annotations

import json

import pytest
import z3
from hypothesis import given, settings

from fatline_verify.cli import main
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.prove.prover import LEMMAS, tasks_for
from fatline_verify.prove.smt import whatif as w
from fatline_verify.prove.smt.cases import Arith, Pt
from fatline_verify.prove.whatif import family_kinds, prove_whatif
from fatline_verify.repair.reach import Family, Kind
from fatline_verify.schedulers.round import closest_dist2, collides, disconnection, lost_edges, snapshot
from tests.test_repairs import repaired, swarms


def _true(e: z3.BoolRef) -> bool:
    value = z3.simplify(e)
    assert z3.is_true(value) or z3.is_false(value), value
    return z3.is_true(value)


def _pt(ar: Arith, p: tuple[int, int]) -> Pt:
    return (z3.IntVal(int(p[0]), ar.ctx), z3.IntVal(int(p[1]), ar.ctx))


def _class(end: tuple[int, int], up: bool, kinds: frozenset[str] = frozenset()) -> str:
    dx, dy = end
    if dx < 0:
        return w.ALONE if w.LEFT_ALONE in kinds else w.LEFTWARD
    if dy == 0:
        return w.HORIZONTAL
    if dx == 0:
        return w.BOTTOM if up else w.TOP
    return w.BOTTOM_CORNER if up else w.TOP_CORNER


SEEN: dict[str, int] = {}
VERTICAL_BRIDGES: list[int] = []


KINDS = [
    frozenset({"left"}),
    frozenset({"left", "corner"}),
    frozenset({"left-alone"}),
    frozenset({"left-alone", "corner"}),
]


@pytest.mark.parametrize("kinds", KINDS)
@settings(max_examples=50, deadline=None)
@given(swarms())
def test_every_leg_the_family_allows_meets_each_asserted_condition(kinds, case):
    _check_family_legs(kinds, case)


@pytest.mark.slow
@pytest.mark.parametrize("kinds", KINDS)
@settings(max_examples=1000, deadline=None)
@given(swarms())
def test_every_leg_the_family_allows_meets_each_asserted_condition_many(kinds, case):
    _check_family_legs(kinds, case)


def _check_family_legs(kinds: frozenset[str], case) -> None:
    """For each leg ``reach``'s family allows a robot (what-if kinds included): its class's shape, and for
    each robot it sees, the asserted conditions hold and its edge is kept or bridged as encoded (under
    corner also through a robot on the mover's vertical)."""
    q, state, _ = case
    model = repaired(q)
    family = Family(model, family_kinds(w.WhatIfSpec(Lemma.CONNECTIVITY, w.KEPT, w.LEFTWARD, w.REST, kinds, q)))
    ar = Arith(q)
    for i in range(len(state)):
        snap = snapshot(state, i, family.model)
        for end, up in family.legs(state, i):
            cls = _class(end, up, kinds)
            SEEN[cls] = SEEN.get(cls, 0) + 1
            assert max(abs(end[0]), abs(end[1])) <= q and min(abs(end[0]), abs(end[1])) >= 0
            m = w.Mover(_pt(ar, (0, 0)), _pt(ar, end), cls)
            for c in snap:
                pc = _pt(ar, c)
                assert _true(w.conditions(ar, model, m, pc)), (state, i, end, c)
                bridges = [w.bridged(ar, model, m, pc, _pt(ar, b), "corner" in kinds) for b in snap if b != c]
                if not _true(z3.Or(w.kept(ar, model, m, pc), *bridges)):
                    assert "corner" in kinds, (state, i, end, c)
                    vertical = [w.vertical_bridged(ar, model, m, pc, _pt(ar, b)) for b in snap if b != c]
                    assert _true(z3.Or(*vertical)), (state, i, end, c)
                    VERTICAL_BRIDGES.append(1)


@pytest.mark.parametrize("state", [((0, 0), (0, -3), (3, -1)), ((0, 0), (0, 4), (3, 2))])
def test_corner_legs_of_known_swarms_meet_each_asserted_condition(state):
    """Swarms where the family allows top-corner and bottom-corner legs (the random ones rarely do)."""
    before = dict(SEEN)
    _check_family_legs(frozenset({"left", "corner"}), (1, state, [0]))
    assert SEEN.get(w.TOP_CORNER, 0) + SEEN.get(w.BOTTOM_CORNER, 0) > before.get(w.TOP_CORNER, 0) + before.get(
        w.BOTTOM_CORNER, 0
    )


def test_the_property_test_saw_the_what_if_classes():
    if not SEEN:
        pytest.skip("run with the property test")
    assert SEEN.get(w.LEFTWARD, 0) > 0 and SEEN.get(w.ALONE, 0) > 0, SEEN


def _spec(key: str, kinds: frozenset[str], q: int) -> w.WhatIfSpec:
    specs = {s.key: s for s in w.whatif_specs(kinds, q, (Lemma.NO_COLLISION, Lemma.CONNECTIVITY))}
    return specs[key]


def test_the_obligations_cover_every_pair_with_a_what_if_leg_and_leave_the_shipped_ones():
    left = w.whatif_specs(frozenset({"left"}), 1, (Lemma.NO_COLLISION, Lemma.CONNECTIVITY))
    assert all(w.LEFTWARD in (s.mine, s.other) for s in left)
    assert len(left) == 5 + 5 + 8  # leg, kept: the 5 pairs with left; bridged: 4 + 4 ordered
    both = w.whatif_specs(frozenset({"left", "corner"}), 1, (Lemma.NO_COLLISION, Lemma.CONNECTIVITY))
    # under corner every pair (its edge tests differ), and the bridge on r's vertical with each leg of it
    assert len(both) == 27 + 27 + 42 + 6 * 7 * 7
    assert {s.form for s in both} - {s.form for s in left} == {w.VERTICAL_BRIDGE}
    model = repaired(1)
    shipped = [t.key for t in tasks_for(model, LEMMAS)]
    assert not {s.key for s in both} & set(shipped)


def test_two_left_legs_never_collide_proved_on_the_lattice(tmp_path):
    model = repaired(1)
    spec = _spec("no-collision/leg-left.and.left@q1", frozenset({"left"}), 1)
    got = prove_whatif(model, spec, timeout=20, out=tmp_path)
    assert got.verdict is Verdict.PROVED and "every size" in got.reason, got.reason
    text = (tmp_path / "no-collision" / "leg-left.and.left.q1.smt2").read_text()
    assert "Why unsat covers swarms of every size" in text and "(check-sat)" in text


def test_a_violated_pair_is_replayed_by_the_family():
    """Two robots of one vertical stepping left, r's edge to o bridged (q = 2): the counterexample's legs
    are legs the family allows from that swarm (not without left legs), and after the round r and o
    are joined neither directly nor through b."""
    model = repaired(2)
    spec = _spec("connectivity/bridged-left.and.left@q2", frozenset({"left"}), 2)
    got = prove_whatif(model, spec, timeout=20, out=None)
    assert got.verdict is Verdict.VIOLATED, got.reason
    state, moves = got.state, dict(got.moves)
    assert set(moves) == {0, 1} and all(end[0] < 0 and end[1] == 0 for end in moves.values())
    family = Family(model, frozenset({Kind.RIGHT, Kind.VERTICAL, Kind.LEFT}))
    for i, end in moves.items():
        assert end in {e for e, _ in family.legs(state, i)}
    without = Family(model, frozenset({Kind.RIGHT, Kind.VERTICAL}))
    assert any(end not in {e for e, _ in without.legs(state, i)} for i, end in moves.items())
    after = tuple((p[0] + moves[i][0], p[1] + moves[i][1]) if i in moves else p for i, p in enumerate(state))
    lost = {pair for pair, _ in lost_edges(state, after, model)}
    assert (0, 1) in lost and lost & {(0, 2), (1, 2)}, lost  # r-o lost, and r-b or b-o: no path of two edges


def test_fatline_prove_with_writes_its_own_rows(tmp_path, capsys):
    code = main(["prove", "repaired", "--with", "left", "--lemma", "no-collision", "--out", str(tmp_path), "-q"])
    out = capsys.readouterr().out
    assert code == 0, out
    doc = json.loads((tmp_path / "repaired" / "whatif-left-q1.json").read_text())
    assert doc["what_if"] == ["left"] and len(doc["obligations"]) == 5
    assert all(r["verdict"] == "PROVED" for r in doc["obligations"])
    assert not (tmp_path / "repaired" / "results.json").exists()
    assert "5 PROVED" in out


@pytest.mark.parametrize(
    "argv, word",
    [
        (["repaired", "--with", "diagonal"], "with='diagonal'"),
        (["repaired", "--q", "2"], "q=2"),
        (["repaired", "--with", "left", "--lemma", "approach"], "lemma=approach"),
        (["paper", "--with", "left"], "model='paper'"),
    ],
)
def test_bad_what_if_input_is_one_line_and_exit_2(argv, word, tmp_path, capsys):
    code = main(["prove", *argv, "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert code == 2 and word in err and len(err.strip().splitlines()) == 1, err
    assert not any(tmp_path.iterdir())


def test_a_corner_leg_against_a_corner_leg_never_collides_proved_on_the_lattice():
    """The pair the reals left undecided (a sqrt(2) leg): exact on the lattice q = 1."""
    spec = _spec("no-collision/leg-top-corner.and.bottom-corner@q1", frozenset({"corner"}), 1)
    got = prove_whatif(repaired(1), spec, timeout=20, out=None)
    assert got.verdict is Verdict.PROVED, got.reason


def test_two_robots_of_one_vertical_stepping_left_split_the_swarm_under_corner():
    """The bridge on r's vertical steps left with r: the replayed round splits the swarm (q = 1)."""
    kinds = frozenset({"left", "corner"})
    spec = _spec("connectivity/bridged-vertical-left.and.rest.via.left@q1", kinds, 1)
    got = prove_whatif(repaired(1), spec, timeout=20, out=None)
    assert got.verdict is Verdict.VIOLATED and "the swarm splits" in got.reason, got.reason
    state, moves = got.state, dict(got.moves)
    assert state[0][0] == state[2][0] and moves[0][0] < 0 and moves[2][0] < 0  # r and b: one vertical, left
    family = Family(repaired(1), family_kinds(spec))
    assert all(end in {e for e, _ in family.legs(state, i)} for i, end in moves.items())
    after = tuple((p[0] + moves[i][0], p[1] + moves[i][1]) if i in moves else p for i, p in enumerate(state))
    assert disconnection(state, after, family.model) is not None


@pytest.mark.slow
def test_a_corner_collision_pair_at_q2_is_proved_once_the_needed_robot_is_named():
    """At q = 2 the plain obligation has an answer (two robots that do not see each other) that is no
    swarm; with the robot below the top-corner named, unsat."""
    spec = _spec("no-collision/leg-top.and.top-corner@q2", frozenset({"corner"}), 2)
    got = prove_whatif(repaired(2), spec, timeout=120, out=None)
    assert got.verdict is Verdict.PROVED and "named" in got.reason, got.reason


@pytest.mark.slow
def test_a_left_leg_and_a_corner_leg_collide_at_q2():
    """Two robots that do not see each other, one stepping left, one right and down: they collide
    (q = 2, left and corner legs both), replayed through the family and the executable model."""
    kinds = frozenset({"left", "corner"})
    spec = _spec("no-collision/leg-left.and.top-corner@q2", kinds, 2)
    model = repaired(2)
    got = prove_whatif(model, spec, timeout=120, out=None)
    assert got.verdict is Verdict.VIOLATED, got.reason
    state, moves = got.state, dict(got.moves)
    family = Family(model, family_kinds(spec))
    assert all(end in {e for e, _ in family.legs(state, i)} for i, end in moves.items())
    paths = {i: (state[i], (state[i][0] + e[0], state[i][1] + e[1])) for i, e in moves.items()}
    assert collides(closest_dist2(paths[0], paths[1], state[0], state[1], family.model), family.model)
    assert not family.model.sees((state[0][0] - state[1][0]) ** 2 + (state[0][1] - state[1][1]) ** 2)
