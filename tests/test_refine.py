"""The liveness cases held to decide (issue 37, holes 3 and 6): every view a robot can have, decide's
decision on it in a declared case with decide's destination (:mod:`fatline_verify.prove.refine`).

The views are counted and enumerated two ways; the compiled evaluator is held to z3 itself; the
paper's cases cover a sample of views (every view: the slow tier); a toy plug-in that leaves a
decision case out gets progress PROVED by its remaining rows, and the check names a view of the
missing case, whose decision replays."""

from __future__ import annotations

import random
from collections.abc import Iterator
from fractions import Fraction

import pytest
import z3

from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model, model_from_mapping
from fatline_verify.prove import refine
from fatline_verify.prove import views as lattice_views
from fatline_verify.prove.live import prove_live
from fatline_verify.prove.smt.cases import Arith, same
from fatline_verify.prove.smt.live_rules import LiveCase, live_cases
from fatline_verify.prove.smt.liveness import ENABLED, LiveSpec
from fatline_verify.prove.tasks import tasks_for
from fatline_verify.rules import registry
from fatline_verify.schedulers.round import collides, decide_all
from tests.test_live import _toy_cases, _toy_decide


@pytest.fixture(scope="module")
def paper():
    return load_model("paper")


# --- the views ------------------------------------------------------------------------------------


def test_the_views_at_q1_rad4_are_counted_as_the_issue_says(paper) -> None:
    """40 points a robot can see another at (49 lattice points within 4, less the 9 within the
    decider's own disc's reach), and 1,624,375 sets of them with disjoint discs, the empty one included."""
    points = lattice_views.view_points(paper)
    assert len(points) == 40
    assert all(4 <= x * x + y * y <= 16 for x, y in points)
    assert lattice_views.count_views(paper) == 1_624_375


def _grown(model) -> set[frozenset[tuple[int, int]]]:
    """Every view, by another route: grown one robot at a time from the empty view."""
    points = lattice_views.view_points(model)
    level = {frozenset()}
    seen = set(level)
    while level:
        nxt = set()
        for view in level:
            for p in points:
                if p not in view and not any(collides((p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2, model) for c in view):
                    nxt.add(view | {p})
        level = nxt - seen
        seen |= level
    return seen


def test_the_enumeration_is_every_view_once_on_a_smaller_lattice() -> None:
    small = model_from_mapping({"name": "small", "rules": "paper", "parameters": {"rad_v": 3, "q": 1}})
    views = list(lattice_views.all_views(small))
    assert len(views) == len(set(views)) == lattice_views.count_views(small)
    assert {frozenset(v) for v in views} == _grown(small)
    assert views[0] == ()


# --- the compiled cases against z3 ----------------------------------------------------------------


def _z3_holds(model, case: LiveCase, view, dest) -> tuple[bool, bool]:
    """z3's answer: does ``case`` hold on ``view`` (roles among the view's robots and the decider),
    and does it with destination ``dest``."""
    ar = Arith(model.parameters.q)
    me = ar.origin()
    universe = [(ar.num(x), ar.num(y)) for x, y in view]
    roles = {name: ar.point(name) for name in case.roles}
    cs, d = case.encode(ar, model, me, roles, universe)
    dom = [me, *universe]
    solver = z3.Solver(ctx=ar.ctx)
    solver.add(*cs)
    solver.add(*[z3.Or(*[same(p, o) for o in dom]) for p in roles.values()])
    held = solver.check() == z3.sat
    solver.add(d[0] == ar.num(dest[0]), d[1] == ar.num(dest[1]))
    return held, held and solver.check() == z3.sat


def test_the_compiled_cases_agree_with_z3_on_random_views(paper) -> None:
    """Per view, the cases the evaluator says hold (and hold with decide's destination) are the
    cases z3 finds roles for, among all 29 of the paper's cases."""
    cases, get = refine.checkers(paper)
    rng = random.Random(3)
    views = list(lattice_views.random_views(paper, 10, seed=11))
    matched = 0
    for view in views:
        dest = registry.decide(view, paper).destination
        hold, match = get(len(view))(view, dest)
        matched += bool(match)
        names = range(len(cases)) if len(view) < 3 else [*hold, *rng.sample(range(len(cases)), 4)]
        for c in names:
            assert _z3_holds(paper, cases[c], view, dest) == (c in hold, c in match), (view, cases[c].name)
    assert matched == len(views)


# --- the paper -------------------------------------------------------------------------------------


def test_the_paper_cases_cover_a_sample_of_views(paper) -> None:
    got = refine.sampled(paper, 3000, seed=1)
    assert got.views == 3000 and not got.exhaustive
    assert got.uncovered == 0, [s.describe(paper) for s in got.uncovered_views]
    assert got.overlapping == 0, [s.describe(paper) for s in got.overlapping_views]
    moving = sum(n for name, n in got.per_case.items() if name.startswith("scenario"))
    assert got.per_case["nomovement-1-alone"] > 0 and moving > 100  # the sample reaches the moving cases
    assert sum(got.per_case.values()) == got.covered == 3000


@pytest.mark.slow
def test_the_paper_cases_cover_every_view(paper) -> None:
    """Every one of the 1,624,375 views at q = 1, each in exactly one case (two processes: 292 s of
    checking and about 30 s of compiling, measured on a shared machine)."""
    got = refine.coverage(paper, processes=2)
    assert got.exhaustive and got.views == 1_624_375
    assert got.uncovered == 0, [s.describe(paper) for s in got.uncovered_views]
    assert got.overlapping == 0, [s.describe(paper) for s in got.overlapping_views]


# --- plug-in toys: the complete case list, and one that leaves a case out --------------------------


@pytest.fixture
def toys() -> Iterator[dict[str, object]]:
    """``toy-far`` (moves right to the nearest robot seen more than one radius right, else stays)
    with both its cases, and ``toy-far-no-stay`` deciding alike with its staying case left out."""
    registry.names()  # every rule set loaded first: the registry is restored to all of them afterwards
    before = dict(registry._REGISTRY)
    full = _toy_cases(1)

    def without_stay(model):
        return [c for c in full(model) if c.name != "stay"]

    for name, cases in (("toy-far", full), ("toy-far-no-stay", without_stay)):
        registry.register(
            registry.RuleSet(
                name,
                _toy_decide(1),
                "a toy: right to the nearest robot seen more than 1 radius right",
                liveness=registry.Liveness(
                    cases, ((-1, 0),), "sum of -x", "x never exceeds the initial greatest x", True
                ),
            )
        )
    yield {
        name: model_from_mapping(
            {
                "name": name,
                "rules": name,
                "parameters": {"rad_v": 4, "q": 1},
                "options": {"scheduler": "ssync"},
                "bounds": {"robots": "2..3", "window": "7x7"},
            }
        )
        for name in ("toy-far", "toy-far-no-stay")
    }
    registry._REGISTRY.clear()
    registry._REGISTRY.update(before)


def test_a_complete_toy_is_covered(toys) -> None:
    model = toys["toy-far"]
    got = refine.sampled(model, 3000, seed=2)
    assert got.uncovered == 0 and got.overlapping == 0
    assert got.per_case["stay"] > 0 and got.per_case["right"] > 0
    row = refine.prove_coverage(model, sample=500)
    assert row.verdict is Verdict.INCONCLUSIVE and row.key == refine.KEY  # a sample proves nothing


def test_a_toy_missing_its_staying_case_is_caught_with_a_view_that_replays(toys, tmp_path) -> None:
    """The issue's hole: with the staying case left out, the remaining enabledness row is PROVED
    (nothing says a robot may stay) while the rules deadlock; the check names a view of the missing
    case, decide stays there, and the complete toy's staying case is that decision."""
    model, complete = toys["toy-far-no-stay"], toys["toy-far"]
    assert [t.key for t in tasks_for(model, (Lemma.PROGRESS,))] == ["progress/enabled-right", refine.KEY]
    proved = prove_live(model, LiveSpec(Lemma.PROGRESS, ENABLED, "right"), timeout=10, out=tmp_path)
    assert proved.verdict is Verdict.PROVED, proved.reason

    got = refine.sampled(model, 400, seed=4)
    assert got.uncovered > 0 and got.uncovered_views
    stay = next(c for c in live_cases(complete) if c.name == "stay")
    _, get = refine.checkers(complete)
    for seen in got.uncovered_views:
        decision = registry.decide(seen.view, model)
        assert not decision.moves and seen.destination == decision.destination == (0, 0)
        assert seen.rule == decision.rule == "stay" and seen.matching == ()
        assert not any(p[0] > model.radius for p in seen.view)  # nothing seen more than a radius right
        _, match = get(len(seen.view))(seen.view, decision.destination)
        assert [live_cases(complete)[c].name for c in match] == [stay.name]
        assert _z3_holds(complete, stay, seen.view, decision.destination) == (True, True)
    # the decisions it does describe are covered
    assert got.per_case["right"] == got.covered > 0

    row = refine.prove_coverage(model, sample=400)
    assert row.verdict is Verdict.VIOLATED and row.key == "progress/coverage-cases"
    view = tuple(tuple(Fraction(v) for v in c.split(",")) for c in row.configuration)
    assert view[0] == (0, 0) and "stay" in row.reason
    assert registry.decide(tuple(model.to_lattice(p) for p in view[1:]), model).rule == "stay"
    assert refine.refinement_gap([_row(row)]) is not None
    assert "VIOLATED" in (refine.refinement_gap([_row(row)]) or "")


def test_a_stuck_swarm_among_the_uncovered_views(toys) -> None:
    """An uncovered view of the toy, its robots and the decider as a swarm: nobody moves (the deadlock
    the bounded checker replays, which the remaining case's PROVED row hid)."""
    model = toys["toy-far-no-stay"]
    got = refine.coverage(model, [((1, 2),), ((2, 0),), ((0, 2), (1, -2))])
    assert got.views == 3 and got.covered == 1
    stuck = [s.view for s in got.uncovered_views]
    assert stuck == [((1, 2),), ((0, 2), (1, -2))]
    for view in stuck:
        state = ((0, 0), *view)
        assert not any(d.moves for d in decide_all(state, model).values())


def _row(result) -> dict[str, object]:
    return {
        "lemma": str(result.lemma),
        "form": result.form,
        "rule": result.rule,
        "case": result.case,
        "verdict": str(result.verdict),
        "reason": result.reason,
    }


def test_the_lemma_level_hook_reads_the_coverage_row() -> None:
    row = {"lemma": "progress", "form": "coverage", "rule": "any", "case": "cases", "verdict": "PROVED"}
    assert refine.refinement_gap([row]) is None
    assert "not run" in (refine.refinement_gap([]) or "")
    assert "INCONCLUSIVE" in (refine.refinement_gap([{**row, "verdict": "INCONCLUSIVE"}]) or "")


def test_a_term_the_evaluator_does_not_know_is_refused_by_name(toys) -> None:
    """A case using integer division: the compiler names it instead of guessing its semantics."""
    model = toys["toy-far"]

    def odd(ar, model, me, roles, universe):
        return [z3.Or(*[(p[0] / ar.num(2)) > ar.num(0) for p in universe]) if universe else ar.true()], (
            ar.num(0),
            ar.num(0),
        )

    with pytest.raises(refine.NotCompilable, match="operator"):
        refine._compile(model, [LiveCase("odd", (), False, odd)], 2)


def test_fatline_cover_names_the_uncovered_view_and_exits_1(toys, tmp_path, capsys) -> None:
    from fatline_verify.cli import main

    for name, code in (("toy-far-no-stay", 1), ("toy-far", 0)):
        path = tmp_path / f"{name}.toml"
        path.write_text(
            f'name = "{name}"\nrules = "{name}"\n[parameters]\nrad_v = 4\nq = 1\n[options]\nscheduler = "ssync"\n'
        )
        assert main(["cover", str(path), "--sample", "300"]) == code
        out = capsys.readouterr().out
        assert out.startswith(f"progress/coverage-cases: {'VIOLATED' if code else 'INCONCLUSIVE'}")
        assert ("decide says stay" in out) == bool(code)
    assert main(["cover", "repaired"]) == 2


def test_the_paper_with_scenario_1_left_out_is_caught_on_its_views(paper) -> None:
    """The paper's own decide and encoding, Scenario 1's case left out of the declaration: exactly
    its views are uncovered, and no other case holds on them (the cases are disjoint there)."""
    from fatline_verify.rules.paper.rule_set import PAPER

    def without_s1(model):
        return [c for c in live_cases(paper) if c.name != "scenario-1"]

    registry.names()  # every rule set loaded first: the registry is restored to all of them afterwards
    before = dict(registry._REGISTRY)
    assert PAPER.liveness is not None
    registry.register(
        registry.RuleSet(
            "paper-no-s1", PAPER.decide, "the paper, Scenario 1 undeclared", options=PAPER.options,
            liveness=registry.Liveness(without_s1, PAPER.liveness.measure, "", ""),
        )
    )  # fmt: skip
    try:
        model = model_from_mapping({"name": "paper-no-s1", "rules": "paper-no-s1", "parameters": {"rad_v": 4, "q": 1}})
        views = [v for v in lattice_views.random_views(paper, 2000, seed=5) if len(v) <= 4]  # few sizes to compile
        s1 = [v for v in views if registry.decide(v, paper).rule == "scenario-1"][:8]
        others = [v for v in views if registry.decide(v, paper).rule != "scenario-1"][:8]
        assert len(s1) == 8 and len(others) == 8
        got = refine.coverage(model, s1 + others)
        assert got.views == 16 and got.covered == 8 and got.overlapping == 0
        assert [s.view for s in got.uncovered_views] == s1[: refine.SHOWN]
        assert all(s.rule == "scenario-1" and s.holding == () for s in got.uncovered_views)
    finally:
        registry._REGISTRY.clear()
        registry._REGISTRY.update(before)


def test_an_uncovered_view_leaves_progress_not_proved_at_lemma_level(toys) -> None:
    """Every row of the toy without its staying case PROVED, its coverage row VIOLATED: progress must
    not be PROVED (nor VIOLATED: an uncovered view is a hole in the argument, not a stuck swarm)."""
    from fatline_verify.prove.coverage import liveness_verdicts

    model = toys["toy-far-no-stay"]
    rows = [
        {"lemma": str(t.lemma), "form": t.form, "rule": "any", "case": t.case, "verdict": "PROVED"}
        for t in tasks_for(model, (Lemma.PROGRESS, Lemma.TERMINATION))
        if t.key != refine.KEY
    ]
    rows.append(_row(refine.prove_coverage(model, sample=300)))
    assert rows[-1]["verdict"] == "VIOLATED"
    assert liveness_verdicts(model, rows)[Lemma.PROGRESS][0] == "NOT PROVED"
