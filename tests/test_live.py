"""The liveness obligations (``progress/enabled-CASE``, ``termination/measure-CASE``): their any-size
argument on random and crowded swarms, the paper's verdicts with a replayed stuck configuration, a
known-live toy rule set PROVED and a known-deadlocking one VIOLATED."""

from __future__ import annotations

import random
from collections.abc import Iterator
from fractions import Fraction

import pytest
import z3
from hypothesis import given, settings
from hypothesis import strategies as st

from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model, model_from_mapping
from fatline_verify.model.geometry import dist2
from fatline_verify.model.swarm import initial_problems, is_connected, is_goal
from fatline_verify.prove.live import measure_of, prove_live
from fatline_verify.prove.smt.cases import same, sees
from fatline_verify.prove.smt.live_rules import LiveCase, live_cases
from fatline_verify.prove.smt.liveness import ENABLED, MEASURE, LiveSpec
from fatline_verify.prove.tasks import LEMMAS, NotEncodedModel, tasks_for
from fatline_verify.rules import registry
from fatline_verify.rules.paper.algorithm import Decision
from fatline_verify.rules.paper.cases import case_of, witnesses
from fatline_verify.schedulers.round import decide_all, play_round, snapshot

LIVE = (Lemma.PROGRESS, Lemma.TERMINATION)


@pytest.fixture(scope="module")
def paper():
    return load_model("paper")


# --- the any-size argument on the executable model ------------------------------------------------


@st.composite
def lattice_swarms(draw, crowded: bool = False):
    """Robots on the lattice q = 1, pairwise disjoint discs; ``crowded``: packed in a small window."""
    span = 4 if crowded else 8
    points = draw(st.lists(st.tuples(st.integers(-span, span), st.integers(-span, span)), min_size=2, max_size=14))
    out: list[tuple[int, int]] = []
    for p in points:
        if all(dist2(p, c) >= 4 for c in out):
            out.append(p)
    return tuple(out)


def named_robots(state, model):
    """The enabledness obligations' named robot: on the left-most vertical, seeing a robot right of it."""
    left = min(p[0] for p in state)
    return [
        i for i, p in enumerate(state) if p[0] == left and any(o[0] > p[0] and model.sees(dist2(o, p)) for o in state)
    ]


def _argument(state, model) -> None:
    if len(state) < 2 or not is_connected(state, model) or is_goal(state, model):
        return
    named = named_robots(state, model)
    assert named, f"a connected non-goal swarm without the named robot: {state}"
    for i in named:
        me = state[i]
        snap = snapshot(state, i, model)
        full = decide_all(state, model, [i])[i]
        case = case_of(full, model)
        g = next(o for o in snap if o[0] > 0)
        kept = list(dict.fromkeys([*witnesses(full, snap, model), g]))
        sub = (me, *((me[0] + x, me[1] + y) for x, y in kept))
        again = decide_all(sub, model, [0])[0]
        assert case_of(again, model) == case, (state, i)
        assert again.destination == full.destination
        assert i in named_robots(state, model) and 0 in named_robots(sub, model)


@settings(max_examples=150, deadline=None)
@given(lattice_swarms())
def test_named_robot_and_its_witnesses_decide_alike_on_random_swarms(paper, state) -> None:
    """Every connected non-goal swarm has the named robot; it, its case's witnesses and g, taken out of
    the swarm, make the same decision (the witness argument of the enabledness obligations)."""
    _argument(state, paper)


@settings(max_examples=150, deadline=None)
@given(lattice_swarms(crowded=True))
def test_named_robot_and_its_witnesses_decide_alike_on_crowded_swarms(paper, state) -> None:
    _argument(state, paper)


def test_every_move_and_every_round_decreases_the_paper_measure_on_random_swarms(paper) -> None:
    """The converse of the PROVED measure rows: each move of the paper's rules makes the mover's term
    fall by a lattice unit or more, and so does any set of movers together (the sum's argument)."""
    rng = random.Random(7)
    moved = 0
    for _ in range(3000):
        state: list[tuple[int, int]] = []
        for _ in range(rng.randint(2, 7)):
            p = (rng.randint(-5, 5), rng.randint(-5, 5))
            if all(dist2(p, c) >= 4 for c in state):
                state.append(p)
        decisions = decide_all(tuple(state), paper)
        movers = [i for i, d in decisions.items() if d.moves]
        for i in movers:
            alone = measure_of(
                paper, [(state[i][0] + decisions[i].destination[0], state[i][1] + decisions[i].destination[1])]
            )
            assert alone < measure_of(paper, [state[i]])
        if movers:
            moved += 1
            active = [i for i in movers if rng.random() < 0.6] or movers[:1]
            after = play_round(tuple(state), active, paper, decisions).after
            assert measure_of(paper, after) < measure_of(paper, state)
    assert moved > 100


# --- the paper's obligations --------------------------------------------------------------------


def test_tasks_include_liveness_by_default_for_a_rule_set_that_declares_it(paper) -> None:
    keys = [t.key for t in tasks_for(paper)]
    assert "progress/enabled-nomovement-4-only-AI" in keys
    assert "termination/measure-scenario-1" in keys
    assert Lemma.PROGRESS in LEMMAS and Lemma.TERMINATION in LEMMAS
    # one enabledness row per case, one measure row per moving case
    cases = live_cases(paper)
    assert sum(k.startswith("progress/enabled-") for k in keys) == len(cases)
    assert "progress/coverage-cases" in keys  # the cases held to decide on views
    assert sum(k.startswith("termination/") for k in keys) == sum(c.moves for c in cases)


def test_a_rule_set_without_a_declaration_has_no_rows_and_is_refused_by_name() -> None:
    repaired = load_model("repaired")
    assert not [t for t in tasks_for(repaired) if isinstance(t, LiveSpec)]
    with pytest.raises(NotEncodedModel, match="declares no liveness"):
        tasks_for(repaired, (Lemma.PROGRESS,))
    with pytest.raises(NotEncodedModel, match="declares no liveness"):  # a family: safety only
        tasks_for(load_model("certified"), LIVE)


def _paper_spec(model, form, case):
    lemma = Lemma.PROGRESS if form == ENABLED else Lemma.TERMINATION
    return LiveSpec(lemma, form, case)


@pytest.mark.parametrize("case", ["nomovement-1-alone", "nomovement-2-F", "nomovement-3-EFG"])
def test_paper_enabledness_proved_where_the_named_robot_cannot_stay(paper, case, tmp_path) -> None:
    got = prove_live(paper, _paper_spec(paper, ENABLED, case), timeout=20, out=tmp_path)
    assert got.verdict is Verdict.PROVED, got.reason
    text = (tmp_path / "progress" / f"enabled-{case}.smt2").read_text()
    assert "Why unsat covers swarms of every size" in text and "left-most vertical" in text


def test_paper_only_ai_is_a_replayed_stuck_configuration(paper, tmp_path) -> None:
    """Lemma 2 fails: the configuration the row names is stuck under the executable model."""
    got = prove_live(paper, _paper_spec(paper, ENABLED, "nomovement-4-only-AI"), timeout=20, out=tmp_path)
    assert got.verdict is Verdict.VIOLATED, got.reason
    state = tuple(paper.to_lattice(tuple(Fraction(v) for v in c.split(","))) for c in got.configuration)
    assert not initial_problems(state, paper) and not is_goal(state, paper)
    assert not any(d.moves for d in decide_all(state, paper).values())
    assert got.witness is not None and got.witness["outcome"] == "deadlock"


@pytest.mark.parametrize("case", ["scenario-1", "scenario-4-I-empty.from-scenario-2"])
def test_paper_measure_proved_on_a_moving_case(paper, case, tmp_path) -> None:
    got = prove_live(paper, _paper_spec(paper, MEASURE, case), timeout=20, out=tmp_path)
    assert got.verdict is Verdict.PROVED, got.reason
    assert "lattice q=1" in got.reason
    assert "NOT argued" in got.comment  # the paper's measure: its sum of y has no bound


def test_a_goal_the_obligations_do_not_encode_is_not_claimed(tmp_path) -> None:
    literal = load_model("paper-literal")
    got = prove_live(literal, LiveSpec(Lemma.PROGRESS, ENABLED, "nomovement-4-only-AI"), timeout=5, out=tmp_path)
    assert got.verdict is Verdict.INCONCLUSIVE and "goal=any-line" in got.reason


# --- plug-in toys: a live rule set and a deadlocking one -----------------------------------------


def _toy_decide(reach: int):
    """Move to the vertical of the nearest robot seen more than ``reach`` radii to the right, at one's
    own height; otherwise stay."""

    def decide(snap, model):
        far = [p for p in snap if p[0] > reach * model.radius]
        if not far:
            return Decision("stay", (0, 0), ((0, 0),), ())  # type: ignore[arg-type]
        x = min(p[0] for p in far)
        return Decision("right", (x, 0), ((0, 0), (x, 0)), ())  # type: ignore[arg-type]

    return decide


def _toy_cases(reach: int):
    def stay(ar, model, me, roles, universe):
        cs = [z3.Or(same(p, me), z3.Implies(sees(ar, model, me, p), p[0] - me[0] <= ar.num(reach))) for p in universe]
        return cs, (ar.num(0), ar.num(0))

    def right(ar, model, me, roles, universe):
        m = roles["m"]
        cs = [z3.Not(same(m, me)), sees(ar, model, me, m), m[0] - me[0] > ar.num(reach)]
        cs += [
            z3.Or(same(p, me), z3.Implies(z3.And(sees(ar, model, me, p), p[0] - me[0] > ar.num(reach)), p[0] >= m[0]))
            for p in universe
        ]
        return cs, (m[0] - me[0], ar.num(0))

    def cases(model):
        return [LiveCase("stay", (), False, stay), LiveCase("right", ("m",), True, right)]

    return cases


TOYS = {"toy-right": 0, "toy-far": 1}


@pytest.fixture
def toys() -> Iterator[dict[str, object]]:
    registry.names()  # every rule set loaded before the registry is saved (and restored after)
    before = dict(registry._REGISTRY)
    for name, reach in TOYS.items():
        registry.register(
            registry.RuleSet(
                name,
                _toy_decide(reach),
                f"a toy: right to the nearest robot seen more than {reach} radii right",
                liveness=registry.Liveness(
                    _toy_cases(reach),
                    ((-1, 0),),
                    "sum of -x",
                    "x never exceeds the initial greatest x (a robot moves to the x of a robot it sees)",
                    True,
                ),
            )
        )
    models = {
        name: model_from_mapping(
            {
                "name": name,
                "rules": name,
                "parameters": {"rad_v": 4, "q": 1},
                "options": {"scheduler": "ssync"},
                "bounds": {"robots": "2..3", "window": "7x7"},
            }
        )
        for name in TOYS
    }
    yield models
    registry._REGISTRY.clear()
    registry._REGISTRY.update(before)


def test_toy_right_is_proved_live(toys, tmp_path) -> None:
    model = toys["toy-right"]
    tasks = tasks_for(model)
    assert {t.key for t in tasks} == {
        "progress/enabled-stay",
        "progress/enabled-right",
        "termination/measure-right",
        "progress/coverage-cases",
    }
    for task in (t for t in tasks if isinstance(t, LiveSpec)):
        got = prove_live(model, task, timeout=10, out=tmp_path)
        assert got.verdict is Verdict.PROVED, (task.key, got.reason)
    with pytest.raises(NotEncodedModel, match="only this rule set's liveness"):
        tasks_for(model, (Lemma.NO_COLLISION,))


def test_toy_far_deadlocks_with_a_replayed_stuck_configuration(toys, tmp_path) -> None:
    model = toys["toy-far"]
    got = prove_live(model, LiveSpec(Lemma.PROGRESS, ENABLED, "stay"), timeout=10, out=tmp_path)
    assert got.verdict is Verdict.VIOLATED, got.reason
    state = tuple(model.to_lattice(tuple(Fraction(v) for v in c.split(","))) for c in got.configuration)
    assert len(state) >= 2 and not initial_problems(state, model) and not is_goal(state, model)
    assert not any(d.moves for d in decide_all(state, model).values())
    # its measure still falls on every move: one non-decreasing round would be a row of its own
    measure = prove_live(model, LiveSpec(Lemma.TERMINATION, MEASURE, "right"), timeout=10, out=tmp_path)
    assert measure.verdict is Verdict.PROVED, measure.reason


def test_a_toy_measure_that_does_not_fall_is_violated_by_a_replayed_round(toys, tmp_path) -> None:
    """The same toy, its measure declared the wrong way round (sum of x): a round of one mover raises it."""
    from dataclasses import replace

    rule_set = registry._REGISTRY["toy-right"]
    assert rule_set.liveness is not None
    registry._REGISTRY["toy-right"] = replace(rule_set, liveness=replace(rule_set.liveness, measure=((1, 0),)))
    model = toys["toy-right"]
    got = prove_live(model, LiveSpec(Lemma.TERMINATION, MEASURE, "right"), timeout=10, out=tmp_path)
    assert got.verdict is Verdict.VIOLATED, got.reason
    state = tuple(model.to_lattice(tuple(Fraction(v) for v in c.split(","))) for c in got.configuration)
    after = play_round(state, [0], model).after
    assert measure_of(model, after) >= measure_of(model, state)


def _rows(model, verdicts):
    """Rows for every liveness obligation of ``model``: PROVED unless ``verdicts`` says otherwise."""
    return [
        {
            "lemma": t.lemma.value,
            "form": t.form,
            "rule": "any",
            "case": t.case,
            "verdict": verdicts.get(t.key, "PROVED"),
        }
        for t in tasks_for(model, LIVE)
    ]


def test_lemma_level_verdicts_stuck_refutes_a_bad_round_does_not(toys) -> None:
    from fatline_verify.prove.coverage import liveness_verdicts

    model = toys["toy-right"]
    got = liveness_verdicts(model, _rows(model, {}))
    assert got[Lemma.PROGRESS] == ("PROVED", "every enabledness row PROVED, every decision in a declared case")
    # the cases not held to decide on every view: neither lemma PROVED
    sampled = liveness_verdicts(model, _rows(model, {"progress/coverage-cases": "INCONCLUSIVE"}))
    assert sampled[Lemma.PROGRESS][0] == sampled[Lemma.TERMINATION][0] == "NOT PROVED"
    assert "progress/coverage-cases INCONCLUSIVE" in sampled[Lemma.PROGRESS][1]
    # every liveness row PROVED, yet no safety rows and no obligation bounding sum(-x): never PROVED
    verdict, why = got[Lemma.TERMINATION]
    assert verdict == "NOT PROVED"
    assert "no-collision: no obligations (the rule set has no safety encoding)" in why
    assert "connectivity: no obligations" in why
    assert "component [-1, 0]: needs rma-fixed's seen rows PROVED" in why
    bad_round = liveness_verdicts(model, _rows(model, {"termination/measure-right": "VIOLATED"}))
    assert bad_round[Lemma.PROGRESS][0] == "PROVED" and bad_round[Lemma.TERMINATION][0] == "NOT PROVED"
    stuck = liveness_verdicts(model, _rows(model, {"progress/enabled-stay": "VIOLATED"}))
    assert stuck[Lemma.PROGRESS][0] == stuck[Lemma.TERMINATION][0] == "VIOLATED"
    open_row = liveness_verdicts(model, _rows(model, {"progress/enabled-right": "INCONCLUSIVE"}))
    assert open_row[Lemma.PROGRESS][0] == "NOT PROVED" and "enabled-right" in open_row[Lemma.PROGRESS][1]
    assert liveness_verdicts(model, []) == {}


def test_a_declared_bound_is_not_believed(toys) -> None:
    """``bounded_proved=True`` is the rule set's word: the bound still needs an obligation of its own."""
    from fatline_verify.prove.coverage import measure_bounds

    model = toys["toy-right"]
    assert registry.of(model).liveness.bounded_proved
    [(component, why, ok)] = measure_bounds(model, _rows(model, {}))
    assert component == (-1, 0) and not ok and "rma-fixed" in why


def _all_rows(model, verdicts):
    """A results row for every obligation of ``model`` (two movers included): PROVED unless ``verdicts`` says."""
    from fatline_verify.prove.tasks import row_key

    out = []
    for t in tasks_for(model, two_movers=True):
        row = {"lemma": str(t.lemma), "form": t.form, "rule": "any", "case": getattr(t, "case", "any") or "any"}
        row.update({"other": t.other} if getattr(t, "other", "") else {})
        row["verdict"] = verdicts.get(row_key(row), "PROVED")
        row["reason"] = "unsat on the lattice q=1" if t.form == "measure" else "unsat over the reals"
        out.append(row)
    return out


def test_termination_proved_only_with_every_part_and_it_says_what_it_rests_on(paper) -> None:
    """The paper's rules with a measure of sum(-x) alone (a what-if: rows all PROVED by hand): termination is
    PROVED only when safety, rma-fixed's seen rows (the bound) and every liveness row are, and then it lists
    what it rests on; one safety row short of that, it is NOT PROVED naming the lemma."""
    from dataclasses import replace

    from fatline_verify.prove.coverage import lemma_verdicts
    from fatline_verify.prove.tasks import row_key

    before = registry._REGISTRY["paper"]
    registry._REGISTRY["paper"] = replace(before, liveness=replace(before.liveness, measure=((-1, 0),)))
    try:
        rows = _all_rows(paper, {})
        keys = [row_key(r) for r in rows]
        got = {v.lemma: v for v in lemma_verdicts(paper, rows)}
        assert got["termination"].verdict == "PROVED", got["termination"].why
        rests = "\n".join(got["termination"].rests_on)
        assert "no-collision: PROVED" in rests and "connectivity: PROVED" in rests
        assert "bound of component [-1, 0]: no x exceeds the initial greatest x" in rests
        assert "lattice: over the reals (every lattice); on the lattice q = 1 only" in rests
        assert "solver: z3 " in rests and "scheduler ssync" in rests
        one = next(k for k in keys if k.startswith("no-collision/one-mover"))
        short = {v.lemma: v for v in lemma_verdicts(paper, _all_rows(paper, {one: "INCONCLUSIVE"}))}
        assert short["termination"].verdict == "NOT PROVED" and "no-collision NOT PROVED" in short["termination"].why
        seen = next(k for k in keys if k.startswith("rma-fixed/seen"))
        unbounded = {v.lemma: v for v in lemma_verdicts(paper, _all_rows(paper, {seen: "INCONCLUSIVE"}))}
        assert unbounded["termination"].verdict == "NOT PROVED"
        assert "component [-1, 0]: needs rma-fixed's seen rows PROVED" in unbounded["termination"].why
    finally:
        registry._REGISTRY["paper"] = before


def test_the_paper_measure_without_a_bound_never_gives_termination(paper) -> None:
    from fatline_verify.prove.coverage import liveness_verdicts

    got = liveness_verdicts(paper, _all_rows(paper, {}))
    assert got[Lemma.PROGRESS][0] == "PROVED"
    verdict, why = got[Lemma.TERMINATION]
    assert verdict == "NOT PROVED" and why == "the measure's bound: component [0, 1]: no obligation bounds it"
