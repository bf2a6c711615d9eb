"""The result of a search (:func:`fatline_verify.check.search.explore`): an :class:`Exploration`
holds, per state, its packed key, parent, parent action, enabled robots and goal, the per-level
summaries of the transitions, and the bounds; everything else (depths, positions, the followed
transitions of the fair-cycle search, the ``edge_*`` columns) is derived on demand (docs/checker.md,
"The compact store"). :class:`Limit` says what stopped a search early."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Any

import numpy as np

from ..lemmas.registry import FLAG_BITS
from ..model.config import Model
from ..schedulers.base import Codec, TransitionSystem
from . import keys as keyset
from .engines import engine_for
from .shard import SUMMARY_COUNTS, Shard, followed


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
        return self.memo(  # type: ignore[no-any-return]
            "depth", lambda: np.repeat(np.arange(len(self.level_sizes), dtype=np.int32), self.level_sizes)
        )

    @property
    def expanded(self) -> np.ndarray:
        """Whether each state was expanded (the ids below :attr:`n_expanded`)."""
        return self.memo("expanded", lambda: np.arange(self.n_states) < self.n_expanded)  # type: ignore[no-any-return]

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
    def _index(self) -> tuple[np.ndarray, np.ndarray]:
        """Every key in ascending order and its state id (built on first use; :meth:`drop_index` frees it)."""

        def make() -> tuple[np.ndarray, np.ndarray]:
            keys = np.asarray(self.keys)
            if keys.dtype.kind == "V":  # two sorts of a word each: far less memory than a radix sort
                w = keyset.words(keys)
                order = np.lexsort(tuple(w[:, i] for i in range(w.shape[1] - 1, -1, -1)))
                del w
            else:
                order = np.argsort(keys, kind="stable")
            order = order.astype(np.int32 if len(keys) < 2**31 else np.int64)
            return keys[order], order

        return self.memo("index", make)  # type: ignore[no-any-return]

    def has_index(self) -> bool:
        """Whether the key index of :meth:`ids_of` is built."""
        return "index" in self._cache

    def drop_index(self) -> None:
        """Free the key index :meth:`ids_of` builds (about 24 bytes a state)."""
        self._cache.pop("index", None)

    def ids_of(self, keys: np.ndarray) -> np.ndarray:
        """The ids of ``keys`` (-1 for a key not explored): looked up in one sorted index of every key
        (each level's keys are sorted, but not the levels together)."""
        out = np.full(len(keys), -1, dtype=np.int64)
        if not len(keys) or not self.n_states:
            return out
        ordered, ids = self._index()
        pos = np.minimum(keyset.searchsorted(ordered, keys), len(ordered) - 1)
        hit = ordered[pos] == keys
        out[hit] = ids[pos[hit]]
        return out

    def _expander(self) -> Shard:
        if self.expander is None:
            eng = engine_for(self.system, self.engine)
            self.expander = Shard(self.system, self.n, self.window, eng, 0, 1, self.after_violation)
        return self.expander

    def memo(self, name: str, make: Any) -> Any:
        """``make()``, computed once per exploration and kept under ``name`` (derived data: the
        exploration itself never changes)."""
        if name not in self._cache:
            self._cache[name] = make()
        return self._cache[name]

    def expander_engine(self) -> Any:
        """The engine that recomputes transitions (:meth:`transitions`), for a batch of array states."""
        return self._expander().engine

    def transitions(self, ids: np.ndarray) -> tuple[np.ndarray, ...]:
        """Every transition of the expanded states ``ids`` (ascending), recomputed: ``(src, dst, action,
        flags, fits, exact)`` in (source id, action) order; ``dst`` is -1 where the search does not follow
        the transition (outside the bound, violating under ``after_violation="stop"``) or beyond a limit."""
        ids = np.asarray(ids, dtype=np.int64)
        expander = self._expander()
        tr = expander.transitions(np.asarray(self.keys[ids]), ids)
        follow = np.flatnonzero(followed(tr.fits, tr.flags, self.after_violation, expander.prune))
        id_type = np.int32 if self.n_states < 2**31 - 1 else np.int64
        dst = np.full(len(tr.src), -1, dtype=id_type)
        dst[follow] = self.ids_of(tr.key)
        return tr.src.astype(id_type, copy=False), dst, tr.action, tr.flags, tr.fits, tr.exact

    def followed_edges(self, nodes: np.ndarray, batch: int = 200_000) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(src, dst, action)`` of the followed transitions between states with ``nodes[id]`` true (only
        expanded states have transitions), recomputed ``batch`` sources at a time (at least an eighth of
        the states: their successors are then looked up in one walk through the key index)."""
        ids = np.flatnonzero(nodes[: self.n_expanded])
        batch = max(batch, self.n_states // 8 + 1)
        out: list[np.ndarray] = []
        filled = 0
        for start in range(0, len(ids), batch):
            src, dst, action, _, _, _ = self.transitions(ids[start : start + batch])
            ok = (dst >= 0) & nodes[np.maximum(dst, 0)]
            got = (src[ok], dst[ok], action[ok])
            if not out or filled + len(got[0]) > len(out[0]):  # at first the transitions' count: no copies
                size = max(self.n_transitions, 2 * (filled + len(got[0])))
                out = [np.concatenate([o[:filled], np.empty(size - filled, o.dtype)]) for o in out] or [
                    np.empty(size, x.dtype) for x in got
                ]
            for o, x in zip(out, got, strict=True):
                o[filled : filled + len(x)] = x
            filled += len(got[0])
        if not out:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int32)
        return out[0][:filled], out[1][:filled], out[2][:filled]

    def _edges(self) -> tuple[np.ndarray, ...]:
        return self.memo("edges", lambda: self.transitions(np.arange(self.n_expanded, dtype=np.int64)))  # type: ignore[no-any-return]

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
