"""The checker catches planted defects.

The paper's algorithm already breaks most lemmas, so the defects are planted in a small algorithm
for which every lemma holds on two robots: a robot that sees a robot to its right at (x, y) moves
vertically to y - 2 (or y + 2 when the other is below), then horizontally to x, ending exactly
touching it; a robot that sees nothing to its right stays. Each mutant changes one thing, and the
checker must report that lemma VIOLATED with a witness that replays under the mutant.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from fatline_verify.check.checker import check
from fatline_verify.lemmas.properties import Lemma, Verdict
from fatline_verify.rules.paper.algorithm import Decision, Rule
from fatline_verify.trace.traces import check_replay
from tests.conftest import make_model


def toy(target):
    """An algorithm from ``target(x, y) -> destination`` for a robot that sees one robot to its right."""

    def rule(snapshot, model):
        right = [c for c in snapshot if c[0] > 0]
        if not right:
            return Decision(Rule.ALONE, (0, 0), ((0, 0),), ())
        x, y = right[0]
        dest = target(x, y)
        if dest == (0, 0):
            return Decision(Rule.ALONE, (0, 0), ((0, 0),), ())
        corner = (0, dest[1])
        path = ((0, 0), dest) if corner in ((0, 0), dest) else ((0, 0), corner, dest)
        return Decision(Rule.SCENARIO_1, dest, path, ())

    return rule


def correct(x, y):
    return (x, y - 2) if y >= 0 else (x, y + 2)


MUTANTS = {
    "correct": correct,
    # no-collision: end one radius short of touching (overlap).
    Lemma.NO_COLLISION: lambda x, y: (x, y - 1) if y >= 0 else (x, y + 1),
    # connectivity: go far away from the other robot's height before moving right.
    Lemma.CONNECTIVITY: lambda x, y: (x, y - 12) if y >= 0 else (x, y + 12),
    # rma-fixed: overshoot the other robot's axis by one.
    Lemma.RMA_FIXED: lambda x, y: (x + 1, y - 2) if y >= 0 else (x + 1, y + 2),
    # progress: freeze.
    Lemma.PROGRESS: lambda x, y: (0, 0),
}


def slide_down():
    """Every robot that sees anything steps down 2, under fsync: the swarm slides away forever."""

    def rule(snapshot, model):
        if not snapshot:
            return Decision(Rule.ALONE, (0, 0), ((0, 0),), ())
        return Decision(Rule.SCENARIO_4_I_EMPTY, (0, -2), ((0, 0), (0, -2)), ())

    model = replace(make_model(scheduler="fsync"), algorithm=rule)
    return model, check(model, (2, 2), (7, 7), engine="fast")


def run(target, **readings):
    model = make_model(path="vertical-then-horizontal", **readings)
    model = replace(model, algorithm=toy(target))
    return model, check(model, (2, 2), (7, 7), engine="fast")


def verdicts(result):
    return {r.lemma: r.verdict for r in result.results}


def test_the_base_algorithm_satisfies_every_lemma():
    _, result = run(correct)
    assert set(verdicts(result).values()) == {Verdict.HOLDS_WITHIN_BOUNDS}, verdicts(result)


@pytest.mark.parametrize("lemma", [Lemma.NO_COLLISION, Lemma.CONNECTIVITY, Lemma.RMA_FIXED])
def test_safety_defects_are_reported_alone(lemma):
    model, result = run(MUTANTS[lemma])
    found = verdicts(result)
    assert found[lemma] is Verdict.VIOLATED
    assert {k for k, v in found.items() if v is Verdict.VIOLATED} == {lemma}
    witness = next(r for r in result.results if r.lemma is lemma).witness
    assert witness["violation"]["property"] == lemma.value
    assert witness["rounds"][-1]["decisions"][0]["rule"] == "scenario-1"
    check_replay(witness, model)


def test_freezing_breaks_progress_and_with_it_every_liveness_lemma():
    model, result = run(MUTANTS[Lemma.PROGRESS])
    found = verdicts(result)
    # A deadlock is also a non-terminating execution with robots left of the RMA.
    assert {k for k, v in found.items() if v is Verdict.VIOLATED} == {Lemma.PROGRESS, Lemma.TERMINATION, Lemma.APPROACH}
    witness = next(r for r in result.results if r.lemma is Lemma.PROGRESS).witness
    assert witness["outcome"] == "deadlock"
    check_replay(witness, model)


def test_a_swarm_that_slides_down_forever_breaks_termination_with_a_fair_lasso():
    # Both robots step down 2 whenever they see anything: the canonical state repeats (a translation),
    # every robot is activated on the cycle, the line never forms.
    model, result = slide_down()
    found = verdicts(result)
    assert found[Lemma.TERMINATION] is Verdict.VIOLATED
    assert found[Lemma.PROGRESS] is Verdict.HOLDS_WITHIN_BOUNDS
    witness = next(r for r in result.results if r.lemma is Lemma.TERMINATION).witness
    assert witness["outcome"] == "cycle" and witness["loop_start"] is not None
    check_replay(witness, model)
    # And the robot left of the RMA never moves right on that cycle.
    assert found[Lemma.APPROACH] is Verdict.VIOLATED


def test_approach_fails_alone_when_the_goal_is_already_met():
    # Two robots always form *some* line: with goal=any-line every state is a goal, so termination and
    # progress hold, but a frozen robot left of the RMA never approaches it.
    model, result = run(MUTANTS[Lemma.PROGRESS], goal="any-line")
    found = verdicts(result)
    assert {k for k, v in found.items() if v is Verdict.VIOLATED} == {Lemma.APPROACH}
    witness = next(r for r in result.results if r.lemma is Lemma.APPROACH).witness
    assert witness["violation"]["robots"]
    check_replay(witness, model)


def test_lasso_replay_rejects_a_broken_loop():
    """Only one robot steps down in the loop's last round: a round FSYNC never plays (both robots are
    enabled), refused as such before the loop is judged; the loop recorded as closing no longer would."""
    model, result = slide_down()
    witness = next(r for r in result.results if r.lemma is Lemma.TERMINATION).witness
    witness["rounds"][-1]["active"] = [0]
    from fatline_verify.errors import ForbiddenRound

    last = len(witness["rounds"])
    with pytest.raises(ForbiddenRound, match=rf"round {last} activates robots 0 of 2; expected every robot"):
        check_replay(witness, model)
