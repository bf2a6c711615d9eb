"""Running a swarm: a seeded, fair random scheduler and the loop that stops at the first outcome;
or an explicit schedule (:func:`parse_schedule`, :func:`play_schedule`) played round by round.

Fairness: under ``ssync`` each enabled robot is activated with probability 1/2 (at least one a
round), and one that has been enabled but idle for ``n`` rounds in a row is activated for sure; under
``centralized`` the robot waiting longest goes when someone has waited ``n`` rounds. So no enabled
robot waits forever, as the paper's "the robots do not stay idle for infinite time" asks.
"""

from __future__ import annotations

import random
import re
from dataclasses import dataclass, field
from enum import StrEnum

from .algorithm import Decision
from .config import Model
from .errors import InvalidInput
from .options import Scheduler
from .schedule import RoundResult, decide_all, enabled, play_round
from .schedulers import round_scheduler
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
        self.scheduler = round_scheduler(kind)
        self.kind = kind
        self.rng = random.Random(seed)
        self.n = n
        self.waiting = [0] * n

    def choose(self, candidates: tuple[int, ...]) -> tuple[int, ...]:
        """The robots to activate among the enabled ``candidates`` (non-empty)."""
        chosen = self.scheduler.choose(self.rng, candidates, self.waiting, self.n)
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


# --- explicit schedules -------------------------------------------------------------------------------

MAX_SCHEDULE_ROUNDS = 1_000_000

_INDEX = re.compile(r"[0-9]+")


def _schedule_expected(n: int) -> str:
    robots = "0" if n == 1 else f"0..{n - 1}"
    return (
        f"expected rounds separated by ';', each 'all' or robot indices {robots} (in --init order) "
        "separated by ',', e.g. '0;1,2;all'"
    )


def parse_schedule(text: str, n: int, scheduler: Scheduler) -> list[tuple[int, ...]]:
    """The activation sets of ``text`` (``"0;1,2;all"``) for ``n`` robots, each checked against
    ``scheduler``: ``centralized`` one robot a round, ``fsync`` every robot, ``ssync`` any non-empty set.

    Robot indices are positions in the initial configuration (0-based); ``all`` is every robot.
    Activating a robot that would not move is allowed (it stays where it is). Anything else is
    :class:`InvalidInput` naming the text, the round (1-based) and what was expected.
    """
    rounds_of = round_scheduler(scheduler)
    expected = _schedule_expected(n)

    def bad(why: str) -> InvalidInput:
        return InvalidInput(f"schedule={text!r}: {why}; {expected}")

    if not text.strip():
        raise bad("no rounds")
    parts = text.split(";")
    if len(parts) > MAX_SCHEDULE_ROUNDS:
        raise bad(f"{len(parts)} rounds, more than {MAX_SCHEDULE_ROUNDS}")
    rounds: list[tuple[int, ...]] = []
    for k, part in enumerate(parts, start=1):
        tokens = [t.strip() for t in part.split(",")]
        if tokens == [""]:
            raise bad(f"round {k} is empty")
        if any(t.lower() == "all" for t in tokens):
            if len(tokens) != 1:
                raise bad(f"round {k} mixes 'all' with other robots ({part.strip()!r})")
            active = tuple(range(n))
        else:
            seen: list[int] = []
            for t in tokens:
                if not t:
                    raise bad(f"round {k} has an empty robot index ({part.strip()!r})")
                if not _INDEX.fullmatch(t):
                    raise bad(f"round {k}: {t!r} is not a robot index")
                i = int(t)
                if i >= n:
                    raise bad(f"round {k}: robot {i} does not exist (there are {n} robots)")
                if i in seen:
                    raise bad(f"round {k} names robot {i} twice")
                seen.append(i)
            active = tuple(sorted(seen))
        why = rounds_of.forbids(active, n)
        if why is not None:
            raise InvalidInput(f"schedule={text!r}: round {k} {why}")
        rounds.append(active)
    return rounds


def play_schedule(initial: State, model: Model, rounds: list[tuple[int, ...]] | tuple[tuple[int, ...], ...]) -> Run:
    """Play exactly the activation sets ``rounds`` from ``initial``, one per round.

    Only a violating round ends the run early (as in every trace); past the goal or a deadlock the
    remaining rounds are still played (a robot that is activated but not enabled stays). The
    outcome is judged on the last state, as :func:`fatline_verify.trace.replay` judges it:
    ``VIOLATION``, ``GOAL``, ``DEADLOCK``, or else ``ROUND_LIMIT`` (the schedule ran out).
    """
    require_initial(initial, model)
    n = len(initial)
    for k, active in enumerate(rounds, start=1):
        if not active or any(not 0 <= i < n for i in active) or len(set(active)) != len(active):
            raise InvalidInput(f"schedule: round {k} activates {list(active)}; {_schedule_expected(n)}")
    state, last = initial, None
    played: list[RoundResult] = []
    for active in rounds:
        last = play_round(state, active, model)
        played.append(last)
        state = last.after
        if last.violations:
            break
    outcome = outcome_after(state, last, model) or Outcome.ROUND_LIMIT
    return Run(model, initial, tuple(played), outcome)
