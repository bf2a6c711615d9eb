"""The certified rule set's move family (``fatline_verify/rules/certified/family.py``): it admits certified's
decisions (the rule set holds each to it: ``Held``), catches a decision outside it, its chains are certified's
closure over hops, its obligations split on the witnesses that rule a leg out and induct over x, and the
prover's verdicts on it (golden: every obligation PROVED)."""

from __future__ import annotations

import random
from fractions import Fraction

import pytest

from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model
from fatline_verify.prove.family import prove_family
from fatline_verify.prove.smt.family import ANSWERED, BRIDGED, FIRST, KEPT, LEG, LINK, RULES, FamilySpec, specs
from fatline_verify.prove.tasks import ViewsSpec, tasks_for
from fatline_verify.prove.views import random_views
from fatline_verify.rules import registry
from fatline_verify.rules.certified.algorithm import allowed, decide, propose, region
from fatline_verify.rules.certified.family import CHAIN, family, family_for_q, steps
from fatline_verify.rules.certified.family import decide as held_decide
from fatline_verify.rules.decision import Decision
from fatline_verify.rules.family.enforce import violators
from fatline_verify.rules.family.lang import Ground, holds
from fatline_verify.rules.registry import RuleSet, register
from fatline_verify.schedulers.round import Collision, play_round

MODEL = load_model("certified")


def certified(q: int = 1):
    return MODEL.with_q(q)


def test_the_rule_set_declares_its_family_for_each_lattice():
    assert registry.family(certified(1)) is family_for_q(1)
    assert registry.family(certified(2)) is family_for_q(2)
    names = [c.name for c in family_for_q(2).classes]
    assert names == ["right", "right-1of2", "up-right", "down-right", "down", "down-1of2", "up", "up-1of2"]
    assert set(family_for_q(1).rules_out.values()) == {c.name for c in family_for_q(1).classes}


@pytest.mark.parametrize(("q", "views"), [(1, 1500), (2, 600)])
def test_the_family_admits_nearly_every_move_of_the_rules_and_the_rule_set_only_those(q, views):
    """On random views (sparse and crowded): the rules' own first choice (``algorithm.decide``) lies in the family
    but for a handful (a robot that sees no robot r sees keeps its edge to r: the region's last exclusion, which
    the guard language does not state); the rule set's decide (``Held``) is the first proposal the family
    admits: the rules' choice wherever it is admitted, an admitted one everywhere."""
    model = certified(q)
    fam = family(model)
    moving = outside = 0
    for view in random_views(model, views, q):
        raw, got = decide(view, model), held_decide(view, model)
        assert fam.admit(view, got, model) is None, (view, got.rule, got.destination)
        if raw.moves:
            moving += 1
            if fam.admit(view, raw, model) is None:
                assert got == raw
            else:
                outside += 1
                assert got in list(propose(view, model))
    assert moving > views // 4
    assert outside <= moving // 100, (outside, moving)


def _step(dest) -> Decision:
    return Decision("reckless", dest, ((0, 0), dest), ())  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("view", "dest", "why"),
    [
        # through a robot at rest: the path is not clear
        (((2, 0),), (1, 0), "fails the guard of right"),
        # a robot left of r 4 radii away may step up-right to (-3, 1), out of view of r's end (1, 0): r's own
        # test refuses the step too (the robot's region has that leg)
        (((-4, 0),), (1, 0), "fails the guard of right"),
        # certified never moves left: no class has that shape
        (((3, 0),), (-1, 0), "no leg class has the shape"),
    ],
)
def test_a_decision_outside_the_family_is_caught(view, dest, why):
    model = certified(1)
    got = family(model).admit(view, _step(dest), model)
    assert got is not None and why in got, got
    if dest == (1, 0) and view == ((-4, 0),):
        c = view[0]
        left = {c: [e for _, e in region(c, view, model)]}
        assert not allowed("right", dest, view, model, {}, left)


def _reckless(snapshot, model):
    """Certified's decision, but one radius right whenever nothing is in the way at rest: what certified's
    regions forbid."""
    if snapshot and all((x - model.radius) ** 2 + y * y >= 4 * model.radius**2 for x, y in snapshot):
        return _step((model.radius, 0))
    return decide(snapshot, model)


RECKLESS = register(
    RuleSet("certified-reckless-test", _reckless, "certified's family, a reckless policy (tests).", family=family)
)


def test_the_in_family_lemma_flags_a_policy_that_leaves_the_family():
    """A rule set with certified's family whose policy steps right past the regions: the step lemma names
    the robot (what the checker reports, with its trace)."""
    from dataclasses import replace

    model = replace(MODEL, rules=RECKLESS.name)
    # r0 sees only r1, 4 left of it; the reckless step right may lose r1 (it may step up-right to (-3, 1))
    before, after = ((0, 0), (-4, 0)), ((1, 0), (-4, 0))
    assert _reckless(((-4, 0),), model).destination == (1, 0)
    assert violators(before, after, model) == [0]
    assert violators(before, before, model) == []


@pytest.mark.parametrize(
    ("view", "dest", "path"),
    [
        # r0 falls; r2 (3, 0) right of it, taken at rest, sees r1 (3, 3): r2 moves or carries the edge
        (((2, 3), (2, 0)), (0, -1), "a robot right of r taken at rest"),
        # r steps right; (-4, 0) is reached through (-2, 0), every place of each seeing every place of the next
        (((-4, 0), (-2, 0), (3, 0)), (1, 0), "two hops"),
    ],
)
def test_a_chain_is_certified_s_closure_over_hops(view, dest, path):
    """The chains of the family reach what certified's closure reaches: a robot right of r at rest, and several
    hops; a direct edge is not needed for either."""
    model = certified(1)
    fam = family(model)
    (cls,) = [c for c in fam.classes if holds(c.shape, Ground(model, (), {"me": (0, 0), "end": dest}))]
    assert holds(cls.guard, Ground(model, view, {"me": (0, 0), "end": dest})), path
    assert not all(model.sees((dest[0] - x) ** 2 + (dest[1] - y) ** 2) for x, y in view), path


# --- the symbolic side -------------------------------------------------------------------------------


def test_the_concrete_and_the_symbolic_guard_agree_on_random_views():
    """The certified family's guards read by both interpreters on ground views (every robot named; a chain is the
    closure over the named robots): the two chains of the test above, and random views of two robots (the z3
    term of a guard with chains grows fast with the robots named: 5 s at three, 18 s at four)."""
    from tests.test_family import _z3_holds

    model = certified(1)
    fam = family(model)
    rng = random.Random(7)
    seen = {True: 0, False: 0}
    cases = [(((2, 3), (2, 0)), (0, -1)), (((-4, 0), (-2, 0), (3, 0)), (1, 0))]
    views = [v[:2] for v in random_views(model, 30, 3) if len(v) >= 2][:8]
    for view in views:
        s = rng.choice(steps(1))
        cases.append((view, (int(s[2]), int(s[3]))))
    for view, dest in cases:
        (cls,) = [c for c in fam.classes if holds(c.shape, Ground(model, (), {"me": (0, 0), "end": dest}))]
        got = holds(cls.guard, Ground(model, view, {"me": (0, 0), "end": dest}))
        assert got == _z3_holds(cls.guard, view, dest, model), (view, cls.name)
        seen[got] += 1
    assert seen[True] >= 2 and seen[False], seen


def test_the_obligations_split_on_every_ruled_out_leg_and_prove_each_chain_link():
    """Plain leg and kept obligations for every pair, a .by.block_W obligation for every class of r and each class
    W of o, the induction's answered rows (o below r), the chain's first links and links (every class or rest of
    each robot), a rules-out row per block role, no bridged row (the chain is no witness), and the views rows."""
    fam = family_for_q(1)
    got = [t for t in tasks_for(MODEL) if isinstance(t, FamilySpec)]
    names = [c.name for c in fam.classes]
    by = {(s.lemma, s.form, s.mine, s.other) for s in got if s.role and s.form in (LEG, KEPT)}
    for lemma, form in ((Lemma.NO_COLLISION, LEG), (Lemma.CONNECTIVITY, KEPT)):
        assert {(lemma, form, a, b) for a in names for b in names} <= by
    assert not [s for s in got if s.form == BRIDGED]
    assert {s.role for s in got if s.form in (FIRST, LINK)} == {CHAIN}
    n = len(names)
    forms = {f: len([s for s in got if s.form == f]) for f in (ANSWERED, FIRST, LINK, RULES)}
    assert forms == {ANSWERED: n * n, FIRST: n * (n + 1), LINK: n * (n + 1) ** 2, RULES: n}
    assert len(got) == 2 * (n + n * (n + 1) // 2 + n * n) + n * n + n * (n + 1) + n * (n + 1) ** 2 + n
    assert len(got) == len(specs(fam, (Lemma.NO_COLLISION, Lemma.CONNECTIVITY)))
    assert {t.lemma for t in tasks_for(MODEL) if isinstance(t, ViewsSpec)} == {Lemma.NO_COLLISION, Lemma.CONNECTIVITY}


@pytest.mark.parametrize(
    "key",
    [
        "no-collision/leg-right.and.up-right",  # the witness roles false: r checks o's leg directly
        "no-collision/leg-right.and.right.by.block_right",  # o's own guard contradicts the witness
        "no-collision/leg-up.and.up.by.block_up",
        "connectivity/kept-right.and.down",
        "connectivity/kept-up.and.down.by.block_down",  # o's guard at the named witness (not a chain's)
        "connectivity/answered-right.and.down",
        "connectivity/chain-first-down.and.up.by.chain",
        "connectivity/chain-link-right.and.down-right.by.chain-up",
        "connectivity/chain-link-up.and.rest.by.chain-right",
        "connectivity/rules-out-rest.and.up.by.block_up",
    ],
)
def test_rows_the_split_proves(key):
    spec = next(s for s in specs(family(MODEL), (Lemma.NO_COLLISION, Lemma.CONNECTIVITY)) if s.key == key)
    got = prove_family(MODEL, spec, timeout=20, out=None)
    assert got.verdict is Verdict.PROVED and got.any_size, got.reason


def test_two_movers_out_of_view_collide_off_the_lattice():
    """A finding of the family's obligations (the plain leg of up and down-right is satisfiable over the reals):
    certified collides, played by its own rules: r0 contracts up while r1, out of its view (just over rad_v
    away) and left of it, steps down-right; a diagonal step is sqrt(2) radii long at q = 1 and the two close
    by sqrt(5) radii. Off the model's lattice only (quarter radii): on the lattice q = 1 every pair of steps
    from out of view stays two radii apart (tests/test_certified.py)."""
    model = MODEL
    state = ((0, 0), (Fraction(-5, 2), Fraction(13, 4)), (0, Fraction(29, 8)))
    result = play_round(state, [0, 1], model)
    assert [d.rule for d in (result.decisions[0], result.decisions[1])] == ["contract-up", "down-right"]
    assert any(isinstance(v, Collision) and v.robots == (0, 1) for v in result.violations)
    assert not model.sees((state[1][0]) ** 2 + (state[1][1]) ** 2)  # r0 and r1 do not see each other


def test_a_ruled_out_case_never_occurs():
    """The .by.block_W obligations: r's witness shows o cannot move by W while o does: PROVED."""
    spec = next(
        s
        for s in specs(family(MODEL), (Lemma.NO_COLLISION,))
        if s.key == "no-collision/leg-up.and.down-right.by.block_down_right"
    )
    got = prove_family(MODEL, spec, timeout=20, out=None)
    assert got.verdict is Verdict.PROVED, got.reason


@pytest.mark.slow
def test_prove_certified_proves_no_collision_and_connectivity(tmp_path, capsys):
    """The whole run (332 rows, a few minutes on 2 cores): both lemmas PROVED at lemma level, every row PROVED."""
    import json

    from fatline_verify.cli import main

    assert main(["prove", "certified", "--out", str(tmp_path), "--jobs", "2"]) == 0
    out = capsys.readouterr().out
    assert "no-collision: PROVED" in out and "connectivity: PROVED" in out, out
    rows = json.loads((tmp_path / "certified" / "results.json").read_text())["obligations"]
    assert len(rows) == 332 and {r["verdict"] for r in rows} == {"PROVED"}
