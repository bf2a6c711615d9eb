"""The round systems (ssync, fsync, centralized): a step is a round of
:func:`~fatline_verify.schedulers.round.play_round`.

"The robots execute this cycle in semi-synchronous scheduling where an arbitrary set of robots look,
compute and move simultaneously." A state is the robots' positions; an action is an activation set
(which sets a round may activate is the :class:`~fatline_verify.schedulers.activation.RoundScheduler`'s business);
its code is the set's bitmask. The array form is ``(x, y)`` per robot on the model's lattice.
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidInput, InvalidTrace
from ..model.config import Model
from ..model.lattice import canonical, key_codec
from ..model.options import Scheduler
from ..model.swarm import State, is_goal
from .activation import RoundScheduler, scheduler_for
from .base import Codec, Expansion, Marks
from .round import RoundResult, decide_all, enabled, global_path, play_round

MAX_SCHEDULE_STEPS = 1_000_000
"""The longest explicit schedule accepted (rounds or events)."""

_INDEX = re.compile(r"[0-9]+")


def _expected(n: int) -> str:
    robots = "0" if n == 1 else f"0..{n - 1}"
    return (
        f"expected rounds separated by ';', each 'all' or robot indices {robots} (in --init order) "
        "separated by ',', e.g. '0;1,2;all'"
    )


class RoundSystem:
    """A synchronous scheduler's transition system: rounds of a shared snapshot and rigid moves."""

    fields = 2
    scale = 1
    step_word = "round"

    def __init__(self, model: Model, kind: Scheduler) -> None:
        self.model = model
        self.kind = kind
        self.rounds: RoundScheduler = scheduler_for(model, kind)

    # --- executable side -------------------------------------------------------------------------
    def start(self, positions: State) -> State:
        return tuple(positions)

    def positions(self, state: State) -> State:
        return state

    def enabled(self, state: State) -> tuple[int, ...]:
        return enabled(decide_all(state, self.model))

    def is_goal(self, state: State) -> bool:
        return is_goal(state, self.model)

    def play(self, state: State, action: tuple[int, ...]) -> RoundResult:
        return play_round(state, action, self.model)

    def successors(self, state: State) -> tuple[int, list[tuple[int, RoundResult]]]:
        """The enabled robots (bitmask) and every round the scheduler offers, by activation bitmask, with
        its result (one snapshot's decisions serve every round)."""
        decisions = decide_all(state, self.model)
        en = sum(1 << i for i, d in decisions.items() if d.moves)
        out = []
        for mask in self.rounds.masks(en, len(state)):
            active = [i for i in range(len(state)) if mask >> i & 1]
            out.append((mask, play_round(state, active, self.model, decisions)))
        return en, out

    def translated(self, a: State, b: State) -> bool:
        """Whether ``b`` is ``a`` moved by one common vector, robot by robot."""
        dx, dy = b[0][0] - a[0][0], b[0][1] - a[0][1]
        return all(q[0] - p[0] == dx and q[1] - p[1] == dy for p, q in zip(a, b, strict=True))

    def exact_array(self, state: State) -> np.ndarray | None:
        """The state on the model's lattice, up to translation, or ``None`` when a robot is between its
        points (a rule set's rational destination): such a successor is judged on its step and counted,
        never rounded onto the lattice (``np.int64`` of ``Fraction(1, 2)`` is 0).

        Robots agree on axes, not on an origin, and every rule set decides from the view relative to
        the robot (so does every goal and lemma), so a state and its translate behave alike: a state
        whose robots all sit off the lattice by one common offset (every robot gathered at a rational
        point; a swarm that moved by a common rational vector) is the lattice state it translates to,
        and is explored as that one. Only a translation: no robot is moved relative to another."""
        if not state:
            return self.to_array(state)
        ox, oy = Fraction(state[0][0]), Fraction(state[0][1])
        shift = (ox - (ox.numerator // ox.denominator), oy - (oy.numerator // oy.denominator))
        moved = [(Fraction(x) - shift[0], Fraction(y) - shift[1]) for x, y in state]
        if any(c.denominator != 1 for p in moved for c in p):
            return None
        return self.to_array(tuple((int(x), int(y)) for x, y in moved))

    def action(self, code: int, order: Sequence[int], state: State) -> tuple[int, ...]:
        return tuple(sorted(int(order[k]) for k in range(len(order)) if code >> k & 1))

    def choose(self, rng: random.Random, state: State, waiting: list[int]) -> tuple[int, ...]:
        candidates = self.enabled(state)
        chosen = self.rounds.choose(rng, candidates, waiting, len(state))
        for i in range(len(state)):
            waiting[i] = 0 if (i in chosen or i not in candidates) else waiting[i] + 1
        return tuple(sorted(chosen))

    def parse_schedule(self, text: str, n: int) -> list[tuple[int, ...]]:
        """``"0;1,2;all"``: one activation set a round, robot indices in ``--init`` order, each set checked
        against the scheduler (``centralized`` one robot, ``fsync`` every robot, ``ssync`` any non-empty
        set). Activating a robot that would not move is allowed (it stays where it is)."""
        expected = _expected(n)

        def bad(why: str) -> InvalidInput:
            return InvalidInput(f"schedule={text!r}: {why}; {expected}")

        if not text.strip():
            raise bad("no rounds")
        parts = text.split(";")
        if len(parts) > MAX_SCHEDULE_STEPS:
            raise bad(f"{len(parts)} rounds, more than {MAX_SCHEDULE_STEPS}")
        out: list[tuple[int, ...]] = []
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
            why = self.rounds.forbids(active, n)
            if why is not None:
                raise InvalidInput(f"schedule={text!r}: round {k} {why}")
            out.append(active)
        return out

    def check_action(self, state: State, action: tuple[int, ...], k: int) -> None:
        n = len(state)
        if not action or any(not 0 <= i < n for i in action) or len(set(action)) != len(action):
            raise InvalidInput(f"schedule: round {k} activates {list(action)}; {_expected(n)}")

    def marks(self, step: Any) -> Marks:
        movers = [i for i in step.active if step.decisions[i].moves]
        return Marks(
            acting=movers[0] if movers else step.active[0],
            arrows=tuple(global_path(step.before[i], step.decisions[i]) for i in movers),
            targets=tuple(step.after[i] for i in movers),
        )

    def step_to_json(self, step: Any) -> dict[str, Any]:
        from ..trace.steps import round_to_json

        return round_to_json(step, self.model)

    def action_from_json(self, record: dict[str, Any], n: int, where: str) -> tuple[int, ...]:
        if "active" not in record or "event" in record:
            raise InvalidTrace(
                f"{where}: an asynchronous event, but model {self.model.name} has scheduler={self.kind}, which plays "
                "rounds; expected a model with scheduler=async"
            )
        bad = [i for i in record["active"] if i >= n]
        if bad:
            raise InvalidTrace(f"{where}/active: robot {bad[0]} does not exist; expected 0..{n - 1}")
        return tuple(record["active"])

    # --- array side ------------------------------------------------------------------------------
    def to_array(self, state: State) -> np.ndarray:
        return np.array(state, dtype=np.int64).reshape(len(state), 2)

    def from_array(self, row: np.ndarray) -> State:
        return tuple((int(x), int(y)) for x, y in row)

    def initial(self, positions: np.ndarray) -> np.ndarray:
        return positions.astype(np.int64)

    def canonical(self, states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return canonical(states)

    def codec(self, n: int, window: tuple[int, int]) -> Codec:
        return key_codec(n, window)

    def array_positions(self, states: np.ndarray) -> np.ndarray:
        return states

    def step_positions(self, states: np.ndarray, ex: Expansion) -> tuple[np.ndarray, np.ndarray, int]:
        """A round's positions before and after, in units of ``1/unit`` lattice unit: the successor itself
        where it is on the lattice (``unit`` 1); where a rule set's rational destination left it (``exact``
        false: the successor is counted, not explored), the executable round's exact positions, all of the
        batch scaled by the least common denominator (never the engine's blank row)."""
        before, after = states[ex.src], ex.after
        inexact = np.flatnonzero(~np.asarray(ex.exact, dtype=bool))
        if not len(inexact):
            return before, after, 1
        exact: dict[int, State] = {}
        for t in inexact.tolist():
            _, steps = self.successors(self.from_array(states[ex.src[t]]))
            exact[t] = next(step.target for code, step in steps if code == ex.action[t])
        unit = math.lcm(*(Fraction(c).denominator for target in exact.values() for p in target for c in p))
        before, after = before * unit, after * unit
        for t, target in exact.items():
            after[t] = [[int(Fraction(c) * unit) for c in p] for p in target]
        return before, after, unit

    default_engine = "compiled"
    """The engine ``check`` uses unless told otherwise."""

    family = "rounds"
    """Engines: :data:`fatline_verify.check.engines.BUILDERS`."""


__all__ = ["MAX_SCHEDULE_STEPS", "RoundSystem"]
