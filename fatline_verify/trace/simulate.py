"""Running a swarm: a seeded, fair random scheduler and the loop that stops at the first outcome;
or an explicit schedule (:func:`parse_schedule`, :func:`play_schedule`) played step by step.

Both work on the model's transition system (:mod:`fatline_verify.schedulers.systems`): a step is a round under
the round schedulers and one event under ``async``. Fairness: under ``ssync`` each enabled robot is
activated with probability 1/2 (at least one a round), and one that has been enabled but idle for
``n`` rounds in a row is activated for sure; under ``centralized`` the robot waiting longest goes when
someone has waited ``n`` rounds; under ``async`` an enabled robot is picked uniformly, and one that
has waited ``2n`` events goes next. So no enabled robot waits forever, as the paper's "the robots do
not stay idle for infinite time" asks.
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from ..model.config import Model
from ..model.options import Scheduler
from ..model.swarm import State, require_initial
from ..schedulers.base import Step
from ..schedulers.systems import TransitionSystem, system_for


class Outcome(StrEnum):
    """How a run ended."""

    GOAL = "goal"
    DEADLOCK = "deadlock"
    VIOLATION = "violation"
    ROUND_LIMIT = "round-limit"
    CYCLE = "cycle"
    """A lasso: the rounds from ``loop_start`` on return the swarm to the same positions up to a
    translation, fairly, so repeating them is an infinite fair execution."""


@dataclass(frozen=True, slots=True)
class Run:
    """A finite execution: the initial state, every round played, and how it ended."""

    model: Model = field(repr=False)
    initial: State
    rounds: tuple[Step, ...] = field(repr=False)
    """The steps played: rounds, or asynchronous events."""
    outcome: Outcome
    loop_start: int | None = None
    """For a lasso: the number of rounds before the loop; the loop is every round after them."""

    def state_at(self, k: int) -> State:
        """The state after ``k`` rounds."""
        return self.rounds[k - 1].after if k else self.initial

    @property
    def final(self) -> State:
        """The state after the last round."""
        return self.rounds[-1].after if self.rounds else self.initial


def outcome_after(
    state: Any, last: Step | None, model: Model, system: TransitionSystem | None = None
) -> Outcome | None:
    """The outcome if the run ends at ``state`` (a state of ``system``, by default the model's) reached by
    ``last``, else ``None``.

    A violating step ends the run; then the goal ("form a straight line", every robot at rest) ends it;
    then a state where no robot is enabled is a deadlock (Lemma "there exists always a robot which will
    move unless the robots in R forms a straight line").
    """
    if last is not None and last.violations:
        return Outcome.VIOLATION
    system = system or system_for(model)
    if system.is_goal(state):
        return Outcome.GOAL
    if not system.enabled(state):
        return Outcome.DEADLOCK
    return None


class FairRandomScheduler:
    """Chooses actions at random, seeded, never starving an enabled robot (the system's own fair choice)."""

    def __init__(self, system: TransitionSystem, seed: int, n: int) -> None:
        self.system = system
        self.rng = random.Random(seed)
        self.waiting = [0] * n

    def choose(self, state: Any) -> Any:
        """The next action in ``state`` (some robot is enabled)."""
        return self.system.choose(self.rng, state, self.waiting)


def simulate(
    initial: State, model: Model, *, scheduler: Scheduler | None = None, seed: int = 0, max_rounds: int = 100
) -> Run:
    """Run the swarm from ``initial`` until the goal, a deadlock, a violation or ``max_rounds`` steps."""
    require_initial(initial, model)
    system = system_for(model, scheduler)
    chooser = FairRandomScheduler(system, seed, len(initial))
    state, last = system.start(initial), None
    steps: list[Step] = []
    while True:
        outcome = outcome_after(state, last, model, system)
        if outcome is not None:
            break
        if len(steps) >= max_rounds:
            outcome = Outcome.ROUND_LIMIT
            break
        last = system.play(state, chooser.choose(state))
        steps.append(last)
        state = last.target
    return Run(model, initial, tuple(steps), outcome)


def registered_violation(run: Run) -> tuple[Run, str] | None:
    """The run up to its first step that breaks a registered step lemma judged for its model (a plug-in's,
    or ``in-family``), with that lemma's name; ``None`` when no step does. The run's own outcome is kept
    for the shortened run (a registered lemma never stops a run of the model: a trace names it instead)."""
    from ..lemmas.registry import judged

    lemmas = judged(run.model)
    if not lemmas:
        return None
    system = system_for(run.model)
    for k, step in enumerate(run.rounds, start=1):
        for lemma in lemmas:
            if lemma.violators(step.before, step.after, run.model):
                outcome = outcome_after(step.target, step, run.model, system) or Outcome.ROUND_LIMIT
                return Run(run.model, run.initial, run.rounds[:k], outcome), lemma.name
    return None


# --- explicit schedules -------------------------------------------------------------------------------


def parse_schedule(text: str, n: int, scheduler: Scheduler, model: Model | None = None) -> list[Any]:
    """The actions of ``text`` for ``n`` robots under ``scheduler``: rounds ``"0;1,2;all"`` for the round
    schedulers, events ``"L0;M0;L1"`` for ``async``
    (:meth:`~fatline_verify.schedulers.base.TransitionSystem.parse_schedule`).

    Robot indices are positions in the initial configuration (0-based). Anything else is
    :class:`InvalidInput` naming the text, the step (1-based) and what was expected.
    """
    return system_for(model or Model(), scheduler).parse_schedule(text, n)


def play_schedule(initial: State, model: Model, actions: Sequence[Any]) -> Run:
    """Play exactly ``actions`` from ``initial``, one per step, under the model's scheduler.

    Only a violating step ends the run early (as in every trace); past the goal or a deadlock the
    remaining steps are still played (a robot that is activated but not enabled stays). The outcome is
    judged on the last state, as :func:`fatline_verify.trace.traces.replay` judges it: ``VIOLATION``, ``GOAL``,
    ``DEADLOCK``, or else ``ROUND_LIMIT`` (the schedule ran out). An action that cannot be played where
    it comes (an asynchronous look of a moving robot) is :class:`InvalidInput`.
    """
    require_initial(initial, model)
    system = system_for(model)
    state, last = system.start(initial), None
    played: list[Step] = []
    for k, action in enumerate(actions, start=1):
        system.check_action(state, action, k)
        last = system.play(state, action)
        played.append(last)
        state = last.target
        if last.violations:
            break
    outcome = outcome_after(state, last, model, system) or Outcome.ROUND_LIMIT
    return Run(model, initial, tuple(played), outcome)
