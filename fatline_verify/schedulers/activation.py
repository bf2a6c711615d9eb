"""The round schedulers: which robots may act together in one round. One object per scheduler.

The paper's model: "The robots execute this cycle in semi-synchronous scheduling where an arbitrary
set of robots look, compute and move simultaneously." Every synchronous scheduler plays rounds in
which the active robots decide on one shared snapshot and move; they differ only in which sets may
be active. Everything that depends on that — the checker's activation sets (scalar and vectorised),
the fair random scheduler of ``simulate``, the check of an explicit ``--schedule``, the legality of
a prover model — asks the scheduler's object here, so a new round scheduler is one class and one
registry entry. (ASYNC is not a round scheduler: its steps are single look-compute or move events.)
"""

from __future__ import annotations

import random
from typing import Any, Protocol

import numpy as np

from ..errors import InvalidModel, Unsupported
from ..model.options import Scheduler, SchedulerName, parse_reading
from ..model.seams import declared, filled


class RoundScheduler(Protocol):
    """Which activation sets a scheduler allows in one round."""

    kind: Scheduler
    alone: bool
    """Whether it may activate one robot alone while others are enabled (a deadlock for every
    algorithm needs it: :func:`fatline_verify.repair.reach.universal_deadlock`)."""
    encoded: bool
    """Whether the prover's obligations encode its rounds (every mover decides on one shared snapshot)."""

    def masks(self, enabled: int, n: int) -> list[int]:
        """The activation sets offered in a state whose enabled robots are ``enabled`` (a bitmask), as
        bitmasks in increasing order. Activating an idle robot is a self-loop, so only sets of enabled
        robots are offered; none when no robot is enabled."""
        ...

    def valid(self, masks: np.ndarray, enabled: np.ndarray) -> np.ndarray:
        """:meth:`masks` for a batch: ``(m, len(masks))`` bool, whether ``masks[j]`` is offered in state ``i``."""
        ...

    def forbids(self, active: tuple[int, ...], n: int) -> str | None:
        """Why this scheduler never activates exactly ``active`` (sorted indices) among ``n`` robots, or
        ``None`` when it may (an explicit schedule may also activate robots that would not move)."""
        ...

    def choose(self, rng: random.Random, candidates: tuple[int, ...], waiting: list[int], n: int) -> set[int]:
        """A fair random choice among the enabled ``candidates`` (non-empty); ``waiting[i]`` counts the
        rounds robot ``i`` has been enabled but idle. No enabled robot waits more than ``n`` rounds."""
        ...

    # Optional, for a scheduler with parameters of its own (:mod:`fatline_verify.model.seams`):
    # ``parameters: dict[str, Param]`` and ``configured(**values) -> RoundScheduler``.


def _subsets(enabled: int) -> list[int]:
    out, sub = [], enabled
    while sub:
        out.append(sub)
        sub = (sub - 1) & enabled
    return sorted(out)


def _shown(active: tuple[int, ...]) -> str:
    return ",".join(map(str, active))


class SemiSynchronous:
    """ssync: "an arbitrary set of robots look, compute and move simultaneously" — any non-empty set."""

    kind = Scheduler.SSYNC
    alone = True
    encoded = True

    def masks(self, enabled: int, n: int) -> list[int]:
        return _subsets(enabled)

    def valid(self, masks: np.ndarray, enabled: np.ndarray) -> np.ndarray:
        return (masks[None, :] & ~enabled[:, None]) == 0  # type: ignore[no-any-return]

    def forbids(self, active: tuple[int, ...], n: int) -> str | None:
        return None if active else "activates no robot; expected at least one robot per round"

    def choose(self, rng: random.Random, candidates: tuple[int, ...], waiting: list[int], n: int) -> set[int]:
        chosen = {i for i in candidates if rng.random() < 0.5 or waiting[i] >= n}
        return chosen or {rng.choice(candidates)}


class FullySynchronous:
    """fsync: every robot in every round."""

    kind = Scheduler.FSYNC
    alone = False
    encoded = True

    def masks(self, enabled: int, n: int) -> list[int]:
        return [enabled] if enabled else []

    def valid(self, masks: np.ndarray, enabled: np.ndarray) -> np.ndarray:
        return (masks[None, :] == enabled[:, None]) & (enabled[:, None] != 0)  # type: ignore[no-any-return]

    def forbids(self, active: tuple[int, ...], n: int) -> str | None:
        if len(active) == n:
            return None
        return (
            f"activates robots {_shown(active)} of {n}; expected every robot ('all') in every round under "
            "scheduler=fsync"
        )

    def choose(self, rng: random.Random, candidates: tuple[int, ...], waiting: list[int], n: int) -> set[int]:
        return set(range(n))


class Centralized:
    """centralized: exactly one robot a round."""

    kind = Scheduler.CENTRALIZED
    alone = True
    encoded = True

    def masks(self, enabled: int, n: int) -> list[int]:
        return [1 << i for i in range(n) if enabled >> i & 1]

    def valid(self, masks: np.ndarray, enabled: np.ndarray) -> np.ndarray:
        single = (masks & (masks - 1)) == 0
        return ((masks[None, :] & ~enabled[:, None]) == 0) & single[None, :]  # type: ignore[no-any-return]

    def forbids(self, active: tuple[int, ...], n: int) -> str | None:
        if len(active) == 1:
            return None
        return (
            f"activates {len(active)} robots ({_shown(active)}); expected exactly one robot per round under "
            "scheduler=centralized"
        )

    def choose(self, rng: random.Random, candidates: tuple[int, ...], waiting: list[int], n: int) -> set[int]:
        starved = [i for i in candidates if waiting[i] >= n]
        pool = [max(starved, key=lambda i: waiting[i])] if starved else list(candidates)
        return {rng.choice(pool)}


ROUND_SCHEDULERS: dict[str, RoundScheduler] = {
    s.kind.value: s for s in (SemiSynchronous(), FullySynchronous(), Centralized())
}
"""Every round scheduler by name: the paper's three, then registered ones (:func:`register`)."""


def register(scheduler: RoundScheduler) -> RoundScheduler:
    """Add a round scheduler of one's own (a plug-in: one module, one call). Its ``kind`` is its name
    (a :class:`~fatline_verify.model.options.SchedulerName`), which a model's ``scheduler`` option
    names; it says whether it may activate one robot alone, and ``encoded`` must be false: the
    prover's obligations encode the paper's schedulers only."""
    name = str(scheduler.kind)
    if name in {s.value for s in Scheduler}:
        raise ValueError(f"scheduler {name!r}: the paper's scheduler of that name cannot be replaced")
    if scheduler.encoded:
        raise ValueError(f"scheduler {name!r}: encoded=True, but the prover's obligations encode no plug-in")
    if declared(scheduler) and not callable(getattr(scheduler, "configured", None)):
        raise ValueError(f"scheduler {name!r}: declares parameters but no configured(**values) to take them")
    ROUND_SCHEDULERS.setdefault(name, scheduler)
    from ..rules import registry

    registry.claim("scheduler", name)  # the plug-in package registering it, if any
    return ROUND_SCHEDULERS[name]


def round_scheduler(kind: Scheduler | str) -> RoundScheduler:
    """The scheduler object of ``kind``; the one place that says which schedulers play rounds."""
    found = ROUND_SCHEDULERS.get(str(kind))
    if found is None:
        from ..rules import registry

        registry.names()  # loads the plug-ins, which may register schedulers
        found = ROUND_SCHEDULERS.get(str(kind))
    if found is None:
        known = ", ".join(ROUND_SCHEDULERS)
        raise Unsupported(f"scheduler={str(kind)!r}: not implemented yet; expected one of {known}") from None
    return found


def scheduler_for(model: Any, kind: Scheduler | str | None = None) -> RoundScheduler:
    """The round scheduler ``model`` plays rounds under (or ``kind``), with the values the model sets for
    the parameters it declares (``configured(**values)``; defaults for another ``kind`` than the model's)."""
    found = round_scheduler(kind or model.options.scheduler)
    params = declared(found)
    if not params:
        return found
    own = kind is None or str(kind) == str(model.options.scheduler)
    return found.configured(**(model.setting("scheduler") if own else filled(params, {})))  # type: ignore[attr-defined, no-any-return]


def scheduler_named(name: str, where: str = "options.scheduler") -> Scheduler | SchedulerName:
    """The scheduler called ``name``: one of the paper's or a registered one (plug-ins loaded), or a
    one-line :class:`InvalidModel` naming ``where`` and every scheduler there is."""
    try:
        reading = parse_reading("scheduler", name)
        if not isinstance(reading, Scheduler):
            round_scheduler(reading)
        return reading  # type: ignore[return-value]
    except (InvalidModel, Unsupported):
        known = ", ".join([*ROUND_SCHEDULERS, Scheduler.ASYNC.value])
        raise InvalidModel(f"{where}={name!r}: unknown scheduler; expected one of {known}") from None


def encoded_schedulers() -> tuple[Scheduler, ...]:
    """The schedulers whose rounds the prover's obligations encode."""
    return tuple(s.kind for s in ROUND_SCHEDULERS.values() if s.encoded)


__all__ = [
    "ROUND_SCHEDULERS",
    "RoundScheduler",
    "encoded_schedulers",
    "register",
    "round_scheduler",
    "scheduler_for",
    "scheduler_named",
]
