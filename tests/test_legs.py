"""The repaired rule set's leg obligations (``fatline_verify/prove/smt/legs.py``): every condition they assert
holds on the repaired rules' own decisions (random swarms, beyond any window), the argument's chain
holds on real rounds, a solution of a weakened obligation is not reported as a counterexample, and a
repaired model without the repairs the legs rest on is refused in one line."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
import z3
from hypothesis import given, settings

from fatline_verify.errors import InvalidInput
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.prove.legs import prove_leg
from fatline_verify.prove.prover import tasks_for
from fatline_verify.prove.smt import legs
from fatline_verify.prove.smt.cases import Arith, Pt
from fatline_verify.prove.smt.legs import LegSpec, Mover, bridged, conditions, kept
from fatline_verify.rules.repaired.algorithm import Leg, leg_of
from fatline_verify.schedulers.round import decide_all, play_round, snapshot
from tests.test_repairs import repaired, swarms


def _pt(ar: Arith, model, p) -> Pt:
    x, y = model.from_lattice(p)
    return (ar.num(Fraction(x)), ar.num(Fraction(y)))


def _true(e: z3.BoolRef) -> bool:
    value = z3.simplify(e)
    assert z3.is_true(value) or z3.is_false(value), value
    return z3.is_true(value)


CLASSES: dict[Leg, int] = {leg: 0 for leg in legs.CLASSES}
"""Moves per leg class seen by the property test (the next test checks each class was exercised)."""
BRIDGES: list[int] = []


PROGRESS = ["off", "detour"]
"""``repair_progress``: the detour's moves are legs of the same classes, so the same tests hold them."""


@pytest.mark.parametrize("progress", PROGRESS)
@settings(max_examples=300, deadline=None)
@given(swarms())
def test_every_repaired_move_is_a_leg_meeting_each_asserted_condition(progress, case):
    """For each robot the repaired rules move: its move is a leg of one class (horizontal ones go
    right), and for each robot it sees, the conditions the obligations assert hold, and its edge
    test is kept or bridged by a robot the lock holds at rest."""
    q, state, _ = case
    model = repaired(q, repair_progress=progress)
    ar = Arith(None)
    decisions = decide_all(state, model)
    for i, d in decisions.items():
        if not d.moves:
            continue
        snap = snapshot(state, i, model)
        leg = leg_of(d.destination, snap)
        CLASSES[leg] += 1
        dx, dy = d.destination
        assert max(abs(dx), abs(dy)) <= model.radius
        assert dx > 0 if leg is Leg.HORIZONTAL else dy != 0
        assert leg is not Leg.BOTTOM or dy > 0
        end = (state[i][0] + dx, state[i][1] + dy)
        m = Mover(_pt(ar, model, state[i]), _pt(ar, model, end), leg)
        for j, c in enumerate(state):
            if j == i:
                continue
            cz = _pt(ar, model, c)
            assert _true(conditions(ar, model, m, cz)), (state, i, j)
            if not model.sees((c[0] - state[i][0]) ** 2 + (c[1] - state[i][1]) ** 2):
                continue
            if _true(kept(ar, model, m, cz)):
                continue
            bridges = [
                k
                for k, b in enumerate(state)
                if k not in (i, j) and _true(bridged(ar, model, m, cz, _pt(ar, model, b)))
            ]
            assert bridges, (state, i, j)
            assert all(not decisions[k].moves for k in bridges), (state, i, bridges)
            BRIDGES.append(len(bridges))


def test_the_property_test_saw_every_leg_class_and_a_bridge():
    if not sum(CLASSES.values()):
        pytest.skip("run with the property test")
    assert all(CLASSES.values()), CLASSES
    assert BRIDGES
    print("moves per leg class:", CLASSES, "edges bridged:", len(BRIDGES))


@pytest.mark.parametrize("progress", PROGRESS)
@settings(max_examples=200, deadline=None)
@given(swarms())
def test_each_edge_before_a_round_is_a_path_of_at_most_two_edges_after(progress, case):
    """The argument's conclusion on real rounds: every edge of the graph before the round is an edge
    after it, or a path through a robot at rest."""
    q, state, active = case
    model = repaired(q, repair_progress=progress)
    result = play_round(state, active, model)
    still = set(active) - {i for i in active if result.decisions[i].moves}
    at_rest = [k for k in range(len(state)) if k not in active or k in still]

    def sees(a, b) -> bool:
        return model.sees((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)

    before, after = result.before, result.after
    for i in range(len(state)):
        for j in range(i + 1, len(state)):
            if sees(before[i], before[j]) and not sees(after[i], after[j]):
                assert any(sees(after[i], after[k]) and sees(after[k], after[j]) for k in at_rest), (state, active)


def test_the_obligations_cover_every_pair_of_leg_classes():
    specs = [t for t in tasks_for(repaired()) if isinstance(t, LegSpec)]
    pairs = {(s.lemma, s.form, s.mine, s.other) for s in specs}
    assert len(pairs) == len(specs) == 30
    for mine in legs.CLASSES:
        for other in [legs.REST, *(leg.value for leg in legs.CLASSES)]:
            assert (Lemma.CONNECTIVITY, legs.BRIDGED, mine, other) in pairs  # r: the mover whose test bridged
            either = {(mine, other)} | ({(Leg(other), mine.value)} if other != legs.REST else set())
            for lemma, form in ((Lemma.NO_COLLISION, legs.LEG), (Lemma.CONNECTIVITY, legs.KEPT)):
                assert any((lemma, form, a, b) in pairs for a, b in either), (form, mine, other)


def test_a_leg_obligation_is_proved_and_its_file_states_the_argument(tmp_path):
    spec = LegSpec(Lemma.CONNECTIVITY, legs.KEPT, Leg.TOP, Leg.BOTTOM.value)
    got = prove_leg(repaired(), spec, timeout=20, out=tmp_path)
    assert got.verdict is Verdict.PROVED and got.any_size, got.reason
    text = (tmp_path / "connectivity" / "kept-top.and.bottom.smt2").read_text()
    assert "Why unsat covers swarms of every size" in text and "(check-sat)" in text


def test_two_vertical_tops_that_see_each_other_never_occur():
    got = prove_leg(repaired(), LegSpec(Lemma.CONNECTIVITY, legs.KEPT, Leg.TOP, Leg.TOP.value), timeout=10, out=None)
    assert got.verdict is Verdict.PROVED and "never occur together" in got.reason


def test_a_solution_of_weaker_conditions_is_not_reported_as_a_counterexample(monkeypatch):
    """Without the clearance condition the solver finds r's leg through o; the repaired rules refuse
    that leg, so the replay says so (INCONCLUSIVE), never VIOLATED."""
    weak = legs.conditions

    def without_clearance(ar, model, m, c):
        return weak(ar, model, Mover(m.at, m.at, m.leg), c)  # the clearance of a leg of length 0

    monkeypatch.setattr(legs, "conditions", without_clearance)
    got = prove_leg(repaired(), LegSpec(Lemma.NO_COLLISION, legs.LEG, Leg.HORIZONTAL, legs.REST), timeout=10, out=None)
    assert got.verdict is Verdict.INCONCLUSIVE, got.reason
    assert "not a counterexample" in got.reason, got.reason
    print(got.reason)


@pytest.mark.parametrize("missing", ["repair_lock", "repair_step", "repair_clear", "repair_edges"])
def test_a_repaired_model_without_the_repairs_the_legs_need_is_refused(missing, capsys, tmp_path):
    from fatline_verify.cli import main
    from fatline_verify.model.config import shipped_models

    with pytest.raises(InvalidInput, match=rf"{missing}=.* not set"):
        tasks_for(repaired(**{missing: "off"}))
    source = next(p for p in shipped_models() if p.stem == "repaired").read_text()
    lines = [f'{missing} = "off"' if line.startswith(f"{missing} =") else line for line in source.splitlines()]
    model = tmp_path / "weaker.toml"
    model.write_text("\n".join(lines).replace('name = "repaired"', 'name = "weaker"') + "\n")
    assert main(["prove", str(model), "--out", str(tmp_path / "p"), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert f"{missing}=" in err and "not set" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "p").exists()


def test_a_model_with_corner_legs_is_refused_before_any_work(capsys, tmp_path):
    """``repair_progress = corner`` makes legs the obligations do not cover: one line, exit 2, no files."""
    from fatline_verify.cli import main

    with pytest.raises(InvalidInput, match=r"repair_progress='corner'.*expected off or detour"):
        tasks_for(repaired(repair_progress="corner"))
    source = (Path(__file__).resolve().parent.parent / "bench" / "repaired-progress.toml").read_text()
    model = tmp_path / "corner.toml"
    model.write_text(source.replace('repair_progress = "detour"', 'repair_progress = "corner"'))
    assert 'repair_progress = "corner"' in model.read_text()
    assert main(["prove", str(model), "--out", str(tmp_path / "p"), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert "repair_progress='corner'" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "p").exists()
