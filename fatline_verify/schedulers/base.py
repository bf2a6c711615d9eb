"""The transition system: one interface for everything that differs between schedulers.

Like stateright's ``Model`` (``init_states``, ``actions``, ``next_state``) or a TLA+ spec against TLC,
a :class:`TransitionSystem` says what a state is, which actions a state offers, what one action does
(and which lemmas the step violates), how a state is written as an int64 array, canonicalised and
packed into a key, how a step is written in a trace, and how a schedule is read. The explorer, both
engines' drivers, liveness, witness reconstruction, ``simulate``, ``replay`` and the reports are
written once against it; a scheduler is one implementation plus one registry entry
(:mod:`fatline_verify.schedulers.systems`).

Two sides, one semantics:

- the *executable* side works on exact states (``int``/``Fraction`` positions) one action at a time;
  it is the reference that every trace is replayed by;
- the *array* side (states as ``(m, n, fields)`` int64 arrays, actions as int64 codes relative to the
  canonical robot order) is what the explorer stores; an engine expands a batch of array states, and
  the scalar engine does so through the executable side, so the two cannot drift apart.

An action code's low ``n`` bits are the robots that act in it (the activation set of a round, the one
robot of an asynchronous event); liveness reads fairness from them. Higher bits are the system's own.
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from ..errors import InvalidInput
from ..model.config import Model
from ..model.geometry import Path
from ..model.numbers import Point
from ..model.options import Scheduler
from ..model.swarm import State
from ..rules.decision import Decision
from .round import Violation


class Step(Protocol):
    """One action played by the executable model."""

    @property
    def active(self) -> tuple[int, ...]:
        """The robots that acted."""
        ...

    @property
    def decisions(self) -> dict[int, Decision]:
        """Decisions taken in this step (Look-Compute), by robot."""
        ...

    @property
    def before(self) -> State:
        """Robot positions before the step."""
        ...

    @property
    def after(self) -> State:
        """Robot positions after the step."""
        ...

    @property
    def violations(self) -> tuple[Violation, ...]:
        """What went wrong in this step."""
        ...

    @property
    def source(self) -> Any:
        """The system state before the step."""
        ...

    @property
    def target(self) -> Any:
        """The system state after the step."""
        ...


@dataclass(frozen=True, slots=True)
class Marks:
    """What a picture of one step draws besides the discs (global lattice coordinates): the system says
    what a step looks like, the picture code only draws."""

    acting: int
    """The robot whose view (visibility circle, bands) is shown."""
    arrows: tuple[Path, ...] = ()
    """Motion in this step (a round's moves; an event's swept sub-path)."""
    targets: tuple[Point, ...] = ()
    """Where this step's movers end (dotted discs)."""
    remaining: tuple[Path, ...] = ()
    """Moves under way before the step: from the robot's current point to its destination (dashed)."""
    ghosts: tuple[Point, ...] = ()
    """The positions the acting robot decided on, where they differ from now (faint discs)."""
    note: str = ""
    """A short caption fragment (``"r1 looks"``, ``"r0 step 2 of 2"``)."""


@dataclass(frozen=True, slots=True)
class Expansion:
    """What an engine computes for a batch of canonical array states.

    Per state: the robots that have an action (``enabled``, a bitmask: activating any other robot is a
    self-loop) and whether it meets the goal. Per transition: its source row, its action code (in the
    source's canonical robot order), the successor (robots in the source's order, not canonical), its
    violation bits (:data:`fatline_verify.lemmas.properties.FLAG`), and whether the successor is exactly
    representable as an array state (``False`` when a position leaves the system's lattice).
    """

    enabled: np.ndarray
    """(m,) int64 bitmask."""
    goal: np.ndarray
    """(m,) bool."""
    src: np.ndarray
    """(t,) int64 row of the source state in the batch."""
    action: np.ndarray
    """(t,) int64 action code."""
    after: np.ndarray
    """(t, n, fields) int64 successors, robots in the source's order."""
    flags: np.ndarray
    """(t,) int64 violation bits of the step."""
    exact: np.ndarray
    """(t,) bool: the successor lies on the lattice (else ``after`` is meaningless and it is not explored)."""


@dataclass(slots=True)
class KeyExpansion:
    """What the search needs of a batch of frontier keys: :class:`Expansion` with each successor
    replaced by its canonical key (in the search's codec) and whether it fits the exploration bound."""

    enabled: np.ndarray
    """(m,) int64 bitmask, per frontier key."""
    goal: np.ndarray
    """(m,) bool."""
    src: np.ndarray
    """(t,) int64 row of the source key in the batch."""
    action: np.ndarray
    """(t,) int64 action code."""
    key: np.ndarray
    """(t,) the successor's canonical key (zero where it does not fit)."""
    flags: np.ndarray
    """(t,) int64 violation bits."""
    fits: np.ndarray
    """(t,) bool: the successor is on the lattice and inside the bound."""
    exact: np.ndarray
    """(t,) bool: the successor is on the system's lattice."""


class Engine(Protocol):
    """An exploration engine for one transition system. An engine may also offer
    ``expand_keys(keys, codec) -> KeyExpansion`` doing the whole step from keys to keys (a compiled
    kernel does); :func:`expand_keys` uses it when present."""

    name: str

    def expand(self, states: np.ndarray) -> Expansion:
        """Expand a batch of canonical array states."""
        ...


class Codec(Protocol):
    """Packs canonical array states inside a window into sortable keys (``int64``, or a fixed-width
    byte string when one word is not enough) and back."""

    dtype: np.dtype[Any]
    n: int
    """The robots a state holds."""

    def fits(self, canon: np.ndarray) -> np.ndarray:
        """Which canonical states lie inside the window."""
        ...

    def encode(self, canon: np.ndarray) -> np.ndarray:
        """Keys of canonical states that fit (the caller filters with :meth:`fits`)."""
        ...

    def decode(self, keys: np.ndarray) -> np.ndarray:
        """Canonical states from keys."""
        ...


class TransitionSystem(Protocol):
    """One scheduler's semantics of the algorithm (see the module docstring)."""

    kind: Scheduler
    model: Model
    fields: int
    """int64 columns per robot in the array form."""
    step_word: str
    """What one step is called in messages and traces ("round", "event")."""

    # --- executable side -------------------------------------------------------------------------
    def start(self, positions: State) -> Any:
        """The state of a swarm at rest at ``positions`` (an initial state)."""
        ...

    def positions(self, state: Any) -> State:
        """Where the robots are."""
        ...

    def enabled(self, state: Any) -> tuple[int, ...]:
        """Robots with an action that changes something (none: the state is terminal)."""
        ...

    def is_goal(self, state: Any) -> bool:
        """Whether the swarm has formed the line and is at rest there."""
        ...

    def play(self, state: Any, action: Any) -> Step:
        """Play one action (as made by :meth:`action`, :meth:`parse_schedule` or :meth:`choose`)."""
        ...

    def successors(self, state: Any) -> tuple[int, Sequence[tuple[int, Step]]]:
        """The enabled robots (bitmask) and every action the scheduler offers (those that change
        something), as ``(code, step)`` with codes in this state's robot order (the scalar engine)."""
        ...

    def translated(self, a: Any, b: Any) -> bool:
        """Whether ``b`` is ``a`` moved by one common vector, robot by robot (a lasso closes)."""
        ...

    def exact_array(self, state: Any) -> np.ndarray | None:
        """:meth:`to_array`, or ``None`` when the state is off the system's lattice."""
        ...

    def action(self, code: int, order: Sequence[int], state: Any) -> Any:
        """The executable action of array action ``code``, whose robot bit ``k`` means robot ``order[k]``."""
        ...

    def choose(self, rng: random.Random, state: Any, waiting: list[int]) -> Any:
        """A fair random action among the enabled robots' (non-empty); ``waiting[i]`` counts the steps
        robot ``i`` has been enabled without acting, and is updated."""
        ...

    def parse_schedule(self, text: str, n: int) -> list[Any]:
        """The actions of an explicit ``--schedule``, checked against this scheduler."""
        ...

    def check_action(self, state: Any, action: Any, k: int) -> None:
        """Raise :class:`~fatline_verify.errors.InvalidInput` when ``action`` (the ``k``-th, 1-based) cannot
        be played in ``state``."""
        ...

    def marks(self, step: Step) -> Marks:
        """What a picture of ``step`` draws."""
        ...

    def step_to_json(self, step: Step) -> dict[str, Any]:
        """One step as a trace record."""
        ...

    def action_from_json(self, record: dict[str, Any], n: int, where: str) -> Any:
        """The action a trace record replays (:class:`~fatline_verify.errors.InvalidTrace` when malformed)."""
        ...

    # --- array side ------------------------------------------------------------------------------
    def to_array(self, state: Any) -> np.ndarray:
        """``(n, fields)`` int64."""
        ...

    def from_array(self, row: np.ndarray) -> Any:
        """The state an array row stands for."""
        ...

    def initial(self, positions: np.ndarray) -> np.ndarray:
        """Array states ``(m, n, fields)`` of canonical initial positions ``(m, n, 2)`` (robots at rest)."""
        ...

    def canonical(self, states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Canonical forms of a batch and the robot order: ``canon[i, k] = translated[i, order[i, k]]``."""
        ...

    def codec(self, n: int, window: tuple[int, int]) -> Codec:
        """The key codec for ``n`` robots whose base-lattice bounding box is at most ``window``."""
        ...

    default_engine: str
    """The engine name ``check`` uses unless told otherwise (one of :data:`ENGINES`)."""

    family: str
    """Which engines expand this system (:data:`fatline_verify.check.engines.BUILDERS`)."""

    def array_positions(self, states: np.ndarray) -> np.ndarray:
        """``(m, n, 2)`` positions of array states, exact, in units of the base lattice divided by
        :attr:`scale` (integers)."""
        ...

    scale: int
    """How many array units make one base lattice unit."""

    def step_positions(self, states: np.ndarray, ex: Expansion) -> tuple[np.ndarray, np.ndarray, int]:
        """Every transition of ``ex`` (expanded from ``states``) as the executable model plays it: the
        positions before and after the step, ``(t, n, 2)`` integers in units of the base lattice
        divided by the returned unit, robots in the source's order. Exact for every transition, also
        one whose successor is off the lattice (``ex.after`` is meaningless there): the registered step
        lemmas are judged on these (:func:`fatline_verify.lemmas.registry.extra_flags`)."""
        ...


ENGINES = ("compiled", "fast", "scalar")
"""The engine names (:func:`fatline_verify.check.engines.engine_for`); a system may lack some."""


def unknown_engine(name: str) -> InvalidInput:
    """The one-line error for an engine name not in :data:`ENGINES`."""
    return InvalidInput(f"engine={name!r}: expected compiled, fast or scalar")


def expand_keys(system: TransitionSystem, engine: Engine, codec: Codec, keys: np.ndarray) -> KeyExpansion:
    """One search step from frontier keys: the engine's own ``expand_keys`` when it has one, else
    decode, :meth:`Engine.expand`, canonicalise and encode."""
    own = getattr(engine, "expand_keys", None)
    if own is not None:
        return own(keys, codec)  # type: ignore[no-any-return]
    ex = engine.expand(codec.decode(keys))
    canon, _ = system.canonical(ex.after) if len(ex.after) else (ex.after, None)
    fits = (codec.fits(canon) & ex.exact) if len(canon) else np.zeros(0, dtype=bool)
    key = np.zeros(len(canon), dtype=codec.dtype)
    if fits.any():
        key[fits] = codec.encode(canon[fits])
    return KeyExpansion(ex.enabled, ex.goal, ex.src, ex.action, key, ex.flags, fits, ex.exact)


__all__ = [
    "ENGINES",
    "Codec",
    "Engine",
    "Expansion",
    "KeyExpansion",
    "Marks",
    "Step",
    "TransitionSystem",
    "expand_keys",
    "unknown_engine",
]
