"""The reference engine: every state and every activation set through the executable model.

Slow and plain on purpose: each round is :func:`fatline_verify.schedule.play_round`, so the
vectorised engine is tested against exactly what ``fatline simulate`` and ``fatline replay`` do.
"""

from __future__ import annotations

import numpy as np

from ..config import Model
from ..options import Scheduler
from ..properties import FLAG, Lemma
from ..schedule import Collision, Disconnection, RmaMoved, decide_all, play_round
from ..schedulers import round_scheduler
from ..swarm import is_goal
from .expand import Expansion, activation_masks

_FLAG_OF = {
    Collision: FLAG[Lemma.NO_COLLISION],
    Disconnection: FLAG[Lemma.CONNECTIVITY],
    RmaMoved: FLAG[Lemma.RMA_FIXED],
}


def require_runnable(model: Model) -> Scheduler:
    """The model's scheduler, if an engine can explore it."""
    return round_scheduler(model.options.scheduler).kind


class ScalarEngine:
    """Reference engine: the executable model, one round at a time."""

    name = "scalar"

    def __init__(self, model: Model) -> None:
        self.model = model
        self.scheduler = require_runnable(model)

    def expand(self, states: np.ndarray) -> Expansion:
        m, n, _ = states.shape
        enabled = np.zeros(m, dtype=np.int64)
        goal = np.zeros(m, dtype=bool)
        src, masks, after, flags = [], [], [], []
        for row in range(m):
            state = tuple((int(x), int(y)) for x, y in states[row])
            decisions = decide_all(state, self.model)
            en = sum(1 << i for i, d in decisions.items() if d.moves)
            enabled[row] = en
            goal[row] = is_goal(state, self.model)
            for mask in activation_masks(en, n, self.scheduler):
                active = [i for i in range(n) if mask >> i & 1]
                result = play_round(state, active, self.model, decisions)
                bits = 0
                for v in result.violations:
                    bits |= _FLAG_OF[type(v)]
                src.append(row)
                masks.append(mask)
                after.append(result.after)
                flags.append(bits)
        return Expansion(
            enabled,
            goal,
            np.array(src, dtype=np.int64),
            np.array(masks, dtype=np.int64),
            np.array(after, dtype=np.int64).reshape(len(after), n, 2),
            np.array(flags, dtype=np.int64),
        )
