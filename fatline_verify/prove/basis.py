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

Each query asks the linear relaxation first (an unsat relaxation is an unsat query), then the
linearization, then z3 over the reals, within :data:`BUDGET` seconds in all; a query that does not
answer leaves the stronger kind unclaimed (a row is called vacuous or immediate only on an unsat answer).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from ..lemmas.properties import Verdict
from ..model.config import Model

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


def _unsat(built: Any, seconds: float) -> bool:
    """Whether ``built`` is shown unsat within ``seconds``: its linear relaxation, its linearization
    (exact cuts of every squared distance: :mod:`fatline_verify.prove.smt.linearize`), then z3 over the reals.
    A solution the linearization finds satisfies every comparison exactly: the query is sat, and z3 is not
    asked to look for an unsat that cannot come."""
    from .search import Budget
    from .smt.linearize import Linearization
    from .smt.solving import relaxation

    spend = Budget(seconds)
    if spend.solve(relaxation(built), seconds / 4).status == "unsat":
        return True
    linear = spend.ask(Linearization(built).check, seconds / 2).status
    if linear != "unknown":  # unsat; or sat: a solution of the query itself (every comparison exact), no unsat to find
        return linear == "unsat"
    return spend.solve(built, spend.left()).status == "unsat"


def basis_of(model: Model, task: Any, result: ProofResult, budget: float = BUDGET) -> str:
    """The kind of a PROVED ``result`` of ``task`` under ``model`` (the model its obligation was built
    for); ``""`` for any other verdict or a task without a case (the global form)."""
    from .smt.cases import Arith
    from .smt.claims import Spec
    from .smt.family import FamilySpec

    if result.verdict is not Verdict.PROVED:
        return ""
    if isinstance(task, Spec):
        from .smt.claims import build as build_spec

        def build(**kw: bool) -> Any:
            return build_spec(Arith(None), model, task, **kw)
    elif isinstance(task, FamilySpec):
        from ..rules import registry
        from .smt.family import build as build_family

        family = registry.family(model)

        def build(**kw: bool) -> Any:
            return build_family(Arith(None), model, family, task, **kw)
    else:
        return ""
    if any(word in result.reason for word in FOUND_VACUOUS):
        return VACUOUS
    if _unsat(build(vacuity=True), budget):
        return VACUOUS
    if _unsat(build(immediate=True), budget):
        return IMMEDIATE
    return SUBSTANTIVE


def classified(result: ProofResult, basis: str) -> ProofResult:
    """``result`` with its basis; a vacuous row whose reason does not say so gets :data:`VACUOUS_NOTE`."""
    reason = result.reason
    if basis == VACUOUS and not any(word in reason for word in FOUND_VACUOUS):
        reason = f"{VACUOUS_NOTE}; {reason}"
    return replace(result, basis=basis, reason=reason)


def decided(fn: Callable[..., ProofResult], model: Model, task: Any, **kwargs: Any) -> ProofResult:
    """``fn(model, task, **kwargs)`` (one obligation decided), then its basis if PROVED: what
    :func:`fatline_verify.prove.prover.prove` runs in each obligation's fresh process."""
    result = fn(model, task, **kwargs)
    return classified(result, basis_of(model, task, result))


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
