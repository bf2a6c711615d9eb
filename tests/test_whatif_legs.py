"""The what-if legs as a move family (``rules/repaired/whatif.py``): ``fatline reach``'s legs are the family's
admitted legs (the hand-written copy's answers kept as a fixture), ``fatline prove repaired --with`` builds its
obligations with the family builder and gives the verdicts the hand-built obligations gave, a violated pair
is replayed by the family's own legs, and the command's rows are kept apart from the shipped obligations."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.cli.prove_whatif import obligations
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.prove.family import prove_family
from fatline_verify.prove.prover import LEMMAS, tasks_for
from fatline_verify.repair.reach import PROVED, Family, Kind, family_legs
from fatline_verify.rules.family.lang import Ground, holds
from fatline_verify.rules.repaired.whatif import legs_family, shapes
from fatline_verify.schedulers.round import disconnection, lost_edges
from fatline_verify.synth.table import parse_view
from tests.test_repairs import repaired

FIXTURE = Path(__file__).parent / "fixtures" / "reach_legs.json"
KINDS = {
    "right,vertical": PROVED,
    "left": PROVED | {Kind.LEFT},
    "left-alone": PROVED | {Kind.LEFT_ALONE},
    "corner": PROVED | {Kind.CORNER},
    "left,corner": PROVED | {Kind.LEFT, Kind.CORNER},
    "left-alone,corner": PROVED | {Kind.LEFT_ALONE, Kind.CORNER},
}
BOTH = (Lemma.NO_COLLISION, Lemma.CONNECTIVITY)


def _rows() -> list[dict[str, object]]:
    return json.loads(FIXTURE.read_text())["rows"]


def test_reach_s_legs_are_those_the_hand_written_copy_gave():
    """460 random views of repaired at q = 1 and 2 (some with corner legs, some with none) and six leg families:
    the legs read from the family by the concrete interpreter equal, in order, those the hand-written copy of
    the guard gave (the fixture, made by it before it was deleted)."""
    corner = 0
    for row in _rows():
        model = repaired(int(row["q"]))  # type: ignore[arg-type]
        view = parse_view(str(row["view"]))
        for name, want in row["legs"].items():  # type: ignore[union-attr]
            kinds = KINDS[name]
            got = family_legs(view, Family(model, kinds).model, kinds)
            assert [e for e, _ in got] == list(parse_view(want)), (row["q"], view, name)
            corner += sum(1 for (a, b), _ in got if a and b)
    assert corner > 50  # the fixture exercises the corner classes


def test_each_leg_is_admitted_by_the_family_in_its_class_and_nothing_else_is():
    """On the fixture's views: every lattice end within the longest step is a leg exactly when the family's
    classify admits it, and the class reach names is one whose shape and guard hold there."""
    for row in _rows()[::7]:
        model = repaired(int(row["q"]))  # type: ignore[arg-type]
        view = parse_view(str(row["view"]))
        for kinds in KINDS.values():
            family = legs_family(model, kinds)
            legs = dict(family_legs(view, model, kinds))
            ends = {e for e, _ in shapes(family, model)}
            for end in ends:
                assert (end in legs) == (family.classify(view, end, model) is not None), (view, end)
            for end, name in legs.items():
                cls = family.get(name)
                g = Ground(model, view, {"me": (0, 0), "end": end})
                assert holds(cls.shape, g) and holds(cls.guard, g)


def test_the_obligations_are_the_family_s_without_the_shipped_pairs():
    model = repaired(1)
    left = obligations(legs_family(model, {"left"}), frozenset({"left"}), BOTH)
    assert all("left" in (s.mine, s.other, s.witness) for s in left)
    assert len([s for s in left if s.form != "bridged"]) == 5 + 5  # leg, kept: the 5 pairs with left
    both = obligations(legs_family(model, {"left", "corner"}), frozenset({"left", "corner"}), BOTH)
    # under corner every pair (its edge tests differ); bridged through a robot right of r and one on r's vertical
    assert {s.role for s in both if s.form == "bridged"} == {"bridge", "vertical"}
    assert len(both) == 27 + 27 + 2 * 6 * 7 * 7
    shipped = [t.key for t in tasks_for(model, LEMMAS)]
    assert not {f"{s.key}@q1" for s in both} & set(shipped)


def _spec(key: str, kinds: set[str], q: int):  # type: ignore[no-untyped-def]
    family = legs_family(repaired(q), kinds)
    return family, {s.key: s for s in obligations(family, frozenset(kinds), BOTH)}[key]


def _prove(key: str, kinds: set[str], q: int, timeout: float = 30, out: Path | None = None):  # type: ignore[no-untyped-def]
    family, spec = _spec(key, kinds, q)
    return prove_family(repaired(q), spec, timeout=timeout, out=out, family=family)


def _state(got, q: int) -> tuple[tuple[int, int], ...]:  # type: ignore[no-untyped-def]
    """The replayed robots (the row's configuration, radii) in lattice units."""
    return tuple((int(Fraction(a) * q), int(Fraction(b) * q)) for a, b in (c.split(",") for c in got.configuration))


def test_two_left_legs_never_collide_proved_on_the_lattice(tmp_path):
    got = _prove("no-collision/leg-left.and.left", {"left"}, 1, out=tmp_path)
    assert got.verdict is Verdict.PROVED and "every size" in got.reason, got.reason
    text = (tmp_path / "no-collision" / "leg-left.and.left.smt2").read_text()
    assert "Why unsat covers swarms of every size" in text and "(check-sat)" in text


def test_a_violated_pair_is_replayed_by_the_family():
    """Two robots of one vertical stepping left, r's edge to o bridged (q = 2): each leg is one the family
    admits from its own view there (not without left legs), and after the round r and o are joined neither
    directly nor through b."""
    model = repaired(2)
    got = _prove("connectivity/bridged-left.and.left.by.bridge-rest", {"left"}, 2)
    assert got.verdict is Verdict.VIOLATED, got.reason
    state = _state(got, 2)
    family = Family(model, KINDS["left"])
    without = Family(model, PROVED)
    moves = {
        i: end
        for i in (0, 1)
        for end in {e for e, _ in family.legs(state, i)}
        if end[0] < 0 and end[1] == 0 and f"({i}, ({end[0]}, {end[1]}))" in got.reason
    }
    assert set(moves) == {0, 1}, got.reason
    assert all(end not in {e for e, _ in without.legs(state, i)} for i, end in moves.items())
    after = tuple((p[0] + moves[i][0], p[1] + moves[i][1]) if i in moves else p for i, p in enumerate(state))
    lost = {pair for pair, _ in lost_edges(state, after, model)}
    assert (0, 1) in lost and lost & {(0, 2), (1, 2)}, lost  # r-o lost, and r-b or b-o: no path of two edges


def test_a_corner_leg_against_a_corner_leg_never_collides_proved_on_the_lattice():
    """The pair the reals left undecided (a sqrt(2) leg): exact on the lattice q = 1."""
    got = _prove("no-collision/leg-top-corner.and.bottom-corner", {"corner"}, 1)
    assert got.verdict is Verdict.PROVED, got.reason


def test_two_robots_of_one_vertical_stepping_left_split_the_swarm_under_corner():
    """The bridge on r's vertical steps left with r: the replayed round splits the swarm (q = 1)."""
    got = _prove("connectivity/bridged-left.and.rest.by.vertical-left", {"left", "corner"}, 1, timeout=60)
    assert got.verdict is Verdict.VIOLATED and "the swarm splits" in got.reason, got.reason
    state = _state(got, 1)
    assert state[0][0] == state[2][0]  # r and b: one vertical
    family = Family(repaired(1), KINDS["left,corner"])
    after = tuple((x - 1, y) if i in (0, 2) else (x, y) for i, (x, y) in enumerate(state))
    assert (-1, 0) in {e for e, _ in family.legs(state, 0)} and (-1, 0) in {e for e, _ in family.legs(state, 2)}
    assert disconnection(state, after, family.model) is not None


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


GOLDEN = Path(__file__).parent / "fixtures" / "whatif_verdicts.json"
"""The verdicts of ``fatline prove repaired --with KINDS --q Q --timeout 60`` by the hand-built what-if
obligations (before the family builder), each row under the family's key."""


def _golden_case(with_: str, q: int, tmp_path: Path, capsys) -> None:  # type: ignore[no-untyped-def]
    want = json.loads(GOLDEN.read_text())[f"{with_}@q{q}"]
    code = main(["prove", "repaired", "--with", with_, "--q", str(q), "--timeout", "60", "--out", str(tmp_path), "-q"])
    capsys.readouterr()
    tag = "-".join(sorted(with_.split(",")))
    rows = json.loads((tmp_path / "repaired" / f"whatif-{tag}-q{q}.json").read_text())["obligations"]
    got = {r["key"]: r["verdict"] for r in rows}
    decided = {k: v for k, v in want.items() if v != "INCONCLUSIVE"}  # out of budget then, on a loaded machine
    assert {k: got.get(k) for k in decided} == decided
    assert set(want) <= set(got)
    extra = {k: v for k, v in got.items() if k not in want}  # a bridge moving: it sees r left of it, held
    assert set(extra.values()) <= {"PROVED"}, extra
    assert code == (1 if "VIOLATED" in want.values() else 3 if "INCONCLUSIVE" in got.values() else 0)


@pytest.mark.parametrize("with_", ["left", "left-alone"])
def test_the_what_if_verdicts_are_those_of_the_hand_built_obligations(with_, tmp_path, capsys):
    _golden_case(with_, 1, tmp_path, capsys)


@pytest.mark.slow
@pytest.mark.parametrize(
    "with_, q",
    [(k, q) for q in (1, 2) for k in ("left", "left-alone", "corner", "left,corner", "left-alone,corner")],
)
def test_the_what_if_verdicts_are_those_of_the_hand_built_obligations_everywhere(with_, q, tmp_path, capsys):
    _golden_case(with_, q, tmp_path, capsys)


def test_a_leg_witness_may_be_a_robot_the_obligation_names():
    """A leg's witness (the robot below a top-corner mover) may be the other mover itself: r at (0, 0) takes
    its top-corner leg to (1, -1) seeing o below it and a robot at (3, 0) ahead; o, 4 below, takes its
    bottom leg up. The concrete interpreter admits both legs, so the obligation with the witnesses named
    must keep this configuration (sat): naming a witness apart from every other robot left it out, and an
    unsat there would have been a PROVED the guards do not earn."""
    import z3

    from fatline_verify.prove.smt.cases import Arith
    from fatline_verify.prove.smt.family import FamilySpec, build
    from fatline_verify.schedulers.round import snapshot

    model = repaired(1)
    family = legs_family(model, frozenset({"corner"}))
    state = ((0, 0), (0, -4), (3, 0))
    assert family.classify(snapshot(state, 0, model), (1, -1), model) == "top-corner"
    assert family.classify(snapshot(state, 1, model), (0, 1), model) == "bottom"
    spec = FamilySpec(Lemma.NO_COLLISION, "leg", "top-corner", "bottom")
    for witnesses in (False, True):
        built = build(Arith(1), model, family, spec, vacuity=True, witnesses=witnesses)
        solver = z3.Solver(ctx=built.ar.ctx)
        solver.add(*built.assertions, *built.bounds)
        pin = {"o.x": 0, "o.y": -4, "r.end.x": 1, "r.end.y": -1, "o.end.x": 0, "o.end.y": -3}
        if witnesses:
            pin |= {"w.r.ahead.x": 3, "w.r.ahead.y": 0}
        solver.add(*(z3.Int(name, built.ar.ctx) == value for name, value in pin.items()))
        solver.set("timeout", 60000)
        assert solver.check() == z3.sat, witnesses
