"""``fatline prove`` on the repaired rule set: each leg obligation (:mod:`fatline_verify.prove.smt.legs`)
decided over the reals, in the prover's rounds (:func:`fatline_verify.prove.search.rounds`).

1. **Vacuity** (until answered): if the two legs cannot occur together (two robots on one vertical
   both moving as its top, say), PROVED, "these legs never occur together".
2. **The reals**: ``unsat`` is PROVED for swarms of every size (the header's argument). ``sat`` is
   an assignment of the legs' conditions, not yet a counterexample: it is replayed by the executable
   model (the named robots as a swarm, their own repaired decisions). Only if the named movers make
   the legs of the answer and the round breaks the claim from an initial configuration is the
   verdict VIOLATED; otherwise INCONCLUSIVE, with the configuration and what the rules did there
   (the conditions are weaker than the rules: a weakness of the argument, not a counterexample).
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Any

from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.numbers import Point, show_point
from ..model.swarm import initial_problems
from ..rules.repaired.algorithm import leg_of
from ..schedulers.round import Collision, decide_all, lost_edges, play_round, snapshot
from ..trace.simulate import Outcome, Run, outcome_after
from ..trace.traces import replayed_document
from .search import MIN_CHECK, PROVED_REASON, Budget, rounds, rounds_text
from .smt.legs import BRIDGED, REST, LegSpec, argument, build
from .tasks import ProofResult

VACUITY_SHARE = 0.05
"""The vacuity check's share of a round."""


def prove_leg(model: Model, spec: LegSpec, *, timeout: float, out: Path | None) -> ProofResult:
    """Decide one leg obligation; write its real-number form (with its argument) under ``out``."""
    from .smt.cases import Arith
    from .smt.solving import write

    full = build(Arith(None), model, spec)
    full.comment = argument(model, spec, full)
    path = ""
    if out is not None:
        target = out / spec.lemma / f"{spec.key.split('/', 1)[1]}.smt2"
        write(full, target)
        path = target.as_posix()
    spend = Budget(timeout)
    fires, last = False, "budget exhausted"

    def result(
        verdict: Verdict, reason: str, doc: dict[str, Any] | None = None, config: tuple[str, ...] = ()
    ) -> ProofResult:
        named = len([n for n in full.bodies if not n.endswith("'")]) - 1
        return ProofResult(
            spec.lemma, spec.form, "any", verdict, named, True, spend.wall, reason, path, doc, full.comment,
            spec.name, spec.other, config,
        )  # fmt: skip

    for budget in rounds(timeout):
        if not fires:
            ans = spend.solve(build(Arith(None), model, spec, vacuity=True), budget * VACUITY_SHARE)
            if ans.status == "unsat":
                return result(Verdict.PROVED, "these legs never occur together (vacuous)")
            fires = ans.status == "sat"
        if min(budget, spend.left()) < MIN_CHECK:
            break
        ans = spend.solve(full, budget * (1 - (0 if fires else VACUITY_SHARE)))
        if ans.status == "unsat":
            return result(Verdict.PROVED, PROVED_REASON)
        if ans.status == "sat":
            verdict, reason, doc, config = replay_legs(model, spec, ans.positions)
            return result(verdict, reason, doc, config)
        last = ans.reason
    return result(
        Verdict.INCONCLUSIVE,
        f"solver: {last} {rounds_text(timeout)}; rerun with a larger --timeout",
    )


def replay_legs(
    model: Model, spec: LegSpec, positions: dict[str, tuple[Fraction, Fraction]]
) -> tuple[Verdict, str, dict[str, Any] | None, tuple[str, ...]]:
    """The named robots of a solution as a swarm, under the repaired rules: VIOLATED only if the movers
    make the answer's legs and the round breaks the claim from an initial configuration."""
    names = ["r", "o", *(["b"] if spec.form == BRIDGED else [])]
    state = tuple(model.to_lattice(positions[n]) for n in names)
    config = tuple(f"{x},{y}" for x, y in (positions[n] for n in names))
    shown = ", ".join(f"{n} at {show_point(positions[n])}" for n in names)
    decisions = decide_all(state, model)
    movers = [0] if spec.other == REST else [0, 1]
    for i in movers:
        name, want = names[i], spec.mine if i == 0 else spec.other
        d = decisions[i]
        end = (state[i][0] + d.destination[0], state[i][1] + d.destination[1])
        wanted: Point = model.to_lattice(positions[f"{name}'"])
        if not d.moves or leg_of(d.destination, snapshot(state, i, model)) != want or end != wanted:
            did = f"moves to {show_point(model.from_lattice(end))}" if d.moves else "stays"
            return (
                Verdict.INCONCLUSIVE,
                f"the legs' conditions admit a violation ({shown}), but the repaired rules do not make these moves "
                f"there ({name} {did}, by {d.rule}): not a counterexample; the argument needs a stronger condition",
                None,
                config,
            )
    if spec.other == REST and 1 in decisions and decisions[1].moves:
        return (Verdict.INCONCLUSIVE, f"in the replay of {shown}, o moves too", None, config)
    result = play_round(state, movers, model, decisions)
    if spec.lemma is Lemma.NO_COLLISION:
        broken = any(isinstance(v, Collision) and v.robots == (0, 1) for v in result.violations)
        what = "collision"
    else:
        broken = bool(lost_edges(result.before, result.after, model))
        what = "an edge is lost"
    if not broken:
        return (Verdict.INCONCLUSIVE, f"the replayed round of {shown} keeps the claim", None, config)
    run = Run(model, state, (result,), outcome_after(result.after, result, model) or Outcome.ROUND_LIMIT)
    origin = {"tool": "fatline prove", "lemma": spec.lemma, "form": spec.form, "case": spec.name, "other": spec.other}
    focus = Lemma.NO_COLLISION if spec.lemma is Lemma.NO_COLLISION else Lemma.CONNECTIVITY_EDGE
    doc = replayed_document(run, origin, focus)
    problems = initial_problems(state, model)
    if problems:
        return (Verdict.INCONCLUSIVE, f"{what} in {shown}, not an initial configuration ({problems[0]})", doc, config)
    return (Verdict.VIOLATED, f"{what}, from an initial configuration of {len(state)} robots (replayed)", doc, config)


__all__ = ["prove_leg", "replay_legs"]
