"""What the two compiled engines (:mod:`.compiled`, :mod:`.compiled_async`) share: the per-state kernels
of connectivity and the goal, the first pass's loop that fills the caches from the model until every
answer is known, and the second pass's output arrays sized from the events each state offers."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields
from typing import Any, TypeVar

import numpy as np
from numba import njit

from ..goals.registry import KERNELS
from ..model.options import Goal

GOALS = {reading: KERNELS[reading.value] for reading in Goal}
"""The paper's three goals (the ``goal`` option's readings) as the kernels number them; every goal with a
kernel, ``point`` too, by name: :data:`fatline_verify.goals.registry.KERNELS`."""


# --- per-state kernels ----------------------------------------------------------------------------
@njit(cache=True)
def connected(pos: np.ndarray, view2: int, nbrs: np.ndarray) -> bool:
    """Whether the graph of pairs at squared distance at most ``view2`` is connected (``nbrs``: scratch)."""
    n = pos.shape[0]
    if n <= 1:
        return True
    for i in range(n):
        nbrs[i] = 0
    for i in range(n):
        for j in range(i + 1, n):
            dx = pos[i, 0] - pos[j, 0]
            dy = pos[i, 1] - pos[j, 1]
            if dx * dx + dy * dy <= view2:
                nbrs[i] |= 1 << j
                nbrs[j] |= 1 << i
    reach = 1
    while True:
        grown = reach
        for i in range(n):
            if (reach >> i) & 1:
                grown |= nbrs[i]
        if grown == reach:
            break
        reach = grown
    return reach == (1 << n) - 1


@njit(cache=True)
def at_goal(pos: np.ndarray, kind: int, width: int) -> bool:
    """:func:`~fatline_verify.model.lattice.goal_positions` of one state (``kind``: a goal's number in
    :data:`~fatline_verify.goals.registry.KERNELS`; 3 is ``point``; -1, a goal without a kernel: false here,
    judged after the kernel by :func:`fatline_verify.goals.registry.judge_batch`)."""
    n = pos.shape[0]
    if kind < 0:
        return False
    if kind == 3:
        same = True
        for i in range(1, n):
            same = same and pos[i, 0] == pos[0, 0] and pos[i, 1] == pos[0, 1]
        return same
    if kind == 0:
        same = True
        for i in range(1, n):
            same = same and pos[i, 0] == pos[0, 0]
        return same
    if n <= 2:
        return True
    distinct = 0
    for i in range(n):
        ci = pos[i, 0] * 1_000_003 + pos[i, 1]
        seen = False
        for j in range(i):
            if pos[j, 0] * 1_000_003 + pos[j, 1] == ci:
                seen = True
                break
        if not seen:
            distinct += 1
    if distinct < 3:
        return True
    for a in range(n):
        for b in range(n):
            abx = pos[b, 0] - pos[a, 0]
            aby = pos[b, 1] - pos[a, 1]
            if abx == 0 and aby == 0:
                continue
            limit = width * width * (abx * abx + aby * aby)
            line, nonneg, nonpos, near = True, True, True, True
            for c in range(n):
                cross = abx * (pos[c, 1] - pos[a, 1]) - aby * (pos[c, 0] - pos[a, 0])
                if cross != 0:
                    line = False
                if cross < 0:
                    nonneg = False
                if cross > 0:
                    nonpos = False
                if cross * cross > limit:
                    near = False
            if kind == 1 and line:
                return True
            if kind == 2 and (nonneg or nonpos) and near:
                return True
    return False


# --- pass 1: the caches filled until every answer is known -------------------------------------------
class Rows:
    """Per-state arrays of a first pass (a dataclass's fields, ``status`` among them: 0 where every answer
    was found in the caches)."""

    __slots__ = ()
    status: np.ndarray

    def put(self, rows: np.ndarray, other: Any) -> None:
        """Rows ``rows`` of every array from ``other`` (the same pass run again on those states)."""
        for f in fields(self):  # type: ignore[arg-type]
            getattr(self, f.name)[rows] = getattr(other, f.name)


R = TypeVar("R", bound=Rows)
M = TypeVar("M")


def settle(
    states: np.ndarray, run: Callable[[np.ndarray], tuple[R, M]], learn: Callable[[M], None], rounds: int, engine: str
) -> R:
    """Pass 1 to completion: ``run`` over ``states`` gives the rows and the keys missing from the caches;
    ``learn`` asks the model about those and fills the caches; ``run`` again on the states that had
    misses, at most ``rounds`` times (the answers of one round may uncover the keys of the next)."""
    result, misses = run(states)
    rows = np.arange(len(states))
    for _ in range(rounds):
        learn(misses)
        redo = rows[np.flatnonzero(result.status[rows])]
        if not len(redo):
            return result
        again, misses = run(states[redo])
        result.put(redo, again)
        rows = redo
    raise AssertionError(f"the {engine} engine's caches did not settle")  # pragma: no cover


# --- pass 2: one row an event ---------------------------------------------------------------------
@dataclass(slots=True)
class Events:
    """Pass 2's arrays: ``offsets[s]`` is state ``s``'s first event; per event its source state, action,
    flags, and either the state after (``after``) or its canonical key with the bound check (``keys``,
    ``fits``), the other left empty."""

    offsets: np.ndarray
    src: np.ndarray
    action: np.ndarray
    flags: np.ndarray
    after: np.ndarray
    keys: np.ndarray
    fits: np.ndarray

    @classmethod
    def empty(cls, counts: np.ndarray, row: tuple[int, ...], words: int | None, want_keys: bool) -> Events:
        """For ``counts[s]`` events of state ``s``: a state after is ``row`` int64s; a key is one int64
        (``words`` None) or ``words`` of them."""
        offsets = np.zeros(len(counts) + 1, dtype=np.int64)
        np.cumsum(counts, out=offsets[1:])
        t = int(offsets[-1])
        k = t if want_keys else 0
        return cls(
            offsets,
            np.empty(t, dtype=np.int64),
            np.empty(t, dtype=np.int64),
            np.empty(t, dtype=np.int64),
            np.empty((t - k, *row), dtype=np.int64),
            np.empty((k,) if words is None else (k, words), dtype=np.int64),
            np.empty(k, dtype=np.bool_),
        )


__all__ = ["GOALS", "Events", "Rows", "at_goal", "connected", "settle"]
