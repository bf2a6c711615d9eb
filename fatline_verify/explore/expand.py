"""What an exploration engine computes for a batch of canonical states: the expansion.

An engine (scalar reference or vectorised) takes canonical states ``(m, n, 2)`` and returns, per
state, the enabled robots and whether it is a goal state, and per SSYNC (FSYNC, centralized)
transition the activation mask, the positions after the round (in the source's robot order) and
the violation flags of the round (bits of :data:`fatline_verify.properties.FLAG`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from ..options import Scheduler
from ..schedulers import round_scheduler


@dataclass(frozen=True, slots=True)
class Expansion:
    """Engine output for one batch."""

    enabled: np.ndarray
    """(m,) int64 bitmask of robots whose destination differs from their position."""
    goal: np.ndarray
    """(m,) bool."""
    src: np.ndarray
    """(t,) int64 row of the source state in the batch."""
    mask: np.ndarray
    """(t,) int64 activation bitmask."""
    after: np.ndarray
    """(t, n, 2) int64 positions after the round, robots in the source's order."""
    flags: np.ndarray
    """(t,) int64 violation bits of the round."""


class Engine(Protocol):
    """An exploration engine."""

    name: str

    def expand(self, states: np.ndarray) -> Expansion:
        """Expand a batch of canonical states."""
        ...


def activation_masks(enabled: int, n: int, scheduler: Scheduler) -> list[int]:
    """The activation sets a state's scheduler offers, as bitmasks, in increasing order
    (:meth:`fatline_verify.schedulers.RoundScheduler.masks`)."""
    return round_scheduler(scheduler).masks(enabled, n)
