"""What a PROVED row rests on: ``vacuous``, ``immediate`` or ``substantive``, each found by a solver
query, never by a list of names.

- **vacuous**: the case's firing condition alone has no solution over the reals: the obligation built
  with ``vacuity=True`` (r, and a second mover, make their decisions, the claim left out;
  :func:`fatline_verify.prove.smt.claims.build`, :func:`fatline_verify.prove.smt.family.build`) is unsat.
  Asked of every PROVED row, however the search reached its unsat (a case whose blocker would be out of
  view is vacuous even where the full obligation came out unsat first); a row whose search already found
  it ("the case never fires", "these legs never occur together") is not asked again.
- **immediate**: true by the rule's construction: the obligation built with ``immediate=True`` is
  unsat. That query keeps the claim's premises only: the witnesses of the deciders' cases, the
  destination built from them, disjoint discs (a leg: its shape and the form's own kept / bridged
  test), and leaves out every universal condition over the robots a decider sees. So the claim follows
  from how the destination is made (Scenarios 1-3 move to the x of a robot r sees: ``seen`` and
  ``x-nondecreasing`` mostly are), not from the rest of the swarm.
- **substantive**: neither: the proof needed the universal conditions.

Each query asks, within :data:`BUDGET` seconds in all: the linear relaxation (an unsat relaxation is
an unsat query); z3 over the reals for a sliver of the budget (:data:`QUICK`: most queries of the
shipped models are decided there in a hundredth of a second); for a vacuity query, the configurations of
the shipped counterexamples of r's case (:func:`fatline_verify.prove.corpus.firing`: every named robot at
one of their robots, z3 choosing which; a solution makes the query sat); the coarsest lattice
(:data:`LATTICE`: a solution there, confirmed over the reals with every named robot fixed at it, makes
the query sat); the linearization; then z3 over the reals for what is left. A query that does not answer
leaves the stronger kind unclaimed (a row is called vacuous or immediate only on an unsat answer); a
solution only ends a query early, and a step without one leaves the steps after it a little less of the
budget (every shipped model proved afresh with this order: no row's kind changed). The queries of
one case are the same text under every lemma that asks them: a run answers each once
(:mod:`fatline_verify.prove.memo`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..lemmas.properties import Verdict
from ..model.config import Model
from .memo import key_of, remembered

if TYPE_CHECKING:  # the counts are read by the report pages, which do not load z3
    from .tasks import ProofResult

SUBSTANTIVE = "substantive"
IMMEDIATE = "immediate"
VACUOUS = "vacuous"
BASES = (SUBSTANTIVE, IMMEDIATE, VACUOUS)
"""The kinds of a PROVED row, in the order counts show them."""

BUDGET = 10.0
"""Solver seconds (z3's resource count) per query: vacuity, then immediacy."""

FOUND_VACUOUS = ("the case never fires", "these legs never occur together")
"""How the search's own reasons say it found a row vacuous."""

VACUOUS_NOTE = "the case never fires under these readings (vacuous: its firing condition alone is unsat)"
"""Appended to the reason of a PROVED row the search reached by the full obligation but that cannot fire."""


QUICK = 0.05
"""The share of a query's budget z3 over the reals gets first. Measured on the paper's model (176
queries): the 137 that both z3 and the linearization decide take z3 0.85 s in all, the linearization
20 s."""

LATTICE = 1
"""The lattice ``x = X / q`` searched for a solution before the linearization. Measured on the paper's
model: of the 13 vacuity queries z3 leaves undecided in its sliver (cases that fire, under every lemma
that asks), 6 have a solution on q = 1 found in about a second, where the linearization took 4 to 15 s
to find one or give up (94 s of the 13 queries' time before, 59 s after; repaired's 30: 138 s, 95 s); none
has one on q = 2 that q = 1 lacks."""

KNOWN_SHARE = 0.05
"""The share of a query's budget each known configuration's check gets (:func:`_sat_at_known`)."""

MAX_KNOWN = 3
"""Known configurations tried per query, the model's own first. Measured on the paper's model: the four
vacuity texts nothing else decides (each spent its whole budget, 10 s) are sat at a configuration of the
shipped corpus, found in a tenth of a second."""

Configuration = tuple[tuple[Fraction, Fraction], ...]
"""Robots' centres in radii, r first at the origin."""

LATTICE_SHARE = 0.1
"""The lattice's share of a query's budget, for its search and again for the confirmation (measured: a
quarter decides no more queries and takes longer in all)."""


def _unsat(
    build: Callable[[Any], Any], seconds: float, memo: Path | None = None, known: Sequence[Configuration] = ()
) -> bool:
    """Whether the query ``build(arith)`` builds is shown unsat within ``seconds`` (the steps of the
    module docstring), asked once per run (:func:`fatline_verify.prove.memo.remembered`). ``known``:
    configurations that may solve it (a solution only ends the query early: the answer is the same)."""
    from .smt.cases import Arith
    from .smt.solving import smt2

    built = build(Arith(None))
    key = key_of("basis", f"{seconds!r}", smt2(built))
    return remembered(memo, key, lambda: _ask(build, built, seconds, known))


def _ask(build: Callable[[Any], Any], built: Any, seconds: float, known: Sequence[Configuration] = ()) -> bool:
    """The steps of :func:`_unsat`. A solution the linearization finds satisfies every comparison
    exactly: the query is sat, and z3 is not asked to look for an unsat that cannot come."""
    from .search import Budget
    from .smt.linearize import Linearization
    from .smt.solving import relaxation

    spend = Budget(seconds)
    if spend.solve(relaxation(built), seconds / 4).status == "unsat":
        return True
    quick = spend.solve(built, seconds * QUICK).status
    if quick != "unknown":
        return quick == "unsat"
    if _sat_at_known(built, known, spend, seconds * KNOWN_SHARE):
        return False
    if _sat_on_lattice(build, built, LATTICE, spend, seconds * LATTICE_SHARE):
        return False
    linear = spend.ask(Linearization(built).check, seconds / 2).status
    if linear != "unknown":  # unsat; or sat: a solution of the query itself (every comparison exact), no unsat to find
        return linear == "unsat"
    return spend.solve(built, spend.left()).status == "unsat"


def _sat_on_lattice(build: Callable[[Any], Any], built: Any, q: int, spend: Any, seconds: float) -> bool:
    """Whether the query has a solution on the lattice ``q`` that the reals' query ``built`` confirms:
    every named robot fixed where the lattice put it, the reals' solver finds the rest (a lattice's
    query is the reals' restricted to multiples of ``1/q``, so this only checks the restriction). Both
    checks are charged to ``spend``, each within ``seconds``."""
    from .smt.cases import Arith
    from .smt.claims import NotEncoded
    from .smt.solving import fixed

    try:
        lattice = build(Arith(q))
    except (ValueError, NotEncoded):  # a constant off this lattice: no solution to look for here
        return False
    found = spend.solve(lattice, seconds)
    return found.status == "sat" and spend.solve(fixed(built, found.positions), seconds).status == "sat"


def _sat_at_known(built: Any, known: Sequence[Configuration], spend: Any, seconds: float) -> bool:
    """Whether the query has a solution among the robots of one of the ``known`` configurations (every named
    robot but r at one of its points; z3 decides which): a finite choice, decided in a fraction of a second
    where the query over the reals may not be at all. Each check within ``seconds``, charged to ``spend``."""
    from .smt.solving import among

    return any(spend.solve(among(built, points), seconds).status == "sat" for points in known[:MAX_KNOWN])


def basis_of(model: Model, task: Any, result: ProofResult, budget: float = BUDGET, memo: Path | None = None) -> str:
    """The kind of a PROVED ``result`` of ``task`` under ``model`` (the model its obligation was built
    for); ``""`` for any other verdict or a task without a case (the global form). ``memo``: the run's
    shared answers (:mod:`fatline_verify.prove.memo`)."""
    from .smt.cases import Arith
    from .smt.claims import Spec
    from .smt.family import FamilySpec

    if result.verdict is not Verdict.PROVED:
        return ""
    if isinstance(task, Spec):
        from .smt.claims import build as build_spec

        def build(kind: str) -> Callable[[Arith], Any]:
            return lambda ar: build_spec(ar, model, task, **{kind: True})
    elif isinstance(task, FamilySpec):
        from ..rules import registry
        from .smt.family import build as build_family

        family = registry.family(model)

        def build(kind: str) -> Callable[[Arith], Any]:
            return lambda ar: build_family(ar, model, family, task, **{kind: True})
    else:
        return ""
    if any(word in result.reason for word in FOUND_VACUOUS):
        return VACUOUS
    known: list[Configuration] = []
    if isinstance(task, Spec):  # the shipped counterexamples of r's case: a configuration in which it fires
        from .corpus import firing

        known = firing(task.name, model.name)
    if _unsat(build("vacuity"), budget, memo, known):
        return VACUOUS
    if _unsat(build("immediate"), budget, memo):
        return IMMEDIATE
    return SUBSTANTIVE


def classified(result: ProofResult, basis: str) -> ProofResult:
    """``result`` with its basis; a vacuous row whose reason does not say so gets :data:`VACUOUS_NOTE`."""
    reason = result.reason
    if basis == VACUOUS and not any(word in reason for word in FOUND_VACUOUS):
        reason = f"{VACUOUS_NOTE}; {reason}"
    return replace(result, basis=basis, reason=reason)


def decided(
    fn: Callable[..., ProofResult], model: Model, task: Any, *, memo: str | None = None, **kwargs: Any
) -> ProofResult:
    """``fn(model, task, **kwargs)`` (one obligation decided), then its basis if PROVED: what
    :func:`fatline_verify.prove.prover.prove` runs in each obligation's fresh process. ``memo``: the
    directory of the run's shared answers (:mod:`fatline_verify.prove.memo`)."""
    result = fn(model, task, **kwargs)
    return classified(result, basis_of(model, task, result, memo=Path(memo) if memo else None))


def counts(rows: list[dict[str, Any]]) -> dict[str, int]:
    """PROVED rows by basis (``unclassified``: a row saved before bases were recorded)."""
    out = dict.fromkeys(BASES, 0)
    for row in rows:
        if row.get("verdict") == "PROVED":
            key = row.get("basis") or "unclassified"
            out[key] = out.get(key, 0) + 1
    return {k: v for k, v in out.items() if v or k in BASES}


def counts_text(rows: list[dict[str, Any]]) -> str:
    """``3 substantive, 40 immediate, 20 vacuous`` for the PROVED rows of ``rows``."""
    return ", ".join(f"{n} {k}" for k, n in counts(rows).items() if n)


__all__ = ["BASES", "IMMEDIATE", "SUBSTANTIVE", "VACUOUS", "basis_of", "classified", "counts", "counts_text", "decided"]
