"""One hash partition of the breadth-first search: its share of the visited set and of the frontier.

DESIGN.md, "The explorer": the visited set and the frontier are partitioned by a hash of the canonical
key into P shards; each level every shard expands its frontier, routes successor keys to their owner
shard, and the owners de-duplicate. A :class:`Shard` is plain data and numpy, so the same object serves
in process (P = 1), as a Dask actor on a worker (:mod:`.workers`), or rebuilt from a checkpoint. The
shard never numbers states: the coordinator (:mod:`.search`) numbers each level in key order after the
merge, which is what makes state ids, parents and witnesses independent of P.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..config import Model
from ..systems import system_for
from ..systems.base import Engine, TransitionSystem, expand_keys

_MIX = np.uint64(0x9E3779B97F4A7C15)


def owners(keys: np.ndarray, count: int) -> np.ndarray:
    """The shard that owns each key (a multiplicative hash of its bytes, so neighbouring keys spread)."""
    if count == 1:
        return np.zeros(len(keys), dtype=np.int64)
    if keys.dtype == np.int64:
        words = keys.view(np.uint64)
    else:  # fixed-width byte keys: fold their 64-bit words
        raw = np.ascontiguousarray(keys).view(np.uint64).reshape(len(keys), -1)
        words = np.bitwise_xor.reduce(raw, axis=1)
    with np.errstate(over="ignore"):
        mixed = words * _MIX
    return ((mixed >> np.uint64(33)) % np.uint64(count)).astype(np.int64)


@dataclass(slots=True)
class Level:
    """What a shard's expansion of its frontier gives the coordinator."""

    ids: np.ndarray
    """(m,) the expanded states' ids (ascending)."""
    enabled: np.ndarray
    goal: np.ndarray
    src: np.ndarray
    """(t,) the source state's id, transitions ordered by (source id, action)."""
    action: np.ndarray
    key: np.ndarray
    flags: np.ndarray
    fits: np.ndarray
    exact: np.ndarray
    routed: list[tuple[np.ndarray, np.ndarray, np.ndarray]]
    """Per owner shard: the candidate successors ``(key, source id, action)`` it must de-duplicate,
    each key once, with its least ``(source id, action)`` among this shard's transitions."""


class Shard:
    """The states whose keys hash to ``index`` of ``count``; expands them and owns their de-duplication."""

    def __init__(
        self,
        system: TransitionSystem | Model,
        n: int,
        bound: tuple[int, int],
        engine: Engine | str,
        index: int = 0,
        count: int = 1,
        after_violation: str = "stop",
    ) -> None:
        self.system = system_for(system) if isinstance(system, Model) else system
        self.engine = self.system.engine(engine) if isinstance(engine, str) else engine
        self.codec = self.system.codec(n, bound)
        self.index, self.count = index, count
        self.after_violation = after_violation
        self.visited = np.zeros(0, dtype=self.codec.dtype)
        self.frontier = np.zeros(0, dtype=self.codec.dtype)
        self.frontier_ids = np.zeros(0, dtype=np.int64)

    def seed(self, visited: np.ndarray, frontier: np.ndarray, frontier_ids: np.ndarray) -> int:
        """Start (or resume) with these owned keys: ``visited`` sorted, the frontier a sorted subset."""
        self.visited, self.frontier, self.frontier_ids = visited, frontier, frontier_ids
        return len(self.visited)

    def expand(self, batch: int, progress: Callable[[int, int], None] | None = None) -> Level:
        """Expand the whole frontier, ``batch`` states at a time (``progress(done, frontier)`` after each)."""
        parts = []
        for start in range(0, len(self.frontier), batch):
            ex = expand_keys(self.system, self.engine, self.codec, self.frontier[start : start + batch])
            parts.append((ex, self.frontier_ids[start : start + batch]))
            if progress:
                progress(min(start + batch, len(self.frontier)), len(self.frontier))
        cat = _concat
        ids = cat([p[1] for p in parts], np.int64)
        src = cat([ids_[ex.src] for ex, ids_ in parts], np.int64)
        action = cat([ex.action for ex, _ in parts], np.int64)
        key = cat([ex.key for ex, _ in parts], self.codec.dtype)
        flags = cat([ex.flags for ex, _ in parts], np.int64)
        fits = cat([ex.fits for ex, _ in parts], bool)
        usable = fits if self.after_violation == "continue" else fits & (flags == 0)
        # Transitions are generated in (source id, action) order, so a key's first occurrence is its least.
        ck, first = np.unique(key[usable], return_index=True)
        cs, ca = src[usable][first], action[usable][first]
        owner = owners(ck, self.count)
        routed = [(ck[owner == o], cs[owner == o], ca[owner == o]) for o in range(self.count)]
        return Level(
            ids,
            cat([ex.enabled for ex, _ in parts], np.int64),
            cat([ex.goal for ex, _ in parts], bool),
            src,
            action,
            key,
            flags,
            fits,
            cat([ex.exact for ex, _ in parts], bool),
            routed,
        )

    def merge(self, parts: list[tuple[np.ndarray, np.ndarray, np.ndarray]]) -> tuple[np.ndarray, ...]:
        """De-duplicate the candidates routed here: the new keys (sorted), each with its least
        ``(source id, action)``; they join the visited set. The frontier waits for :meth:`assign`."""
        ck = _concat([p[0] for p in parts], self.codec.dtype)
        cs = _concat([p[1] for p in parts], np.int64)
        ca = _concat([p[2] for p in parts], np.int64)
        if len(parts) > 1:
            order = np.lexsort((ca, cs, ck))
            ck, cs, ca = ck[order], cs[order], ca[order]
            first = np.ones(len(ck), dtype=bool)
            first[1:] = ck[1:] != ck[:-1]
            ck, cs, ca = ck[first], cs[first], ca[first]
        if len(self.visited) and len(ck):
            pos = np.minimum(np.searchsorted(self.visited, ck), len(self.visited) - 1)
            new = self.visited[pos] != ck
            ck, cs, ca = ck[new], cs[new], ca[new]
        merged = np.concatenate([self.visited, ck])
        self.visited = np.sort(merged, kind="stable" if merged.dtype == np.int64 else None)  # two sorted runs
        self.frontier = ck
        return ck, cs, ca

    def assign(self, ids: np.ndarray) -> None:
        """The ids the coordinator gave the new keys of :meth:`merge` (same order)."""
        self.frontier_ids = ids

    def visited_bytes(self) -> int:
        return int(self.visited.nbytes + self.frontier.nbytes + self.frontier_ids.nbytes)


def _concat(parts: list[np.ndarray], dtype: object) -> np.ndarray:
    return np.concatenate(parts) if parts else np.zeros(0, dtype=dtype)  # type: ignore[call-overload]


__all__ = ["Level", "Shard", "owners"]
