"""The transition systems, one per scheduler, behind :class:`~fatline_verify.schedulers.base.TransitionSystem`.

:func:`system_for` is the one place that maps a model's ``scheduler`` option to its semantics: a new
scheduler is one module implementing the interface and one entry in :data:`SYSTEMS`.
"""

from __future__ import annotations

from collections.abc import Callable

from ..model.config import Model
from ..model.options import Scheduler
from .activation import round_scheduler
from .base import Codec, Engine, Expansion, Step, TransitionSystem


def _rounds(model: Model, kind: Scheduler) -> TransitionSystem:
    from .rounds import RoundSystem

    return RoundSystem(model, kind)


def _async(model: Model, kind: Scheduler) -> TransitionSystem:
    from .asynchronous import AsyncSystem

    return AsyncSystem(model)


SYSTEMS: dict[Scheduler, Callable[[Model, Scheduler], TransitionSystem]] = {
    Scheduler.SSYNC: _rounds,
    Scheduler.FSYNC: _rounds,
    Scheduler.CENTRALIZED: _rounds,
    Scheduler.ASYNC: _async,
}


def system_for(model: Model, scheduler: Scheduler | None = None) -> TransitionSystem:
    """The transition system of ``model`` (under its own scheduler, or ``scheduler``)."""
    kind = scheduler or model.options.scheduler
    make = SYSTEMS.get(kind)  # type: ignore[call-overload]
    if make is None:
        round_scheduler(kind)  # a registered round scheduler's, or a one-line Unsupported
        make = _rounds
    return make(model, kind)


__all__ = ["SYSTEMS", "Codec", "Engine", "Expansion", "Step", "TransitionSystem", "system_for"]
