"""Move families (``fatline_verify/rules/family``, ``fatline_verify/prove/smt/family.py``): the two interpreters
of the guard language agree, the repaired rule set's decisions lie in its family and its obligations are
PROVED, and the argument's conclusion holds on real rounds."""

from __future__ import annotations

import random
from fractions import Fraction
from pathlib import Path

import pytest
import z3
from hypothesis import given, settings

from fatline_verify.errors import InvalidInput
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.prove.family import check_views, prove_family, prove_views
from fatline_verify.prove.prover import tasks_for
from fatline_verify.prove.smt.cases import Arith
from fatline_verify.prove.smt.family import BRIDGED, KEPT, LEG, FamilySpec, Scene, assumed, specs
from fatline_verify.prove.tasks import ViewsSpec
from fatline_verify.rules.family import REST, LegClass, MoveFamily, clear, end, exists, forall, me, sees
from fatline_verify.rules.family.lang import Ground, holds
from fatline_verify.rules.repaired.family import LEGS
from fatline_verify.schedulers.round import decide_all, play_round, snapshot
from tests.test_repairs import repaired, swarms


def _z3_holds(cond, view, destination, model) -> bool:
    """``cond`` by the symbolic interpreter on a ground view (every robot seen named: exact), simplified."""
    ar = Arith(None)

    def pt(p):
        x, y = model.from_lattice(p)
        return (ar.num(Fraction(x)), ar.num(Fraction(y)))

    at = {"me": pt((0, 0)), **{f"v{k}": pt(p) for k, p in enumerate(view)}}
    scene = Scene(ar, model, at)
    term = assumed(cond, scene, "me", {"me": at["me"], "end": pt(destination)}, exact=True)
    value = z3.simplify(term)
    assert z3.is_true(value) or z3.is_false(value), value
    return z3.is_true(value)


def _views(model, n: int, seed: int):
    """Random views, and crowded ones: robots packed around the decider (every robot within 4 radii)."""
    from fatline_verify.prove.views import random_views

    yield from random_views(model, n, seed)
    rng = random.Random(seed)
    rho = model.radius
    for _ in range(n):
        pts: list[tuple[int, int]] = []
        for _ in range(40):
            p = (rng.randint(-4 * rho, 4 * rho), rng.randint(-4 * rho, 4 * rho))
            d2 = p[0] ** 2 + p[1] ** 2
            apart = all((p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 >= model.contact2 for c in pts)
            if model.sees(d2) and d2 >= model.contact2 and apart:
                pts.append(p)
        yield tuple(sorted(pts))


@pytest.mark.parametrize("q", [1, 2])
def test_the_concrete_and_the_symbolic_guard_agree_on_random_and_crowded_views(q):
    """For each leg class of the repaired family, each end in one radius, on random and crowded views: the
    concrete interpreter (what the engines run) equals the z3 term (what the prover assumes) on the ground
    view, for the shape, the guard (with its witnesses) and at_rest."""
    model = repaired(q)
    rho = model.radius
    ends = [(dx, dy) for dx in range(-rho, rho + 1) for dy in range(-rho, rho + 1) if (dx, dy) != (0, 0)]
    rng = random.Random(q)
    seen = {"true": 0, "false": 0}
    for view in _views(model, 40, q):
        for cls in LEGS.classes:
            for destination in rng.sample(ends, 3):
                g = Ground(model, view, {"me": (0, 0), "end": destination})
                for cond in (cls.shape, cls.guard, LEGS.at_rest):
                    got = holds(cond, g)
                    assert got == _z3_holds(cond, view, destination, model), (view, cls.name, destination)
                    seen["true" if got else "false"] += 1
    assert seen["true"] and seen["false"], seen


def test_a_condition_is_never_a_python_bool():
    with pytest.raises(TypeError, match="not a bool"):
        bool(me.x > 0)
    with pytest.raises(TypeError, match="not a bool"):
        if forall(lambda c: sees(end, c)):  # an `if` on a guard is caught where it is written
            pass


PROGRESS = ["off", "detour"]
"""``repair_progress``: the detour's moves are legs of the same classes."""


@pytest.mark.parametrize("progress", PROGRESS)
@settings(max_examples=200, deadline=None)
@given(swarms())
def test_every_repaired_decision_is_in_its_family(progress, case):
    """What the checker's in-family lemma judges, on random swarms: each move of the repaired rules is
    admitted by its family (a leg of a class whose shape and guard hold)."""
    q, state, _ = case
    model = repaired(q, repair_progress=progress)
    for i, d in decide_all(state, model).items():
        assert LEGS.admit(snapshot(state, i, model), d, model) is None, (state, i, d)


@pytest.mark.parametrize("progress", PROGRESS)
@settings(max_examples=200, deadline=None)
@given(swarms())
def test_each_edge_before_a_round_is_a_path_of_at_most_two_edges_after(progress, case):
    """The argument's conclusion on real rounds: every edge of the graph before the round is an edge
    after it, or a path of two edges."""
    q, state, active = case
    model = repaired(q, repair_progress=progress)
    result = play_round(state, active, model)

    def sees2(a, b) -> bool:
        return model.sees((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)

    before, after = result.before, result.after
    for i in range(len(state)):
        for j in range(i + 1, len(state)):
            if sees2(before[i], before[j]) and not sees2(after[i], after[j]):
                assert any(sees2(after[i], after[k]) and sees2(after[k], after[j]) for k in range(len(state))), (
                    state,
                    active,
                )


def test_the_obligations_cover_every_pair_of_classes_and_each_witness():
    got = [t for t in tasks_for(repaired()) if isinstance(t, FamilySpec)]
    pairs = {(s.lemma, s.form, s.mine, s.other, s.witness) for s in got}
    assert len(pairs) == len(got) == len(specs(LEGS, (Lemma.NO_COLLISION, Lemma.CONNECTIVITY)))
    names = [c.name for c in LEGS.classes]
    for mine in names:
        for other in (REST, *names):
            for witness in (REST, *names):
                assert (Lemma.CONNECTIVITY, BRIDGED, mine, other, witness) in pairs
            either = {(mine, other), (other, mine)}
            for lemma, form in ((Lemma.NO_COLLISION, LEG), (Lemma.CONNECTIVITY, KEPT)):
                assert any((lemma, form, a, b, "") in pairs for a, b in either), (form, mine, other)
    views = [t for t in tasks_for(repaired()) if isinstance(t, ViewsSpec)]
    assert {v.lemma for v in views} == {Lemma.NO_COLLISION, Lemma.CONNECTIVITY}


@pytest.mark.parametrize(
    "spec",
    [s for s in specs(LEGS, (Lemma.NO_COLLISION, Lemma.CONNECTIVITY))],
    ids=lambda s: s.key,
)
def test_every_obligation_of_the_repaired_family_is_proved(spec):
    """The repaired verdicts, golden: every obligation of its family PROVED for every swarm size."""
    got = prove_family(repaired(), spec, timeout=30, out=None)
    assert got.verdict is Verdict.PROVED and got.any_size, got.reason


def test_an_obligation_file_states_the_argument(tmp_path):
    spec = FamilySpec(Lemma.CONNECTIVITY, KEPT, "top", "bottom")
    got = prove_family(repaired(), spec, timeout=20, out=tmp_path)
    assert got.verdict is Verdict.PROVED, got.reason
    text = (tmp_path / "connectivity" / "kept-top.and.bottom.smt2").read_text()
    assert "Why unsat covers swarms of every size" in text and "(check-sat)" in text and "move family" in text


def test_a_guard_weaker_than_the_rules_gives_no_counterexample():
    """Without the clearance the family admits r's leg through o; the repaired rules refuse that leg, so
    the replay says so (INCONCLUSIVE), never VIOLATED."""
    horizontal = LEGS.get("horizontal")
    weak = LegClass("horizontal", horizontal.shape, forall(lambda c: c.x >= me.x), "no clearance")
    family = MoveFamily("weak", (weak,), max_step=1, at_rest=LEGS.at_rest)
    from fatline_verify.prove import family as proving

    spec = FamilySpec(Lemma.NO_COLLISION, LEG, "horizontal", REST)
    original = proving.family_for
    try:
        proving.family_for = lambda model: family  # type: ignore[assignment]
        got = prove_family(repaired(), spec, timeout=10, out=None)
    finally:
        proving.family_for = original  # type: ignore[assignment]
    assert got.verdict is Verdict.INCONCLUSIVE, got.reason
    assert "not a counterexample" in got.reason or "keeps the claim" in got.reason, got.reason


def test_the_views_row_reads_the_rule_set_on_a_sample():
    model = repaired()
    got = prove_views(model, ViewsSpec(Lemma.NO_COLLISION), sample=3000)
    assert got.verdict is Verdict.INCONCLUSIVE and "no decision leaves the family" in got.reason, got.reason
    assert check_views(model, 3000).moving > 0


@pytest.mark.slow
def test_every_view_of_the_lattice_is_in_the_family():
    """The row PROVED: decide on every view at q = 1 (1,624,375 views, about 40 s)."""
    got = prove_views(repaired(), ViewsSpec(Lemma.CONNECTIVITY))
    assert got.verdict is Verdict.PROVED, got.reason


def test_a_family_refuses_what_it_cannot_mean():
    with pytest.raises(ValueError, match="at least one leg class"):
        MoveFamily("empty", (), max_step=1)
    with pytest.raises(ValueError, match="not 'rest'"):
        LegClass("rest", end.x > me.x, forall(lambda c: clear(c)))
    with pytest.raises(ValueError, match="positive length"):
        MoveFamily("still", LEGS.classes, max_step=0)
    with pytest.raises(ValueError, match="at_rest names a witness"):
        MoveFamily("odd", LEGS.classes, max_step=1, at_rest=exists(lambda b: b.x < me.x, role="left"))
    with pytest.raises(TypeError, match="constants only"):
        me.x * me.y


@pytest.mark.parametrize("missing", ["repair_lock", "repair_step", "repair_clear", "repair_edges"])
def test_a_repaired_model_without_the_repairs_the_family_needs_is_refused(missing, capsys, tmp_path):
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
    """``repair_progress = corner`` makes legs the family does not have: one line, exit 2, no files."""
    from fatline_verify.cli import main

    with pytest.raises(InvalidInput, match=r"repair_progress='corner'.*expected off or detour"):
        tasks_for(repaired(repair_progress="corner"))
    source = (Path(__file__).resolve().parent.parent / "bench" / "repaired-progress.toml").read_text()
    model = tmp_path / "corner.toml"
    model.write_text(source.replace('repair_progress = "detour"', 'repair_progress = "corner"'))
    assert main(["prove", str(model), "--out", str(tmp_path / "p"), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert "repair_progress='corner'" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "p").exists()


def test_edge_roles_are_the_witnesses_inside_a_forall_only():
    """A witness inside a ``forall`` vouches for an edge (a bridge: bridged rows, and the coverage asks for
    them); one outside every ``forall`` is what the leg needs its mover to see, and bridges no edge."""
    from fatline_verify.rules.family.lang import edge_roles, exists, forall, roles, sees

    ahead = exists(lambda a: a.x > me.x, role="ahead")
    bridged = forall(lambda c: sees(end, c) | exists(lambda b: sees(b, c), role="bridge"))
    assert roles(ahead & bridged) == ("ahead", "bridge")
    assert edge_roles(ahead & bridged) == ("bridge",)
    assert edge_roles(ahead) == ()


# --- a policy held to its family by construction -----------------------------------------------------

_HELD_FAMILY = MoveFamily(
    "held-test-right",
    (
        LegClass(
            "right",
            (end.y == me.y) & (end.x > me.x) & (end.x <= me.x + 1),
            forall(lambda c: clear(c) & sees(end, c)),
        ),
    ),
    max_step=1,
)


def _proposals(snapshot, model):
    """Left first (no class has that shape), then right (admitted where the way is clear), then a stay."""
    from fatline_verify.rules.decision import stay, step

    yield step("left", (-model.radius, 0))
    yield step("right", (model.radius, 0))
    yield stay("wait")


def test_a_held_policy_takes_the_first_proposal_its_family_admits():
    from fatline_verify.rules.family.held import HELD, held

    model = repaired()
    decide = held(_proposals, _HELD_FAMILY)
    rho = model.radius
    assert decide(((3 * rho, 0),), model).rule == "right"  # left refused, right admitted
    assert decide(((2 * rho, 0),), model).rule == "wait"  # right meets the robot: the stay
    only_bad = held(lambda s, m: iter([_proposals(s, m).__next__()]), _HELD_FAMILY)
    assert only_bad(((3 * rho, 0),), model).rule == HELD  # nothing admitted, nothing proposed after: stays


def test_the_views_row_of_a_held_rule_set_is_proved_by_construction_without_reading_a_view():
    from dataclasses import replace

    from fatline_verify.rules.family.held import held
    from fatline_verify.rules.registry import RuleSet, register

    rule_set = register(RuleSet("held-test-right", held(_proposals, _HELD_FAMILY), "held (tests)", family=_HELD_FAMILY))
    model = replace(repaired(), rules=rule_set.name)
    got = prove_views(model, ViewsSpec(Lemma.CONNECTIVITY))
    assert got.verdict is Verdict.PROVED and "by construction" in got.reason and got.seconds == 0.0, got.reason
    loose = register(RuleSet("held-test-loose", held(_proposals, None), "held to nothing (tests)", family=_HELD_FAMILY))
    got = prove_views(replace(repaired(), rules=loose.name), ViewsSpec(Lemma.CONNECTIVITY), sample=200)
    assert "by construction" not in got.reason, got.reason  # held to no family: the views are read
