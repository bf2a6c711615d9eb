"""``fatline prove`` on a rule set with a move family: each obligation of the family
(:mod:`fatline_verify.prove.smt.family`) decided over the reals, in the prover's rounds
(:func:`fatline_verify.prove.search.rounds`), and the family held to the rule set's ``decide`` on views.

1. **Vacuity** (until answered): if the two legs cannot occur together (two robots on one vertical
   both moving as its top, say), PROVED, "these legs never occur together".
2. **The reals**: ``unsat`` is PROVED for swarms of every size (the header's argument). ``sat`` is an
   assignment of the family's conditions, not yet a counterexample: it is replayed by the executable
   model (the named robots as a swarm, their own decisions). Only if the named movers make moves of the
   answer's classes and the round breaks the claim from an initial configuration is the verdict
   VIOLATED; otherwise INCONCLUSIVE, with the configuration and what the rules did there (the family's
   guards are weaker than the rules: a weakness of the family's argument, not a counterexample).
3. **In the family on views** (:func:`prove_views`, the rows ``LEMMA/in-family-views``): ``decide`` on every
   view of the model's lattice (:func:`fatline_verify.prove.views.all_views`: every input it can get) makes
   a decision the family admits. The obligations prove safety of the family; this row ties the rule set
   to it for every swarm size on that lattice (the checker's ``in-family`` lemma holds each run to it too).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from pathlib import Path
from typing import Any

from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.numbers import Point, show_point
from ..model.swarm import initial_problems
from ..rules import registry
from ..rules.family.family import REST, MoveFamily
from ..schedulers.round import Collision, decide_all, lost_edges, play_round, snapshot
from ..trace.simulate import Outcome, Run, outcome_after
from ..trace.traces import replayed_document
from .search import MIN_CHECK, PROVED_REASON, Budget, rounds, rounds_text
from .smt.family import FamilySpec, argument, build
from .tasks import VIEWS_FORM, ProofResult, ViewsSpec
from .views import all_views, count_views, random_views

VACUITY_SHARE = 0.05
"""The vacuity check's share of a round."""

EXHAUSTIVE_VIEWS = 3_000_000
"""Up to this many views of the lattice, the views row reads every one (PROVED possible); beyond, a sample."""

SAMPLE_VIEWS = 20_000
"""The sample of views read when the lattice has more than :data:`EXHAUSTIVE_VIEWS`."""


def family_for(model: Model) -> MoveFamily:
    """The model's family (the tasks were made from it)."""
    family = registry.family(model)
    if family is None:  # pragma: no cover - tasks_for asks only a model with one
        raise ValueError(f"model {model.name}: its rule set declares no move family for these options")
    return family


def prove_family(model: Model, spec: FamilySpec, *, timeout: float, out: Path | None) -> ProofResult:
    """Decide one obligation of the model's family; write its real-number form (with its argument) under ``out``."""
    from .smt.cases import Arith
    from .smt.solving import write

    family = family_for(model)
    full = build(Arith(None), model, family, spec)
    full.comment = argument(model, family, spec, full)
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
            spec.name, spec.other_name, config,
        )  # fmt: skip

    for budget in rounds(timeout):
        if not fires:
            ans = spend.solve(build(Arith(None), model, family, spec, vacuity=True), budget * VACUITY_SHARE)
            if ans.status == "unsat":
                return result(Verdict.PROVED, "these legs never occur together (vacuous)")
            fires = ans.status == "sat"
        if min(budget, spend.left()) < MIN_CHECK:
            break
        ans = spend.solve(full, budget * (1 - (0 if fires else VACUITY_SHARE)))
        if ans.status == "unsat":
            return result(Verdict.PROVED, PROVED_REASON)
        if ans.status == "sat":
            verdict, reason, doc, config = replay_family(model, family, spec, ans.positions)
            if verdict is not Verdict.VIOLATED:  # ask for one from an initial configuration (delta apart, connected)
                initial = build(Arith(None), model, family, spec, initial=True)
                again = spend.solve(initial, min(budget, spend.left()) / 2)
                if again.status == "sat":
                    better = replay_family(model, family, spec, again.positions)
                    if better[0] is Verdict.VIOLATED:
                        verdict, reason, doc, config = better
            return result(verdict, reason, doc, config)
        last = ans.reason
    return result(Verdict.INCONCLUSIVE, f"solver: {last} {rounds_text(timeout)}; rerun with a larger --timeout")


def replay_family(
    model: Model, family: MoveFamily, spec: FamilySpec, positions: dict[str, tuple[Fraction, Fraction]]
) -> tuple[Verdict, str, dict[str, Any] | None, tuple[str, ...]]:
    """The named robots of a solution as a swarm, under the rule set's own ``decide``: VIOLATED only if the
    movers make moves of the answer's classes (to the answer's ends or others) and the round the executable
    model plays breaks the claim from an initial configuration."""
    names = ["r", "o", *(["b"] if spec.role else [])]
    classes = {"r": spec.mine, "o": spec.other, "b": spec.witness}
    state = tuple(model.to_lattice(positions[n]) for n in names)
    config = tuple(f"{x},{y}" for x, y in (positions[n] for n in names))
    shown = ", ".join(f"{n} at {show_point(positions[n])}" for n in names)
    decisions = decide_all(state, model)
    movers = [i for i, n in enumerate(names) if classes[n] != REST and (classes[n] or decisions[i].moves)]
    for i, name in enumerate(names):
        d = decisions[i]
        want = classes[name]
        if not want:  # a witness that rules a class out: its own move is not assumed
            continue
        if want == REST:
            if d.moves:
                return (Verdict.INCONCLUSIVE, f"in the replay of {shown}, {name} moves too", None, config)
            continue
        end = (state[i][0] + d.destination[0], state[i][1] + d.destination[1])
        got = family.classify(snapshot(state, i, model), d.destination, model) if d.moves else REST
        if got != want:  # its own end may differ from the answer's: the round below is what is judged
            did = f"moves to {show_point(model.from_lattice(end))} ({got})" if d.moves else "stays"
            return (
                Verdict.INCONCLUSIVE,
                f"the family's conditions admit a violation ({shown}), but the rules do not make these moves there "
                f"({name} {did}, by {d.rule}): not a counterexample; the family's guard needs a stronger condition",
                None,
                config,
            )
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
    origin = {
        "tool": "fatline prove",
        "lemma": spec.lemma,
        "form": spec.form,
        "case": spec.name,
        "other": spec.other_name,
    }
    focus = Lemma.NO_COLLISION if spec.lemma is Lemma.NO_COLLISION else Lemma.CONNECTIVITY_EDGE
    doc = replayed_document(run, origin, focus)
    problems = initial_problems(state, model)
    if problems:
        return (Verdict.INCONCLUSIVE, f"{what} in {shown}, not an initial configuration ({problems[0]})", doc, config)
    return (Verdict.VIOLATED, f"{what}, from an initial configuration of {len(state)} robots (replayed)", doc, config)


@dataclass(frozen=True)
class ViewsCheck:
    """What :func:`check_views` found."""

    views: int
    moving: int
    exhaustive: bool
    seconds: float
    outside: tuple[tuple[tuple[Point, ...], str], ...]
    """The first views whose decision leaves the family, each with why."""
    count: int


@cache
def check_views(model: Model, sample: int = 0) -> ViewsCheck:
    """``decide`` on every view of ``model``'s lattice (``sample``: that many random views instead), each
    decision held to the family (once per model and process: both lemmas' rows read it)."""
    family = family_for(model)
    decide = registry.decider(model)
    started = time.perf_counter()
    views = random_views(model, sample, 0) if sample else all_views(model)
    n = moving = bad = 0
    outside: list[tuple[tuple[Point, ...], str]] = []
    for view in views:
        n += 1
        d = decide(view, model)
        if not d.moves:
            continue
        moving += 1
        why = family.admit(view, d, model)
        if why is not None:
            bad += 1
            if len(outside) < 5:
                outside.append((tuple(view), f"{d.rule}: {why}"))
    return ViewsCheck(n, moving, not sample, time.perf_counter() - started, tuple(outside), bad)


def prove_views(model: Model, spec: ViewsSpec, *, sample: int | None = None) -> ProofResult:
    """The row ``spec``: PROVED when every view's decision is in the family (every view read), VIOLATED
    (with the first view) when one is not, INCONCLUSIVE on a sample that found none."""
    total = count_views(model)
    if sample is None:
        sample = 0 if total <= EXHAUSTIVE_VIEWS else SAMPLE_VIEWS
    got = check_views(model, sample)
    scope = " (every view of the lattice)" if got.exhaustive else f" of {total:,} (a sample)"
    what = f"lattice q={model.parameters.q}: {got.views:,} views{scope}"
    what += f", {got.moving:,} with a move, {got.seconds:.1f} s"
    if got.count:
        view, why = got.outside[0]
        shown = " ".join(show_point(model.from_lattice(p)) for p in view)
        verdict, reason = (
            Verdict.VIOLATED,
            f"{got.count:,} decisions leave the family; first: view {shown}: {why} ({what})",
        )
        config: tuple[str, ...] = tuple(
            f"{x},{y}" for x, y in ((Fraction(0), Fraction(0)), *map(model.from_lattice, view))
        )
    elif got.exhaustive:
        verdict, reason, config = Verdict.PROVED, f"every decision is in the family: {what}", ()
    else:
        verdict, reason, config = Verdict.INCONCLUSIVE, f"no decision leaves the family on {what}", ()
    return ProofResult(
        spec.lemma, spec.form, "any", verdict, 0, got.exhaustive, got.seconds, reason, "", None, "", "any", "", config
    )


__all__ = ["VIEWS_FORM", "ViewsSpec", "check_views", "prove_family", "prove_views", "replay_family"]
