"""``fatline prove``: each lemma per decision case with z3: PROVED for swarms of every size, or
VIOLATED with a counterexample the executable model replays from an initial configuration.

Obligations (:mod:`fatline_verify.smt.claims`) name r, the witnesses of r's case, and the robot the
claim is about; the rest of any swarm is covered by the witness argument written in each one's
header. Each obligation runs in a fresh process (:mod:`fatline_verify.fresh`) and is decided in
rounds of growing budget (2 s, then 4 times more, the last round taking what is left of
``--timeout``); each round runs every step still open, each step with its own z3 context and
deterministic budget:

1. **Vacuity** (until answered): if "r makes this case's decision" has no solution over the reals, the
   case never fires under the model's readings: PROVED, "the case never fires".
2. **Lattices first**: the named robots on the lattices ``x = X / q`` (q = 1, 2, 4, 8, 20; integer
   arithmetic) with the paper's initial condition on them. A solution is replayed by the executable
   model: if r decides the same case, the claim fails and the configuration is initial, VIOLATED. A
   placement that does not replay as initial is blocked (in every later round too) and the search
   goes on; a lattice with no solution is not searched again.
3. **The reals** (not for two movers: their group obligations are beyond any budget tried), without
   the initial condition: ``unsat`` is PROVED (every size, by the header's argument); ``sat`` is
   replayed, VIOLATED if the configuration is initial; otherwise the reals are searched with the
   initial condition (in this round and the later ones), and without an initial solution the verdict
   is INCONCLUSIVE with the configuration and what would decide it; ``unknown`` after the last round
   is INCONCLUSIVE with the budget.

A replay that disagrees with the encoding (r decides another case, or the claim holds) is a bug of
the tool and reported as "encoding disagreement". The global form of Lemma 1 (the whole graph)
has no witness argument and keeps its bounded slot encoding (:func:`prove_global`).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .algorithm import Band, Decision
from .cases import Case, case_of, moving_cases, staying_cases
from .config import Model
from .errors import InvalidInput, InvalidTrace
from .fresh import isolated, run_fresh
from .geometry import dist2
from .numbers import Point, show_point
from .options import Scheduler
from .properties import Lemma, Verdict
from .repair_options import RepairProgress
from .schedule import Collision, decide_all, lost_edges, play_round
from .schedulers import round_scheduler
from .simulate import Outcome, Run, outcome_after
from .smt import obligations as ob
from .smt.claims import (
    CLOSER,
    GLOBAL,
    ONE_MOVER,
    SEEN,
    TWO_MOVERS,
    X_NONDECREASING,
    Built,
    NotEncoded,
    Spec,
    argument,
)
from .smt.legs import LegSpec, leg_specs, missing_repairs
from .swarm import initial_problems
from .trace import initial_radii, replayed_document

if TYPE_CHECKING:
    from .smt.solving import Answer, Positions

ENCODED = (Scheduler.SSYNC, Scheduler.FSYNC, Scheduler.CENTRALIZED)
"""The schedulers the obligations encode: every mover decides on one shared snapshot."""

LATTICES = (1, 2, 4, 8, 20)
"""The lattices ``x = X / q`` searched for an initial counterexample before the reals."""
LATTICES_TEXT = ", ".join(map(str, LATTICES))
"""How reasons name them (``q=1, 2, 4``)."""

SHARE = {"vacuity": 0.05, "lattices": 0.7, "reals": 0.15, "reals-initial": 0.1}
"""Each step's share of a round's budget. Measured on the shipped models: a search that finds a
counterexample mostly finds it on a lattice (the slowest took 15 s at q = 8), and the reals answer
within a second (the median PROVED) or not within a minute."""

LATTICE_WEIGHT = {1: 3, 2: 2, 4: 2, 8: 2, 20: 2}
"""How the lattices' share of a round is split among the lattices still open (the coarsest, where most
counterexamples lie, gets the most; a lattice without solutions gives its part to the others)."""

FIRST_ROUND = 2.0
"""The first round's budget in seconds (most obligations are decided in it)."""
GROWTH = 4
"""Each round's budget is this many times the last one's."""

MIN_CHECK = 0.01
"""Seconds below which a check is not started."""

MAX_BLOCKED = 4
"""Non-initial lattice placements blocked per lattice before moving on."""


class NotEncodedModel(InvalidInput):
    """``fatline prove`` on a model the obligations do not encode (exit 2, before any work): a scheduler
    other than :data:`ENCODED`, or a repair (:mod:`fatline_verify.repairs`)."""


@dataclass(frozen=True, slots=True)
class ProofResult:
    """One obligation's verdict."""

    lemma: Lemma
    form: str
    rule: str
    verdict: Verdict
    slots: int
    """Named robots besides r (the global form: slot robots)."""
    any_size: bool
    seconds: float
    reason: str
    smt2: str
    witness: dict[str, Any] | None = field(default=None, repr=False, compare=False)
    comment: str = field(default="", repr=False, compare=False)
    case: str = "any"
    other: str = ""
    configuration: tuple[str, ...] = ()
    """For a claim without a trace (``seen``, ``x-nondecreasing``, ``closer``): the replayed
    configuration, r first, as exact ``x,y`` strings in radii."""

    @property
    def key(self) -> str:
        tail = f".and.{self.other}" if self.other else ""
        return f"{self.lemma}/{self.form}-{self.case}{tail}"


# --- which obligations a model has ----------------------------------------------------------------

DEFAULT_SLOTS = 3
"""Slot robots of the global connectivity form, unless asked otherwise."""
DEFAULT_TIMEOUT = 60.0
"""Solver seconds per obligation, unless asked otherwise."""

LEMMAS = (Lemma.NO_COLLISION, Lemma.CONNECTIVITY, Lemma.RMA_FIXED, Lemma.APPROACH)
"""The lemmas the prover decides, in results order."""


@dataclass(frozen=True, slots=True)
class GlobalTask:
    """Lemma 1 in its global form (the whole graph after one round)."""

    lemma: Lemma = Lemma.CONNECTIVITY
    form: str = GLOBAL

    @property
    def key(self) -> str:
        return f"{self.lemma}/{GLOBAL}-any"


Task = Spec | GlobalTask | LegSpec
"""An obligation: a decision case of the paper's rules, the global form, or a repaired rule set's leg."""


def rule_groups(cases: Sequence[Case]) -> list[tuple[str, tuple[Case, ...]]]:
    """The moving cases grouped by rule (a second mover's obligations take one group each)."""
    groups: dict[str, list[Case]] = {}
    for case in cases:
        groups.setdefault(case.rule.value, []).append(case)
    return [(name, tuple(group)) for name, group in groups.items()]


def check_encoded(model: Model) -> None:
    """Refuse a model the obligations do not encode: never another scheduler's semantics, never the
    paper's rules in place of a repaired rule set the leg obligations do not cover."""
    scheduler = model.options.scheduler
    if scheduler not in ENCODED:
        raise NotEncodedModel(
            f"scheduler={scheduler}: fatline prove encodes rounds in which every mover decides on one shared "
            f"snapshot ({', '.join(s.value for s in ENCODED)}); an asynchronous robot may decide on a stale view. "
            f"Use fatline check {model.name} for this scheduler"
        )
    if model.options.repaired:
        missing = missing_repairs(model)
        if missing:
            raise NotEncodedModel(
                f"{', '.join(missing)} not set: fatline prove encodes a repaired rule set by its legs, which rest "
                f"on the lock, unit steps, clear paths and kept edges together. Set them, or use fatline check "
                f"{model.name}"
            )
        if model.options.repair_progress is RepairProgress.CORNER:
            raise NotEncodedModel(
                "repair_progress='corner': the leg obligations do not cover corner legs (right and vertical at "
                "once, up to sqrt(2) long, so two far movers may close a gap of more than rad_v to less than 2 "
                f"unless their neighbours rule it out); expected off or detour. Use fatline check {model.name}"
            )


PAPER_PART_NOTE = (
    "Repaired model: these are the paper's rules under its readings, its repairs off. A repaired move is one leg "
    "toward their destination (never farther right, never left of r), or a repair's own: repair-align to the "
    "greatest x r sees, repair-approach 2 radii short of psi_right (right of r), repair-contract vertical."
)
"""The header line of a repaired model's per-case obligations: what they say of the repaired rules."""


def paper_part(model: Model) -> Model:
    """The paper's rules under ``model``'s readings (its repairs off): what the per-case obligations
    of a repaired model encode (a repaired move is a leg toward their destination, or a repair's own)."""
    if not model.options.repaired:
        return model
    from dataclasses import replace

    off = {name: "off" for name in model.options.as_dict() if name.startswith("repair_")}
    return replace(model, options=model.options.with_(**off))


def tasks_for(model: Model, lemmas: tuple[Lemma, ...] = LEMMAS, *, two_movers: bool = False) -> list[Task]:
    """Every obligation ``prove`` decides for ``model`` and ``lemmas``, in results order.

    ``two_movers``: also the two-mover obligations (one per pair of rules; searched on the lattices
    only, as their real form is beyond the budgets tried), which ``fatline prove --two-movers`` asks for."""
    check_encoded(model)
    if model.options.repaired:
        return _repaired_tasks(model, lemmas)
    scheduler = model.options.scheduler
    moving = moving_cases(model)
    stays = tuple(staying_cases(model)) if scheduler is Scheduler.FSYNC else ()
    groups = rule_groups(moving) if two_movers and scheduler is not Scheduler.CENTRALIZED else []
    tasks: list[Task] = []
    for lemma in lemmas:
        if lemma in (Lemma.NO_COLLISION, Lemma.CONNECTIVITY):
            tasks += [Spec.of(lemma, ONE_MOVER, c, stays, "o-stays" if stays else "") for c in moving]
            tasks += [
                Spec(lemma, TWO_MOVERS, mine, theirs, other)
                for k, (_, mine) in enumerate(groups)
                for other, theirs in groups[k:]
            ]
        if lemma is Lemma.CONNECTIVITY:
            tasks += [Spec.of(lemma, CLOSER, c) for c in moving if c.rule.value in CLOSER_RULES]
            tasks.append(GlobalTask())
        if lemma is Lemma.RMA_FIXED:
            tasks += [Spec.of(lemma, SEEN, c) for c in moving]
        if lemma is Lemma.APPROACH:
            tasks += [Spec.of(lemma, X_NONDECREASING, c) for c in moving]
    return tasks


def _repaired_tasks(model: Model, lemmas: tuple[Lemma, ...]) -> list[Task]:
    """A repaired model's obligations: the leg obligations of the collision and connectivity lemmas
    (:mod:`fatline_verify.smt.legs`), and the per-case claims ``seen`` and ``x-nondecreasing`` of the
    paper's rules under its readings (:func:`paper_part`; the legs' rightward horizontal rests on
    the latter)."""
    moving = moving_cases(paper_part(model))
    tasks: list[Task] = []
    for lemma in lemmas:
        tasks += leg_specs((lemma,))
        if lemma is Lemma.RMA_FIXED:
            tasks += [Spec.of(lemma, SEEN, c) for c in moving]
        if lemma is Lemma.APPROACH:
            tasks += [Spec.of(lemma, X_NONDECREASING, c) for c in moving]
    return tasks


CLOSER_RULES = ("scenario-1", "scenario-2", "scenario-3", "uncovered-search")
"""The rules Lemma 1's proof argues about ("under scenario 2 and 3 ... it becomes closer")."""


def task_key(task: Task) -> str:
    """``lemma/form-case[.and.other]``: how results rows and witness files name an obligation."""
    return task.key


# --- replay -----------------------------------------------------------------------------------------


@dataclass
class Replayed:
    """A solver answer turned into a configuration and checked by the executable model."""

    state: tuple[Point, ...]
    """Lattice units, r first."""
    focus: int | None
    initial: bool
    problems: list[str]
    doc: dict[str, Any] | None
    what: str


def _state(model: Model, positions: dict[str, tuple[Fraction, Fraction]], focus: str) -> tuple[list[Point], int | None]:
    """The distinct robots named (equal centres are one robot), r first, and the focus's index."""
    points: list[Point] = []
    for name in ["r", *[n for n in positions if n != "r"]]:
        p = model.to_lattice(positions[name])
        if p not in points:
            points.append(p)
    index = points.index(model.to_lattice(positions[focus])) if focus else None
    return points, index


def replay(model: Model, spec: Spec, positions: dict[str, tuple[Fraction, Fraction]], focus: str) -> Replayed | str:
    """Replay a solution: the state, r's case, the claim; or why it does not reproduce."""
    points, j = _state(model, positions, focus)
    state = tuple(points)
    decisions = decide_all(state, model)
    got = case_of(decisions[0], model)
    if got not in spec.mine:
        return f"r decides {got.name}, not {spec.name}"
    problems = initial_problems(state, model)
    initial = not problems
    form = spec.form
    if form in (SEEN, X_NONDECREASING, CLOSER):
        what = _claim_fails(model, spec, state, decisions[0], j)
        if what is None:
            return "the claim holds on the replayed configuration"
        return Replayed(state, j, initial, problems, None, what)
    assert j is not None
    other = case_of(decisions[j], model)
    fsync = model.options.scheduler is Scheduler.FSYNC
    if form == TWO_MOVERS and other not in spec.other:
        return f"the second robot decides {other.name}, not one of {spec.other_name}"
    if form == ONE_MOVER and fsync and other not in spec.other:
        return f"the robot at rest decides {other.name}, and moves"
    active = list(range(len(state))) if fsync else [0, j] if form == TWO_MOVERS else [0]
    if round_scheduler(model.options.scheduler).forbids(tuple(active), len(state)) is not None:
        return f"activation {active} is not a round of the scheduler"
    result = play_round(state, active, model, decisions)
    if spec.lemma is Lemma.NO_COLLISION:
        hit = [v for v in result.violations if isinstance(v, Collision) and v.robots == (0, j)]
        if not hit:
            return f"r and robot {j} do not collide in the replayed round"
        focus_lemma, what = Lemma.NO_COLLISION, "collision"
    else:
        if not any(pair == (0, j) for pair, _ in lost_edges(result.before, result.after, model)):
            return f"r and robot {j} keep their edge in the replayed round"
        split = any(v.lemma == Lemma.CONNECTIVITY for v in result.violations)
        focus_lemma = Lemma.CONNECTIVITY if split else Lemma.CONNECTIVITY_EDGE
        what = "an edge is lost and the graph splits" if split else "an edge is lost (the graph stays connected)"
    run = Run(model, state, (result,), outcome_after(result.after, result, model) or Outcome.ROUND_LIMIT)
    origin = {"tool": "fatline prove", "lemma": spec.lemma, "form": form, "case": spec.name}
    if spec.other_name:
        origin["other"] = spec.other_name
    doc = replayed_document(run, origin, focus_lemma)
    return Replayed(state, j, initial, problems, doc, what)


def replay_known(model: Model, spec: Spec, doc: dict[str, Any]) -> Replayed | None:
    """An earlier run's counterexample of ``spec`` (its trace file), replayed by the executable model
    as the search would replay a solver's answer: the same case, the same claim broken, from an
    initial configuration; ``None`` if it does not (the readings changed, say), and the search runs."""
    try:
        state = initial_radii(doc)
        j = int(doc["violation"]["robots"][1])
    except (KeyError, IndexError, TypeError, ValueError, InvalidTrace):
        return None
    if not 0 < j < len(state):
        return None
    focus = "s" if spec.form == TWO_MOVERS else "o"
    positions = {"r": state[0], **{f"x{k}": p for k, p in enumerate(state[1:], 1) if k != j}, focus: state[j]}
    got = replay(model, spec, {k: (Fraction(x), Fraction(y)) for k, (x, y) in positions.items()}, focus)
    return got if isinstance(got, Replayed) and got.initial and got.doc is not None else None


def _claim_fails(model: Model, spec: Spec, state: Sequence[Point], dec: Decision, j: int | None) -> str | None:
    """How r's decision breaks a per-rule claim on ``state`` (``None`` if it does not)."""
    dx, dy = dec.destination
    dest = show_point(model.from_lattice(dec.destination))
    if spec.form == X_NONDECREASING:
        return f"r moves to {dest}: x decreases" if dx < 0 else None
    if spec.form == SEEN:
        seen = [c for c, _ in dec.classification]
        if dx > 0 and all(c[0] < dx for c in seen):
            return f"r moves to {dest}, right of itself and of every robot it sees"
        return None
    assert j is not None
    rel = (state[j][0] - state[0][0], state[j][1] - state[0][1])
    bands = dict(dec.classification).get(rel, frozenset())
    if bands & {Band.B, Band.C, Band.D} and dist2(rel, (dx, dy)) >= dist2(rel, (0, 0)):
        where = show_point(model.from_lattice(rel))
        return f"r moves to {dest} and is not closer to the robot at {where} in {'/'.join(sorted(bands))}"
    return None


# --- one obligation ---------------------------------------------------------------------------------


def rounds(timeout: float) -> list[float]:
    """The budgets of successive rounds within ``timeout``: :data:`FIRST_ROUND` seconds, then
    :data:`GROWTH` times more each round, the last taking whatever is left (60 s: 2, 8, 50)."""
    budgets: list[float] = []
    left, budget = timeout, min(FIRST_ROUND, timeout)
    while left > 1e-9:
        take = left if left <= budget * (1 + GROWTH) else budget
        budgets.append(take)
        left -= take
        budget *= GROWTH
    return budgets


def rounds_text(timeout: float) -> str:
    """Where an exhausted budget ran out: ``in the last of 3 rounds (60 s in all)``."""
    n = len(rounds(timeout))
    return f"in the last of {n} rounds ({timeout:g} s in all)" if n > 1 else f"in its one round of {timeout:g} s"


class Budget:
    """An obligation's solver budget, spent by every check it makes (the per-case search of
    :func:`prove_spec`, the leg obligations of :mod:`fatline_verify.leg_prover`)."""

    def __init__(self, timeout: float) -> None:
        self.timeout = timeout
        self.spent = 0.0
        """Budget used, in z3 resource units as seconds (deterministic: it decides what is left)."""
        self.wall = 0.0
        """Wall-clock seconds of the checks (reported, never deciding)."""

    def left(self) -> float:
        """Seconds of budget a check may still take: the budget not yet used (z3's resource count,
        so the same on every run), divided by :data:`~fatline_verify.smt.solving.WALL` so that even
        checks stopped by the wall clock end about within ``timeout``."""
        from .smt.solving import WALL

        return max(0.0, self.timeout - self.spent) / WALL

    def solve(self, built: Built, seconds: float, blocked: Sequence[Positions] = ()) -> Answer:
        """Check ``built`` (``blocked`` answers excluded) for at most ``seconds`` of what is left;
        ``unknown`` without a check if that is less than :data:`MIN_CHECK`."""
        from .smt.solving import Answer, block, check, solver_for

        seconds = min(seconds, self.left())
        if seconds < MIN_CHECK:
            return Answer("unknown", 0.0, "budget exhausted")
        solver = solver_for(built, seconds)
        for placement in blocked:
            block(solver, built, placement)
        ans = check(solver, built, seconds)
        self.spent += ans.budget
        self.wall += ans.seconds
        return ans


class _Search(Budget):
    """One obligation's search, in rounds of growing budget (see :func:`prove_spec`)."""

    def __init__(self, model: Model, spec: Spec, full: Built, path: str, timeout: float) -> None:
        super().__init__(timeout)
        self.model, self.spec, self.full, self.path = model, spec, full, path
        self.blocked: dict[int, list[Positions]] = {q: [] for q in LATTICES}
        self.off_lattice: set[int] = set()
        """Lattices the obligation cannot be put on (a constant off it), or a form searched over the reals only."""
        self.exhausted: set[int] = set()
        """Lattices with no solution at all (unsat): nothing more to find there."""
        self.non_initial: Replayed | None = None
        """A replayed violation over the reals whose configuration is not initial."""
        self.initial_unsat = False
        """No violation from an initial configuration over the reals at all."""
        self.irrational: str | None = None
        """Why the reals' counterexample, irrational and rounded, does not reproduce."""
        self.last = ""
        self.fires = False
        """Whether "r decides this case" is known to have a solution (vacuity is asked until answered)."""

    def result(self, verdict: Verdict, reason: str, rep: Replayed | None = None) -> ProofResult:
        named = len(self.full.bodies) - 1
        return _result(self.spec, verdict, named, self.wall, reason, self.path, rep, self.full.comment)

    def vacuous(self, budget: float) -> ProofResult | None:
        from .smt.cases import Arith
        from .smt.claims import build

        if self.fires:
            return None
        vac = build(Arith(None), self.model, self.spec, vacuity=True)
        status = self.solve(vac, budget * SHARE["vacuity"]).status
        if status == "unsat":
            return self.result(Verdict.PROVED, "the case never fires under these readings (vacuous)")
        self.fires = status == "sat"
        return None

    def lattices(self, budget: float) -> ProofResult | None:
        from .smt.cases import Arith
        from .smt.claims import build

        for q in LATTICES:
            if q in self.off_lattice or q in self.exhausted:
                continue
            try:
                lat = build(Arith(q), self.model, self.spec, initial=True)
            except (ValueError, NotEncoded):
                self.off_lattice.add(q)
                continue
            open_weight = sum(LATTICE_WEIGHT[k] for k in LATTICES if k not in self.off_lattice | self.exhausted)
            left = budget * SHARE["lattices"] * LATTICE_WEIGHT[q] / open_weight  # shared by the blocked retries
            for _ in range(MAX_BLOCKED):
                if left < MIN_CHECK:
                    break
                ans = self.solve(lat, left, self.blocked[q])
                left -= ans.budget
                if ans.status == "unsat":
                    self.exhausted.add(q)
                if ans.status != "sat":
                    break
                got = replay(self.model, self.spec, ans.positions, lat.focus)
                if isinstance(got, str):
                    return self.result(Verdict.INCONCLUSIVE, f"encoding disagreement (lattice q={q}): {got}")
                if got.initial:
                    return self.result(Verdict.VIOLATED, _found(got, f"lattice q={q}"), got)
                self.blocked[q].append(ans.positions)
        return None

    def reals(self, budget: float) -> ProofResult | None:
        if self.non_initial is None and self.irrational is None:
            ans = self.solve(self.full, budget * SHARE["reals"])
            if ans.status == "unsat":
                return self.result(
                    Verdict.PROVED, "unsat over the reals: holds for swarms of every size (the header's argument)"
                )
            if ans.status == "unknown":
                self.last = ans.reason
                return None
            got = replay(self.model, self.spec, ans.positions, self.full.focus)
            if isinstance(got, str) and ans.rounded:
                self.irrational = got  # the lattices and the initial search may still find a rational one
                return self.reals_initial(budget)
            if isinstance(got, str):
                return self.result(Verdict.INCONCLUSIVE, f"encoding disagreement (reals): {got}")
            if got.initial:
                return self.result(Verdict.VIOLATED, _found(got, "reals", ans.rounded), got)
            self.non_initial = got
        return self.reals_initial(budget)

    def reals_initial(self, budget: float) -> ProofResult | None:
        """A violation exists, from a configuration that is not initial: look for an initial one."""
        from .smt.cases import Arith
        from .smt.claims import build

        again = build(Arith(None), self.model, self.spec, initial=True)
        more = self.solve(again, budget * SHARE["reals-initial"])
        if more.status == "unsat":
            self.initial_unsat = True
        if more.status != "sat":
            return None
        found = replay(self.model, self.spec, more.positions, again.focus)
        if isinstance(found, str) and more.rounded:
            return None  # irrational again: left to the lattices
        if isinstance(found, str):
            return self.result(Verdict.INCONCLUSIVE, f"encoding disagreement (reals, initial): {found}")
        if found.initial:
            return self.result(Verdict.VIOLATED, _found(found, "reals", more.rounded), found)
        return None

    def done(self) -> bool:
        """Nothing left to search: no initial violation over the reals (so none on a lattice), or,
        for two movers (lattices only), every lattice exhausted."""
        lattices_done = len(self.exhausted | self.off_lattice) == len(LATTICES)
        return self.initial_unsat or (self.spec.form == TWO_MOVERS and lattices_done)

    def give_up(self, timeout: float) -> ProofResult:
        """INCONCLUSIVE after every round, with what is known and what would decide it."""
        lattices = f"no initial counterexample on the lattices q={LATTICES_TEXT}"
        if self.spec.form == TWO_MOVERS:
            return self.result(
                Verdict.INCONCLUSIVE,
                f"{lattices}; two-mover obligations (every case of both rules, with both robots' witnesses) are not "
                "searched over the reals: their real form, written to the .smt2 file, is beyond this budget",
            )
        got = self.non_initial
        if got is None and self.irrational is not None:
            return self.result(
                Verdict.INCONCLUSIVE,
                f"the solver's counterexample has irrational coordinates and its rational rounding does not reproduce "
                f"({self.irrational}): a boundary case exact rational replay cannot confirm; {lattices}",
            )
        if got is None:
            return self.result(
                Verdict.INCONCLUSIVE,
                f"solver: {self.last} {rounds_text(timeout)}; {lattices}; rerun with a larger --timeout",
            )
        initial_too = (
            "none from an initial configuration over the reals"
            if self.initial_unsat
            else f"no initial one on the lattices q={LATTICES_TEXT} or the reals within the budget"
        )
        return self.result(
            Verdict.INCONCLUSIVE,
            f"{got.what} in a configuration of {len(got.state)} robots that is not initial ({got.problems[0]}); "
            f"{initial_too}; whether it is reachable is not decided: rerun with a larger --timeout, or check the "
            "configuration's swarm size with fatline check",
            got,
        )


def prove_spec(
    model: Model, spec: Spec, *, timeout: float, out: Path | None, note: str = "", known: dict[str, Any] | None = None
) -> ProofResult:
    """Decide one obligation (see the module docstring); write its real-number form under ``out``.

    The search runs in rounds of growing budget (:func:`rounds`), each round every step that is still
    open (vacuity in the first only), so an easy answer costs a small round and a hard one gets most
    of ``timeout``."""
    from .smt.cases import Arith
    from .smt.claims import build
    from .smt.solving import write

    try:
        full = build(Arith(None), model, spec)
    except NotEncoded as exc:
        return _result(spec, Verdict.INCONCLUSIVE, 0, 0.0, f"not encoded: {exc}", "", None)
    full.comment = argument(model, spec, full) + (f"\n{note}" if note else "")
    path = ""
    if out is not None:
        target = out / spec.lemma / f"{spec.key.split('/', 1)[1]}.smt2"
        write(full, target)
        path = target.as_posix()
    search = _Search(model, spec, full, path, timeout)
    again = replay_known(model, spec, known) if known is not None else None
    if again is not None:
        return search.result(Verdict.VIOLATED, _found(again, "an earlier run's counterexample, replayed first"), again)
    for budget in rounds(timeout):
        found = search.vacuous(budget) or search.lattices(budget)
        if found is None and spec.form != TWO_MOVERS:
            found = search.reals(budget)
        if found is not None:
            return found
        if search.done() or search.left() < MIN_CHECK:
            break
    return search.give_up(timeout)


def _found(got: Replayed, where: str, rounded: bool = False) -> str:
    """The reason of a VIOLATED verdict; ``rounded``: the solver's values were algebraic."""
    tail = "; values rounded from algebraic numbers and re-checked" if rounded else ""
    return f"{got.what}, from an initial configuration of {len(got.state)} robots ({where}, replayed){tail}"


def _result(
    spec: Spec,
    verdict: Verdict,
    named: int,
    seconds: float,
    reason: str,
    path: str,
    rep: Replayed | None,
    comment: str = "",
) -> ProofResult:
    config: tuple[str, ...] = ()
    if rep is not None and rep.doc is None:
        config = tuple(f"{x},{y}" for x, y in rep.state)
    return ProofResult(
        spec.lemma,
        spec.form,
        spec.mine[0].rule.value,
        verdict,
        named,
        True,
        seconds,
        reason,
        path,
        rep.doc if rep is not None else None,
        comment,
        spec.name,
        spec.other_name,
        config,
    )


def prove_global(model: Model, *, slots: int, timeout: float, out: Path | None) -> ProofResult:
    """Lemma 1, global form, for configurations of at most ``slots + 1`` robots."""
    full = ob.build_global(model, slots)
    path = ""
    if out is not None:
        target = out / Lemma.CONNECTIVITY.value / "global.smt2"
        ob.write(full, target)
        path = str(target)
    spent = 0.0

    def result(verdict: Verdict, k: int, reason: str, doc: dict[str, Any] | None = None) -> ProofResult:
        return ProofResult(
            Lemma.CONNECTIVITY, "global", "any", verdict, k, False, spent, reason, path, doc, full.comment
        )

    from .smt.solving import WALL

    attempts = [(k, True, timeout / 2 / slots) for k in range(1, slots + 1)] + [(slots, False, timeout / 2)]
    last = None
    for k, initial, planned in attempts:
        limit = min(planned, max(0.0, timeout - spent)) / WALL  # even stopped by the wall clock, within timeout
        if limit < MIN_CHECK:
            return result(
                Verdict.INCONCLUSIVE,
                k,
                f"budget exhausted before the {k + 1}-robot attempt; rerun with a larger --timeout",
            )
        obligation = ob.build_global(model, k, initial=initial)
        ans = ob.solve(obligation, limit)
        spent += ans.seconds
        last = (k, ans)
        if ans.status != "sat":
            continue
        active_flags, present = ans.flags[: k + 1], ans.flags[k + 1 :]
        state = ((0, 0), *(model.to_lattice(p) for p in ans.positions))
        index = [0] + [1 + sum(present[:i]) for i in range(k)]  # state index of r and of each slot
        active = [index[i] for i in range(k + 1) if active_flags[i] and (i == 0 or present[i - 1])]
        if round_scheduler(model.options.scheduler).forbids(tuple(active), len(state)) is not None:
            return result(
                Verdict.INCONCLUSIVE, k, f"encoding disagreement: activation set {active} breaks the scheduler"
            )
        run_result = play_round(state, active, model)
        if not any(v.lemma == Lemma.CONNECTIVITY for v in run_result.violations):
            return result(
                Verdict.INCONCLUSIVE, k, "encoding disagreement: the replayed round keeps the graph connected"
            )
        run = Run(model, state, (run_result,), Outcome.VIOLATION)
        origin = {"tool": "fatline prove", "lemma": Lemma.CONNECTIVITY.value, "form": "global"}
        doc = replayed_document(run, origin, Lemma.CONNECTIVITY)
        if not initial_problems(state, model):
            return result(
                Verdict.VIOLATED, k, f"the graph splits, from an initial configuration of {k + 1} robots", doc
            )
        if not initial:
            return result(Verdict.INCONCLUSIVE, k, "disconnecting configuration found, not an initial one", doc)
    assert last is not None
    k, ans = last
    if ans.status == "unsat":
        return result(Verdict.HOLDS_WITHIN_BOUNDS, k, f"unsat for configurations of at most {k + 1} robots")
    return result(Verdict.INCONCLUSIVE, k, f"solver: {ans.reason}")


def prove(
    model: Model,
    lemmas: tuple[Lemma, ...] = LEMMAS,
    *,
    slots: int = DEFAULT_SLOTS,
    timeout: float = DEFAULT_TIMEOUT,
    out: Path | None = None,
    jobs: int | None = None,
    progress: Callable[[str], None] | None = None,
    tasks: list[Task] | None = None,
    on_result: Callable[[ProofResult], None] | None = None,
    traces: Path | None = None,
) -> list[ProofResult]:
    """Every obligation of ``lemmas`` (or exactly ``tasks``) for ``model``; ``.smt2`` files under ``out``.

    Each obligation runs in a fresh process (:func:`fatline_verify.fresh.run_fresh`), which also
    spreads them over the cores. ``on_result`` sees each result as it finishes (so a caller can save
    it at once); the list returned is in task order. An interrupt stops the workers and propagates.
    ``traces``: where earlier runs wrote their counterexamples (default ``out/traces``); an
    obligation's own is replayed before any search, so a counterexample once found stays found.
    """
    tasks = tasks_for(model, lemmas) if tasks is None else tasks
    if not tasks:
        return []
    check_encoded(model)
    from .leg_prover import prove_leg

    workers = max(1, min(jobs or os.cpu_count() or 1, len(tasks)))
    calls: list[tuple[Callable[..., ProofResult], tuple[Any, ...], dict[str, Any]]] = []
    for task in tasks:
        if isinstance(task, LegSpec):
            calls.append((prove_leg, (model, task), {"timeout": timeout, "out": out}))
        elif isinstance(task, Spec):
            note = PAPER_PART_NOTE if model.options.repaired else ""
            known = _known(model, task, traces if traces is not None else out / "traces" if out else None)
            kwargs = {"timeout": timeout, "out": out, "note": note, "known": known}
            calls.append((prove_spec, (paper_part(model), task), kwargs))
        else:
            calls.append((prove_global, (model,), {"slots": slots, "timeout": timeout, "out": out}))
    results: list[ProofResult | None] = [None] * len(tasks)

    def done(k: int, result: ProofResult) -> None:
        results[k] = result
        if on_result:
            on_result(result)
        if progress:
            progress(task_key(tasks[k]))

    run_fresh(calls, workers, done)
    return [r for r in results if r is not None]


def witness_path(model: Model, directory: Path, key: str) -> Path:
    """``DIRECTORY/MODEL-prove-LEMMA-FORM-RULE.json`` for the obligation ``key``."""
    from .outputs import child

    lemma, rest = key.split("/", 1)
    return child(directory, f"{model.name}-prove-{lemma}-{rest}", ".json")


def _known(model: Model, task: Spec, traces: Path | None) -> dict[str, Any] | None:
    """The counterexample an earlier run wrote for ``task`` under ``traces``, if any."""
    from .outputs import Kind, is_output, read_json

    if traces is None:
        return None
    path = witness_path(model, traces, task.key)
    return read_json(path) if path.is_file() and is_output(path, Kind.TRACE) else None


def prove_fingerprint(model: Model, slots: int, timeout: float) -> str:
    """What a prover result depends on: the model, the settings, the encoding's version."""
    from .cache import fingerprint

    return fingerprint(model, "prove", slots=slots, timeout=timeout, encoding=ENCODING_VERSION)


ENCODING_VERSION = 7
"""Bumped whenever an obligation's search or meaning changes (part of the cache fingerprint). 3:
role-assigned obligations per decision case; 4: lattices q = 1, 2, 4 with their own shares, an
initial search over the reals after a non-initial solution, fsync replays activate every robot;
5: rounds of growing budget, lattices q = 1, 2, 4, 8, 20, an irrational answer searched past;
6: an obligation's checks end within its budget (blocked retries share their lattice's share), and
vacuity is asked in every round until answered (the repaired rule set's leg obligations were added
under 6: new obligations, no existing one changed); 7: budgets are spent by z3's resource count, not
the wall clock, so verdicts and reasons are the same on every run."""


__all__ = [
    "LEMMAS",
    "Budget",
    "GlobalTask",
    "ProofResult",
    "Task",
    "isolated",
    "prove",
    "prove_global",
    "prove_spec",
    "task_key",
    "tasks_for",
    "witness_path",
]
