"""Breadth-first search over canonical states, shared by every engine.

From all initial configurations at once, level by level. Within a level the new states are
numbered in key order and each one's parent is its least ``(source id, mask)`` transition, so state
ids, parent pointers and hence witnesses are the same whatever the engine, and every witness is a
shortest one. A state reached only through a violating step is not explored further (the
``after_violation="stop"`` semantics, counted in ``violating_only``); states that outgrow the window
or leave the system's lattice are counted (``escaped``, ``off_lattice``) and make liveness verdicts
INCONCLUSIVE. States, keys and actions are the transition system's
(:class:`~fatline_verify.systems.base.TransitionSystem`); the search knows nothing of schedulers.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..config import Model
from ..systems.base import Engine, TransitionSystem


@dataclass(slots=True)
class Exploration:
    """The explored transition system (arrays indexed by state id / transition number)."""

    model: Model = field(repr=False)
    system: TransitionSystem = field(repr=False)
    n: int
    window: tuple[int, int]
    engine: str
    n_initial: int
    states: np.ndarray = field(repr=False)
    keys: np.ndarray = field(repr=False)
    parent: np.ndarray = field(repr=False)
    parent_action: np.ndarray = field(repr=False)
    depth: np.ndarray = field(repr=False)
    expanded: np.ndarray = field(repr=False)
    enabled: np.ndarray = field(repr=False)
    goal: np.ndarray = field(repr=False)
    edge_src: np.ndarray = field(repr=False)
    edge_dst: np.ndarray = field(repr=False)
    """Destination id, or -1 when the destination was not explored (outside the window, off the
    lattice, reached only through a violating step, or beyond the state bound)."""
    edge_action: np.ndarray = field(repr=False)
    """The step's action code, in the source state's canonical robot order."""
    edge_flags: np.ndarray = field(repr=False)
    edge_fits: np.ndarray = field(repr=False)
    """The destination is on the lattice and inside the window."""
    edge_exact: np.ndarray = field(repr=False)
    """The destination is on the system's lattice (``False``: counted in :attr:`off_lattice`)."""
    truncated: bool = False
    after_violation: str = "stop"

    @property
    def n_states(self) -> int:
        return len(self.keys)

    @property
    def n_transitions(self) -> int:
        return len(self.edge_src)

    @property
    def escaped(self) -> int:
        """Transitions from explored states to states outside the window or off the lattice."""
        return int((~self.edge_fits).sum())

    @property
    def off_lattice(self) -> int:
        """Transitions to states whose positions leave the system's lattice (ASYNC: a K-fine step)."""
        return int((~self.edge_exact).sum())

    @property
    def violating_only(self) -> int:
        """Transitions whose destination was reached only through a violating round (not explored)."""
        return int(((self.edge_dst < 0) & self.edge_fits & (self.edge_flags != 0)).sum())

    def path(self, state_id: int) -> list[tuple[int, int]]:
        """``[(source id, action), ...]`` from an initial state to ``state_id``."""
        steps = []
        while self.parent[state_id] >= 0:
            steps.append((int(self.parent[state_id]), int(self.parent_action[state_id])))
            state_id = int(self.parent[state_id])
        return steps[::-1]

    def root(self, state_id: int) -> int:
        """The initial state a state's shortest path starts from."""
        while self.parent[state_id] >= 0:
            state_id = int(self.parent[state_id])
        return state_id


def explore(
    system: TransitionSystem,
    initial: np.ndarray,
    window: tuple[int, int],
    engine: Engine,
    *,
    max_states: int = 1_000_000,
    after_violation: str = "stop",
    batch: int = 50_000,
    progress: Callable[[int, int, int, int], None] | None = None,
) -> Exploration:
    """Breadth-first search from every state of ``initial`` (canonical array states of ``system``)."""
    m0, n, nf = initial.shape
    codec = system.codec(n, window)
    keys0 = codec.encode(initial)
    first_order = np.argsort(keys0, kind="stable")
    initial, keys0 = initial[first_order], keys0[first_order]
    keys = [keys0]
    states = [initial]
    parent = [np.full(m0, -1, dtype=np.int64)]
    paction = [np.zeros(m0, dtype=np.int64)]
    depth = [np.zeros(m0, dtype=np.int64)]
    enabled_parts, goal_parts = [], []
    e_src, e_key, e_action, e_flags, e_fits, e_exact = [], [], [], [], [], []
    visited = keys0.copy()
    frontier_ids = np.arange(m0, dtype=np.int64)
    frontier = initial
    total = m0
    truncated = False
    level = 0
    while len(frontier):
        if total > max_states:
            truncated = True
            break
        lvl_src, lvl_action, lvl_key, lvl_flags, lvl_fits, lvl_exact = [], [], [], [], [], []
        for start in range(0, len(frontier), batch):
            chunk = frontier[start : start + batch]
            ex = engine.expand(chunk)
            enabled_parts.append(ex.enabled)
            goal_parts.append(ex.goal)
            canon, _ = system.canonical(ex.after) if len(ex.after) else (ex.after, None)
            fits = (codec.fits(canon) & ex.exact) if len(canon) else np.zeros(0, dtype=bool)
            k = np.zeros(len(canon), dtype=codec.dtype)
            if fits.any():
                k[fits] = codec.encode(canon[fits])
            lvl_src.append(frontier_ids[start : start + batch][ex.src])
            lvl_action.append(ex.action)
            lvl_key.append(k)
            lvl_flags.append(ex.flags)
            lvl_fits.append(fits)
            lvl_exact.append(ex.exact)
            if progress:
                progress(level, start + len(chunk), len(frontier), total)
        src, action, key = np.concatenate(lvl_src), np.concatenate(lvl_action), np.concatenate(lvl_key)
        flags, fits = np.concatenate(lvl_flags), np.concatenate(lvl_fits)
        e_src.append(src)
        e_action.append(action)
        e_key.append(key)
        e_flags.append(flags)
        e_fits.append(fits)
        e_exact.append(np.concatenate(lvl_exact))
        usable = fits if after_violation == "continue" else fits & (flags == 0)
        ck, cs, ca = key[usable], src[usable], action[usable]
        order = np.lexsort((ca, cs, ck))
        ck, cs, ca = ck[order], cs[order], ca[order]
        first = np.ones(len(ck), dtype=bool)
        first[1:] = ck[1:] != ck[:-1]
        ck, cs, ca = ck[first], cs[first], ca[first]
        pos = np.searchsorted(visited, ck)
        pos = np.minimum(pos, len(visited) - 1)
        new = visited[pos] != ck
        ck, cs, ca = ck[new], cs[new], ca[new]
        level += 1
        new_ids = np.arange(total, total + len(ck), dtype=np.int64)
        frontier = codec.decode(ck) if len(ck) else np.zeros((0, n, nf), dtype=np.int64)
        keys.append(ck)
        states.append(frontier)
        parent.append(cs)
        paction.append(ca)
        depth.append(np.full(len(ck), level, dtype=np.int64))
        visited = np.sort(np.concatenate([visited, ck]))
        frontier_ids = new_ids
        total += len(ck)

    all_keys = np.concatenate(keys)
    n_expanded = sum(len(p) for p in enabled_parts)
    expanded = np.zeros(total, dtype=bool)
    expanded[:n_expanded] = True
    enabled = np.zeros(total, dtype=np.int64)
    goal = np.zeros(total, dtype=bool)
    if n_expanded:
        enabled[:n_expanded] = np.concatenate(enabled_parts)
        goal[:n_expanded] = np.concatenate(goal_parts)
    edge_key = np.concatenate(e_key) if e_key else np.zeros(0, dtype=codec.dtype)
    edge_fits = np.concatenate(e_fits) if e_fits else np.zeros(0, dtype=bool)
    by_key = np.argsort(all_keys, kind="stable")
    sorted_keys = all_keys[by_key]
    pos = np.minimum(np.searchsorted(sorted_keys, edge_key), len(sorted_keys) - 1)
    hit = (sorted_keys[pos] == edge_key) & edge_fits
    edge_flags = np.concatenate(e_flags) if e_flags else np.zeros(0, dtype=np.int64)
    dst = np.where(hit, by_key[pos], -1)
    if after_violation == "stop":  # a destination reached through a violating step is not an edge of the search
        dst = np.where(edge_flags == 0, dst, -1)
    return Exploration(
        model=system.model,
        system=system,
        n=n,
        window=window,
        engine=engine.name,
        n_initial=m0,
        states=np.concatenate(states),
        keys=all_keys,
        parent=np.concatenate(parent),
        parent_action=np.concatenate(paction),
        depth=np.concatenate(depth),
        expanded=expanded,
        enabled=enabled,
        goal=goal,
        edge_src=np.concatenate(e_src) if e_src else np.zeros(0, dtype=np.int64),
        edge_dst=dst.astype(np.int64),
        edge_action=np.concatenate(e_action) if e_action else np.zeros(0, dtype=np.int64),
        edge_flags=edge_flags,
        edge_fits=edge_fits,
        edge_exact=np.concatenate(e_exact) if e_exact else np.zeros(0, dtype=bool),
        truncated=truncated,
        after_violation=after_violation,
    )
