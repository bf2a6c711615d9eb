"""The reference engine: every state and every action through the executable model.

Slow and plain on purpose: each successor is the transition system's own executable step
(:meth:`~fatline_verify.schedulers.base.TransitionSystem.successors`), so the vectorised engines are tested
against exactly what ``fatline simulate`` and ``fatline replay`` do. One engine serves every system.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..schedulers.base import Expansion


class ScalarEngine:
    """Reference engine: the executable model, one state and one action at a time."""

    name = "scalar"

    def __init__(self, system: Any) -> None:
        self.system = system
        self.model = system.model

    def expand(self, states: np.ndarray) -> Expansion:
        system = self.system
        m, n, f = states.shape
        enabled = np.zeros(m, dtype=np.int64)
        goal = np.zeros(m, dtype=bool)
        src, actions, after, flags, exact = [], [], [], [], []
        blank = np.zeros((n, f), dtype=np.int64)
        for row in range(m):
            state = system.from_array(states[row])
            en, steps = system.successors(state)
            enabled[row] = en
            goal[row] = system.is_goal(state)
            for code, step in steps:
                arr = system.exact_array(step.target)
                bits = 0
                for v in step.violations:
                    bits |= v.lemma.flag
                src.append(row)
                actions.append(code)
                after.append(blank if arr is None else arr)
                flags.append(bits)
                exact.append(arr is not None)
        return Expansion(
            enabled,
            goal,
            np.array(src, dtype=np.int64),
            np.array(actions, dtype=np.int64),
            np.array(after, dtype=np.int64).reshape(len(after), n, f),
            np.array(flags, dtype=np.int64),
            np.array(exact, dtype=bool),
        )
