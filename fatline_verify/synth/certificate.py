"""What backs a ``fatline synth`` answer, checked apart from the search that gave it.

* **sat**: the table is played through the executable model (:func:`.replay.replay`) from every initial
  configuration, under the scheduler it was found for.
* **unsat**: each configuration of the core is replayed on its own: a shortest way to a line by any
  rounds of the family (a central planner's, which no oblivious table follows from all of them at once)
  is played by :func:`fatline_verify.repair.search.replay_witness` (under centralized, rounds of one mover),
  or none exists (the family is stuck there whatever it does, by an exhaustive search); whether
  a table exists for that configuration alone; and the core is solved again with a fresh encoding and
  another SAT solver (:func:`.encode.independent_check`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..model.config import Model
from ..model.options import Scheduler
from ..repair.reach import Family, State
from ..repair.search import replay_witness, way_to_line
from .encode import SOLVERS, SynthResult, independent_check, synthesise
from .replay import Replay, replay


@dataclass(frozen=True)
class CoreRow:
    """One configuration of an unsat core, replayed."""

    state: State
    planner: int | None
    """Rounds of a shortest way to a line by any rounds of the family, replayed (``None``: there is none)."""
    alone: bool
    """Whether some table is safe and live from this configuration alone."""


@dataclass(frozen=True)
class Certificate:
    """The checks of the module docstring for one :class:`.encode.SynthResult`."""

    replay: Replay | None = None
    core: tuple[CoreRow, ...] = ()
    again: str | None = None
    """Unsat: the solver that found the core unsat again from a fresh encoding (``None``: not asked)."""

    @property
    def problems(self) -> list[str]:
        return list(self.replay.problems) if self.replay is not None else []


def other_solver(name: str) -> str:
    """A python-sat solver other than ``name``, for the independent check."""
    return next(s for s in SOLVERS if s != name)


def certify(model: Model, result: SynthResult, *, again: bool = True) -> Certificate:
    """Check ``result`` (module docstring); a core configuration whose way to a line does not replay, or
    that reaches a line after all when the search said it does not, raises ``AssertionError``."""
    if result.table is not None:
        return Certificate(replay(result.table, model, result.counts, result.window, result.kinds, result.scheduler))
    family = Family(model, result.kinds)
    rows = []
    for s in result.core:
        steps = way_to_line(s, family, one_mover=result.scheduler is Scheduler.CENTRALIZED)
        if steps is not None:
            problems = replay_witness(s, steps, family)
            if problems:
                raise AssertionError(f"the way to a line from {s} does not replay: {problems[0]}")
        alone = synthesise(
            model, result.n, result.window, result.kinds, scheduler=result.scheduler, minimise=False, only=[s]
        ).sat
        rows.append(CoreRow(s, None if steps is None else len(steps), alone))
    solver = other_solver(result.solver) if again else None
    if solver is not None and not independent_check(model, result, solver):
        raise AssertionError(f"the core {result.core} is sat under {solver}")
    return Certificate(None, tuple(rows), solver)


__all__ = ["Certificate", "CoreRow", "certify", "other_solver"]
