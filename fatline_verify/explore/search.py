"""Breadth-first search over canonical states, shared by every engine.

From all initial configurations at once, level by level. Within a level the new states are
numbered in key order and each one's parent is its least ``(source id, mask)`` transition, so state
ids, parent pointers and hence witnesses are the same whatever the engine, and every witness is a
shortest one. A state reached only through a violating round is not explored further (the
``after_violation="stop"`` semantics, counted in ``violating_only``); states that outgrow the window
are counted (``escaped``) and make liveness verdicts INCONCLUSIVE.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..config import Model
from .expand import Engine
from .lattice import KeyCodec, canonical


@dataclass(slots=True)
class Exploration:
    """The explored transition system (arrays indexed by state id / transition number)."""

    model: Model = field(repr=False)
    n: int
    window: tuple[int, int]
    engine: str
    n_initial: int
    states: np.ndarray = field(repr=False)
    keys: np.ndarray = field(repr=False)
    parent: np.ndarray = field(repr=False)
    parent_mask: np.ndarray = field(repr=False)
    depth: np.ndarray = field(repr=False)
    expanded: np.ndarray = field(repr=False)
    enabled: np.ndarray = field(repr=False)
    goal: np.ndarray = field(repr=False)
    edge_src: np.ndarray = field(repr=False)
    edge_dst: np.ndarray = field(repr=False)
    """Destination id, or -1 when the destination was not explored (outside the window, reached only
    through a violating round, or beyond the state bound)."""
    edge_mask: np.ndarray = field(repr=False)
    edge_flags: np.ndarray = field(repr=False)
    edge_fits: np.ndarray = field(repr=False)
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
        """Transitions from explored states to states outside the window."""
        return int((~self.edge_fits).sum())

    @property
    def violating_only(self) -> int:
        """Transitions whose destination was reached only through a violating round (not explored)."""
        return int(((self.edge_dst < 0) & self.edge_fits & (self.edge_flags != 0)).sum())

    def path(self, state_id: int) -> list[tuple[int, int]]:
        """``[(source id, mask), ...]`` from an initial state to ``state_id``."""
        steps = []
        while self.parent[state_id] >= 0:
            steps.append((int(self.parent[state_id]), int(self.parent_mask[state_id])))
            state_id = int(self.parent[state_id])
        return steps[::-1]

    def root(self, state_id: int) -> int:
        """The initial state a state's shortest path starts from."""
        while self.parent[state_id] >= 0:
            state_id = int(self.parent[state_id])
        return state_id


def explore(
    model: Model,
    initial: np.ndarray,
    window: tuple[int, int],
    engine: Engine,
    *,
    max_states: int = 1_000_000,
    after_violation: str = "stop",
    batch: int = 50_000,
    progress: Callable[[int, int, int, int], None] | None = None,
) -> Exploration:
    """Breadth-first search from every state of ``initial`` (canonical, sorted by key)."""
    m0, n, _ = initial.shape
    codec = KeyCodec(n, window)
    keys = [codec.encode(initial)]
    states = [initial]
    parent = [np.full(m0, -1, dtype=np.int64)]
    pmask = [np.zeros(m0, dtype=np.int64)]
    depth = [np.zeros(m0, dtype=np.int64)]
    enabled_parts, goal_parts = [], []
    e_src, e_key, e_mask, e_flags, e_fits = [], [], [], [], []
    visited = np.sort(keys[0])
    frontier_ids = np.arange(m0, dtype=np.int64)
    frontier = initial
    total = m0
    truncated = False
    level = 0
    while len(frontier):
        if total > max_states:
            truncated = True
            break
        lvl_src, lvl_mask, lvl_key, lvl_flags, lvl_fits = [], [], [], [], []
        for start in range(0, len(frontier), batch):
            chunk = frontier[start : start + batch]
            ex = engine.expand(chunk)
            enabled_parts.append(ex.enabled)
            goal_parts.append(ex.goal)
            canon, _ = canonical(ex.after) if len(ex.after) else (ex.after, None)
            fits = codec.fits(canon) if len(canon) else np.zeros(0, dtype=bool)
            k = np.full(len(canon), -1, dtype=np.int64)
            if fits.any():
                k[fits] = codec.encode(canon[fits])
            lvl_src.append(frontier_ids[start : start + batch][ex.src])
            lvl_mask.append(ex.mask)
            lvl_key.append(k)
            lvl_flags.append(ex.flags)
            lvl_fits.append(fits)
            if progress:
                progress(level, start + len(chunk), len(frontier), total)
        src, mask, key = np.concatenate(lvl_src), np.concatenate(lvl_mask), np.concatenate(lvl_key)
        flags, fits = np.concatenate(lvl_flags), np.concatenate(lvl_fits)
        e_src.append(src)
        e_mask.append(mask)
        e_key.append(key)
        e_flags.append(flags)
        e_fits.append(fits)
        usable = fits if after_violation == "continue" else fits & (flags == 0)
        ck, cs, cm = key[usable], src[usable], mask[usable]
        order = np.lexsort((cm, cs, ck))
        ck, cs, cm = ck[order], cs[order], cm[order]
        first = np.ones(len(ck), dtype=bool)
        first[1:] = ck[1:] != ck[:-1]
        ck, cs, cm = ck[first], cs[first], cm[first]
        pos = np.searchsorted(visited, ck)
        pos = np.minimum(pos, len(visited) - 1)
        new = visited[pos] != ck
        ck, cs, cm = ck[new], cs[new], cm[new]
        level += 1
        new_ids = np.arange(total, total + len(ck), dtype=np.int64)
        frontier = codec.decode(ck)
        keys.append(ck)
        states.append(frontier)
        parent.append(cs)
        pmask.append(cm)
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
    edge_key = np.concatenate(e_key) if e_key else np.zeros(0, dtype=np.int64)
    by_key = np.argsort(all_keys)
    sorted_keys = all_keys[by_key]
    pos = np.minimum(np.searchsorted(sorted_keys, edge_key), len(sorted_keys) - 1)
    hit = (sorted_keys[pos] == edge_key) & (edge_key >= 0)
    edge_flags = np.concatenate(e_flags) if e_flags else np.zeros(0, dtype=np.int64)
    dst = np.where(hit, by_key[pos], -1)
    if after_violation == "stop":  # a destination reached through a violating round is not an edge of the search
        dst = np.where(edge_flags == 0, dst, -1)
    return Exploration(
        model=model,
        n=n,
        window=window,
        engine=engine.name,
        n_initial=m0,
        states=np.concatenate(states),
        keys=all_keys,
        parent=np.concatenate(parent),
        parent_mask=np.concatenate(pmask),
        depth=np.concatenate(depth),
        expanded=expanded,
        enabled=enabled,
        goal=goal,
        edge_src=np.concatenate(e_src) if e_src else np.zeros(0, dtype=np.int64),
        edge_dst=dst.astype(np.int64),
        edge_mask=np.concatenate(e_mask) if e_mask else np.zeros(0, dtype=np.int64),
        edge_flags=edge_flags,
        edge_fits=np.concatenate(e_fits) if e_fits else np.zeros(0, dtype=bool),
        truncated=truncated,
        after_violation=after_violation,
    )
