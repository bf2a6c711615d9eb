"""Running a swarm: a seeded, fair random scheduler and the loop that stops at the first outcome.

Fairness: under ``ssync`` each enabled robot is activated with probability 1/2 (at least one a
round), and one that has been enabled but idle for ``n`` rounds in a row is activated for sure; under
``centralized`` the robot waiting longest goes when someone has waited ``n`` rounds. So no enabled
robot waits forever, as the paper's "the robots do not stay idle for infinite time" asks.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from enum import StrEnum

from .algorithm import Decision
from .config import Model
from .errors import Unsupported
from .options import Scheduler
from .schedule import RoundResult, decide_all, enabled, play_round
from .swarm import State, is_goal, require_initial


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
    rounds: tuple[RoundResult, ...] = field(repr=False)
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
    state: State, last: RoundResult | None, model: Model, decisions: dict[int, Decision] | None = None
) -> Outcome | None:
    """The outcome if the run ends at ``state`` (reached by ``last``), else ``None``.

    A violating round ends the run; then the goal ("form a straight line") ends it; then a state
    where no robot is enabled is a deadlock (Lemma "there exists always a robot which will move
    unless the robots in R forms a straight line").
    """
    if last is not None and last.violations:
        return Outcome.VIOLATION
    if is_goal(state, model):
        return Outcome.GOAL
    if not enabled(decide_all(state, model) if decisions is None else decisions):
        return Outcome.DEADLOCK
    return None


class FairRandomScheduler:
    """Chooses activation sets at random, seeded, never starving an enabled robot."""

    def __init__(self, kind: Scheduler, seed: int, n: int) -> None:
        if kind is Scheduler.ASYNC:
            raise Unsupported("scheduler='async': not implemented yet; expected one of ssync, fsync, centralized")
        self.kind = kind
        self.rng = random.Random(seed)
        self.n = n
        self.waiting = [0] * n

    def choose(self, candidates: tuple[int, ...]) -> tuple[int, ...]:
        """The robots to activate among the enabled ``candidates`` (non-empty)."""
        if self.kind is Scheduler.FSYNC:
            chosen = set(range(self.n))
        elif self.kind is Scheduler.CENTRALIZED:
            starved = [i for i in candidates if self.waiting[i] >= self.n]
            pool = [max(starved, key=lambda i: self.waiting[i])] if starved else list(candidates)
            chosen = {self.rng.choice(pool)}
        else:
            chosen = {i for i in candidates if self.rng.random() < 0.5 or self.waiting[i] >= self.n}
            if not chosen:
                chosen = {self.rng.choice(candidates)}
        for i in range(self.n):
            self.waiting[i] = 0 if (i in chosen or i not in candidates) else self.waiting[i] + 1
        return tuple(sorted(chosen))


def simulate(
    initial: State, model: Model, *, scheduler: Scheduler | None = None, seed: int = 0, max_rounds: int = 100
) -> Run:
    """Run the swarm from ``initial`` until the goal, a deadlock, a violation or ``max_rounds``."""
    require_initial(initial, model)
    chooser = FairRandomScheduler(scheduler or model.options.scheduler, seed, len(initial))
    state, last = initial, None
    rounds: list[RoundResult] = []
    while True:
        decisions = decide_all(state, model)
        outcome = outcome_after(state, last, model, decisions)
        if outcome is not None:
            break
        if len(rounds) >= max_rounds:
            outcome = Outcome.ROUND_LIMIT
            break
        active = chooser.choose(enabled(decisions))
        last = play_round(state, active, model, decisions)
        rounds.append(last)
        state = last.after
    return Run(model, initial, tuple(rounds), outcome)
