"""One hash partition of the breadth-first search: its share of the visited set and of the frontier.

docs/checker.md, "Shards, workers, checkpoints, memory": the visited set and the frontier are
partitioned by a hash of the canonical key into P shards; each level every shard expands its frontier,
routes successor keys to their owner shard, and the owners de-duplicate. A :class:`Shard` is plain data
and numpy, so the same object serves in process (P = 1), as a Dask actor on a worker (:mod:`.workers`),
or rebuilt from a checkpoint. The shard never numbers states: the coordinator (:mod:`.search`) numbers
each level in key order after the merge, which is what makes state ids, parents and witnesses
independent of P.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..lemmas.registry import CORE_FLAGS, extra_flags, registered
from ..model.config import Model
from ..schedulers.base import Engine, TransitionSystem, expand_keys
from ..schedulers.systems import system_for
from . import keys as keyset
from .engines import engine_for

_MIX = np.uint64(0x9E3779B97F4A7C15)


def owners(keys: np.ndarray, count: int) -> np.ndarray:
    """The shard that owns each key (a multiplicative hash of its bytes, so neighbouring keys spread)."""
    if count == 1:
        return np.zeros(len(keys), dtype=np.int64)
    if keys.dtype == np.int64:
        words = keys.view(np.uint64)
    else:  # fixed-width byte keys: fold their 64-bit words
        raw = np.ascontiguousarray(keys).view(np.uint64).reshape(len(keys), keys.dtype.itemsize // 8)
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
    """The destination keys of the followed transitions (:func:`followed`), in transition order."""
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
        self.engine = engine_for(self.system, engine) if isinstance(engine, str) else engine
        self.codec = self.system.codec(n, bound)
        self.index, self.count = index, count
        self.after_violation = after_violation
        self.visited = np.zeros(0, dtype=self.codec.dtype)
        self.frontier = np.zeros(0, dtype=self.codec.dtype)
        self.frontier_ids = np.zeros(0, dtype=np.int64)
        self.lemmas = registered()
        """Registered step lemmas: judged on every transition, by one numpy pass over its positions."""

    def seed(self, visited: np.ndarray, frontier: np.ndarray, frontier_ids: np.ndarray) -> int:
        """Start (or resume) with these owned keys: ``visited`` sorted, the frontier a sorted subset."""
        self.visited, self.frontier, self.frontier_ids = visited, frontier, frontier_ids
        return len(self.visited)

    def expand(self, batch: int, progress: Callable[[int, int], None] | None = None) -> Level:
        """Expand the whole frontier, ``batch`` states at a time (``progress(done, frontier)`` after each)."""
        cols: dict[str, list[np.ndarray]] = {name: [] for name in COLUMNS}
        for start in range(0, len(self.frontier), batch):
            ids = self.frontier_ids[start : start + batch]
            ex = expand_keys(self.system, self.engine, self.codec, self.frontier[start : start + batch])
            src = ids[ex.src]
            flags = ex.flags
            if self.lemmas:
                flags = flags | self._lemma_flags(self.frontier[start : start + batch], ex.src, ex.action)
            flags = flags.astype(np.uint8)
            follow = followed(ex.fits, flags, self.after_violation)
            # Compact each batch at once (int32 ids and actions, uint8 flags, keys of followed
            # transitions only), so a level's peak is its compact columns, not the engine's.
            cols["ids"].append(ids)
            cols["enabled"].append(ex.enabled.astype(np.int32))
            cols["goal"].append(ex.goal)
            cols["src"].append(src.astype(np.int32) if len(src) and src[-1] < 2**31 - 1 else src)
            cols["action"].append(ex.action.astype(np.int32))
            cols["key"].append(ex.key[follow])
            cols["flags"].append(flags)
            cols["fits"].append(ex.fits)
            cols["exact"].append(ex.exact)
            del ex
            if progress:
                progress(min(start + batch, len(self.frontier)), len(self.frontier))
        dtypes: dict[str, Any] = {"ids": np.int64, "enabled": np.int32, "goal": bool, "src": np.int32}
        dtypes["action"] = np.int32
        dtypes |= {"key": self.codec.dtype, "flags": np.uint8, "fits": bool, "exact": bool}
        col = {name: _concat(parts, dtypes[name]) for name, parts in cols.items()}
        del cols
        _in_action_order(col, self.after_violation)
        follow = followed(col["fits"], col["flags"], self.after_violation)
        # Transitions are generated in (source id, action) order, so a key's first occurrence is its least.
        ck, first = keyset.unique_first(col["key"])
        cs, ca = col["src"][follow][first], col["action"][follow][first]
        owner = owners(ck, self.count)
        routed = [(ck[owner == o], cs[owner == o].astype(np.int64), ca[owner == o]) for o in range(self.count)]
        return Level(**col, routed=routed)

    def _lemma_flags(self, keys: np.ndarray, src: np.ndarray, action: np.ndarray) -> np.ndarray:
        """The registered lemmas' bits of a batch's transitions: the engine's own successors, robot by
        robot (the keyed ones are canonical), checked to be the same transitions."""
        states = self.codec.decode(keys)
        full = self.engine.expand(states)
        if not (np.array_equal(full.src, src) and np.array_equal(full.action, action)):
            raise RuntimeError("the engine's keyed and positional expansions list different transitions")
        positions = self.system.array_positions(states)
        return extra_flags(positions[full.src], self.system.array_positions(full.after), self.system.model, self.lemmas)

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
            pos = np.minimum(keyset.searchsorted(self.visited, ck), len(self.visited) - 1)
            new = self.visited[pos] != ck
            ck, cs, ca = ck[new], cs[new], ca[new]
        self.visited = keyset.merge_sorted(self.visited, ck)  # two sorted runs
        self.frontier = ck
        return ck, cs, ca

    def assign(self, ids: np.ndarray) -> None:
        """The ids the coordinator gave the new keys of :meth:`merge` (same order)."""
        self.frontier_ids = ids

    def visited_bytes(self) -> int:
        return int(self.visited.nbytes + self.frontier.nbytes + self.frontier_ids.nbytes)


COLUMNS = ("ids", "enabled", "goal", "src", "action", "key", "flags", "fits", "exact")
"""A :class:`Level`'s columns, in order (the checkpoint files hold the same)."""


def _in_action_order(col: dict[str, np.ndarray], after_violation: str) -> None:
    """Put a level's transitions in (source id, action) order where an engine generated them otherwise
    (the ASYNC engines list a robot's stop after its move), so the first transition reaching a key is
    its least and the edge columns are ordered the same for every engine."""
    src, action = col["src"], col["action"]
    if not len(src) or ((src[1:] != src[:-1]) | (action[1:] > action[:-1])).all():
        return
    order = np.lexsort((action, src))
    follow = followed(col["fits"], col["flags"], after_violation)
    full = np.zeros(len(src), dtype=col["key"].dtype)
    full[follow] = col["key"]
    for name in ("src", "action", "flags", "fits", "exact"):
        col[name] = col[name][order]
    col["key"] = full[order][follow[order]]


def followed(fits: np.ndarray, flags: np.ndarray, after_violation: str) -> np.ndarray:
    """The transitions the search follows: inside the bound and, unless ``after_violation`` is
    ``"continue"``, violating none of the paper's step lemmas (a registered lemma never prunes:
    :mod:`fatline_verify.lemmas.registry`)."""
    return fits if after_violation == "continue" else fits & ((flags & CORE_FLAGS) == 0)  # type: ignore[no-any-return]


def _concat(parts: list[np.ndarray], dtype: object) -> np.ndarray:
    return np.concatenate(parts) if parts else np.zeros(0, dtype=dtype)  # type: ignore[call-overload]


__all__ = ["COLUMNS", "Level", "Shard", "followed", "owners"]
