"""The guarded left leg (``left-alone``): a robot steps left only when it sees no other robot on its own
vertical, and no farther than :func:`fatline_verify.repair.reach.left_alone_reach`. Its guard on random
swarms against the family (the argument's premise: no robot that sees a left-alone mover moves in the
same round), its obligations PROVED where the unguarded leg's were VIOLATED, the length bound's reason,
and ``fatline synth`` over the guarded family at its smallest unsat robot count."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings

from fatline_verify.cli import main
from fatline_verify.cli.prove_whatif import obligations
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.options import Scheduler
from fatline_verify.prove.family import prove_family
from fatline_verify.prove.smt.cases import Arith
from fatline_verify.prove.smt.family import build
from fatline_verify.repair.reach import PROVED, Family, Kind, canonical, family_legs, left_alone_reach
from fatline_verify.repair.search import confirm_stuck, reach, way_to_line
from fatline_verify.rules.repaired.whatif import family, legs_family
from fatline_verify.schedulers.round import closest_dist2, collides, snapshot
from fatline_verify.synth.certificate import certify
from fatline_verify.synth.encode import synthesise
from fatline_verify.synth.replay import replay
from tests.test_cli import assert_one_line_error, run_cli
from tests.test_repairs import repaired, swarms

ALONE = PROVED | {Kind.LEFT_ALONE}
ALONE_CORNER = PROVED | {Kind.LEFT_ALONE, Kind.CORNER}
LEFT_CORNER = PROVED | {Kind.LEFT, Kind.CORNER}
LEMMAS = (Lemma.NO_COLLISION, Lemma.CONNECTIVITY)
STUCK = ((0, 1), (0, 4), (0, 7), (2, 0))
"""A configuration of 4 robots at q = 1 the guarded family (with corner legs) brings to no line: three
robots of one vertical, one right of them; the unguarded family does."""


def _spec(key: str, kinds: frozenset[str], q: int):  # type: ignore[no-untyped-def]
    fam = legs_family(repaired(q), kinds)
    return fam, {s.key: s for s in obligations(fam, kinds, LEMMAS)}[key]


def _prove(key: str, kinds: frozenset[str], q: int, timeout: float = 30, out=None):  # type: ignore[no-untyped-def]
    fam, spec = _spec(key, kinds, q)
    return prove_family(repaired(q), spec, timeout=timeout, out=out, family=fam)


def test_the_longest_left_alone_leg_is_the_lattice_s_own_answer():
    """One radius unless a robot the mover does not see can reach its path: with corner legs at q = 2, a
    one-radius left leg meets the corner leg of a robot beyond view (the collision the unguarded what-if
    found, ``leg-left.and.top-corner@q2``), so the guarded leg is half a radius there."""
    assert left_alone_reach(repaired(1), ALONE) == 1
    assert left_alone_reach(repaired(1), ALONE_CORNER) == 1
    assert left_alone_reach(repaired(2), ALONE) == 2
    assert left_alone_reach(repaired(2), ALONE_CORNER) == 1
    m = repaired(2)
    mover, other = ((0, 0), (-2, 0)), ((-7, 4), (-5, 2))  # a one-radius left leg; a corner leg (2, -2)
    assert not m.sees(7 * 7 + 4 * 4)
    assert collides(closest_dist2(mover, other, mover[0], other[0], m), m)
    half = ((0, 0), (-1, 0))
    assert not collides(closest_dist2(half, other, half[0], other[0], m), m)


@pytest.mark.parametrize("kinds", [ALONE, ALONE_CORNER], ids=["left-alone", "left-alone-corner"])
@settings(max_examples=80, deadline=None)
@given(swarms())
def test_the_guard_on_random_swarms(kinds, case):
    """Every left leg the guarded family allows: the mover sees no robot on its vertical, sees one right of
    it, the leg is no longer than the bound, and is a leg the unguarded family allows too; and every robot
    that sees the mover has no leg at all (the lock holds it), so no pair of movers that see each other,
    and no bridge, includes a left-alone leg: the premise of the vacuous rows."""
    q, state, _ = case
    family = Family(repaired(q), kinds)
    unguarded = Family(repaired(q), (kinds - {Kind.LEFT_ALONE}) | {Kind.LEFT})
    longest = left_alone_reach(family.model, kinds)
    for i in range(len(state)):
        snap = snapshot(state, i, family.model)
        left = [end for end, _ in family.legs(state, i) if end[0] < 0]
        guarded = all(c[0] != 0 for c in snap)
        expected = [e for e, _ in unguarded.legs(state, i) if e[0] < 0 and -e[0] <= longest] if guarded else []
        assert left == expected, (state, i)
        for end in left:
            assert end[1] == 0 and 1 <= -end[0] <= longest
            assert any(c[0] > 0 for c in snap) and all(c[0] > 0 for c in snap)
            for j, (x, y) in enumerate(state):
                d2 = (x - state[i][0]) ** 2 + (y - state[i][1]) ** 2
                if j != i and family.model.sees(d2):
                    assert family.legs(state, j) == (), (state, i, j)


def test_the_guard_stops_the_unguarded_counterexample():
    """The swarm of ``bridged-horizontal.and.left@q1`` (VIOLATED without the guard): o, on r's vertical,
    steps left there; under the guard it has no left leg."""
    state = ((0, 0), (0, -4), (3, -2), (1, -2))
    m = repaired(1)
    assert (-1, 0) in {e for e, _ in Family(m, PROVED | {Kind.LEFT}).legs(state, 1)}
    assert all(e[0] >= 0 for e, _ in Family(m, ALONE).legs(state, 1))
    assert all(e[0] >= 0 for e, _ in family_legs(snapshot(state, 1, m), m, ALONE_CORNER))


@pytest.mark.parametrize(
    ("key", "kinds", "q"),
    [
        ("connectivity/bridged-horizontal.and.left-alone.by.bridge-rest", frozenset({"left-alone"}), 1),
        ("connectivity/bridged-top.and.left-alone.by.bridge-rest", frozenset({"left-alone"}), 1),
        ("connectivity/kept-horizontal.and.left-alone", frozenset({"left-alone"}), 2),
        ("connectivity/bridged-left-alone.and.left-alone.by.bridge-rest", frozenset({"left-alone"}), 2),
        ("connectivity/bridged-left-alone.and.rest.by.vertical-left-alone", frozenset({"left-alone", "corner"}), 1),
    ],
)
def test_formerly_violated_pairs_are_proved_under_the_guard(key, kinds, q):
    """Each pair VIOLATED with the unguarded left leg (docs/repaired.md): two robots of one vertical moving
    at once, one stepping left. Under the guard they never occur together."""
    got = _prove(key, kinds, q)
    assert got.verdict is Verdict.PROVED and "never occur together" in got.reason, (key, got.reason)
    if q == 1:  # the unguarded twin (q = 2: tests/test_whatif_legs.py, bridged-left.and.left)
        plain = frozenset(k.replace("left-alone", "left") for k in kinds)
        assert _prove(key.replace("left-alone", "left"), plain, q, timeout=60).verdict is Verdict.VIOLATED


def test_a_left_alone_leg_against_a_robot_at_rest_is_proved_for_every_size(tmp_path):
    """Not vacuous: the solver's unsat, with the header's any-size argument naming the guard."""
    got = _prove("no-collision/leg-left-alone.and.rest", frozenset({"left-alone"}), 1, out=tmp_path)
    assert got.verdict is Verdict.PROVED and "every size" in got.reason, got.reason
    text = (tmp_path / "no-collision" / "leg-left-alone.and.rest.smt2").read_text()
    assert "every robot seen strictly right of it" in text and "Why unsat covers swarms of every size" in text


@pytest.mark.slow
def test_the_half_radius_bound_is_what_proves_left_alone_against_a_corner_at_q2():
    """``leg-left-alone.and.top-corner@q2``: PROVED with the bound (half a radius); with a one-radius leg the
    same obligation, each leg's witness named, has a violation (sat): the bound is needed and the family
    agrees with it."""
    from fatline_verify.prove.smt.solving import check, solver_for

    key = "no-collision/leg-left-alone.and.top-corner"
    kinds = frozenset({"left-alone", "corner"})
    fam, spec = _spec(key, kinds, 2)
    assert "dx <= 1/2" in fam.get("left-alone").says
    got = _prove(key, kinds, 2, timeout=120)
    assert got.verdict is Verdict.PROVED, got.reason
    longer = family(kinds, 2, left_units=2)
    built = build(Arith(2), repaired(2), longer, spec, witnesses=True)
    assert check(solver_for(built, 120), built, 120).status == "sat"


def test_fatline_prove_with_left_alone_writes_its_rows(tmp_path, capsys):
    code = main(["prove", "repaired", "--with", "left-alone", "--out", str(tmp_path), "-q"])
    out = capsys.readouterr().out
    assert code == 0, out
    doc = json.loads((tmp_path / "repaired" / "whatif-left-alone-q1.json").read_text())
    rows = doc["obligations"]
    assert doc["what_if"] == ["left-alone"] and len(rows) == 62
    assert all(r["verdict"] == "PROVED" for r in rows), [r["key"] for r in rows if r["verdict"] != "PROVED"]
    assert "62 PROVED" in out


@pytest.mark.parametrize("command", [["prove", "repaired", "--out", "OUT"], ["reach"], ["synth"]])
def test_left_and_left_alone_together_are_refused(command, capsys, tmp_path):
    argv = [tmp_path.as_posix() if a == "OUT" else a for a in command]
    code, _, err = run_cli(capsys, *argv, "--with", "left,left-alone,corner", "-q")
    assert_one_line_error(code, err, "with=left,left-alone")
    assert not any(tmp_path.iterdir())


def test_the_guard_brings_a_stuck_configuration_back():
    """Liveness: at q = 1 with corner legs the unguarded family reaches a line from every 4-robot
    configuration; the guarded one does not from ``STUCK`` (searched exhaustively), and a line is
    reachable there with the unguarded left leg."""
    m = repaired(1)
    assert confirm_stuck(canonical(STUCK), Family(m, ALONE_CORNER)) > 0
    assert way_to_line(canonical(STUCK), Family(m, LEFT_CORNER)) is not None


def test_reach_with_the_guard_follows_no_unsafe_round():
    """The proof's consequence, checked by the executable model: no round of the guarded family with corner
    legs collides, splits the swarm or crosses the RMA (3 robots, q = 1 and 2)."""
    for q in (1, 2):
        got = reach(repaired(q), 3, (9, 9), ALONE_CORNER)
        assert got.unsafe == 0 and got.stuck == ()


@pytest.mark.parametrize("scheduler", [Scheduler.CENTRALIZED, Scheduler.SSYNC])
def test_synth_over_the_guarded_family_is_sat_for_3_and_unsat_at_4(scheduler):
    """The smallest unsat robot count of the guarded family (q = 1, 9x9): a table for 2..3 robots, replayed;
    at 4 the core ``STUCK`` alone is unsat, another solver agreeing, and no line is reachable from it
    (fast twin of the slow full search)."""
    m = repaired(1)
    r = synthesise(m, 3, (9, 9), ALONE_CORNER, scheduler=scheduler, smallest=2)
    assert r.sat
    assert replay(r.table, m, range(2, 4), (9, 9), ALONE_CORNER, scheduler).problems == []
    core = canonical(STUCK)
    u = synthesise(m, 4, (9, 9), ALONE_CORNER, scheduler=scheduler, only=[core])
    assert not u.sat and u.core == (core,)
    cert = certify(m, u)
    assert cert.problems == [] and cert.again == "glucose4"
    assert [(c.planner, c.alone) for c in cert.core] == [(None, False)]


@pytest.mark.slow
@pytest.mark.parametrize("scheduler", [Scheduler.CENTRALIZED, Scheduler.SSYNC])
def test_synth_over_the_guarded_family_2_to_4_is_unsat_with_a_core_of_one(scheduler):
    m = repaired(1)
    r = synthesise(m, 4, (9, 9), ALONE_CORNER, scheduler=scheduler, smallest=2)
    assert not r.sat and len(r.core) == 1
    assert set(r.core) <= set(reach(m, 4, (9, 9), ALONE_CORNER).stuck)
    assert certify(m, r).problems == []
