"""Breadth-first search over canonical states, shared by every engine and every number of shards.

From all initial configurations at once, level by level. Within a level the new states are
numbered in key order and each one's parent is its least ``(source id, action)`` transition, so state
ids, parent pointers and hence witnesses are the same whatever the engine and however many shards
(:mod:`.shard`) share the work, and every witness is a shortest one. A state reached only through a
violating step is not explored further (the ``after_violation="stop"`` semantics, counted in
``violating_only``); states that outgrow the exploration bound or leave the system's lattice are
counted (``escaped``, ``off_lattice``) and make liveness verdicts INCONCLUSIVE. States, keys and
actions are the transition system's (:class:`~fatline_verify.schedulers.base.TransitionSystem`); the
search knows nothing of schedulers.

Only packed keys and compact per-state and per-transition columns are kept; positions are decoded from
keys on demand (:meth:`Exploration.state_array`). The search stops cleanly, before the next level, when
it holds more than ``max_states`` states or its arrays more than ``max_bytes`` bytes.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from enum import Enum
from functools import partial
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from ..lemmas.registry import CORE_FLAGS
from ..model.config import Model
from ..resources import BYTES_PER_STATE, PEAK_FACTOR
from ..schedulers.base import Codec, Engine, TransitionSystem
from . import keys as keyset
from .engines import engine_for
from .shard import COLUMNS, Level, Shard, followed, owners

ProgressTick = Callable[[int, int, int, int], None]
"""``tick(level, done, frontier, states)``."""


class Limit(Enum):
    """What stopped a search before its frontier was empty."""

    NONE = "none"
    MAX_STATES = "max-states"
    MAX_MEMORY = "max-memory"


_STATE_COLUMNS = ("keys", "parent", "parent_action", "depth", "expanded", "enabled", "goal")
_EDGE_COLUMNS = ("edge_src", "edge_dst", "edge_action", "edge_flags", "edge_fits", "edge_exact")


@dataclass(slots=True)
class Exploration:
    """The explored transition system (arrays indexed by state id / transition number)."""

    model: Model = field(repr=False)
    system: TransitionSystem = field(repr=False)
    n: int
    window: tuple[int, int]
    """The exploration bound (the codec's window)."""
    engine: str
    n_initial: int
    codec: Codec = field(repr=False)
    keys: np.ndarray = field(repr=False)
    parent: np.ndarray = field(repr=False)
    parent_action: np.ndarray = field(repr=False)
    depth: np.ndarray = field(repr=False)
    expanded: np.ndarray = field(repr=False)
    enabled: np.ndarray = field(repr=False)
    goal: np.ndarray = field(repr=False)
    edge_src: np.ndarray = field(repr=False)
    edge_dst: np.ndarray = field(repr=False)
    """Destination id, or -1 when the destination was not explored (outside the bound, off the
    lattice, reached only through a violating step, or beyond a limit)."""
    edge_action: np.ndarray = field(repr=False)
    """The step's action code, in the source state's canonical robot order."""
    edge_flags: np.ndarray = field(repr=False)
    edge_fits: np.ndarray = field(repr=False)
    """The destination is on the lattice and inside the bound."""
    edge_exact: np.ndarray = field(repr=False)
    """The destination is on the system's lattice (``False``: counted in :attr:`off_lattice`)."""
    limit: Limit = Limit.NONE
    after_violation: str = "stop"
    needed_bytes: int = 0
    """When stopped by ``max_bytes``: the peak the next level was projected to need (held arrays plus
    the next level's estimate, times :data:`~fatline_verify.resources.PEAK_FACTOR`)."""
    initial_window: tuple[int, int] | None = None
    """The window the initial configurations came from, when not the bound."""

    @property
    def start_window(self) -> tuple[int, int]:
        return self.window if self.initial_window is None else self.initial_window

    @property
    def truncated(self) -> bool:
        return self.limit is not Limit.NONE

    @property
    def n_states(self) -> int:
        return len(self.keys)

    @property
    def n_transitions(self) -> int:
        return len(self.edge_src)

    @property
    def escaped(self) -> int:
        """Transitions from explored states to states outside the bound or off the lattice."""
        return int((~self.edge_fits).sum())

    @property
    def off_lattice(self) -> int:
        """Transitions to states whose positions leave the system's lattice (ASYNC: a K-fine step)."""
        return int((~self.edge_exact).sum())

    @property
    def violating_only(self) -> int:
        """Violating transitions (within the bound) whose destination no followed transition reaches, so it
        is not explored: a count of transitions, not of states (two may lead to one state)."""
        return int(((self.edge_dst < 0) & self.edge_fits & ((self.edge_flags & CORE_FLAGS) != 0)).sum())

    @property
    def nbytes(self) -> int:
        """Bytes held by the exploration's arrays."""
        return sum(int(getattr(self, f).nbytes) for f in (*_STATE_COLUMNS, *_EDGE_COLUMNS))

    @property
    def states(self) -> np.ndarray:
        """Every state's canonical array, decoded (small searches; large ones use :meth:`state_array`)."""
        return self.codec.decode(self.keys)

    def state_array(self, ids: np.ndarray | int) -> np.ndarray:
        """The canonical array states of ``ids`` (one state for an int), decoded from their keys."""
        if isinstance(ids, int | np.integer):
            return self.codec.decode(self.keys[[int(ids)]])[0]
        return self.codec.decode(self.keys[ids])

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


# --- shard pools --------------------------------------------------------------------------------------


class LocalShards:
    """P shards in this process, run one after another (P = 1 is the plain search)."""

    def __init__(self, shards: list[Shard]) -> None:
        self.shards = shards

    @property
    def count(self) -> int:
        return len(self.shards)

    def map(self, method: str, args: list[tuple[Any, ...]]) -> list[Any]:
        return [getattr(s, method)(*a) for s, a in zip(self.shards, args, strict=True)]

    def close(self) -> None:
        pass


class ShardPool(Protocol):
    """What :func:`explore_keys` needs of its shards: ``count``, ``map(method, per-shard args)`` and
    ``close()``. :class:`LocalShards` and :class:`.workers.DaskShards` implement it."""

    @property
    def count(self) -> int: ...

    def map(self, method: str, args: list[tuple[Any, ...]]) -> list[Any]: ...

    def close(self) -> None: ...


# --- the search ---------------------------------------------------------------------------------------


@dataclass(slots=True)
class _Records:
    """The coordinator's growing columns, one list entry per level (keys/parents) or per expansion."""

    keys: list[np.ndarray] = field(default_factory=list)
    parent: list[np.ndarray] = field(default_factory=list)
    paction: list[np.ndarray] = field(default_factory=list)
    ids: list[np.ndarray] = field(default_factory=list)
    enabled: list[np.ndarray] = field(default_factory=list)
    goal: list[np.ndarray] = field(default_factory=list)
    src: list[np.ndarray] = field(default_factory=list)
    action: list[np.ndarray] = field(default_factory=list)
    key: list[np.ndarray] = field(default_factory=list)
    flags: list[np.ndarray] = field(default_factory=list)
    fits: list[np.ndarray] = field(default_factory=list)
    exact: list[np.ndarray] = field(default_factory=list)

    def nbytes(self) -> int:
        return sum(int(a.nbytes) for name in self.__slots__ for a in getattr(self, name))

    def add_level(self, keys: np.ndarray, parent: np.ndarray, paction: np.ndarray) -> None:
        self.keys.append(keys)
        self.parent.append(parent)
        self.paction.append(paction)

    def add_expansion(self, lv: Level) -> None:
        """One level's expansion (already compacted by the shard: int32 ids and actions, uint8 flags)."""
        self.add_expansion_arrays(
            lv.ids, lv.enabled, lv.goal, lv.src, lv.action, lv.key, lv.flags, lv.fits, lv.exact
        )  # fmt: skip

    def add_expansion_arrays(self, *arrays: np.ndarray) -> None:
        """The columns of one expansion in :data:`.shard.COLUMNS` order."""
        for name, a in zip(COLUMNS, arrays, strict=True):
            getattr(self, name).append(a)


def _merge_levels(parts: list[Level], after_violation: str) -> Level:
    """The shards' expansions of one level as one, transitions in (source id, action) order."""
    if len(parts) == 1:
        return parts[0]
    cat = np.concatenate
    ids = cat([p.ids for p in parts])
    by_id = np.argsort(ids, kind="stable")
    src = cat([p.src for p in parts])
    by_src = np.argsort(src, kind="stable")  # each source lives in one shard, actions already ascending

    def edges(name: str) -> np.ndarray:
        return cat([getattr(p, name) for p in parts])[by_src]  # type: ignore[no-any-return]

    flags, fits = cat([p.flags for p in parts]), cat([p.fits for p in parts])
    follow = followed(fits, flags, after_violation)
    keys = np.zeros(len(src), dtype=parts[0].key.dtype)
    keys[follow] = cat([p.key for p in parts])
    return Level(
        ids[by_id],
        cat([p.enabled for p in parts])[by_id],
        cat([p.goal for p in parts])[by_id],
        src[by_src],
        edges("action"),
        keys[by_src][follow[by_src]],
        flags[by_src],
        fits[by_src],
        edges("exact"),
        [],
    )


def explore(
    system: TransitionSystem,
    initial: np.ndarray,
    window: tuple[int, int],
    engine: Engine | str,
    **options: Any,
) -> Exploration:
    """Breadth-first search from every state of ``initial`` (canonical array states of ``system``),
    bounded by ``window``; ``options`` as :func:`explore_keys`."""
    n = initial.shape[1]
    codec = system.codec(n, window)
    return explore_keys(system, n, np.sort(codec.encode(initial)), window, engine, **options)


def explore_keys(
    system: TransitionSystem,
    n: int,
    initial: np.ndarray,
    bound: tuple[int, int],
    engine: Engine | str,
    *,
    max_states: int | None = 1_000_000,
    max_bytes: int | None = None,
    after_violation: str = "stop",
    batch: int = 50_000,
    progress: ProgressTick | None = None,
    pool: ShardPool | None = None,
    checkpoint: Path | None = None,
    initial_window: tuple[int, int] | None = None,
) -> Exploration:
    """Breadth-first search from the sorted keys ``initial`` (in ``system.codec(n, bound)``).

    ``pool`` shares the work among shards (default: one in this process, running ``engine``);
    ``checkpoint`` is a directory the search saves itself to after every level and resumes from.
    """
    from .checkpoint import Checkpoint

    codec = system.codec(n, bound)
    engine_name = engine if isinstance(engine, str) else engine.name
    own_pool = pool is None
    if pool is None:
        eng = engine_for(system, engine) if isinstance(engine, str) else engine
        pool = LocalShards([Shard(system, n, bound, eng, 0, 1, after_violation)])
    count = pool.count
    rec = _Records()
    saved = Checkpoint(checkpoint, system.model, n, bound, initial, after_violation)
    if not saved.load(rec):
        rec.add_level(initial, np.full(len(initial), -1, dtype=np.int64), np.zeros(len(initial), dtype=np.int32))
        saved.start(rec)
    visited = np.concatenate(rec.keys)
    frontier = rec.keys[-1]
    frontier_ids = np.arange(len(visited) - len(frontier), len(visited), dtype=np.int64)
    limit, needed = Limit.NONE, 0
    owner_all, owner_front = owners(visited, count), owners(frontier, count)
    pool.map(
        "seed",
        [
            (np.sort(visited[owner_all == o]), frontier[owner_front == o], frontier_ids[owner_front == o])
            for o in range(count)
        ],
    )
    total = sum(len(k) for k in rec.keys)
    level = len(rec.keys) - 1
    while len(frontier) and limit is Limit.NONE:
        held = rec.nbytes() + sum(pool.map("visited_bytes", [()] * count))
        if max_states is not None and total > max_states:
            limit = Limit.MAX_STATES
            break
        projected = int((held + _next_level_estimate(rec, len(frontier))) * PEAK_FACTOR)
        if max_bytes is not None and projected > max_bytes:
            limit, needed = Limit.MAX_MEMORY, projected
            break
        if progress and isinstance(pool, LocalShards) and count == 1:
            lv_parts = [pool.shards[0].expand(batch, partial(_tick, progress, level, total))]
        else:
            lv_parts = pool.map("expand", [(batch,)] * count)
        lv = _merge_levels(lv_parts, after_violation)
        rec.add_expansion(lv)
        merged = pool.map("merge", [([p.routed[o] for p in lv_parts],) for o in range(count)])
        new_keys = np.concatenate([m[0] for m in merged])
        new_src = np.concatenate([m[1] for m in merged])
        new_act = np.concatenate([m[2] for m in merged])
        order = np.argsort(new_keys, kind="stable") if count > 1 else np.arange(len(new_keys))
        rank = np.empty(len(order), dtype=np.int64)
        rank[order] = np.arange(len(order), dtype=np.int64)
        new_ids = total + rank
        bounds = np.cumsum([0] + [len(m[0]) for m in merged])
        pool.map("assign", [(new_ids[bounds[o] : bounds[o + 1]],) for o in range(count)])
        frontier = new_keys[order]
        rec.add_level(frontier, new_src[order], new_act[order].astype(np.int32))
        level += 1
        total += len(frontier)
        saved.save_level(rec, level)
        if progress:
            progress(level, len(frontier), len(frontier), total)
    if own_pool:
        pool.close()
    ex = _build(system, n, bound, engine_name, codec, rec, limit, needed, after_violation)
    ex.initial_window = None if initial_window == bound else initial_window
    return ex


def _tick(progress: ProgressTick, level: int, states: int, done: int, frontier: int) -> None:
    progress(level, done, frontier, states)


def _next_level_estimate(rec: _Records, frontier: int) -> int:
    """Bytes the next level will add: the last level's bytes per expanded state times the frontier."""
    if not rec.ids:
        return BYTES_PER_STATE * frontier
    last = sum(int(getattr(rec, f)[-1].nbytes) for f in ("ids", "enabled", "goal", "src", "action", "key"))
    last += sum(int(getattr(rec, f)[-1].nbytes) for f in ("flags", "fits", "exact"))
    per_state = last / max(1, len(rec.ids[-1])) + 3 * (rec.keys[-1].itemsize + 12)
    return int(per_state * frontier)


def _build(
    system: TransitionSystem,
    n: int,
    bound: tuple[int, int],
    engine_name: str,
    codec: Codec,
    rec: _Records,
    limit: Limit,
    needed: int,
    after_violation: str,
) -> Exploration:
    """The finished search as one :class:`Exploration` (destination ids looked up by key)."""

    def take(name: str, dtype: Any) -> np.ndarray:
        """Concatenate one column and let go of its parts (the peak stays near the finished arrays)."""
        parts = getattr(rec, name)
        out = np.concatenate(parts) if parts else np.zeros(0, dtype=dtype)
        parts.clear()
        return out  # type: ignore[no-any-return]

    n_initial = len(rec.keys[0])
    depth = np.concatenate([np.full(len(k), d, dtype=np.int32) for d, k in enumerate(rec.keys)])
    all_keys = take("keys", codec.dtype)
    total = len(all_keys)
    id_type = np.int32 if total < 2**31 - 1 else np.int64
    n_expanded = sum(len(i) for i in rec.ids)
    expanded = np.zeros(total, dtype=bool)
    expanded[:n_expanded] = True
    enabled = np.zeros(total, dtype=np.int32)
    goal = np.zeros(total, dtype=bool)
    enabled[:n_expanded] = take("enabled", np.int32)
    goal[:n_expanded] = take("goal", bool)
    rec.ids.clear()
    edge_fits = take("fits", bool)
    edge_flags = take("flags", np.uint8)
    # Only the transitions the search follows have a destination id (a violating one's is -1 under "stop").
    wanted = np.nonzero(followed(edge_fits, edge_flags, after_violation))[0]
    looked = take("key", codec.dtype)
    by_key = keyset.argsort(all_keys)
    pos = np.minimum(keyset.searchsorted(all_keys[by_key], looked), total - 1)
    hit = all_keys[by_key[pos]] == looked
    dst = np.full(len(edge_fits), -1, dtype=id_type)
    dst[wanted[hit]] = by_key[pos[hit]]
    del by_key, pos, hit, looked, wanted
    return Exploration(
        model=system.model,
        system=system,
        n=n,
        window=bound,
        engine=engine_name,
        n_initial=n_initial,
        codec=codec,
        keys=all_keys,
        parent=take("parent", np.int64).astype(id_type),
        parent_action=take("paction", np.int32),
        depth=depth,
        expanded=expanded,
        enabled=enabled,
        goal=goal,
        edge_src=take("src", np.int64).astype(id_type, copy=False),
        edge_dst=dst,
        edge_action=take("action", np.int32),
        edge_flags=edge_flags,
        edge_fits=edge_fits,
        edge_exact=take("exact", bool),
        limit=limit,
        after_violation=after_violation,
        needed_bytes=needed,
    )


__all__ = ["Exploration", "Limit", "LocalShards", "ShardPool", "explore", "explore_keys"]
