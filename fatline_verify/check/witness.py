"""Witnesses: turn a path of the explored graph into a trace, and replay it before anyone sees it.

The search knows canonical array states only; a witness follows real robots. From the initial state
(robot i = canonical index i) each step's action, given in the canonical order of its source state, is
mapped to robot identities by canonicalising the current state, and played by the executable model
of the transition system. The result must land on the recorded canonical state at every step and must
replay from its JSON form; otherwise the engine and the model disagree, which is a bug of the tool
and is raised, never reported as a counterexample. When the compiled engine read answers kept by an
earlier run (:mod:`.answers`), the message says they may be stale and how to check without them.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np

from ..errors import FatlineError, TraceDidNotReproduce
from ..lemmas.properties import Lemma
from ..lemmas.registry import StepLemma
from ..trace.simulate import Outcome, Run, outcome_after
from ..trace.traces import replayed_document
from .exploration import Exploration


class EngineDisagreement(FatlineError):
    """The exploration and the executable model disagree on a witness (a bug of the tool)."""


@contextmanager
def _kept_answers_named(ex: Exploration) -> Iterator[None]:
    """Re-raise a disagreement of the engine and the model with, when the compiled engine's kept
    answers for this model and robot count were there to be read, that they may be stale (one line)."""
    try:
        yield
    except (EngineDisagreement, TraceDidNotReproduce) as exc:
        from .answers import ENV, answers_path

        path = answers_path(ex.model, ex.n) if ex.engine == "compiled" else None
        if path is None or not path.is_file():
            raise
        raise type(exc)(
            f"{exc}; the compiled engine's answers kept between runs ({path.as_posix()}) may be stale: "
            f"run again with {ENV}=off to check without them"
        ) from exc


def _follow(ex: Exploration, start_id: int, steps: list[tuple[int, int]]) -> tuple[Any, list[Any]]:
    system = ex.system
    state = system.from_array(ex.state_array(ex.root(start_id)))
    initial, played = system.positions(state), []
    with _kept_answers_named(ex):
        for sid, code in steps:
            arr = system.exact_array(state)  # a lattice state, or one a common offset makes one
            if arr is None:
                raise EngineDisagreement(f"witness step from state {sid}: {state} is off the lattice")
            canon, order = system.canonical(arr[None])
            if not np.array_equal(canon[0], ex.state_array(sid)):
                raise EngineDisagreement(f"witness step from state {sid}: {state} is not that state")
            step = system.play(state, system.action(code, order[0], state))
            played.append(step)
            state = step.target
    return initial, played


def _finish(ex: Exploration, run: Run, lemma: Lemma | StepLemma) -> dict[str, Any]:
    origin = {
        "tool": "fatline check",
        "lemma": lemma.value,
        "engine": ex.engine,
        "robots": ex.n,
        "window": list(ex.start_window),
    }
    if ex.initial_window is not None:
        origin["bound"] = list(ex.window)
    with _kept_answers_named(ex):
        doc = replayed_document(run, origin, lemma.value)
        if doc["violation"] is None or doc["violation"]["property"] != lemma.value:
            raise EngineDisagreement(f"{lemma} witness: the executable model does not show the violation")
    return doc


def transition_witness(ex: Exploration, src: int, action: int, lemma: Lemma | StepLemma) -> dict[str, Any]:
    """A shortest path to the state ``src`` and the violating step ``action`` from it."""
    steps = [*ex.path(src), (src, action)]
    initial, played = _follow(ex, src, steps)
    if isinstance(lemma, Lemma):
        outcome = Outcome.VIOLATION
    else:  # a registered lemma: the step breaks no safety of the model's own, and the run goes on
        outcome = outcome_after(played[-1].target, played[-1], ex.model, ex.system) or Outcome.ROUND_LIMIT
    return _finish(ex, Run(ex.model, initial, tuple(played), outcome), lemma)


def state_witness(ex: Exploration, state_id: int, lemma: Lemma) -> dict[str, Any]:
    """A shortest path to a terminal state (no robot enabled): a deadlock, or robots stuck off the RMA."""
    initial, played = _follow(ex, state_id, ex.path(state_id))
    outcome = Outcome.GOAL if ex.goal[state_id] else Outcome.DEADLOCK
    return _finish(ex, Run(ex.model, initial, tuple(played), outcome), lemma)


def lasso_run(ex: Exploration, start: int, cycle: tuple[tuple[int, int], ...]) -> Run:
    """A shortest path to the loop's first state, then the fair loop, played by the executable model."""
    prefix = ex.path(start)
    initial, played = _follow(ex, start, [*prefix, *cycle])
    return Run(ex.model, initial, tuple(played), Outcome.CYCLE, len(prefix))


def lasso_witness(run: Run, ex: Exploration, lemma: Lemma) -> dict[str, Any]:
    """The trace of a lasso run (from :func:`lasso_run`), replayed."""
    return _finish(ex, run, lemma)
