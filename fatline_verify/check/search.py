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
from enum import Enum
from functools import partial
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from ..lemmas.registry import FLAG_BITS
from ..model.config import Model
from ..resources import PEAK_FACTOR
from ..schedulers.base import Codec, Engine, TransitionSystem
from . import guard
from .engines import engine_for
from .shard import COLUMNS, SUMMARY_COUNTS, Level, Shard, enabled_dtype, fold_summaries, followed, owners

ProgressTick = Callable[[int, int, int, int], None]
"""``tick(level, done, frontier, states)``."""


class Limit(Enum):
    """What stopped a search before its frontier was empty."""

    NONE = "none"
    MAX_STATES = "max-states"
    MAX_MEMORY = "max-memory"


_STATE_COLUMNS = ("keys", "parent", "parent_action", "enabled", "goal")


@dataclass(slots=True)
class Exploration:
    """The explored transition system: per state (indexed by id) its key, parent, enabled robots and
    goal; the transitions as counts and least violating ones, recomputed on demand."""

    model: Model = field(repr=False)
    system: TransitionSystem = field(repr=False)
    n: int
    window: tuple[int, int]
    """The exploration bound (the codec's window)."""
    engine: str
    n_initial: int
    codec: Codec = field(repr=False)
    keys: np.ndarray = field(repr=False)
    """Sorted within each level (ids are given in key order, level by level)."""
    parent: np.ndarray = field(repr=False)
    parent_action: np.ndarray = field(repr=False)
    level_sizes: np.ndarray = field(repr=False)
    """States first reached at each depth."""
    n_expanded: int
    """The states with ids below this were expanded (a stopped search leaves the rest)."""
    enabled: np.ndarray = field(repr=False)
    """The enabled robots' mask (0 for unexpanded states)."""
    goal: np.ndarray = field(repr=False)
    summary: np.ndarray = field(repr=False)
    """The transitions' counts (:data:`.shard.SUMMARY_COUNTS`) and least ``(source id, action)`` per
    violation flag bit (:func:`.shard.summarise`)."""
    limit: Limit = Limit.NONE
    after_violation: str = "stop"
    needed_bytes: int = 0
    """When stopped by ``max_bytes``: the peak the next level was projected to need (:mod:`.guard`: held
    arrays plus the level's bytes, from a sample of its frontier or from the share of it expanded
    before it stopped, times :data:`~fatline_verify.resources.PEAK_FACTOR`)."""
    initial_window: tuple[int, int] | None = None
    """The window the initial configurations came from, when not the bound."""
    on_disk: bool = False
    """The levels were moved to disk (memory-mapped columns)."""
    expander: Shard | None = field(default=None, repr=False)
    """Recomputes transitions (the search's own engine, its caches warm, when it ran in this process)."""
    _cache: dict[str, Any] = field(default_factory=dict, repr=False)

    @property
    def start_window(self) -> tuple[int, int]:
        return self.window if self.initial_window is None else self.initial_window

    @property
    def truncated(self) -> bool:
        return self.limit is not Limit.NONE

    @property
    def n_states(self) -> int:
        return len(self.keys)

    def _count(self, name: str) -> int:
        return int(self.summary[SUMMARY_COUNTS.index(name)])

    @property
    def n_transitions(self) -> int:
        return self._count("transitions")

    @property
    def escaped(self) -> int:
        """Transitions from explored states to states outside the bound or off the lattice."""
        return self._count("escaped")

    @property
    def off_lattice(self) -> int:
        """Transitions to states whose positions leave the system's lattice (ASYNC: a K-fine step)."""
        return self._count("off_lattice")

    @property
    def violating_only(self) -> int:
        """Violating transitions (within the bound) whose destination no followed transition reaches, so it
        is not explored: a count of transitions, not of states (two may lead to one state)."""
        return self._count("violating_only")

    def least_violating(self, flag: int) -> tuple[int, int] | None:
        """The least ``(source id, action)`` among the transitions whose flags have the bit ``flag``."""
        bit = int(flag).bit_length() - 1
        if not 0 <= bit < FLAG_BITS or flag != 1 << bit:
            raise ValueError(f"flag={flag}: expected one bit of the violation flags")
        i = len(SUMMARY_COUNTS) + 2 * bit
        return None if self.summary[i] < 0 else (int(self.summary[i]), int(self.summary[i + 1]))

    @property
    def nbytes(self) -> int:
        """Bytes held by the exploration's arrays (in memory or, levels on disk, mapped)."""
        return sum(int(getattr(self, f).nbytes) for f in _STATE_COLUMNS)

    @property
    def depth(self) -> np.ndarray:
        """Every state's depth (its level), computed from the level sizes."""
        got = self._cache.get("depth")
        if got is None:
            got = self._cache["depth"] = np.repeat(np.arange(len(self.level_sizes), dtype=np.int32), self.level_sizes)
        return got  # type: ignore[no-any-return]

    @property
    def expanded(self) -> np.ndarray:
        """Whether each state was expanded (the ids below :attr:`n_expanded`)."""
        got = self._cache.get("expanded")
        if got is None:
            got = self._cache["expanded"] = np.arange(self.n_states) < self.n_expanded
        return got  # type: ignore[no-any-return]

    @property
    def states(self) -> np.ndarray:
        """Every state's canonical array, decoded (small searches; large ones use :meth:`state_array`)."""
        return self.codec.decode(np.asarray(self.keys))

    def state_array(self, ids: np.ndarray | int) -> np.ndarray:
        """The canonical array states of ``ids`` (one state for an int), decoded from their keys."""
        if isinstance(ids, int | np.integer):
            return self.codec.decode(np.asarray(self.keys[[int(ids)]]))[0]
        return self.codec.decode(np.asarray(self.keys[ids]))

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

    # --- transitions, recomputed ------------------------------------------------------------------
    def ids_of(self, keys: np.ndarray) -> np.ndarray:
        """The ids of ``keys`` (-1 for a key not explored): looked up level by level (each is sorted)."""
        out = np.full(len(keys), -1, dtype=np.int64)
        start = 0
        for size in self.level_sizes.tolist():
            level = self.keys[start : start + size]
            if size and len(keys):
                pos = np.minimum(np.searchsorted(level, keys), size - 1)
                hit = level[pos] == keys
                out[hit] = start + pos[hit]
            start += size
        return out

    def _expander(self) -> Shard:
        if self.expander is None:
            eng = engine_for(self.system, self.engine)
            self.expander = Shard(self.system, self.n, self.window, eng, 0, 1, self.after_violation)
        return self.expander

    def transitions(self, ids: np.ndarray) -> tuple[np.ndarray, ...]:
        """Every transition of the expanded states ``ids`` (ascending), recomputed: ``(src, dst, action,
        flags, fits, exact)`` in (source id, action) order; ``dst`` is -1 where the search does not follow
        the transition (outside the bound, violating under ``after_violation="stop"``) or beyond a limit."""
        ids = np.asarray(ids, dtype=np.int64)
        tr = self._expander().transitions(np.asarray(self.keys[ids]), ids)
        follow = np.flatnonzero(followed(tr.fits, tr.flags, self.after_violation))
        id_type = np.int32 if self.n_states < 2**31 - 1 else np.int64
        dst = np.full(len(tr.src), -1, dtype=id_type)
        dst[follow] = self.ids_of(tr.key)
        return tr.src.astype(id_type, copy=False), dst, tr.action, tr.flags, tr.fits, tr.exact

    def followed_edges(self, nodes: np.ndarray, batch: int = 200_000) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(src, dst, action)`` of the followed transitions between states with ``nodes[id]`` true (only
        expanded states have transitions), recomputed ``batch`` sources at a time."""
        ids = np.flatnonzero(nodes[: self.n_expanded])
        parts: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []
        for start in range(0, len(ids), batch):
            src, dst, action, _, _, _ = self.transitions(ids[start : start + batch])
            ok = (dst >= 0) & nodes[np.maximum(dst, 0)]
            parts.append((src[ok], dst[ok], action[ok]))
        if not parts:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int32)
        return tuple(np.concatenate([p[k] for p in parts]) for k in range(3))  # type: ignore[return-value]

    def _edges(self) -> tuple[np.ndarray, ...]:
        got = self._cache.get("edges")
        if got is None:
            got = self._cache["edges"] = self.transitions(np.arange(self.n_expanded, dtype=np.int64))
        return got  # type: ignore[no-any-return]

    @property
    def edge_src(self) -> np.ndarray:
        """Every transition's source id (recomputed on first use, then kept: small searches only)."""
        return self._edges()[0]

    @property
    def edge_dst(self) -> np.ndarray:
        """Destination id, or -1 when the destination was not explored (outside the bound, off the
        lattice, reached only through a violating step, or beyond a limit)."""
        return self._edges()[1]

    @property
    def edge_action(self) -> np.ndarray:
        """The step's action code, in the source state's canonical robot order."""
        return self._edges()[2]

    @property
    def edge_flags(self) -> np.ndarray:
        return self._edges()[3]

    @property
    def edge_fits(self) -> np.ndarray:
        """The destination is on the lattice and inside the bound."""
        return self._edges()[4]

    @property
    def edge_exact(self) -> np.ndarray:
        """The destination is on the system's lattice (``False``: counted in :attr:`off_lattice`)."""
        return self._edges()[5]


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
    frontier_ids = np.arange(len(visited) - len(frontier), len(visited), dtype=np.int64)
    limit, needed = Limit.NONE, 0
    if count == 1:  # no copies: the shard's visited set is sorted keys, the frontier its last level
        pool.map("seed", [(np.sort(visited) if len(rec.keys) > 1 else visited, frontier, frontier_ids)])
    else:
        owner_all = owners(visited, count)
        initial_level = len(frontier) == len(visited)  # the initial level is the whole visited set, sorted
        owner_front = owner_all if initial_level else owners(frontier, count)
        seeds = []
        for o in range(count):
            mine = visited[owner_all == o]
            front = None if initial_level else frontier[owner_front == o]  # None: the shard's visited set
            seeds.append((mine if initial_level else np.sort(mine), front, frontier_ids[owner_front == o]))
            del mine, front
        pool.map("seed", seeds)
        del seeds
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
        else:
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
            pool.map("assign", [(np.arange(total, total + len(new_keys), dtype=np.int64),)])
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


def _tick(progress: ProgressTick, level: int, states: int, done: int, frontier: int) -> None:
    progress(level, done, frontier, states)


def _held(pool: ShardPool, rec: _Records, frontier: np.ndarray) -> tuple[int, int]:
    """The bytes the search holds in memory (its columns, the frontier, its shards' visited sets and
    frontiers: each buffer once, :func:`.guard.held_bytes`; shards in other processes as they report)
    and its states."""
    arrays = [frontier] + [a for name in _RECORD_COLUMNS for a in getattr(rec, name)]
    remote = 0
    if isinstance(pool, LocalShards):
        arrays += [a for s in pool.shards for a in (s.visited, s.frontier, s.frontier_ids)]
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
