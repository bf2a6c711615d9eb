"""A reachable deadlock is evidence (issue 37, hole 8): a replayed deadlock reached after some rounds
VIOLATES the enabledness row of its named robot's case, and with it progress and termination, given
with ``fatline prove --known`` or found by the small swarms' runs; ``--known`` refuses in one line what
it cannot use, and names a trace no row used."""

from __future__ import annotations

import json
import shutil
from collections.abc import Iterator
from fractions import Fraction
from pathlib import Path

import pytest
import z3

from fatline_verify.check.initial import initial_array
from fatline_verify.cli import main
from fatline_verify.errors import InvalidTrace
from fatline_verify.integrity import seal
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.model.config import load_model, model_from_mapping
from fatline_verify.model.swarm import initial_problems, is_connected, is_goal
from fatline_verify.prove.coverage import liveness_verdicts
from fatline_verify.prove.deadlock import matching_cases, named_robots
from fatline_verify.prove.known import read_known, unused_line
from fatline_verify.prove.live import prove_live, small_stuck
from fatline_verify.prove.smt.cases import d2, same, sees
from fatline_verify.prove.smt.live_rules import LiveCase
from fatline_verify.prove.smt.liveness import ENABLED, LiveSpec
from fatline_verify.prove.tasks import tasks_for
from fatline_verify.rules import registry
from fatline_verify.rules.paper.algorithm import Decision
from fatline_verify.schedulers.round import decide_all
from fatline_verify.trace.simulate import Outcome, parse_schedule, play_schedule
from fatline_verify.trace.traces import check_replay, load_trace, replayed_document, write_trace

ROOT = Path(__file__).resolve().parent.parent
AI = "nomovement-4-only-AI"
REACHED = ((0, 0), (1, 4), (2, 2))
"""paper: every robot active in round 1, r0 moves right by Scenario 1 to (2, 0); then no robot moves."""


def _trace(model, initial, rounds: str, path: Path) -> Path:
    """The run of the schedule ``rounds`` (``fatline simulate --schedule``) from ``initial`` (lattice
    units), written as a trace."""
    steps = parse_schedule(rounds, len(initial), model.options.scheduler, model) if rounds else []
    run = play_schedule(initial, model, steps)
    doc = replayed_document(run, {"tool": "test"}, Lemma.PROGRESS if run.outcome is Outcome.DEADLOCK else None)
    write_trace(doc, path)
    return path


def _refused(argv: list[str], capsys) -> str:
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1, (code, err)
    return err


# --- the paper: a checker-style deadlock after a round, given with --known ---------------------------


def test_a_paper_deadlock_reached_after_a_round_violates_progress_and_termination(tmp_path, capsys) -> None:
    """The committed paper rows, the stuck row left open (as a run that left it open wrote it, its own
    trace gone): --known with a deadlock reached after one round decides it, its reason says so, its
    trace replays to the deadlock, and progress and termination are VIOLATED at lemma level."""
    model = load_model("paper")
    known = _trace(model, REACHED, "all", tmp_path / "reached.json")
    doc = load_trace(known)
    assert doc["outcome"] == "deadlock" and len(doc["rounds"]) == 1
    assert not initial_problems(REACHED, model)
    assert any(d.moves for d in decide_all(REACHED, model).values())  # not stuck at the start: reached

    out = tmp_path / "proofs"
    shutil.copytree(ROOT / "proofs" / "paper", out / "paper")
    results = out / "paper" / "results.json"
    data = json.loads(results.read_text())
    for row in data["obligations"]:
        if row["lemma"] == "progress" and row["case"] == AI:
            row["verdict"] = "INCONCLUSIVE"
    results.write_text(json.dumps(seal(data)))
    (out / "paper" / "traces" / f"paper-prove-progress-enabled-{AI}.json").unlink(missing_ok=True)

    argv = ["prove", "paper", "--lemma", "liveness", "--redo-inconclusive", "--known", str(known)]
    code = main([*argv, "--out", str(out), "--timeout", "1", "--jobs", "2", "--no-corpus", "-q", "--coverage", "200"])
    printed = capsys.readouterr().out
    assert code == 1, printed
    assert "not used" not in printed
    rows = json.loads(results.read_text())["obligations"]
    row = next(r for r in rows if r["lemma"] == "progress" and r["case"] == AI)
    assert row["verdict"] == "VIOLATED" and row["decided_by"] == "given", row
    assert (
        "a deadlock reached after 1 round from the initial configuration (0, 0), (1, 4), (2, 2) "
        f"(given with --known {known}, replayed)" in row["reason"]
    ), row["reason"]
    witness = load_trace(out / "paper" / "traces" / f"paper-prove-progress-enabled-{AI}.json")
    run = check_replay(witness, model)
    assert run.outcome is Outcome.DEADLOCK and len(run.rounds) == 1 and run.initial == REACHED
    final = run.final
    assert not any(d.moves for d in decide_all(final, model).values())
    assert is_connected(final, model) and not is_goal(final, model)
    lemmas = liveness_verdicts(model, rows)
    assert lemmas[Lemma.PROGRESS][0] == lemmas[Lemma.TERMINATION][0] == "VIOLATED", lemmas


def test_known_refuses_what_it_cannot_use_in_one_line_before_any_work(tmp_path, capsys) -> None:
    model = load_model("paper")
    out = tmp_path / "p"
    base = ["prove", "paper", "--lemma", "liveness", "--out", str(out), "-q", "--coverage", "200", "--known"]
    other = ROOT / "reports" / "traces" / "repaired-check-progress-n3.json"
    err = _refused([*base, str(other)], capsys)
    assert "a trace of rule set 'repaired'" in err and "expected a trace of model paper's rule set 'paper'" in err
    goal = _trace(model, ((0, 0), (0, 3)), "", tmp_path / "goal.json")
    err = _refused([*base, str(goal)], capsys)
    assert "outcome 'goal'; expected a deadlock" in err and "goal.json" in err
    doc = load_trace(_trace(model, REACHED, "all", tmp_path / "reached.json"))
    doc["rounds"][0]["positions"][0] = [3, 0]
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(doc))
    err = _refused([*base, str(tampered)], capsys)
    assert "does not replay under model paper" in err and "tampered.json" in err
    doc = load_trace(goal)
    doc.update(initial=[[0, 0], [0, 2]], outcome="deadlock")  # discs touching: closer than delta
    crowded = tmp_path / "crowded.json"
    crowded.write_text(json.dumps(doc))
    err = _refused([*base, str(crowded)], capsys)
    assert "its first configuration is not initial" in err and "closer than delta" in err
    # a deadlock where the model has no enabledness row: the repaired rule set declares no liveness
    repaired = ["prove", "repaired", "--out", str(out), "-q", "--known", str(other)]
    assert "a deadlock, but model repaired has no enabledness obligation" in _refused(repaired, capsys)
    assert not out.exists()  # refused before any work


def test_a_trace_no_row_of_the_run_uses_is_named_with_why(tmp_path) -> None:
    model = load_model("paper")
    known = read_known(model, str(_trace(model, REACHED, "all", tmp_path / "r.json")), tasks_for(model))
    assert known.deadlock is not None and known.deadlock.cases == {AI: 1}
    safety_only = [t for t in tasks_for(model) if t.lemma is Lemma.NO_COLLISION]
    line = unused_line(known, safety_only, [])
    assert line.startswith(f"--known {known.name}: not used: ") and f"progress/enabled-{AI}" in line
    row = {"decided_by": "given", "reason": f"... (given with --known {known.name}, replayed): ..."}
    assert unused_line(known, tasks_for(model), [row]) == ""


# --- the prover's own small swarms: deadlocks reached from them ------------------------------------


def test_the_small_swarms_find_a_reached_deadlock_the_initial_ones_do_not(tmp_path) -> None:
    """paper-drop-touch, Scenario 4 after Scenario 2 with I non-empty: no small initial configuration is
    stuck with its named robot in this case (the committed row was INCONCLUSIVE), but a run of one
    reaches a deadlock that is: VIOLATED, its trace replayed."""
    model = load_model("paper-drop-touch")
    spec = LiveSpec(Lemma.PROGRESS, ENABLED, "scenario-4-I-nonempty.from-scenario-2")
    got = small_stuck(model, spec)
    assert got is not None and got[0] is Verdict.VIOLATED
    assert "a deadlock reached after" in got[1] and "found among the small swarms" in got[1], got[1]
    run = check_replay(got[2], model)
    assert run.outcome is Outcome.DEADLOCK and run.rounds and not initial_problems(run.initial, model)
    assert any(d.moves for d in decide_all(run.initial, model).values())  # reached, not stuck at the start


# --- a plug-in rule set whose deadlocks are all reached --------------------------------------------


def _touch_decide(snap, model):
    """Stay when a robot seen is closer than delta (never so initially); else move to the vertical of
    the nearest robot seen right of it, at one's own height; else stay."""
    if any(not model.initially_apart(x * x + y * y) for x, y in snap):
        return Decision("close", (0, 0), ((0, 0),), ())  # type: ignore[arg-type]
    right = [p for p in snap if p[0] > 0]
    if not right:
        return Decision("stay", (0, 0), ((0, 0),), ())  # type: ignore[arg-type]
    x = min(p[0] for p in right)
    return Decision("right", (x, 0), ((0, 0), (x, 0)), ())  # type: ignore[arg-type]


def _touch_cases(model):
    delta = Fraction(model.parameters.delta)

    def near(ar, me, p):
        return z3.And(z3.Not(same(p, me)), sees(ar, model, me, p), ar.cmp2(d2(me, p), "<", delta))

    def close(ar, model_, me, roles, universe):
        return [near(ar, me, roles["c"])], (ar.num(0), ar.num(0))

    def stay(ar, model_, me, roles, universe):
        cs = [z3.Not(near(ar, me, p)) for p in universe]
        cs += [z3.Or(same(p, me), z3.Implies(sees(ar, model, me, p), p[0] <= me[0])) for p in universe]
        return cs, (ar.num(0), ar.num(0))

    def right(ar, model_, me, roles, universe):
        m = roles["m"]
        cs = [z3.Not(near(ar, me, p)) for p in universe]
        cs += [z3.Not(same(m, me)), sees(ar, model, me, m), m[0] > me[0]]
        cs += [
            z3.Or(same(p, me), z3.Implies(z3.And(sees(ar, model, me, p), p[0] > me[0]), p[0] >= m[0])) for p in universe
        ]
        return cs, (m[0] - me[0], ar.num(0))

    return [
        LiveCase("close", ("c",), False, close),
        LiveCase("stay", (), False, stay),
        LiveCase("right", ("m",), True, right),
    ]


@pytest.fixture
def touch() -> Iterator[object]:
    before = dict(registry._REGISTRY)
    registry.register(
        registry.RuleSet(
            "toy-touch",
            _touch_decide,
            "a toy: stay beside a robot closer than delta, else right to the nearest robot seen right",
            liveness=registry.Liveness(
                _touch_cases, ((-1, 0),), "sum of -x", "x never exceeds the initial greatest x", True
            ),
        )
    )
    yield model_from_mapping(
        {
            "name": "toy-touch",
            "rules": "toy-touch",
            "parameters": {"rad_v": 4, "q": 1},
            "options": {"scheduler": "ssync"},
            "bounds": {"robots": "2..3", "window": "7x7"},
        }
    )
    registry._REGISTRY.clear()
    registry._REGISTRY.update(before)


TOUCH = ((0, 0), (3, 2), (5, 0))
"""toy-touch: r0 alone moves to (3, 0), touching (3, 2): then (3, 0) and (3, 2) stay beside each other
and (5, 0) sees no robot right of it."""


def test_a_plug_in_whose_deadlocks_are_all_reached_goes_from_inconclusive_to_violated(touch, tmp_path) -> None:
    model = touch
    # no initial configuration is stuck: the named robot moves wherever no robot is closer than delta
    for n in (2, 3):
        for row in initial_array(n, (7, 7), model):
            state = tuple((int(x), int(y)) for x, y in row)
            if not is_goal(state, model):
                assert any(d.moves for d in decide_all(state, model).values()), state
    spec = LiveSpec(Lemma.PROGRESS, ENABLED, "close")
    before = prove_live(model, spec, timeout=5, out=tmp_path)
    assert before.verdict is Verdict.INCONCLUSIVE, before.reason

    path = _trace(model, TOUCH, "0", tmp_path / "touch.json")
    known = read_known(model, str(path), tasks_for(model))
    assert known.deadlock is not None and known.deadlock.rounds == 1
    final = known.deadlock.final
    assert final == ((3, 0), (3, 2), (5, 0)) and named_robots(final, model) == [0, 1]
    assert known.deadlock.cases == {"close": 0}
    after = prove_live(model, spec, timeout=5, out=tmp_path, given=[known.deadlock])
    assert after.verdict is Verdict.VIOLATED and after.decided_by == "given", after.reason
    assert "a deadlock reached after 1 round from the initial configuration (0, 0), (3, 2), (5, 0)" in after.reason
    assert after.witness is not None and check_replay(after.witness, model).final == final
    # the other rows are not touched by it: its named robots decide close only
    for case in ("stay", "right"):
        other = prove_live(model, LiveSpec(Lemma.PROGRESS, ENABLED, case), timeout=5, out=None, given=[known.deadlock])
        assert other.verdict is Verdict.PROVED, other.reason
    rows = [
        {"lemma": t.lemma.value, "form": t.form, "rule": "any", "case": t.case, "verdict": "PROVED"}
        for t in tasks_for(model)
    ]
    for row in rows:
        if row["form"] == ENABLED and row["case"] == "close":
            row["verdict"] = before.verdict.value
    assert liveness_verdicts(model, rows)[Lemma.PROGRESS][0] == "NOT PROVED"
    for row in rows:
        if row["form"] == ENABLED and row["case"] == "close":
            row["verdict"] = after.verdict.value
    got = liveness_verdicts(model, rows)
    assert got[Lemma.PROGRESS][0] == got[Lemma.TERMINATION][0] == "VIOLATED", got


def test_a_generic_decision_is_matched_against_the_declared_cases(touch) -> None:
    """The z3 match on concrete points: a robot touching another decides close (and no other case); one
    seeing a robot right of it and none near decides right with that destination."""
    model = touch
    state = ((3, 0), (3, 2), (5, 0))
    decisions = decide_all(state, model)
    assert matching_cases(model, state, 0, decisions[0]) == ["close"]
    assert matching_cases(model, state, 2, decisions[2]) == ["close"]  # (5, 0) sees (3, 0) at distance 2
    start = decide_all(TOUCH, model)
    assert start[0].destination == (3, 0) and matching_cases(model, TOUCH, 0, start[0]) == ["right"]
    wrong = Decision("right", (5, 0), ((0, 0), (5, 0)), ())  # type: ignore[arg-type]
    assert matching_cases(model, TOUCH, 0, wrong) == []  # not the nearest robot's vertical: no case


def test_a_deadlock_whose_named_robots_decide_no_declared_case_is_refused(touch, tmp_path) -> None:
    """With the close case left out of the declaration, the deadlock's named robots match no case: the
    trace is refused in one line (it cannot decide a row), not ignored."""
    from dataclasses import replace

    rule_set = registry._REGISTRY["toy-touch"]
    assert rule_set.liveness is not None
    fewer = replace(rule_set.liveness, encoding=lambda m: [c for c in _touch_cases(m) if c.name != "close"])
    registry._REGISTRY["toy-touch"] = replace(rule_set, liveness=fewer)
    path = _trace(touch, TOUCH, "0", tmp_path / "touch.json")
    with pytest.raises(InvalidTrace, match="decides one of rule set 'toy-touch'"):
        read_known(touch, str(path), tasks_for(touch))


# --- an enabledness question's solution on a finer lattice ------------------------------------------


def test_a_finer_lattice_answers_the_enabledness_question_a_replayed_solution() -> None:
    """paper, Scenario 4 with I non-empty (r on the left-most vertical, from uncovered-neither): no solution
    on the model's lattice, one on q = 4 (r stays above a robot at x in [sqrt 3, 2), one below r's height,
    in C and in I). The step confirms it over the reals with every named robot fixed: z3's answer, and the
    executable model puts r in that case, staying, on those very points."""
    from fatline_verify.prove import live
    from fatline_verify.prove.search import Budget
    from fatline_verify.prove.smt.cases import Arith
    from fatline_verify.prove.smt.liveness import build_enabled
    from fatline_verify.rules.paper.algorithm import decide
    from fatline_verify.rules.paper.cases import case_of

    model = load_model("paper")
    spec = LiveSpec(Lemma.PROGRESS, ENABLED, "scenario-4-I-nonempty.from-uncovered-neither")
    case = live._case(model, spec)
    full = build_enabled(Arith(None), model, case)
    got = live._finer_solution(model, case, full, Budget(60), 30.0)
    assert got is not None and got.status == "sat"
    points = set(got.positions.values())
    assert all((4 * c).denominator == 1 for p in points for c in p)
    assert any((2 * c).denominator != 1 for p in points for c in p)  # not on q = 2: the finer lattice found it
    origin = (Fraction(0), Fraction(0))
    assert got.positions["r"] == origin
    seen = [p for p in points if p != origin and model.sees(p[0] ** 2 + p[1] ** 2)]
    decision = decide(seen, model)
    assert not decision.moves and case_of(decision, model).name == spec.case
