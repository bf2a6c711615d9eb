"""One decision-case obligation decided (:func:`prove_spec`), in rounds of growing budget (2 s, then 4
times more, the last round taking what is left of ``--timeout``); each round runs every step still
open, each step with its own z3 context and deterministic budget (:class:`Budget`):

1. **Vacuity** (until answered): if "r makes this case's decision" has no solution over the reals, the
   case never fires under the model's readings: PROVED, "the case never fires". Its linear relaxation
   (:func:`~fatline_verify.prove.smt.solving.relaxation`) is asked first, once, as is the obligation's
   before the reals: an unsat relaxation is an unsat obligation, found in milliseconds where the
   nonlinear search may run out of budget.
2. **Lattices first**: the named robots on the lattices ``x = X / q`` (q = 1, 2, 4, 8, 20; integer
   arithmetic) with the paper's initial condition on them. A solution is replayed by the executable
   model: if r decides the same case, the claim fails and the configuration is initial, VIOLATED. A
   placement that does not replay as initial is blocked (in every later round too) and the search
   goes on; a lattice with no solution is not searched again.
3. **The linearization** (:mod:`~fatline_verify.prove.smt.linearize`; not for two movers): the obligation
   over linear arithmetic, its squared distances bounded by exact cuts refined where a solution
   breaks them. ``unsat`` is PROVED; a solution of the obligation itself (directly, or polished: the
   few coordinates it gets wrong solved for over the reals, the rest fixed) is replayed, VIOLATED if
   initial; one that is not initial, or a linearization that cannot go on, starts the same search
   with the initial condition.
4. **The reals** (not for two movers: their group obligations are beyond any budget tried), without
   the initial condition: ``unsat`` is PROVED (every size, by the header's argument); ``sat`` is
   replayed, VIOLATED if the configuration is initial; otherwise the reals are searched with the
   initial condition (in this round and the later ones), and without an initial solution the verdict
   is INCONCLUSIVE with the configuration and what would decide it; ``unknown`` after the last round
   is INCONCLUSIVE with the budget.

After the first round, an obligation still open has its **small swarms enumerated**
(:mod:`~fatline_verify.prove.small`: every initial configuration of 2 to 4 robots in a 9x9 window at
q = 1 and q = 2, each robot as r, by the executable model alone), once: where most roles fall on a
few robots, a counterexample the solver's search of a dozen named robots misses is there.

A replay that disagrees with the encoding (r decides another case, or the claim holds) is a bug of
the tool and reported as "encoding disagreement".
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from ..lemmas.properties import Verdict
from ..model.config import Model
from ..model.numbers import Point
from ..outputs import write_text
from .corpus import CORPUS, EARLIER, GIVEN
from .known import given_source
from .replay import Known, Replayed, replay, replay_known
from .small import SMALL_TEXT, given_counterexample, small_swarm_counterexample
from .smt.claims import (
    TWO_MOVERS,
    Built,
    NotEncoded,
    Spec,
    argument,
)
from .tasks import ProofResult

if TYPE_CHECKING:
    from .smt.linearize import Linearization
    from .smt.solving import Answer, Positions


LATTICES = (1, 2, 4, 8, 20)
"""The lattices ``x = X / q`` searched for an initial counterexample before the reals."""
LATTICES_TEXT = ", ".join(map(str, LATTICES))
"""How reasons name them (``q=1, 2, 4``)."""

SHARE = {"vacuity": 0.05, "lattices": 0.45, "linear": 0.25, "reals": 0.15, "reals-initial": 0.1}
"""Each step's share of a round's budget. Measured on the shipped models: a search that finds a
counterexample mostly finds it on a lattice (the slowest took 15 s at q = 8), and the reals answer
within a second (the median PROVED) or not within a minute. What vacuity and the lattices leave of
their shares in a round goes to the reals in that round: under ``paper-literal``, Scenario 2 and 3
cases whose lattices are all empty within a second need 10-20 s of the reals' budget to come out
unsat."""

LATTICE_WEIGHT = {1: 3, 2: 2, 4: 2, 8: 2, 20: 2}
"""How the lattices' share of a round is split among the lattices still open (the coarsest, where most
counterexamples lie, gets the most; a lattice without solutions gives its part to the others)."""

FIRST_ROUND = 2.0
"""The first round's budget in seconds (most obligations are decided in it)."""
GROWTH = 4
"""Each round's budget is this many times the last one's."""

MIN_CHECK = 0.01
"""Seconds below which a check is not started."""

Given = tuple[str, tuple[Point, ...]]
"""A configuration handed to the prover (``fatline prove --known FILE``): where it came from, and its
positions in radii."""

MAX_BLOCKED = 4
"""Non-initial lattice placements blocked per lattice before moving on."""


PROVED_REASON = "unsat over the reals: holds for swarms of every size (the header's argument)"
RELAXED = (
    "shown on its linear relaxation, every nonlinear comparison a free Boolean: each solution is one of the "
    "relaxation, which has none"
)
"""Why an unsat linear relaxation (:func:`~fatline_verify.prove.smt.solving.relaxation`) decides."""


def linearized(refinements: int) -> str:
    """Why an unsat :class:`~fatline_verify.prove.smt.linearize.Linearization` decides."""
    return (
        f"shown on its linearization after {refinements} refinement(s): each solution satisfies its exact tangent "
        "lines and sector half-planes, which nothing does"
    )


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
    :func:`prove_spec`, the leg obligations of :mod:`fatline_verify.prove.family`)."""

    def __init__(self, timeout: float) -> None:
        self.timeout = timeout
        self.spent = 0.0
        """Budget used, in z3 resource units as seconds (deterministic: it decides what is left)."""
        self.wall = 0.0
        """Wall-clock seconds of the checks (reported, never deciding)."""

    def left(self) -> float:
        """Seconds of budget a check may still take: the budget not yet used (z3's resource count,
        so the same on every run), divided by :data:`~fatline_verify.prove.smt.solving.WALL` so that even
        checks stopped by the wall clock end about within ``timeout``."""
        from .smt.solving import WALL

        return max(0.0, self.timeout - self.spent) / WALL

    def ask(self, check: Callable[[float], Answer], seconds: float) -> Answer:
        """Run ``check`` with at most ``seconds`` of what is left and charge what it used; ``unknown``
        without a check if that is less than :data:`MIN_CHECK`."""
        from .smt.solving import Answer

        seconds = min(seconds, self.left())
        if seconds < MIN_CHECK:
            return Answer("unknown", 0.0, "budget exhausted")
        ans = check(seconds)
        self.spent += ans.budget
        self.wall += ans.seconds
        return ans

    def solve(self, built: Built, seconds: float, blocked: Sequence[Positions] = ()) -> Answer:
        """Check ``built`` (``blocked`` answers excluded) for at most ``seconds`` of what is left
        (:meth:`ask`)."""
        from .smt.solving import block, check, solver_for

        def run(budget: float) -> Answer:
            solver = solver_for(built, budget)
            for placement in blocked:
                block(solver, built, placement)
            return check(solver, built, budget)

        return self.ask(run, seconds)


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
        self.relaxed_vacuity = False
        """Whether the linear relaxation of the vacuity question was asked (once)."""
        self.linear_full: Linearization | None = None
        self.linear_initial: Linearization | None = None
        self.linear_done = self.linear_initial_done = False
        """Whether the obligation's linearization answered (or cannot go on; then the initial search's runs),
        whether the initial search's did."""
        self.small_done = False
        """Whether the small swarms (:mod:`~fatline_verify.prove.small`) were enumerated (once)."""

    def result(self, verdict: Verdict, reason: str, rep: Replayed | None = None) -> ProofResult:
        named = len(self.full.bodies) - 1
        return _result(self.spec, verdict, named, self.wall, reason, self.path, rep, self.full.comment)

    def vacuous(self, budget: float) -> ProofResult | None:
        from .smt.cases import Arith
        from .smt.claims import build
        from .smt.solving import relaxation

        if self.fires:
            return None
        vac = build(Arith(None), self.model, self.spec, vacuity=True)
        if not self.relaxed_vacuity:
            self.relaxed_vacuity = True
            if self.solve(relaxation(vac), budget * SHARE["vacuity"]).status == "unsat":
                return self.result(Verdict.PROVED, f"the case never fires under these readings (vacuous; {RELAXED})")
        status = self.solve(vac, budget * SHARE["vacuity"]).status
        if status == "unsat":
            return self.result(Verdict.PROVED, "the case never fires under these readings (vacuous)")
        self.fires = status == "sat"
        return None

    def small(self) -> ProofResult | None:
        """The small swarms of :mod:`~fatline_verify.prove.small`, enumerated once: VIOLATED with the
        first configuration whose r decides this case and breaks the claim from an initial configuration
        (replayed). No solver is asked, so no budget is spent; its seconds are counted."""
        import time

        if self.small_done:
            return None
        self.small_done = True
        start = time.perf_counter()
        found = small_swarm_counterexample(self.model, self.spec)
        self.wall += time.perf_counter() - start
        if found is None:
            return None
        got, q = found
        return self.result(Verdict.VIOLATED, _found(got, f"small swarms enumerated, lattice q={q}"), got)

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

    def linear(self, budget: float) -> ProofResult | None:
        """The linearization's step of a round (:mod:`~fatline_verify.prove.smt.linearize`): the obligation's
        until it answers (unsat: PROVED; a solution replayed: VIOLATED if initial) or cannot go on (the
        comparisons its solution breaks are not distances, and too many to polish), then the initial
        search's (unsat: no initial violation over the reals), in the same round if the share allows."""
        share = budget * SHARE["linear"]
        while True:
            before = self.spent
            found, asked = self._linear_step(share)
            share -= self.spent - before
            if found is not None or not asked or share < MIN_CHECK:
                return found

    def _linear_step(self, share: float) -> tuple[ProofResult | None, bool]:
        """One linearization check; whether one was made."""
        from .smt.cases import Arith
        from .smt.claims import build
        from .smt.linearize import STUCK, Linearization

        if self.linear_full is None:
            self.linear_full = Linearization(self.full)
        lin, initial = self.linear_full, False
        if self.linear_done:
            if self.initial_unsat or self.linear_initial_done:
                return None, False
            if self.linear_initial is None:
                self.linear_initial = Linearization(build(Arith(None), self.model, self.spec, initial=True))
            lin, initial = self.linear_initial, True
        ans = self.ask(lin.check, share)
        if ans.status == "unknown":
            stuck = ans.reason == STUCK
            self.linear_initial_done = initial and stuck
            self.linear_done = self.linear_done or stuck
            return None, stuck
        if ans.status == "unsat" and initial:
            self.initial_unsat = True
            return None, False
        if ans.status == "unsat":
            if self.path:
                write_text(Path(self.path).with_suffix(".linear.smt2"), lin.script())  # atomic
            return self.result(Verdict.PROVED, f"{PROVED_REASON} ({linearized(lin.refinements)})"), True
        self.linear_done = True
        self.linear_initial_done = initial
        got = replay(self.model, self.spec, ans.positions, lin.built.focus)
        if isinstance(got, str):
            disagree = self.result(Verdict.INCONCLUSIVE, f"encoding disagreement (linearization): {got}")
            return (None if ans.rounded else disagree), True
        if got.initial:
            return self.result(Verdict.VIOLATED, _found(got, "linearization", ans.rounded), got), True
        if not initial and self.non_initial is None:
            self.non_initial = got
        return None, True

    def reals(self, budget: float, unused: float = 0.0) -> ProofResult | None:
        """The reals' step of a round: its own share, and ``unused``, what the steps before it left of
        theirs (a lattice found empty, or off the obligation, spends none)."""
        if self.non_initial is None and self.irrational is None:
            ans = self.solve(self.full, budget * SHARE["reals"] + unused)
            if ans.status == "unsat":
                return self.result(Verdict.PROVED, PROVED_REASON)
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
        if self.small_done:
            lattices += f" or among small swarms ({SMALL_TEXT})"
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
            + (f", nor among small swarms ({SMALL_TEXT})" if self.small_done else "")
        )
        return self.result(
            Verdict.INCONCLUSIVE,
            f"{got.what} in a configuration of {len(got.state)} robots that is not initial ({got.problems[0]}); "
            f"{initial_too}; whether it is reachable is not decided: rerun with a larger --timeout, or check the "
            "configuration's swarm size with fatline check",
            got,
        )


def prove_spec(
    model: Model,
    spec: Spec,
    *,
    timeout: float,
    out: Path | None,
    note: str = "",
    known: Sequence[Known] = (),
    small: bool = True,
    given: Sequence[Given] = (),
    corpus: Sequence[Known] = (),
) -> ProofResult:
    """Decide one obligation (see the module docstring); write its real-number form under ``out``.
    ``small=False`` leaves out the small swarms' enumeration (the solver's search alone). ``given``:
    configurations handed in (``fatline prove --known``), each replayed before any search with every
    robot tried as r. ``corpus``: the shipped corpus's candidates (:mod:`~fatline_verify.prove.corpus`),
    replayed first of all; then ``known`` (an earlier run's), then ``given``. A result says which
    decided it (:attr:`ProofResult.decided_by`).

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
    for decider, candidates in ((CORPUS, corpus), (EARLIER, known)):
        for where, doc in candidates:
            again = replay_known(model, spec, doc, initial=False)
            if again is not None and again.initial:
                first = search.result(Verdict.VIOLATED, _found(again, where, how="replayed first"), again)
                return replace(first, decided_by=decider)
            if again is not None and search.non_initial is None:
                # A violation is known to exist (so no unsat can come): the search looks for an initial one,
                # and if it finds none the verdict keeps this configuration instead of losing it.
                search.non_initial = again
                search.linear_done = True
    for where, radii in given:
        hit = given_counterexample(model, spec, radii)
        if hit is not None:
            first = search.result(Verdict.VIOLATED, _found(hit, given_source(where), how="replayed first"), hit)
            return replace(first, decided_by=GIVEN)
    for budget in rounds(timeout):
        before = search.spent
        found = search.vacuous(budget) or search.lattices(budget)
        if found is None and spec.form != TWO_MOVERS:
            found = search.linear(budget)
            unused = budget * (SHARE["vacuity"] + SHARE["lattices"] + SHARE["linear"]) - (search.spent - before)
            found = found or search.reals(budget, max(0.0, unused))
        if found is not None:
            return found
        if search.done():
            break
        found = search.small() if small else None  # after the first round: most are decided in it
        if found is not None:
            return found
        if search.left() < MIN_CHECK:
            break
    return search.give_up(timeout)


def _found(got: Replayed, where: str, rounded: bool = False, how: str = "replayed") -> str:
    """The reason of a VIOLATED verdict; ``rounded``: the solver's values were algebraic; ``how``: when
    the executable model replayed it."""
    tail = "; values rounded from algebraic numbers and re-checked" if rounded else ""
    return f"{got.what}, from an initial configuration of {len(got.state)} robots ({where}, {how}){tail}"


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
