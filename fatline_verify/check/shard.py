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

from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..lemmas import registry as lemma_registry
from ..lemmas.registry import CORE_FLAGS, FLAG_BITS, extra_flags
from ..model.config import Model
from ..resources import return_freed_memory
from ..rules.registry import lemma_flags
from ..schedulers.base import Engine, TransitionSystem, expand_keys
from ..schedulers.systems import system_for
from . import keys as keyset
from .engines import engine_for
from .guard import CONSOLIDATE, CONSOLIDATE_MIN, Watch

_MIX = np.uint64(0x9E3779B97F4A7C15)


def owners(keys: np.ndarray, count: int) -> np.ndarray:
    """The shard that owns each key (a multiplicative hash of its bytes, so neighbouring keys spread), in
    the smallest integer type that holds ``count - 1``."""
    small = np.uint8 if count <= 256 else np.uint16 if count <= 65536 else np.int64
    if count == 1:
        return np.zeros(len(keys), dtype=small)
    if keys.dtype == np.int64:
        words = keys.view(np.uint64)
    else:  # fixed-width byte keys: fold their 64-bit words
        raw = np.ascontiguousarray(keys).view(np.uint64).reshape(len(keys), keys.dtype.itemsize // 8)
        words = np.bitwise_xor.reduce(raw, axis=1)
    with np.errstate(over="ignore"):
        mixed = words * _MIX
    return ((mixed >> np.uint64(33)) % np.uint64(count)).astype(small)


SUMMARY_COUNTS = ("transitions", "escaped", "off_lattice", "violating_only")
"""The counts at the head of a level's :data:`Level.summary`."""

SUMMARY_LENGTH = len(SUMMARY_COUNTS) + 2 * FLAG_BITS


def empty_summary() -> np.ndarray:
    """A summary of no transitions: zero counts, no least violating transition for any flag bit."""
    out = np.zeros(SUMMARY_LENGTH, dtype=np.int64)
    out[len(SUMMARY_COUNTS) :] = -1
    return out


def summarise(src: np.ndarray, action: np.ndarray, flags: np.ndarray, fits: np.ndarray, exact: np.ndarray,
              after_violation: str, prune: int = CORE_FLAGS) -> np.ndarray:  # fmt: skip
    """The summary of transitions in (source id, action) order: their counts (as :data:`SUMMARY_COUNTS`)
    and, per flag bit, the least ``(source id, action)`` whose flags have that bit (``-1, -1``: none).

    ``violating_only`` counts the violating transitions inside the bound that the search does not follow
    (under ``after_violation="stop"`` no followed transition is violating, so their destinations are
    not reached through them)."""
    out = empty_summary()
    core = fits & ((flags & prune) != 0)
    out[:4] = (
        len(src),
        int((~fits).sum()),
        int((~exact).sum()),
        0 if after_violation == "continue" else int(core.sum()),
    )
    for bit in range(FLAG_BITS):
        hit = np.flatnonzero(flags & (1 << bit))
        if len(hit):
            out[4 + 2 * bit : 6 + 2 * bit] = (src[hit[0]], action[hit[0]])
    return out


def fold_summaries(parts: list[np.ndarray]) -> np.ndarray:
    """Summaries of disjoint sets of transitions as one: counts added, the least transition per bit."""
    out = empty_summary()
    for part in parts:
        out[:4] += part[:4]
        for bit in range(FLAG_BITS):
            i = 4 + 2 * bit
            if part[i] >= 0 and (out[i] < 0 or (part[i], part[i + 1]) < (out[i], out[i + 1])):
                out[i : i + 2] = part[i : i + 2]
    return out


@dataclass(slots=True)
class Transitions:
    """Every transition of some expanded states, in (source id, action) order."""

    ids: np.ndarray
    """(m,) the expanded states' ids (ascending)."""
    enabled: np.ndarray
    goal: np.ndarray
    src: np.ndarray
    """(t,) the source state's id."""
    action: np.ndarray
    key: np.ndarray
    """The destination keys of the followed transitions (:func:`followed`), in transition order."""
    flags: np.ndarray
    fits: np.ndarray
    exact: np.ndarray


@dataclass(slots=True)
class Level:
    """What a shard's expansion of its frontier gives the coordinator: per state, and a summary of the
    transitions (docs/checker.md, "The compact store"); the transitions themselves are not kept."""

    ids: np.ndarray
    """(m,) the expanded states' ids (ascending)."""
    enabled: np.ndarray
    """(m,) the enabled robots' mask, in :func:`enabled_dtype`."""
    goal: np.ndarray
    summary: np.ndarray
    """(:data:`SUMMARY_LENGTH`,) int64: counts and the least violating transition per flag bit."""
    routed: list[tuple[np.ndarray, np.ndarray, np.ndarray]]
    """Per owner shard: the candidate successors ``(key, source id, action)`` it must de-duplicate,
    each key once, with its least ``(source id, action)`` among this shard's transitions."""
    needed: int = 0
    """Not 0: the expansion stopped at its budget (:class:`.guard.Watch`), nothing kept; the bytes the
    whole level would have added, extrapolated."""


def enabled_dtype(n: int) -> Any:
    """The smallest unsigned integer type holding a mask of ``n`` robots."""
    return np.uint8 if n <= 8 else np.uint16 if n <= 16 else np.uint32 if n <= 32 else np.uint64


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
        return_freed_memory()  # in this process, whichever process the shard lives in
        self.system = system_for(system) if isinstance(system, Model) else system
        self.engine = engine_for(self.system, engine) if isinstance(engine, str) else engine
        self.codec = self.system.codec(n, bound)
        self.index, self.count = index, count
        self.after_violation = after_violation
        self.base = np.zeros(0, dtype=self.codec.dtype)
        """The keys the shard was seeded with, sorted, held as given (in process, the store's first
        level itself: no copy of the largest level)."""
        self.visited = np.zeros(0, dtype=self.codec.dtype)
        """The keys found since, sorted: together with :attr:`base` (disjoint) the visited set."""
        self.frontier = np.zeros(0, dtype=self.codec.dtype)
        self.frontier_ids = np.zeros(0, dtype=np.int64)
        self.lemmas = lemma_registry.judged(self.system.model)
        """Registered step lemmas: judged on every transition, by one numpy pass over its positions."""
        judged, self.prune = lemma_flags(self.system.model)
        self.keep = judged | ~CORE_FLAGS
        """The flag bits kept from the engine: the rule set's applicable built-in step lemmas and every
        registered lemma's (a built-in lemma the rule set does not claim is neither judged nor pruned)."""

    def seed(self, visited: np.ndarray, frontier: np.ndarray | None, frontier_ids: np.ndarray) -> int:
        """Start (or resume) with these owned keys: ``visited`` sorted (kept as :attr:`base`, not copied),
        the frontier a sorted subset (``None``: all of them, one array, not a copy sent beside it)."""
        self.base, self.visited = visited, np.zeros(0, dtype=self.codec.dtype)
        self.frontier = visited if frontier is None else frontier
        self.frontier_ids = frontier_ids
        return self.known()

    def known(self) -> int:
        """The visited set's size."""
        return len(self.base) + len(self.visited)

    def _seen(self, keys: np.ndarray) -> np.ndarray:
        """Which of ``keys`` (sorted) are in the visited set."""
        seen = np.zeros(len(keys), dtype=bool)
        for run in (self.base, self.visited):
            if len(run) and len(keys):
                pos = np.minimum(keyset.searchsorted(run, keys), len(run) - 1)
                seen |= run[pos] == keys
        return seen

    def _batches(
        self, keys: np.ndarray, ids: np.ndarray, batch: int, progress: Callable[[int, int], None] | None = None
    ) -> Iterator[Transitions]:
        """The transitions of ``keys`` (ids ``ids``), ``batch`` states at a time, each batch compacted
        (int32 ids and actions, uint8 flags, keys of followed transitions only) and in (source, action)
        order."""
        for start in range(0, len(keys), batch):
            part = keys[start : start + batch]
            got = ids[start : start + batch]
            ex = expand_keys(self.system, self.engine, self.codec, np.asarray(part))
            src = got[ex.src]
            flags = ex.flags & self.keep
            if self.lemmas:
                flags = flags | self._lemma_flags(np.asarray(part), ex.src, ex.action)
            flags = flags.astype(np.uint8)
            follow = followed(ex.fits, flags, self.after_violation, self.prune)
            col = {
                "src": src.astype(np.int32) if len(src) and src[-1] < 2**31 - 1 else src,
                "action": ex.action.astype(np.int32),
                "key": ex.key[follow],
                "flags": flags,
                "fits": ex.fits,
                "exact": ex.exact,
            }
            enabled, goal = ex.enabled.astype(enabled_dtype(self.codec.n)), ex.goal
            del ex
            _in_action_order(col, self.after_violation, self.prune)
            yield Transitions(np.asarray(got), enabled, goal, **col)
            if progress:
                progress(min(start + batch, len(keys)), len(keys))

    def expand(
        self,
        batch: int,
        progress: Callable[[int, int], None] | None = None,
        room: int | None = None,
        spill: Callable[[], int] | None = None,
    ) -> Level:
        """Expand the whole frontier, ``batch`` states at a time (``progress(done, frontier)`` after each):
        per state its enabled robots and goal, the transitions folded into a summary as they come, and
        the followed successors routed to their owners. ``room``: the bytes the level may add here; it
        stops (:attr:`Level.needed`) before a consolidation or a merge whose peak, computed from what it
        has gathered, would pass that, unless ``spill`` (the search's levels moved to disk) makes room
        (:class:`.guard.Watch`)."""
        watch = None
        if room is not None:
            size = self.codec.dtype.itemsize
            watch = Watch(room, len(self.frontier), self.known(), size, self.count, spill)
        # per state, filled batch by batch (the expanded states are the frontier's, in its order)
        enabled = np.empty(len(self.frontier), dtype=enabled_dtype(self.codec.n))
        goal = np.empty(len(self.frontier), dtype=bool)
        summaries = []
        ck, cs, ca = np.zeros(0, dtype=self.codec.dtype), np.zeros(0, dtype=np.int32), np.zeros(0, dtype=np.int32)
        parts: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []
        pending = done = 0
        for tr in self._batches(self.frontier, self.frontier_ids, batch, progress):
            enabled[done : done + len(tr.ids)] = tr.enabled
            goal[done : done + len(tr.ids)] = tr.goal
            done += len(tr.ids)
            summaries.append(
                summarise(tr.src, tr.action, tr.flags, tr.fits, tr.exact, self.after_violation, self.prune)
            )
            follow = followed(tr.fits, tr.flags, self.after_violation, self.prune)
            # A key's first occurrence is its least (source, action): batches ascend, so do their firsts.
            bk, first = keyset.unique_first(tr.key)
            unseen = self._unseen(bk)
            if unseen is not None:
                bk, first = bk[unseen], first[unseen]
            bs = tr.src[follow][first]
            parts.append(
                (bk, bs.astype(np.int32) if len(bs) and bs.max() < 2**31 - 1 else bs, tr.action[follow][first])
            )
            pending += len(bk)
            transitions = len(tr.src)
            del tr
            if watch is not None and not watch.fits(done, len(ck) + pending, transitions=transitions):
                return _stopped(watch, self.codec.n)
            if pending > min(CONSOLIDATE, max(CONSOLIDATE_MIN, len(ck))):  # fold them into one sorted set:
                # geometric steps (each fold at most doubles the set), at most CONSOLIDATE pending
                ck, cs, ca = _first_of(ck, cs, ca, parts, self.codec.dtype)
                parts, pending = [], 0
        ck, cs, ca = _first_of(ck, cs, ca, parts, self.codec.dtype)
        del parts
        if watch is not None and not watch.fits(done, len(ck), final=True):
            return _stopped(watch, self.codec.n)
        owner = owners(ck, self.count)
        routed = [(ck[owner == o], cs[owner == o], ca[owner == o]) for o in range(self.count)]
        if self.count == 1:
            routed = [(ck, cs, ca)]
        return Level(np.asarray(self.frontier_ids), enabled, goal, fold_summaries(summaries), routed)

    def _unseen(self, keys: np.ndarray) -> np.ndarray | None:
        """Which of ``keys`` (sorted, distinct) are not in this shard's visited set, as a mask (``None``:
        all are). A key another shard owns is kept (its owner decides, in :meth:`merge`). The visited
        set does not change during a level, so dropping the seen ones while gathering is what the merge
        would do (with one shard it does not look again) and bounds the level's candidates by the states
        it adds."""
        if not self.known() or not len(keys):
            return None
        unseen = ~self._seen(keys)
        if self.count > 1:
            unseen |= owners(keys, self.count) != self.index
        return None if unseen.all() else unseen

    def transitions(self, keys: np.ndarray, ids: np.ndarray, batch: int = 50_000) -> Transitions:
        """Every transition of the states ``keys`` (ids ``ids``, ascending), recomputed (the search keeps
        summaries only; the fair-cycle search and :attr:`.search.Exploration.edge_src` ask again)."""
        parts = list(self._batches(keys, ids, batch))
        names = ("ids", "enabled", "goal", "src", "action", "key", "flags", "fits", "exact")
        dtypes: dict[str, Any] = {"ids": np.int64, "enabled": enabled_dtype(self.codec.n), "goal": bool}
        dtypes |= {"src": np.int32, "action": np.int32, "key": self.codec.dtype, "flags": np.uint8}
        dtypes |= {"fits": bool, "exact": bool}
        return Transitions(**{f: _concat([getattr(p, f) for p in parts], dtypes[f]) for f in names})

    def _lemma_flags(self, keys: np.ndarray, src: np.ndarray, action: np.ndarray) -> np.ndarray:
        """The registered lemmas' bits of a batch's transitions: each step's exact positions before and
        after, robot by robot (the keyed successors are canonical), from the engine's own expansion,
        checked to list the same transitions."""
        states = self.codec.decode(keys)
        full = self.engine.expand(states)
        if not (np.array_equal(full.src, src) and np.array_equal(full.action, action)):
            raise RuntimeError("the engine's keyed and positional expansions list different transitions")
        before, after, unit = self.system.step_positions(states, full)
        return extra_flags(before, after, self.system.model, self.lemmas, unit)

    def merge(self, parts: list[tuple[np.ndarray, np.ndarray, np.ndarray]]) -> tuple[np.ndarray, ...]:
        """De-duplicate the candidates routed here: the new keys (sorted), each with its least
        ``(source id, action)``; they join the visited set. The frontier waits for :meth:`assign`."""
        if len(parts) == 1:
            ck, cs, ca = parts[0]
        else:
            ck = _concat([p[0] for p in parts], self.codec.dtype)
            cs = _concat([p[1] for p in parts], np.int64)
            ca = _concat([p[2] for p in parts], np.int64)
        if len(parts) > 1:
            order = np.lexsort((ca, cs, ck))
            ck, cs, ca = ck[order], cs[order], ca[order]
            first = np.ones(len(ck), dtype=bool)
            first[1:] = ck[1:] != ck[:-1]
            ck, cs, ca = ck[first], cs[first], ca[first]
        if self.count > 1 and self.known() and len(ck):  # one shard: gathered unseen (:meth:`_unseen`)
            new = ~self._seen(ck)
            ck, cs, ca = ck[new], cs[new], ca[new]
        self.visited = _merged(self.visited, ck)
        self.frontier = ck
        return ck, cs, ca

    def assign(self, ids: np.ndarray) -> None:
        """The ids the coordinator gave the new keys of :meth:`merge` (same order)."""
        self.frontier_ids = ids

    def visited_bytes(self) -> int:
        """Bytes of the visited set, the frontier (unless it is one of the visited set's arrays) and its
        ids."""
        front = 0 if self.frontier is self.visited or self.frontier is self.base else self.frontier.nbytes
        return int(self.base.nbytes + self.visited.nbytes + front + self.frontier_ids.nbytes)


COLUMNS = ("enabled", "goal", "summary")
"""A :class:`Level`'s columns kept by the search, in order (the checkpoint files hold the same)."""


def _in_action_order(col: dict[str, np.ndarray], after_violation: str, prune: int = CORE_FLAGS) -> None:
    """Put a level's transitions in (source id, action) order where an engine generated them otherwise
    (the ASYNC engines list a robot's stop after its move), so the first transition reaching a key is
    its least and the edge columns are ordered the same for every engine."""
    src, action = col["src"], col["action"]
    if not len(src) or ((src[1:] != src[:-1]) | (action[1:] > action[:-1])).all():
        return
    order = np.lexsort((action, src))
    follow = followed(col["fits"], col["flags"], after_violation, prune)
    full = np.zeros(len(src), dtype=col["key"].dtype)
    full[follow] = col["key"]
    for name in ("src", "action", "flags", "fits", "exact"):
        col[name] = col[name][order]
    col["key"] = full[order][follow[order]]


def _stopped(watch: Watch, n: int) -> Level:
    """An expansion stopped at its budget: nothing kept but what it would have needed."""
    ids, enabled, goal = np.zeros(0, dtype=np.int64), np.zeros(0, dtype=enabled_dtype(n)), np.zeros(0, dtype=bool)
    return Level(ids, enabled, goal, empty_summary(), [], max(1, watch.needed))


def _first_of(
    ck: np.ndarray, cs: np.ndarray, ca: np.ndarray, parts: Sequence[tuple[np.ndarray, ...]], dtype: object
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sorted set of ``ck`` and the keys of ``parts`` (later ones after), each key once with its
    first ``(source, action)`` in that order (which is its least: sources ascend)."""
    if not parts:
        return ck, cs, ca
    if len(parts) == 1 and not len(ck):
        return parts[0]  # type: ignore[return-value]
    keys = np.concatenate([ck, *[p[0] for p in parts]])
    narrow = cs.dtype == np.int32 and all(p[1].dtype == np.int32 for p in parts)
    src = np.concatenate([cs, *[p[1] for p in parts]]).astype(np.int32 if narrow else np.int64, copy=False)
    act = np.concatenate([ca, *[p[2] for p in parts]])
    keys, first = keyset.unique_first(keys)  # stable: the first occurrence of each key
    src = src[first]
    return keys, src.astype(np.int32) if len(src) and src.max() < 2**31 - 1 else src, act[first]


def _merged(visited: np.ndarray, new: np.ndarray) -> np.ndarray:
    """Two sorted arrays of distinct keys as one, without sorting again (peak: the two and the result)."""
    if not len(new):
        return visited
    if not len(visited):
        return new
    at = keyset.searchsorted(visited, new) + np.arange(len(new))
    out = np.empty(len(visited) + len(new), dtype=visited.dtype)
    rest = np.ones(len(out), dtype=bool)
    rest[at] = False
    out[at] = new
    out[rest] = visited
    return out


def followed(fits: np.ndarray, flags: np.ndarray, after_violation: str, prune: int = CORE_FLAGS) -> np.ndarray:
    """The transitions the search follows: inside the bound and, unless ``after_violation`` is
    ``"continue"``, violating none of the step lemmas of ``prune`` (the rule set's safety,
    :func:`fatline_verify.rules.registry.lemma_flags`; a registered lemma never prunes:
    :mod:`fatline_verify.lemmas.registry`)."""
    return fits if after_violation == "continue" else fits & ((flags & prune) == 0)  # type: ignore[no-any-return]


def _concat(parts: list[np.ndarray], dtype: object) -> np.ndarray:
    return np.concatenate(parts) if parts else np.zeros(0, dtype=dtype)  # type: ignore[call-overload]


__all__ = [
    "COLUMNS",
    "Level",
    "Shard",
    "Transitions",
    "enabled_dtype",
    "fold_summaries",
    "followed",
    "owners",
    "summarise",
]
