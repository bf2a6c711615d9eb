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

import json
import time
from dataclasses import asdict, dataclass
from fractions import Fraction
from functools import cache
from pathlib import Path
from typing import Any

from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.geometry import dist2
from ..model.numbers import Point, show_point
from ..model.swarm import initial_problems, is_connected
from ..rules import registry
from ..rules.decision import Decision
from ..rules.family.family import REST, MoveFamily
from ..rules.family.held import Held
from ..rules.family.lang import Ground, holds
from ..schedulers.round import Collision, collides, decide_all, disconnection, lost_edges, play_round, snapshot
from ..trace.simulate import Outcome, Run, outcome_after
from ..trace.traces import replayed_document
from .search import MIN_CHECK, PROVED_REASON, Budget, rounds, rounds_text
from .smt.family import BRIDGED, FIRST, LINK, RULES, FamilySpec, argument, build, leg_roles
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


def prove_family(
    model: Model, spec: FamilySpec, *, timeout: float, out: Path | None, family: MoveFamily | None = None
) -> ProofResult:
    """Decide one obligation of the model's family; write its form (with its argument) under ``out``.
    ``family``: a family without a policy (``fatline prove --with``): an answer is replayed by legs the family
    admits (:func:`replay_legs`), not by a rule set's ``decide``. A family with ``lattice`` is decided on the
    model's lattice (integers), every other over the reals."""
    from .smt.cases import Arith
    from .smt.solving import write

    policy = family is None
    family = family_for(model) if family is None else family
    q = model.parameters.q if family.lattice else None

    def arith() -> Arith:
        return Arith(q)

    proved = PROVED_REASON if q is None else PROVED_ON.format(q=q)
    replay = replay_family if policy else replay_legs
    full = build(arith(), model, family, spec)
    full.comment = argument(model, family, spec, full)
    path = ""
    if out is not None:
        target = out / str(spec.lemma) / f"{spec.key.split('/', 1)[1]}.smt2"
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
            ans = spend.solve(build(arith(), model, family, spec, vacuity=True), budget * VACUITY_SHARE)
            if ans.status == "unsat":
                where = "" if q is None else f" on the lattice q = {q}"
                return result(Verdict.PROVED, f"these legs never occur together{where} (vacuous)")
            fires = ans.status == "sat"
        if min(budget, spend.left()) < MIN_CHECK:
            break
        ans = spend.solve(full, budget * (1 - (0 if fires else VACUITY_SHARE)))
        if ans.status == "unsat":
            return result(Verdict.PROVED, proved)
        if ans.status == "sat" and spec.form in (FIRST, LINK, RULES):  # about the family, not a round
            where = ", ".join(f"{n} at {show_point(p)}" for n, p in sorted(ans.positions.items()) if "'" not in n)
            return result(
                Verdict.INCONCLUSIVE,
                f"the family's guards do not imply it: a solution ({where}); not a round of the rules, so nothing to "
                "replay: the role's condition needs to say more",
            )
        if ans.status == "sat":
            verdict, reason, doc, config = replay(model, family, spec, ans.positions)
            if verdict is not Verdict.VIOLATED:  # ask for one from an initial configuration (delta apart, connected)
                initial = build(arith(), model, family, spec, initial=True)
                again = spend.solve(initial, min(budget, spend.left()) / 2)
                if again.status == "sat":
                    better = replay(model, family, spec, again.positions)
                    if better[0] is Verdict.VIOLATED:
                        verdict, reason, doc, config = better
            if verdict is not Verdict.VIOLATED and _needs_witnesses(family, spec):
                witnessed = build(arith(), model, family, spec, witnesses=True)
                named = spend.solve(witnessed, spend.left() * WITNESS_SHARE)
                if named.status == "unsat":
                    where = ""
                    if path:  # the obligation that came out unsat, beside the one without the witnesses (sat)
                        named_note = f"The robot each mover's leg needs it to see is named.{WITNESS_NOTE}"
                        witnessed.comment = f"{full.comment}\n{named_note}"
                        other = Path(path).with_suffix(".witnessed.smt2")
                        write(witnessed, other)
                        where = f" ({other.as_posix()})"
                    return result(Verdict.PROVED, proved + WITNESSED + where)
            if verdict is not Verdict.VIOLATED and not policy:
                tried = []
                for extra in range(EXTRA + 1):
                    closed = spend.solve(
                        build(arith(), model, family, spec, closed=extra), spend.left() / (EXTRA + 1 - extra)
                    )
                    if closed.status == "sat":
                        again = replay(model, family, spec, closed.positions)
                        if again[0] is Verdict.VIOLATED:
                            return result(*again)
                    tried.append(f"{extra} more: {closed.status}{', not replayed' if closed.status == 'sat' else ''}")
                reason += (
                    f"; searched again with the named robots and 0 to {EXTRA} more at rest as the whole swarm "
                    f"({'; '.join(tried)}): no counterexample"
                )
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


WITNESSED = ", once the robot each mover's leg needs it to see (its guard's witness outside every forall) is named"
EXTRA = 2
"""Robots at rest added to the named ones when a family without a policy looks for a counterexample its legs
replay (the named robots and they the whole swarm)."""
WITNESS_NOTE = (
    " Each such witness may be any robot its mover sees, one of the named robots or one more (the role is"
    " their disjunction), so no swarm the guards allow is left out."
)
"""What the header of an obligation with its legs' witnesses named adds."""
WITNESS_SHARE = 0.6
"""The share of what is left of the budget, once an answer is not replayed, for the obligation with each
mover's leg witnesses named."""
PROVED_ON = "unsat on the lattice q = {q}: holds for swarms of every size on it (the header's argument)"


def _needs_witnesses(family: MoveFamily, spec: FamilySpec) -> bool:
    """Whether a mover of ``spec`` has a leg witness to name (:func:`~.smt.family.leg_roles`)."""
    movers = [c for c in (spec.mine, spec.other, spec.witness) if c and c != REST]
    return any(leg_roles(family.get(c).guard) for c in movers)


def replay_legs(
    model: Model, family: MoveFamily, spec: FamilySpec, positions: dict[str, tuple[Fraction, Fraction]]
) -> tuple[Verdict, str, dict[str, Any] | None, tuple[str, ...]]:
    """The named robots of a solution as a swarm of a family without a policy (every robot may take any leg
    the family admits from its own view): VIOLATED only if the swarm is connected and collision-free, each
    mover's leg is of its class and admitted from its own view there (not held, its shape and guard by the
    concrete interpreter), and the round the executable model plays breaks the obligation's claim."""
    names = ["r", "o", *(["b"] if spec.role else [])]
    names += sorted(n for n in positions if n[0] in "we" and n[1] in ".0123456789" and not n.endswith("'"))
    classes = {"r": spec.mine, "o": spec.other, "b": spec.witness or REST}
    state = tuple(_on_lattice(model, positions[n]) for n in names)
    moves = {
        i: (
            _on_lattice(model, positions[f"{n}'"])[0] - state[i][0],
            _on_lattice(model, positions[f"{n}'"])[1] - state[i][1],
        )
        for i, n in enumerate(names)
        if classes.get(n, REST) != REST
    }
    config = tuple(f"{x},{y}" for x, y in (positions[n] for n in names))
    shown = f"robots {list(state)} (lattice units, q = {model.parameters.q}; {', '.join(names)}), round " + str(
        sorted(moves.items())
    )
    if not is_connected(state, model) or any(
        collides(dist2(a, b), model) for i, a in enumerate(state) for b in state[i + 1 :]
    ):
        return (Verdict.INCONCLUSIVE, f"the family's conditions admit a violation at {shown}, but those robots are "
                "not a connected swarm of disjoint discs: not a counterexample", None, config)  # fmt: skip
    for i, end in moves.items():
        cls = family.get(classes[names[i]])
        view = snapshot(state, i, model)
        g = Ground(model, view, {"me": (0, 0), "end": end})
        if (
            family.held(view, model)
            or not family.within_step(end, model)
            or not (holds(cls.shape, g) and holds(cls.guard, g))
        ):
            return (Verdict.INCONCLUSIVE, f"the family's conditions admit a violation at {shown}, but the family does "
                    f"not admit robot {names[i]}'s {cls.name} leg from its own view there: not a counterexample; the "
                    "family's argument needs a stronger condition", None, config)  # fmt: skip
    decisions = {i: Decision("family-leg", end, ((0, 0), end), ()) for i, end in moves.items()}  # type: ignore[arg-type]
    played = play_round(state, sorted(moves), model, decisions)
    before, after = played.before, played.after
    if spec.lemma is Lemma.NO_COLLISION:
        broken = any(isinstance(v, Collision) and v.robots == (0, 1) for v in played.violations)
        what = "r and o collide"
    else:
        gone = {pair for pair, _ in lost_edges(before, after, model)}
        broken = (0, 1) in gone and (spec.form != BRIDGED or bool(gone & {(0, 2), (1, 2)}))
        what = "r-o lost" + (" and not bridged through b" if spec.form == BRIDGED else "")
        what += (
            "; the swarm splits" if disconnection(before, after, model) is not None else "; the swarm stays connected"
        )
    if not broken:
        return (Verdict.INCONCLUSIVE, f"the replayed round of {shown} keeps the claim", None, config)
    initial = "an initial configuration" if not initial_problems(state, model) else "a connected swarm (not initial)"
    return (Verdict.VIOLATED, f"{what}: {shown}, from {initial}, each leg admitted by the family from its own view "
            "(replayed by the executable model)", None, config)  # fmt: skip


def _on_lattice(model: Model, p: tuple[Fraction, Fraction]) -> Point:
    x, y = model.to_lattice(p)
    return (int(x), int(y))


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


def shared_views(model: Model, sample: int, memo: Path | None) -> ViewsCheck:
    """:func:`check_views`, computed once per run (:mod:`fatline_verify.prove.memo`): each lemma's views row
    reads the same views against the same family (the model's, fixed for one run), so the rows after the
    first read its answer."""
    from .memo import key_of, remembered

    def compute() -> str:
        got = check_views(model, sample)
        outside = [[[[int(x), int(y)] for x, y in view], why] for view, why in got.outside]
        return json.dumps({**asdict(got), "outside": outside})

    doc = json.loads(remembered(memo, key_of("views", str(sample)), compute))
    outside = tuple((tuple((x, y) for x, y in view), why) for view, why in doc.pop("outside"))
    return ViewsCheck(**doc, outside=outside)


def prove_views(model: Model, spec: ViewsSpec, *, sample: int | None = None, memo: str | None = None) -> ProofResult:
    """The row ``spec``: PROVED when every view's decision is in the family (every view read), VIOLATED
    (with the first view) when one is not, INCONCLUSIVE on a sample that found none. ``memo``: the run's
    shared answers (the other lemma's views row computes the same check)."""
    rule_set = registry.of(model)
    if isinstance(rule_set.decide, Held) and rule_set.decide.holds_to(rule_set.family, model):
        reason = (
            "every decision is in the family by construction: the rule set's decide is a Held "
            "(fatline_verify/rules/family/held.py), which returns a proposal only after the family admits it, or a "
            "stay; no view read"
        )
        return ProofResult(spec.lemma, spec.form, "any", Verdict.PROVED, 0, True, 0.0, reason, "", None, "", "any", "")
    total = count_views(model)
    if sample is None:
        sample = 0 if total <= EXHAUSTIVE_VIEWS else SAMPLE_VIEWS
    got = shared_views(model, sample, Path(memo) if memo else None)
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


__all__ = ["VIEWS_FORM", "ViewsSpec", "check_views", "prove_family", "prove_views", "replay_family", "replay_legs"]
