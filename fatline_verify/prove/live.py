"""``fatline prove`` on the liveness obligations (:mod:`fatline_verify.prove.smt.liveness`): Lemma 2's
enabledness per decision case (r stays), and the rule set's ranking measure per moving case.

- **enabled**: first the deadlocks given with ``fatline prove --known`` (:mod:`fatline_verify.prove.known`):
  one whose named robot decides the case is a counterexample, however many rounds it took to reach
  (VIOLATED, its trace the row's witness). Then over the reals: ``unsat`` is PROVED for swarms of
  every size (the header's argument); when z3's first sliver does not answer, a solution is looked for on
  the finer lattices of :data:`FINER` and confirmed over the reals (it cannot be unsat then), before z3 is
  given the rest of its share. Otherwise the small swarms (the paper's rules: every initial
  configuration of a few robots, fewest first, by the executable model alone; stuck ones first, then
  deadlocks reached from them: :func:`reach`), then the model's lattice with the
  initial condition's pairs are searched; each solution is replayed by the executable model, and only
  a configuration in which *no* robot moves, which is not a goal and meets the initial condition is a
  counterexample (VIOLATED: a stuck configuration, so Lemma 2 and termination fail). A solution
  where r stays but another robot moves is not one: it is blocked and the search goes on; what is
  left is INCONCLUSIVE, saying so (a stuck configuration the solver finds that is not initial is not
  known to be reachable: no counterexample either).
- **measure** (on the model's lattice): ``unsat`` is PROVED for every configuration of the lattice,
  of any size. A solution is replayed: r must make the case's move there; the round (r alone, or
  under ``fsync`` every robot that moves) must leave the measure where it was or raise it. From an
  initial configuration that is VIOLATED: a round that does not decrease the measure, which makes
  the measure NOT PROVED (it is not a run that never ends; only a stuck configuration refutes
  termination).
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.numbers import Point, show_point
from ..model.options import Motion, Scheduler
from ..model.swarm import initial_problems, is_goal
from ..rules import registry
from ..rules.decision import Decision
from ..schedulers.round import decide_all
from ..trace.simulate import Outcome, Run
from .corpus import GIVEN, SEARCH
from .deadlock import Deadlock, deadlock_of, named_cases
from .search import Budget
from .smt.cases import Arith
from .smt.live_rules import LiveCase, live_cases
from .smt.liveness import ENABLED, LiveSpec, build_enabled, build_measure, goal_problem, header
from .tasks import ProofResult, encoding_name

REALS_SHARE = 0.4
"""The share of the budget the real-number question gets before the lattice search."""
QUICK_SHARE = 0.05
"""The share of the real-number question's budget z3 gets first, for an enabledness row (every enabledness
row of the shipped models that is PROVED is unsat there in a hundredth of a second)."""

FINER = (2, 4)
"""For an enabledness row z3 does not decide in its first share: lattices ``x = X / (k q)`` searched for a
solution, each confirmed over the reals with every named robot fixed where the lattice put it. A
confirmed solution answers the real-number question (sat: it cannot be unsat), so z3 is not asked to look
further. Measured on ``paper``: Scenario 4 with I non-empty (from Scenario 2, from Scenario 3) has no
solution on q = 1 or 2 and one on q = 4 (r stays above a robot at (7/4, -1), in C and in I), where z3 over
the reals spent its whole share (36 s of wall clock) without an answer."""

FINER_SHARE = 0.5
"""The share of an enabledness row's budget the lattices of :data:`FINER` get, in all (each lattice what the
ones before it left, less :data:`CONFIRM_SHARE` of it kept for the confirmation). Measured on ``paper``:
q = 4 needs 11 (from Scenario 3) and 20 (from Scenario 2) seconds of budget to find its solution; a
lattice that finds none leaves the real-number question its whole share after it."""

CONFIRM_SHARE = 0.1
"""Of :data:`FINER_SHARE`, what the confirmation over the reals of a lattice's solution may take."""

MAX_TRIES = 12
"""Lattice solutions replayed (each blocked when it is not a counterexample) before giving up."""

Positions = dict[str, tuple[Fraction, Fraction]]


def prove_live(
    model: Model, spec: LiveSpec, *, timeout: float, out: Path | None, given: Sequence[Deadlock] = ()
) -> ProofResult:
    """Decide one liveness obligation; write its SMT-LIB2 form (with its argument) under ``out``.
    ``given``: deadlocks handed in (``fatline prove --known``), replayed already; an enabledness row is
    VIOLATED by the first whose named robot decides its case, before any search."""
    from .smt.solving import block, check, solver_for, write

    case = _case(model, spec)
    enabled = spec.form == ENABLED
    build = build_enabled if enabled else build_measure
    q = model.parameters.q
    full = build(Arith(None) if enabled else Arith(q), model, case)
    full.comment = header(model, spec, case, full, lattice=None if enabled else q)
    path = ""
    if out is not None:
        target = out / str(spec.lemma) / f"{spec.key.split('/', 1)[1]}.smt2"
        write(full, target)
        path = target.as_posix()
    spend = Budget(timeout)
    named = len([n for n in full.bodies if not n.endswith("'")]) - 1

    def result(
        verdict: Verdict,
        reason: str,
        doc: dict[str, Any] | None = None,
        config: Sequence[str] = (),
        decided_by: str = SEARCH,
    ) -> ProofResult:
        return ProofResult(
            spec.lemma, spec.form, "any", verdict, named, True, spend.wall, reason, path, doc, full.comment,
            spec.case, "", tuple(config), decided_by,
        )  # fmt: skip

    if enabled and goal_problem(model):
        return result(Verdict.INCONCLUSIVE, goal_problem(model))
    for deadlock in given if enabled else ():
        if spec.case in deadlock.cases:
            reason = deadlock.reason(model, spec.case)
            return result(Verdict.VIOLATED, reason, deadlock.doc, deadlock.configuration(model, spec.case), GIVEN)
    if not enabled and model.options.motion is not Motion.RIGID:
        return result(
            Verdict.INCONCLUSIVE,
            "motion is not rigid: the measure's argument needs every mover to reach its destination",
        )
    if enabled:
        reals = timeout * REALS_SHARE
        first = spend.solve(full, reals * QUICK_SHARE)
        if first.status == "unknown":
            finer = _finer_solution(model, case, full, spend, timeout * FINER_SHARE)
            first = finer or spend.solve(full, reals * (1 - QUICK_SHARE))
    else:
        first = spend.solve(full, timeout * (1 - REALS_SHARE))
    if first.status == "unsat":
        where = "over the reals" if enabled else f"on the lattice q={q}"
        return result(Verdict.PROVED, f"unsat {where}: holds for swarms of every size (the header's argument)")
    seen: Positions | None = first.positions if first.status == "sat" else None
    why = ""
    if first.status == "sat" and not enabled:
        verdict, why, doc, config = replay_measure(model, spec, first.positions)
        if verdict is Verdict.VIOLATED:
            return result(verdict, why, doc, config)
    small = enabled and encoding_name(model) == "paper"  # the paper's rules: their cases name a decision
    if small:  # the fewest robots first: the smallest stuck configuration, by the executable model alone
        found = small_stuck(model, spec)
        if found is not None:
            return result(*found)
    # the model's lattice, with the initial condition's pairs: a counterexample from an initial configuration
    search = build(Arith(q), model, case, initial=True)
    tries: list[Positions] = []
    while len(tries) < MAX_TRIES:

        def run(budget: float) -> Any:
            solver = solver_for(search, budget)
            for placement in tries:
                block(solver, search, placement)
            return check(solver, search, budget)

        ans = spend.ask(run, spend.left())
        if ans.status != "sat":
            break
        replayed = replay_stuck(model, spec, ans.positions) if enabled else replay_measure(model, spec, ans.positions)
        if replayed[0] is Verdict.VIOLATED:
            return result(*replayed)
        why = why or replayed[1]
        seen = seen or ans.positions
        tries.append(ans.positions)
    config = _config(seen) if seen else ()
    end = {"unsat": "then no more", "unknown": "then the budget ran out"}.get(ans.status, "the most it replays")
    searched = f"the lattice q={q} with the initial condition's pairs: {len(tries)} solution(s) replayed, {end}"
    if small:
        from .small import SMALL

        most = _small_most(SMALL, q)
        searched += (
            f"; no stuck configuration of 2 to {most} robots at q={q} (small swarms), nor a deadlock reached from one "
            f"({REACH_SCHEDULE}), has r in this case"
        )
    if seen is None and first.status != "sat":
        return result(
            Verdict.INCONCLUSIVE,
            f"solver: {first.reason} ({searched}); rerun with a larger --timeout",
        )
    return result(
        Verdict.INCONCLUSIVE,
        f"a solution exists ({why or 'not replayed'}); {searched}: none a counterexample, the named-witness "
        "argument does not decide here",
        None,
        config,
    )


def _finer_solution(model: Model, case: LiveCase, full: Any, spend: Budget, seconds: float) -> Any:
    """A solution of the enabledness question ``full`` (over the reals) found on a lattice of :data:`FINER`
    and confirmed over the reals with every named robot fixed there (z3's answer, positions and all), or
    ``None``; every check charged to ``spend``, within ``seconds`` in all."""
    from .smt.claims import NotEncoded
    from .smt.solving import fixed

    q = model.parameters.q
    start, confirm = spend.spent, seconds * CONFIRM_SHARE
    for k in FINER:
        try:
            lattice = build_enabled(Arith(k * q), model, case)
        except (ValueError, NotEncoded):  # a constant off this lattice: no solution to look for here
            continue
        found = spend.solve(lattice, seconds - confirm - (spend.spent - start))
        if found.status != "sat":
            continue
        confirmed = spend.solve(fixed(full, found.positions), confirm)
        if confirmed.status == "sat":
            return confirmed
    return None


def _small_most(small: Sequence[tuple[int, int, tuple[int, int]]], q: int) -> int:
    return max((n for qq, n, _ in small if qq == q), default=1)


REACH_ROUNDS = 20
"""Rounds the small swarms' runs are played for, looking for a reachable deadlock (:func:`reach`).
Measured on ``paper`` (q = 1, 2 to 4 robots, 9x9, this machine): about 3 s for all of them (most runs
end in a collision within a few rounds); it runs only when no stuck initial configuration decides the
row."""

REACH_SCHEDULE = f"every enabled robot moving each round (one under centralized), at most {REACH_ROUNDS} rounds"
"""How a reason names the schedule of :func:`reach`."""


def reach(model: Model, initial: tuple[Point, ...], rounds: int = REACH_ROUNDS) -> Run | None:
    """The run from ``initial`` in which every enabled robot moves each round (a round of every
    scheduler the obligations encode; under ``centralized`` the first enabled robot alone), if it ends
    in a deadlock after one round or more and within ``rounds``; ``None`` if it reaches a goal, a
    violation, or neither within ``rounds``."""
    from ..schedulers.round import play_round

    one = model.options.scheduler is Scheduler.CENTRALIZED
    state = initial
    steps: list[Any] = []
    for _ in range(rounds + 1):
        if is_goal(state, model):
            return None
        decisions = decide_all(state, model)
        movers = [i for i, d in decisions.items() if d.moves]
        if not movers:
            return Run(model, initial, tuple(steps), Outcome.DEADLOCK) if steps else None
        if len(steps) == rounds:
            return None
        step = play_round(state, movers[:1] if one else movers, model, decisions)
        if step.violations:
            return None
        steps.append(step)
        state = step.after
    return None


def small_stuck(model: Model, spec: LiveSpec) -> tuple[Verdict, str, dict[str, Any] | None, tuple[str, ...]] | None:
    """A deadlock among the small swarms of :mod:`fatline_verify.prove.small` on the model's own lattice
    (every initial configuration of a few robots, by the executable model alone) in which a robot of the
    left-most vertical that sees a robot right of it decides this case (the paper's rules:
    :func:`fatline_verify.rules.paper.cases.case_of` names it), replayed: a stuck initial configuration
    first; then a deadlock reached from one (:func:`reach`)."""
    from .small import _swarms

    q = model.parameters.q
    swarms = [state for at, _, state in _swarms(model) if at == q]
    for state in swarms:
        decisions = decide_all(state, model)
        if any(d.moves for d in decisions.values()) or is_goal(state, model):
            continue
        i = named_cases(model, state, decisions).get(spec.case)
        if i is None:
            continue
        ordered = (state[i], *(o for j, o in enumerate(state) if j != i))
        radii = {f"n{k}": model.from_lattice(o) for k, o in enumerate(ordered)}
        got = replay_stuck(model, spec, radii)  # type: ignore[arg-type]
        if got[0] is Verdict.VIOLATED:
            return got[0], got[1] + " (found among the small swarms)", got[2], got[3]
    origin = {"tool": "fatline prove", "lemma": str(spec.lemma), "form": spec.form, "case": spec.case}
    source = f"found among the small swarms, {REACH_SCHEDULE}"
    for state in swarms:
        run = reach(model, state)
        if run is None or spec.case not in named_cases(model, run.final, decide_all(run.final, model)):
            continue
        found = deadlock_of(model, run, source, origin)
        if found is not None:
            return Verdict.VIOLATED, found.reason(model, spec.case), found.doc, found.configuration(model, spec.case)
    return None


def _case(model: Model, spec: LiveSpec) -> LiveCase:
    for case in live_cases(model):
        if case.name == spec.case:
            return case
    raise KeyError(f"{spec.key}: no such case of rule set {model.rules!r}")


def _config(positions: Positions) -> tuple[str, ...]:
    return tuple(f"{x},{y}" for x, y in _points(positions))


def _points(positions: Positions) -> list[tuple[Fraction, Fraction]]:
    """The named robots' centres (radii), r first, equal centres once (names of one robot)."""
    out: list[tuple[Fraction, Fraction]] = []
    for name, p in positions.items():
        if not name.endswith("'") and p not in out:
            out.append(p)
    return out


def _state(model: Model, positions: Positions) -> tuple[Point, ...] | None:
    """The named robots as a lattice state of ``model`` (``None`` if a centre is off its lattice)."""
    state = tuple(model.to_lattice(p) for p in _points(positions))
    if any(Fraction(c).denominator != 1 for p in state for c in p):
        return None
    return state


def _shown(model: Model, state: Sequence[Point]) -> str:
    return ", ".join(show_point(model.from_lattice(p)) for p in state)


OFF_LATTICE = "a centre off the model's lattice"


def _swarm(model: Model, positions: Positions) -> tuple[tuple[Point, ...], str, dict[int, Decision]] | None:
    """A solution's swarm on the model's lattice, as shown in a reason, and every robot's decision
    there (``None`` if a centre is off the lattice): what both replays start from."""
    state = _state(model, positions)
    if state is None:
        return None
    return state, _shown(model, state), decide_all(state, model)


def replay_stuck(
    model: Model, spec: LiveSpec, positions: Positions
) -> tuple[Verdict, str, dict[str, Any] | None, tuple[str, ...]]:
    """A solution of an enabledness obligation as a swarm: VIOLATED only if no robot moves there, it
    is not a goal, and it meets the initial condition (a stuck configuration, replayed)."""
    config = _config(positions)
    swarm = _swarm(model, positions)
    if swarm is None:
        return Verdict.INCONCLUSIVE, OFF_LATTICE, None, config
    state, shown, decisions = swarm
    if decisions[0].moves:
        return Verdict.INCONCLUSIVE, f"encoding disagreement: in {shown} r moves (by {decisions[0].rule})", None, config
    movers = [i for i, d in decisions.items() if d.moves]
    if movers:
        return Verdict.INCONCLUSIVE, f"in {shown} r stays, but robot {movers[0]} moves: not stuck", None, config
    if is_goal(state, model):
        return Verdict.INCONCLUSIVE, f"{shown} is a goal", None, config
    problems = initial_problems(state, model)
    if problems:
        return Verdict.INCONCLUSIVE, f"{shown} is stuck but not an initial configuration ({problems[0]})", None, config
    rules = ", ".join(sorted({str(d.rule) for d in decisions.values()}))
    return (
        Verdict.VIOLATED,
        f"stuck: no robot of the initial configuration {shown} ({len(state)} robots, not a line) moves "
        f"(rules {rules}; replayed by the executable model)",
        _stuck_trace(model, state, spec),
        config,
    )


def _stuck_trace(model: Model, state: tuple[Point, ...], spec: LiveSpec) -> dict[str, Any] | None:
    """The stuck configuration as a replayed trace (a run that ends in a deadlock at once), if the
    trace format takes it; ``None`` otherwise (the row's configuration still names it)."""
    from ..trace.simulate import simulate
    from ..trace.traces import replayed_document

    origin = {"tool": "fatline prove", "lemma": str(spec.lemma), "form": spec.form, "case": spec.case}
    try:
        run = simulate(state, model, max_rounds=1)
        return replayed_document(run, origin, Lemma.PROGRESS)
    except Exception:  # the trace is a convenience; the verdict rests on the replay above
        return None


def measure_of(model: Model, state: Sequence[Point]) -> tuple[int, ...]:
    """The declared measure of ``state`` (lattice units): per component, the sum over the robots."""
    declared = registry.of(model).liveness
    assert declared is not None
    sums = [sum(a * Fraction(x) + b * Fraction(y) for x, y in state) for a, b in declared.measure]
    return tuple(int(v) if Fraction(v).denominator == 1 else v for v in sums)  # type: ignore[misc]


def replay_measure(
    model: Model, spec: LiveSpec, positions: Positions
) -> tuple[Verdict, str, dict[str, Any] | None, tuple[str, ...]]:
    """A solution of a measure obligation as a swarm: VIOLATED only if r makes the case's move there,
    the round (r alone; under fsync every robot that moves) does not decrease the measure, and the
    configuration meets the initial condition."""
    from ..schedulers.round import play_round

    config = _config(positions)
    swarm = _swarm(model, positions)
    if swarm is None:
        return Verdict.INCONCLUSIVE, OFF_LATTICE, None, config
    state, shown, decisions = swarm
    d = decisions[0]
    r, want = state[0], model.to_lattice(positions["r'"])
    if not d.moves or (r[0] + d.destination[0], r[1] + d.destination[1]) != want:
        return Verdict.INCONCLUSIVE, f"encoding disagreement: in {shown} r does not make the case's move", None, config
    fsync = model.options.scheduler is Scheduler.FSYNC
    movers = [i for i, e in decisions.items() if e.moves] if fsync else [0]
    played = play_round(state, movers, model, decisions)
    before, after = measure_of(model, state), measure_of(model, played.after)
    if after < before:
        return Verdict.INCONCLUSIVE, f"in {shown} the round's movers decrease the measure together", None, config
    problems = initial_problems(state, model)
    if problems:
        return (
            Verdict.INCONCLUSIVE,
            f"a round of {shown} does not decrease the measure, but it is not an initial configuration ({problems[0]})",
            None,
            config,
        )
    return (
        Verdict.VIOLATED,
        f"a round that does not decrease the measure ({list(before)} -> {list(after)}; movers {movers}), from the "
        f"initial configuration {shown} ({len(state)} robots, replayed): the measure is not proved, termination is not "
        "refuted by it",
        None,
        config,
    )


__all__ = ["measure_of", "prove_live", "reach", "replay_measure", "replay_stuck", "small_stuck"]
