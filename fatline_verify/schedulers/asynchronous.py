"""ASYNC: the scheduler of the paper's theorem ("a set of asynchronous, oblivious fat robots can form a
straight line"), one event at a time.

Per robot a phase: *idle* at a point, or *moving* along the path it decided on, ``k`` of
``K = async_steps`` move steps done. Events:

- ``look`` (``L<i>``) of an idle robot: it snapshots the **current** positions (a moving robot is seen
  where it is now, possibly halfway), computes, and if its destination differs from its position it
  becomes moving with ``k = 0``; otherwise nothing changes (a self-loop, never offered).
- ``move`` (``M<i>``) of a moving robot: it advances by ``1/K`` of its path at constant speed (an
  L-shaped path by arc length); at ``k = K`` it is idle at its destination. "The robots do not stop
  before reaching its destination": under ``motion = rigid`` that is the only way a move ends.
- ``stop`` (``S<i>``), ``motion = non-rigid`` only: the scheduler ends a move early, after at least one
  step; the robot is idle where it is.

Collision is judged per move step: the sub-path the step sweeps against every other robot's current
position (the others are still during an event), per ``contact``. Connectivity and the RMA are judged
on the positions before and after each event. Snapshots are stale by construction: a robot may move
on a view that others have changed since.

Array form (``fields = 6``, units of ``1/K`` lattice unit): ``(sx, sy, ex, ey, corner, k)``: the start
and end of the current move (equal for an idle robot), the corner kind of an L-shaped path (0 none,
1 horizontal first, 2 vertical first) and the steps done. A state is stored only when every current
position lies on this ``K``-times-finer lattice (every move then starts there); a successor off it
(a robot decided on a halfway view and its own path's steps fall between lattice points) is counted
and not explored, like a successor outside the window.
"""

from __future__ import annotations

import random
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidInput, InvalidTrace
from ..model.config import Model
from ..model.geometry import Path, point_at, subpath
from ..model.numbers import Point, normalize
from ..model.options import Motion, Scheduler
from ..model.swarm import State, is_goal
from ..rules.decision import Decision
from ..rules.registry import decider
from .base import Codec, Expansion, Marks
from .round import Violation, claimed, collisions, disconnection, global_path, rma_violations, snapshot
from .rounds import MAX_SCHEDULE_STEPS

CORNER_NONE, CORNER_H, CORNER_V = 0, 1, 2


class EventKind(StrEnum):
    """What one asynchronous event does."""

    LOOK = "look"
    MOVE = "move"
    STOP = "stop"

    @property
    def letter(self) -> str:
        """The letter of the ``--schedule`` syntax."""
        return self.value[0].upper()


@dataclass(frozen=True, slots=True)
class Event:
    """One event of one robot."""

    kind: EventKind
    robot: int

    def __str__(self) -> str:
        return f"{self.kind.letter}{self.robot}"


@dataclass(frozen=True, slots=True)
class Robot:
    """One robot's phase: idle at ``path[0]`` (a one-point path), or moving along ``path`` with ``k`` of
    ``K`` steps done."""

    path: Path
    k: int = 0
    seen: State | None = field(default=None, compare=False)
    """The positions the robot decided on (every robot, in global coordinates), kept for traces and
    pictures only: the robots are oblivious and the semantics never reads it."""

    @property
    def moving(self) -> bool:
        return len(self.path) > 1

    @property
    def destination(self) -> Point:
        return self.path[-1]


AsyncState = tuple[Robot, ...]


@dataclass(frozen=True, slots=True)
class EventResult:
    """One event played: the :class:`~fatline_verify.schedulers.base.Step` of the asynchronous system."""

    event: Event
    source: AsyncState = field(repr=False)
    target: AsyncState = field(repr=False)
    before: State = field(repr=False)
    after: State
    decisions: dict[int, Decision] = field(repr=False)
    violations: tuple[Violation, ...] = ()
    swept: Path | None = None
    """The sub-path a move step swept."""

    @property
    def active(self) -> tuple[int, ...]:
        return (self.event.robot,)


_EVENT = re.compile(r"([LMSlms])\s*([0-9]+)")


class AsyncSystem:
    """The asynchronous transition system (module docstring)."""

    kind = Scheduler.ASYNC
    fields = 6
    step_word = "event"

    def __init__(self, model: Model) -> None:
        self.model = model
        self.K = model.parameters.async_steps
        self.scale = self.K
        self.rigid = model.options.motion is Motion.RIGID
        self.rule = decider(model)

    # --- executable side -------------------------------------------------------------------------
    def where(self, robot: Robot) -> Point:
        """Where a robot is now."""
        if not robot.moving:
            return robot.path[0]
        return point_at(robot.path, Fraction(robot.k, self.K))

    def start(self, positions: State) -> AsyncState:
        return tuple(Robot((p,)) for p in positions)

    def positions(self, state: AsyncState) -> State:
        return tuple(self.where(r) for r in state)

    def decide(self, state: AsyncState, i: int) -> Decision:
        """Robot ``i``'s Look-Compute on the current positions."""
        return self.rule(snapshot(self.positions(state), i, self.model), self.model)  # type: ignore[no-any-return]

    def events(self, state: AsyncState, decisions: dict[int, Decision] | None = None) -> list[Event]:
        """The events that change something, by robot: move (and, non-rigid, stop) for a moving robot,
        look for an idle robot whose destination differs from its position."""
        out = []
        for i, r in enumerate(state):
            if r.moving:
                out.append(Event(EventKind.MOVE, i))
                if not self.rigid and r.k >= 1:
                    out.append(Event(EventKind.STOP, i))
            elif (decisions[i] if decisions and i in decisions else self.decide(state, i)).moves:
                out.append(Event(EventKind.LOOK, i))
        return out

    def enabled(self, state: AsyncState) -> tuple[int, ...]:
        return tuple(sorted({e.robot for e in self.events(state)}))

    def is_goal(self, state: AsyncState) -> bool:
        return not any(r.moving for r in state) and is_goal(self.positions(state), self.model)

    def play(self, state: AsyncState, action: Event, decision: Decision | None = None) -> EventResult:
        i = action.robot
        robot = state[i]
        before = self.positions(state)
        if action.kind is EventKind.LOOK:
            if robot.moving:
                raise ValueError(f"{action}: robot {i} is moving; only an idle robot looks")
            d = decision or self.decide(state, i)
            new = Robot(global_path(before[i], d), 0, before) if d.moves else robot
            target = (*state[:i], new, *state[i + 1 :])
            return EventResult(action, state, target, before, before, {i: d})
        if not robot.moving:
            raise ValueError(f"{action}: robot {i} is idle; only a moving robot takes a move step or stops")
        if action.kind is EventKind.STOP:
            if self.rigid or robot.k < 1:
                raise ValueError(f"{action}: a move may end early only under motion=non-rigid, after a step")
            target = (*state[:i], Robot((before[i],)), *state[i + 1 :])
            return EventResult(action, state, target, before, before, {})
        t0, t1 = Fraction(robot.k, self.K), Fraction(robot.k + 1, self.K)
        swept = subpath(robot.path, t0, t1)
        new = Robot((robot.destination,)) if robot.k + 1 == self.K else Robot(robot.path, robot.k + 1, robot.seen)
        target = (*state[:i], new, *state[i + 1 :])
        after = self.positions(target)
        violations: list[Violation] = list(collisions(before, {i: swept}, self.model))
        lost = disconnection(before, after, self.model)
        if lost is not None:
            violations.append(lost)
        violations.extend(rma_violations(before, after))
        return EventResult(action, state, target, before, after, {}, claimed(violations, self.model), swept)

    def successors(self, state: AsyncState) -> tuple[int, list[tuple[int, EventResult]]]:
        """The enabled robots (bitmask) and every offered event with its code and result."""
        n = len(state)
        decisions = {i: self.decide(state, i) for i, r in enumerate(state) if not r.moving}
        out = []
        mask = 0
        for e in self.events(state, decisions):
            mask |= 1 << e.robot
            code = (1 << e.robot) | ((1 << n) if e.kind is EventKind.STOP else 0)
            out.append((code, self.play(state, e, decisions.get(e.robot))))
        return mask, out

    def translated(self, a: AsyncState, b: AsyncState) -> bool:
        """Whether ``b`` is ``a`` moved by one common vector, robot by robot, phases and progress alike."""
        dx, dy = b[0].path[0][0] - a[0].path[0][0], b[0].path[0][1] - a[0].path[0][1]
        return all(
            q.k == p.k
            and len(q.path) == len(p.path)
            and all(v[0] - u[0] == dx and v[1] - u[1] == dy for u, v in zip(p.path, q.path, strict=True))
            for p, q in zip(a, b, strict=True)
        )

    def action(self, code: int, order: Sequence[int], state: AsyncState) -> Event:
        """Code ``1 << k`` is canonical robot ``k``'s look or move (by its phase), plus ``1 << n`` a stop."""
        n = len(order)
        k = (code & ((1 << n) - 1)).bit_length() - 1
        robot = int(order[k])
        if code >> n & 1:
            return Event(EventKind.STOP, robot)
        return Event(EventKind.MOVE if state[robot].moving else EventKind.LOOK, robot)

    def choose(self, rng: random.Random, state: AsyncState, waiting: list[int]) -> Event:
        """Uniform among the enabled robots; one enabled for ``2n`` events without acting goes next. A
        moving robot moves (non-rigid: stops with probability 1/4 after a step)."""
        n = len(state)
        events = self.events(state)
        robots = sorted({e.robot for e in events})
        starved = [i for i in robots if waiting[i] >= 2 * n]
        robot = max(starved, key=lambda i: waiting[i]) if starved else rng.choice(robots)
        mine = [e for e in events if e.robot == robot]
        stop = [e for e in mine if e.kind is EventKind.STOP]
        event = stop[0] if stop and rng.random() < 0.25 else next(e for e in mine if e.kind is not EventKind.STOP)
        for i in range(n):
            waiting[i] = 0 if (i == robot or i not in robots) else waiting[i] + 1
        return event

    def parse_schedule(self, text: str, n: int) -> list[Event]:
        """``"L0;M0;L1;M0"``: one event per item, ``L<i>`` robot ``i`` looks and computes, ``M<i>`` takes one
        move step, ``S<i>`` ends its move (``motion = non-rigid``). Whether an event can be played is
        checked as the schedule is played (:meth:`check_action`)."""
        robots = "0" if n == 1 else f"0..{n - 1}"
        expected = (
            f"expected events separated by ';', each L<i> (look-compute), M<i> (one move step) or S<i> "
            f"(end the move; motion=non-rigid) with i in {robots}, e.g. 'L0;M0;L1;M0'"
        )
        if not text.strip():
            raise InvalidInput(f"schedule={text!r}: no events; {expected}")
        parts = text.split(";")
        if len(parts) > MAX_SCHEDULE_STEPS:
            raise InvalidInput(f"schedule={text!r}: {len(parts)} events, more than {MAX_SCHEDULE_STEPS}; {expected}")
        out = []
        for k, part in enumerate(parts, start=1):
            m = _EVENT.fullmatch(part.strip())
            if m is None:
                raise InvalidInput(f"schedule={text!r}: event {k} {part.strip()!r} is not an event; {expected}")
            kind = {"L": EventKind.LOOK, "M": EventKind.MOVE, "S": EventKind.STOP}[m.group(1).upper()]
            i = int(m.group(2))
            if i >= n:
                raise InvalidInput(f"schedule={text!r}: event {k}: robot {i} does not exist (there are {n} robots)")
            if kind is EventKind.STOP and self.rigid:
                raise InvalidInput(f"schedule={text!r}: event {k} {part.strip()!r}: S<i> needs motion=non-rigid")
            out.append(Event(kind, i))
        return out

    def check_action(self, state: AsyncState, action: Event, k: int) -> None:
        robot = state[action.robot]
        if action.kind is EventKind.LOOK and robot.moving:
            raise InvalidInput(
                f"schedule: event {k} {action}: robot {action.robot} is moving ({robot.k} of {self.K} steps done); "
                f"expected M{action.robot} until it arrives"
            )
        if action.kind is not EventKind.LOOK and not robot.moving:
            raise InvalidInput(
                f"schedule: event {k} {action}: robot {action.robot} is idle; expected L{action.robot} first"
            )
        if action.kind is EventKind.STOP and robot.k < 1:
            raise InvalidInput(f"schedule: event {k} {action}: a move ends early only after at least one step")

    def marks(self, step: Any) -> Marks:
        """A look: the path just decided (it is not walked yet) and the robots moving meanwhile. A move
        step: the swept sub-path; every other move under way as its remaining path; the positions the
        stepping robot decided on, drawn faintly where they differ from now (a stale snapshot)."""
        i = step.event.robot
        robot = step.source[i]
        remaining = tuple(
            self.remaining(r) for j, r in enumerate(step.source) if r.moving and (j != i or step.swept is None)
        )
        if step.event.kind is EventKind.LOOK:
            new = step.target[i]
            arrows = (new.path,) if new.moving else ()
            targets = (new.destination,) if new.moving else ()
            note = f"r{i} looks" + ("" if new.moving else ", stays")
            return Marks(i, arrows, targets, remaining, (), note)
        if step.event.kind is EventKind.STOP:
            return Marks(i, (), (), remaining, (), f"r{i} ends its move")
        seen = robot.seen or ()
        ghosts = tuple(p for j, p in enumerate(seen) if j != i and p != step.before[j])
        arrows = (step.swept,) if step.swept else ()
        rest = self.remaining(step.target[i]) if step.target[i].moving else None
        note = f"r{i} step {robot.k + 1} of {self.K}"
        return Marks(i, arrows, (robot.destination,), remaining + ((rest,) if rest else ()), ghosts, note)

    def remaining(self, robot: Robot) -> Path:
        """A moving robot's path from where it is to its destination."""
        return subpath(robot.path, Fraction(robot.k, self.K), Fraction(1))

    def step_to_json(self, step: Any) -> dict[str, Any]:
        from ..trace.steps import event_to_json

        return event_to_json(step, self)

    def action_from_json(self, record: dict[str, Any], n: int, where: str) -> Event:
        if "event" not in record:
            raise InvalidTrace(
                f"{where}: a round, but model {self.model.name} has scheduler=async, which plays events; expected a "
                "model with a round scheduler (ssync, fsync, centralized)"
            )
        robot = record["robot"]
        if robot >= n:
            raise InvalidTrace(f"{where}/robot: robot {robot} does not exist; expected 0..{n - 1}")
        return Event(EventKind(record["event"]), robot)

    # --- array side ------------------------------------------------------------------------------
    def _fine(self, p: Point) -> tuple[int, int]:
        x, y = Fraction(p[0]) * self.K, Fraction(p[1]) * self.K
        if x.denominator != 1 or y.denominator != 1:
            raise ValueError(f"point {p} is off the {self.K}-times finer lattice")
        return int(x), int(y)

    def to_array(self, state: AsyncState) -> np.ndarray:
        rows = []
        for r in state:
            s, e = self._fine(r.path[0]), self._fine(r.path[-1])
            corner = CORNER_NONE
            if len(r.path) == 3:
                corner = CORNER_H if r.path[1][1] == r.path[0][1] else CORNER_V
            rows.append((*s, *e, corner, r.k))
        return np.array(rows, dtype=np.int64).reshape(len(state), self.fields)

    def exact_array(self, state: AsyncState) -> np.ndarray | None:
        """:meth:`to_array`, or ``None`` when a start, destination or current position is off the lattice."""
        try:
            for r in state:
                self._fine(self.where(r))
            return self.to_array(state)
        except ValueError:
            return None

    def from_array(self, row: np.ndarray) -> AsyncState:
        out = []
        for sx, sy, ex, ey, corner, k in row.tolist():
            s = (normalize(Fraction(sx, self.K)), normalize(Fraction(sy, self.K)))
            e = (normalize(Fraction(ex, self.K)), normalize(Fraction(ey, self.K)))
            if s == e:
                out.append(Robot((s,)))
                continue
            path: Path = (s, e)
            if corner == CORNER_H:
                path = (s, (e[0], s[1]), e)
            elif corner == CORNER_V:
                path = (s, (s[0], e[1]), e)
            out.append(Robot(path, int(k)))
        return tuple(out)

    def initial(self, positions: np.ndarray) -> np.ndarray:
        m, n, _ = positions.shape
        fine = positions.astype(np.int64) * self.K
        zeros = np.zeros((m, n, 2), dtype=np.int64)
        return np.concatenate([fine, fine, zeros], axis=2)

    def canonical(self, states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return async_canonical(states)

    def codec(self, n: int, window: tuple[int, int]) -> Codec:
        return AsyncCodec(n, window, self.K)

    def array_positions(self, states: np.ndarray) -> np.ndarray:
        pos, _ = current_positions(states, self.K)
        return pos

    def step_positions(self, states: np.ndarray, ex: Expansion) -> tuple[np.ndarray, np.ndarray, int]:
        """An event's positions in units of ``1/K^2`` lattice unit, where every move step lands: a look
        or a stop moves no robot; a move step takes its robot one ``1/K`` of its path further (also to a
        point off the ``K``-times finer lattice, a successor that is counted but not explored), as
        :meth:`play` does. The event's robot is the action code's lowest bit (a stop adds bit ``n``)."""
        K, n = self.K, states.shape[1]
        pos, _ = current_positions(states, K)
        before = pos[ex.src] * K
        after = before.copy()
        code = ex.action & ((1 << n) - 1)
        robot = np.rint(np.log2(np.maximum(code & -code, 1))).astype(np.int64)
        source = states[ex.src, robot]  # (t, 6): the event's robot in its source
        moving = (source[:, 0:2] != source[:, 2:4]).any(axis=1)
        step = np.flatnonzero(moving & ((ex.action >> n) & 1 == 0))
        if len(step):
            fine = source[step].copy()
            fine[:, 0:4] *= K  # the path in units of 1/K^2: every step's end is a whole number of them
            fine[:, 5] += 1
            moved, _ = current_positions(fine[:, None, :], K)
            after[step, robot[step]] = moved[:, 0]
        return before, after, K * K

    default_engine = "compiled"
    """The engine ``check`` uses unless told otherwise (:mod:`fatline_verify.check.compiled_async`)."""

    family = "async"
    """Engines: :data:`fatline_verify.check.engines.BUILDERS`."""


# --- array helpers (shared by the engines) --------------------------------------------------------


def current_positions(states: np.ndarray, K: int) -> tuple[np.ndarray, np.ndarray]:
    """Per array state and robot, the current position ``(m, n, 2)`` in array units and whether it is
    exact (on the lattice); a position off it is rounded towards the start and must not be used."""
    s, e = states[..., 0:2], states[..., 2:4]
    corner, k = states[..., 4], states[..., 5]
    d = e - s
    ad = np.abs(d)
    sign = np.sign(d)
    total = ad.sum(axis=-1)  # an L path's length; a straight path is parameterised linearly instead
    along = total * k
    exact_l = along % K == 0
    dist = along // K
    straight = corner == CORNER_NONE
    num = d * k[..., None]
    exact_s = (num % K == 0).all(axis=-1)
    pos_s = s + num // K
    first = np.where(corner == CORNER_H, ad[..., 0], ad[..., 1])
    on_first = dist <= first
    # horizontal first: x moves first
    hx = np.where(on_first, s[..., 0] + sign[..., 0] * dist, e[..., 0])
    hy = np.where(on_first, s[..., 1], s[..., 1] + sign[..., 1] * (dist - first))
    vx = np.where(on_first, s[..., 0], s[..., 0] + sign[..., 0] * (dist - first))
    vy = np.where(on_first, s[..., 1] + sign[..., 1] * dist, e[..., 1])
    pos_l = np.where((corner == CORNER_H)[..., None], np.stack([hx, hy], -1), np.stack([vx, vy], -1))
    pos = np.where(straight[..., None], pos_s, pos_l)
    exact = np.where(straight, exact_s, exact_l)
    return pos, exact


def async_canonical(states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Translate so the least start/end x and y are 0, then sort robots by ``(sx, sy, ex, ey, corner, k)``."""
    m, n, _ = states.shape
    if not m:
        return states.copy(), np.zeros((0, n), dtype=np.int64)
    lo_x = np.minimum(states[..., 0], states[..., 2]).min(axis=1)
    lo_y = np.minimum(states[..., 1], states[..., 3]).min(axis=1)
    shifted = states.copy()
    shifted[..., 0] -= lo_x[:, None]
    shifted[..., 2] -= lo_x[:, None]
    shifted[..., 1] -= lo_y[:, None]
    shifted[..., 3] -= lo_y[:, None]
    span = int(shifted[..., :4].max()) + 1
    kmax = int(shifted[..., 5].max()) + 1
    codes = np.zeros((m, n), dtype=np.int64)
    if span**4 * 3 * kmax < 2**62:
        for f, base in ((0, span), (1, span), (2, span), (3, span), (4, 3), (5, kmax)):
            codes = codes * base + shifted[..., f]
        order = np.argsort(codes, axis=1, kind="stable")
    else:  # very wide spans (successors far outside any window): sort field by field
        order = np.tile(np.arange(n), (m, 1))
        for f in range(5, -1, -1):
            idx = np.argsort(np.take_along_axis(shifted[..., f], order, axis=1), axis=1, kind="stable")
            order = np.take_along_axis(order, idx, axis=1)
    canon = np.take_along_axis(shifted, order[..., None], axis=1)
    return canon, order


class AsyncCodec:
    """Packs canonical asynchronous states into keys: one robot code
    ``((((sx * Hf + sy) * Wf + ex) * Hf + ey) * 3 + corner) * K + k`` in ``bits`` bits, robots in canonical
    order, as one int64 when ``n * bits <= 63``, else as big-endian 64-bit words (``per_word`` robots each)
    viewed as a fixed-width byte string, which sorts the same way."""

    def __init__(self, n: int, window: tuple[int, int], K: int) -> None:
        self.n, self.K = n, K
        w, h = window
        self.wf, self.hf = (w - 1) * K + 1, (h - 1) * K + 1
        self.radix = self.wf * self.hf * self.wf * self.hf * 3 * K
        self.bits = max(1, (self.radix - 1).bit_length())
        if self.bits > 64:
            raise ValueError(f"window={w}x{h} with async_steps={K}: one robot does not pack into 64 bits")
        self.words = 1 if n * self.bits <= 63 else -(-n // (64 // self.bits))
        self.per_word = n if self.words == 1 else 64 // self.bits
        self.dtype = np.dtype(np.int64) if self.words == 1 else np.dtype((np.void, 8 * self.words))

    def fits(self, canon: np.ndarray) -> np.ndarray:
        x = np.maximum(canon[..., 0], canon[..., 2]).max(axis=1)
        y = np.maximum(canon[..., 1], canon[..., 3]).max(axis=1)
        return (x < self.wf) & (y < self.hf)  # type: ignore[no-any-return]

    def _codes(self, canon: np.ndarray) -> np.ndarray:
        c = canon.astype(np.int64)
        return (
            (((c[..., 0] * self.hf + c[..., 1]) * self.wf + c[..., 2]) * self.hf + c[..., 3]) * 3 + c[..., 4]
        ) * self.K + c[..., 5]  # type: ignore[no-any-return]

    def encode(self, canon: np.ndarray) -> np.ndarray:
        codes = self._codes(canon).astype(np.uint64)
        m = len(canon)
        if self.words == 1:
            key = np.zeros(m, dtype=np.int64)
            for k in range(self.n):
                key = (key << self.bits) | codes[:, k].astype(np.int64)
            return key
        words = np.zeros((m, self.words), dtype=np.uint64)
        for k in range(self.n):
            wi = k // self.per_word
            words[:, wi] = (words[:, wi] << np.uint64(self.bits)) | codes[:, k]
        last = self.n - (self.words - 1) * self.per_word  # pad the last word so every word is left-aligned alike
        words[:, -1] <<= np.uint64(self.bits * (self.per_word - last))
        return np.ascontiguousarray(words.astype(">u8")).view(self.dtype).ravel()

    def decode(self, keys: np.ndarray) -> np.ndarray:
        m = len(keys)
        codes = np.empty((m, self.n), dtype=np.int64)
        mask = (1 << self.bits) - 1
        if self.words == 1:
            k64 = np.asarray(keys, dtype=np.int64)
            for k in range(self.n - 1, -1, -1):
                codes[:, k] = k64 & mask
                k64 = k64 >> self.bits
        else:
            words = np.ascontiguousarray(keys).view(">u8").reshape(m, self.words).astype(np.uint64)
            last = self.n - (self.words - 1) * self.per_word
            words[:, -1] >>= np.uint64(self.bits * (self.per_word - last))
            for k in range(self.n - 1, -1, -1):
                wi = k // self.per_word
                codes[:, k] = (words[:, wi] & np.uint64(mask)).astype(np.int64)
                words[:, wi] >>= np.uint64(self.bits)
        out = np.empty((m, self.n, 6), dtype=np.int64)
        for f, base in ((5, self.K), (4, 3), (3, self.hf), (2, self.wf), (1, self.hf), (0, self.wf)):
            out[..., f] = codes % base
            codes = codes // base
        return out


__all__ = ["AsyncCodec", "AsyncState", "AsyncSystem", "Event", "EventKind", "EventResult", "Robot"]
