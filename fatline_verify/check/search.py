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

The compact store (docs/checker.md, "The compact store"): per state only its packed key, parent,
parent action, enabled robots and goal are kept (depth and "expanded" follow from the level sizes);
transitions are folded, batch by batch, into per-level summaries (their counts and, per violation flag
bit, the least violating ``(source id, action)``), which is all a safety verdict needs; witnesses
follow parents; the fair-cycle search recomputes the transitions it needs with the search's engine
(:meth:`Exploration.followed_edges`), and so do the ``edge_*`` columns, on demand. Positions are
decoded from keys on demand (:meth:`Exploration.state_array`). The search stops cleanly, before the
next level, when it holds more than ``max_states`` states. Under ``max_bytes`` the memory guard
(:mod:`.guard`) watches each level's real figures as it runs: when they say the level fits only with
the levels on disk, the levels move there (raw column files read back as memory maps, TLC's
disk-backed state set being the model): the same results, less memory; when even then they do not
fit, the level stops before the step that would pass the budget and the search ends there, as if
stopped before the level.
"""

from __future__ import annotations

import shutil
import tempfile
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from ..resources import PEAK_FACTOR
from ..schedulers.base import Codec, Engine, TransitionSystem
from . import guard
from .engines import engine_for
from .exploration import Exploration, Limit
from .shard import COLUMNS, Level, Shard, enabled_dtype, fold_summaries, owners

ProgressTick = Callable[[int, int, int, int], None]
"""``tick(level, done, frontier, states)``."""


class LocalShards:
    """P shards in this process, run one after another (P = 1 is the plain search)."""

    def __init__(self, shards: list[Shard]) -> None:
        self.shards = shards

    @property
    def count(self) -> int:
        return len(self.shards)

    def map(self, method: str, args: list[tuple[Any, ...]]) -> list[Any]:
        return [getattr(s, method)(*a) for s, a in zip(self.shards, args, strict=True)]

    def call(self, index: int, method: str, args: tuple[Any, ...]) -> Any:
        return getattr(self.shards[index], method)(*args)

    def close(self) -> None:
        pass


class ShardPool(Protocol):
    """What :func:`explore_keys` needs of its shards: ``count``, ``map(method, per-shard args)`` (every
    shard at once), ``call(index, method, args)`` (one shard, waited for) and ``close()``.
    :class:`LocalShards` and :class:`.workers.DaskShards` implement it."""

    @property
    def count(self) -> int: ...

    def map(self, method: str, args: list[tuple[Any, ...]]) -> list[Any]: ...

    def call(self, index: int, method: str, args: tuple[Any, ...]) -> Any: ...

    def close(self) -> None: ...


# --- the search ---------------------------------------------------------------------------------------


class _Disk:
    """A directory of raw column files, each read back as a read-only memory map and unlinked at once
    (the map keeps its pages; the kernel may drop them and read them again), removed with the search."""

    def __init__(self) -> None:
        self.directory = Path(tempfile.mkdtemp(prefix="fatline-levels-"))
        self._count = 0
        self._finalizer = weakref.finalize(self, shutil.rmtree, self.directory, True)

    def _path(self) -> Path:
        self._count += 1
        return self.directory / f"column-{self._count:06d}.bin"

    def put(self, a: np.ndarray) -> np.ndarray:
        """``a`` as a memory map of a file holding its bytes (an empty array stays as it is)."""
        if not len(a) or isinstance(a, np.memmap):
            return a
        path = self._path()
        np.ascontiguousarray(a).tofile(path)
        out = np.memmap(path, dtype=a.dtype, mode="r", shape=a.shape)
        path.unlink()
        return out

    def join(self, parts: list[np.ndarray], dtype: Any) -> np.ndarray:
        """The concatenation of ``parts``, written part by part into one mapped file."""
        total = sum(len(p) for p in parts)
        if not total:
            return np.zeros(0, dtype=dtype)
        path = self._path()
        out = np.memmap(path, dtype=dtype, mode="w+", shape=(total,))
        at = 0
        for p in parts:
            out[at : at + len(p)] = p
            at += len(p)
        out.flush()
        path.unlink()
        return out


def _in_memory(a: np.ndarray) -> int:
    return 0 if isinstance(a, np.memmap) else int(a.nbytes)


@dataclass(slots=True)
class _Records:
    """The coordinator's growing columns, one list entry per level (keys, parents) or per expansion
    (enabled, goal, the summary of its transitions)."""

    keys: list[np.ndarray] = field(default_factory=list)
    parent: list[np.ndarray] = field(default_factory=list)
    paction: list[np.ndarray] = field(default_factory=list)
    enabled: list[np.ndarray] = field(default_factory=list)
    goal: list[np.ndarray] = field(default_factory=list)
    summary: list[np.ndarray] = field(default_factory=list)
    disk: _Disk | None = None

    def nbytes(self) -> int:
        """Bytes held in memory (columns moved to disk not counted)."""
        return sum(_in_memory(a) for name in _RECORD_COLUMNS for a in getattr(self, name))

    def _put(self, a: np.ndarray) -> np.ndarray:
        return a if self.disk is None else self.disk.put(a)

    def add_level(self, keys: np.ndarray, parent: np.ndarray, paction: np.ndarray) -> None:
        id_type = np.int32 if len(parent) == 0 or int(parent.max()) < 2**31 - 1 else np.int64
        self.keys.append(self._put(keys))
        self.parent.append(self._put(parent.astype(id_type, copy=False)))
        self.paction.append(self._put(paction.astype(np.int32, copy=False)))

    def add_expansion(self, lv: Level) -> None:
        """One level's expansion: per state enabled and goal, and the summary of its transitions."""
        self.add_expansion_arrays(lv.enabled, lv.goal, lv.summary)

    def add_expansion_arrays(self, *arrays: np.ndarray) -> None:
        """The columns of one expansion in :data:`.shard.COLUMNS` order."""
        for name, a in zip(COLUMNS, arrays, strict=True):
            getattr(self, name).append(a if name == "summary" else self._put(a))

    def to_disk(self) -> None:
        """Move every level's columns to disk, and the levels to come."""
        if self.disk is None:
            self.disk = _Disk()
        for name in _RECORD_COLUMNS:
            parts = getattr(self, name)
            parts[:] = [self.disk.put(a) for a in parts]


_RECORD_COLUMNS = ("keys", "parent", "paction", "enabled", "goal")


def _merge_levels(parts: list[Level], n: int) -> Level:
    """The shards' expansions of one level as one: states in id order, summaries folded."""
    if len(parts) == 1:
        return parts[0]
    ids = np.concatenate([p.ids for p in parts])
    by_id = np.argsort(ids, kind="stable")
    enabled = np.concatenate([p.enabled for p in parts]).astype(enabled_dtype(n), copy=False)
    return Level(
        ids[by_id],
        enabled[by_id],
        np.concatenate([p.goal for p in parts])[by_id],
        fold_summaries([p.summary for p in parts]),
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
    on_disk: bool = False,
) -> Exploration:
    """Breadth-first search from the sorted keys ``initial`` (in ``system.codec(n, bound)``).

    ``pool`` shares the work among shards (default: one in this process, running ``engine``);
    ``checkpoint`` is a directory the search saves itself to after every level and resumes from;
    ``on_disk`` keeps the levels on disk from the start (otherwise ``max_bytes`` decides).
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
    if on_disk:
        rec.to_disk()
    saved = Checkpoint(checkpoint, system.model, n, bound, initial, after_violation)
    if not saved.load(rec):
        rec.add_level(initial, np.full(len(initial), -1, dtype=np.int64), np.zeros(len(initial), dtype=np.int32))
        saved.start(rec)
    visited = np.concatenate(rec.keys) if len(rec.keys) > 1 else np.asarray(rec.keys[0])
    frontier = np.asarray(rec.keys[-1])
    frontier_ids = _id_range(len(visited) - len(frontier), len(visited))
    limit, needed = Limit.NONE, 0
    if count == 1:  # no copies: the shard's visited set is sorted keys, the frontier its last level
        pool.map("seed", [(np.sort(visited) if len(rec.keys) > 1 else visited, frontier, frontier_ids)])
    else:
        owner_all = owners(visited, count)
        initial_level = len(frontier) == len(visited)  # the initial level is the whole visited set, sorted
        owner_front = owner_all if initial_level else owners(frontier, count)
        for o in range(count):  # one shard at a time: one shard's copy of its keys in flight, not all
            mine = visited[owner_all == o]
            front = None if initial_level else frontier[owner_front == o]  # None: the shard's visited set
            pool.call(o, "seed", (mine if initial_level else np.sort(mine), front, frontier_ids[owner_front == o]))
            del mine, front
        del owner_all, owner_front
    del visited
    total = sum(len(k) for k in rec.keys)
    level = len(rec.keys) - 1
    while len(frontier) and limit is Limit.NONE:
        if max_states is not None and total > max_states:
            limit = Limit.MAX_STATES
            break
        room, spill = None, None
        if max_bytes is not None:
            start = total - len(frontier)  # a level's ids follow its keys' order
            ids = np.arange(start, total, dtype=np.int64)
            room, need, spill = _guard(pool, rec, frontier, ids, max_bytes, codec.dtype.itemsize, batch)
            del ids
            if room is None:
                limit, needed = Limit.MAX_MEMORY, need
                break
        if progress and isinstance(pool, LocalShards) and count == 1:
            lv_parts = [pool.shards[0].expand(batch, partial(_tick, progress, level, total), room, spill)]
        else:  # the shards run elsewhere: the line names the level they expand (done when they return)
            if progress:
                progress(level, 0, len(frontier), total)
            lv_parts = pool.map("expand", [(batch, None, room) + ((spill,) if spill else ())] * count)
        if any(p.needed for p in lv_parts):  # a shard's real figures passed its share of the budget
            level_need = count * max(p.needed for p in lv_parts)
            limit, needed = Limit.MAX_MEMORY, int((_held(pool, rec, frontier)[0] + level_need) * PEAK_FACTOR)
            break
        lv = _merge_levels(lv_parts, n)
        rec.add_expansion(lv)
        merged = pool.map("merge", [([p.routed[o] for p in lv_parts],) for o in range(count)])
        new_keys, new_src, new_act = (  # one shard: its arrays as they are (the frontier it keeps is these keys)
            merged[0] if count == 1 else tuple(np.concatenate([m[k] for m in merged]) for k in range(3))
        )
        bounds = np.cumsum([0] + [len(m[0]) for m in merged])
        del merged, lv_parts, lv
        if count > 1:
            order = np.argsort(new_keys, kind="stable")
            rank = np.empty(len(order), dtype=np.int64)
            rank[order] = np.arange(len(order), dtype=np.int64)
            new_ids = total + rank
            pool.map("assign", [(new_ids[bounds[o] : bounds[o + 1]],) for o in range(count)])
            frontier, new_src, new_act = new_keys[order], new_src[order], new_act[order]
            del order, rank, new_ids
        else:  # one shard: its new keys are sorted already
            pool.map("assign", [(_id_range(total, total + len(new_keys)),)])
            frontier = new_keys
        rec.add_level(frontier, new_src, new_act)
        level += 1
        total += len(frontier)
        saved.save_level(rec, level)
        if progress:
            progress(level, len(frontier), len(frontier), total)
    expander = None
    if own_pool:
        expander = pool.shards[0]  # type: ignore[attr-defined]
        if limit is Limit.NONE and hasattr(expander.engine, "save_answers"):
            expander.engine.save_answers()  # the model's answers, for the next run (:mod:`.answers`)
        expander.seed(np.zeros(0, dtype=codec.dtype), np.zeros(0, dtype=codec.dtype), np.zeros(0, dtype=np.int64))
        pool.close()
    ex = _build(system, n, bound, engine_name, codec, rec, limit, needed, after_violation)
    ex.initial_window = None if initial_window == bound else initial_window
    ex.expander = expander
    return ex


def _id_range(start: int, stop: int) -> np.ndarray:
    """The state ids ``start .. stop - 1`` of a frontier, in 32 bits where they fit (a shard's columns
    are int32 then too)."""
    return np.arange(start, stop, dtype=np.int32 if stop < 2**31 - 1 else np.int64)


def _tick(progress: ProgressTick, level: int, states: int, done: int, frontier: int) -> None:
    progress(level, done, frontier, states)


def _held(pool: ShardPool, rec: _Records, frontier: np.ndarray) -> tuple[int, int]:
    """The bytes the search holds in memory (its columns, the frontier, its shards' visited sets and
    frontiers: each buffer once, :func:`.guard.held_bytes`; shards in other processes as they report)
    and its states."""
    arrays = [frontier] + [a for name in _RECORD_COLUMNS for a in getattr(rec, name)]
    remote = 0
    if isinstance(pool, LocalShards):
        arrays += [a for s in pool.shards for a in (s.base, s.visited, s.frontier, s.frontier_ids)]
    else:
        remote = sum(pool.map("visited_bytes", [()] * pool.count))
    return guard.held_bytes(arrays) + remote, sum(len(k) for k in rec.keys)


def _guard(pool: ShardPool, rec: _Records, frontier: np.ndarray, frontier_ids: np.ndarray, max_bytes: int,
           key: int, batch: int) -> tuple[int | None, int, Callable[[], int] | None]:  # fmt: skip
    """Before a level (:mod:`.guard`): ``(room, projected, spill)``: what each shard's expansion may add
    (``None``: not even the level's fixed part fits, levels on disk; the search stops, ``projected``
    saying what a sample of the frontier measures the level to need); and,
    for shards in this process, ``spill``, which moves the levels to disk when the level's real figures
    say so (:class:`.guard.Watch`). Shards in other processes cannot: for them the levels move to disk
    before the level when it is priced above the budget, at a presumed rate and then at the rate a
    sample of the frontier measures."""
    count = pool.count
    local = isinstance(pool, LocalShards)
    held = partial(_held, pool, rec, frontier)

    def price() -> int:
        rates = guard.presumed(rec.summary, [len(g) for g in rec.goal])
        need = 0 if rates is None else guard.projected(have, len(frontier), rates, visited, key, count)
        if rates is None or need > max_bytes:
            need = guard.projected(have, len(frontier), guard.measure(pool, rec.keys, frontier, frontier_ids),
                                   visited, key, count)  # fmt: skip
        return need

    def spill() -> int:
        """Move the levels to disk; the bytes that freed, a shard's share."""
        if rec.disk is not None:
            return 0
        before = held()[0]
        rec.to_disk()
        return max(0, before - held()[0]) // count

    have, visited = held()
    fixed = guard.level_bytes(len(frontier), guard.Rates(0.0, 0.0, False), visited, key, count)
    most = guard.per_state(rec.summary, [len(g) for g in rec.goal])
    if most is None:  # no level expanded yet: a small sample says what a batch spends
        most = guard.measure(pool, rec.keys, frontier, frontier_ids, guard.FIRST_SAMPLE).transitions
    fixed += guard.first_batch(len(frontier), batch, most)
    if rec.disk is None and (int(max_bytes / PEAK_FACTOR) - have < fixed or (not local and price() > max_bytes)):
        rec.to_disk()
        have, visited = held()
    room = int(max_bytes / PEAK_FACTOR) - have
    if room < fixed:
        return None, price(), None
    return room // count, 0, spill if local and rec.disk is None else None


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
    """The finished search as one :class:`Exploration` (each column's parts joined and let go of, so
    the peak stays near the finished arrays; levels on disk are joined on disk)."""

    def take(name: str, dtype: Any) -> np.ndarray:
        parts = getattr(rec, name)
        if rec.disk is not None:
            out = rec.disk.join(parts, dtype)
        else:
            out = np.concatenate(parts).astype(dtype, copy=False) if parts else np.zeros(0, dtype=dtype)
        parts.clear()
        return out  # type: ignore[no-any-return]

    n_initial = len(rec.keys[0])
    level_sizes = np.array([len(k) for k in rec.keys], dtype=np.int64)
    total = int(level_sizes.sum())
    id_type = np.int32 if total < 2**31 - 1 else np.int64
    n_expanded = sum(len(g) for g in rec.goal)
    edtype = enabled_dtype(n)
    enabled_parts = [*rec.enabled, np.zeros(total - n_expanded, dtype=edtype)]
    goal_parts = [*rec.goal, np.zeros(total - n_expanded, dtype=bool)]
    rec.enabled, rec.goal = enabled_parts, goal_parts
    summary = fold_summaries(rec.summary)
    return Exploration(
        model=system.model,
        system=system,
        n=n,
        window=bound,
        engine=engine_name,
        n_initial=n_initial,
        codec=codec,
        keys=take("keys", codec.dtype),
        parent=take("parent", id_type),
        parent_action=take("paction", np.int32),
        level_sizes=level_sizes,
        n_expanded=n_expanded,
        enabled=take("enabled", edtype),
        goal=take("goal", bool),
        summary=summary,
        limit=limit,
        after_violation=after_violation,
        needed_bytes=needed,
        on_disk=rec.disk is not None,
    )


__all__ = ["Exploration", "Limit", "LocalShards", "ShardPool", "explore", "explore_keys"]
