"""The memory guard of the breadth-first search (:mod:`.search`): what a level needs, measured.

The budget (``--max-memory``) bounds the search's arrays: the bytes it holds (every distinct in-memory
buffer of its columns and of its shards, counted once however many arrays show it; levels on disk not
counted: :func:`held_bytes`) plus what the running level adds at its peak, times
:data:`~fatline_verify.resources.PEAK_FACTOR` (the margin for the process itself and the engine's
caches).

**How the estimate is made.** A level's peak follows from the code that spends the bytes and three
figures: the frontier ``F``, the candidate successors the level gathers (``U`` distinct) and its new
states ``N`` (:func:`expansion_bytes`, :func:`merge_bytes`, :func:`batch_bytes`: bytes a state or
candidate, each term named in the docstring, the batch's cost measured with tracemalloc). ``F`` is
known before the level; ``U`` and ``N`` are not, and are **measured as the level runs** rather than
assumed: after every batch the shard's :class:`Watch` prices the next step (another batch, the next
consolidation of the gathered candidates, the merge) from what it has really gathered, an upper
bound of what that step spends. When a step would pass the budget, the levels move to disk first
(in the search's own process) and the step is priced again; when it still does not fit, the level
stops before the step, keeping nothing, and the search ends after the previous level, naming what
the whole level would have needed (its candidates so far, extrapolated over the frontier). So no
step is begun that the prices say passes the budget, and no level is refused on a presumed size.
With several shards each gets an equal share of the room (their levels run at once). Before the
level only its fixed part is checked (its frontier's columns, the visited set's copy in the merge, a
first batch at the earlier levels' transitions a state or a small sample's).

A **sample** of the frontier (:func:`measure`: an evenly spaced :func:`sample_size` states, expanded
by the shards, their successors de-duplicated and looked up in the visited levels) prices a whole
level in advance where the watch cannot act: shards in other processes cannot move the coordinator's
levels to disk mid-level, so for them the levels move to disk before a level whose price passes the
budget (first at a presumed rate, :func:`presumed`, then the sample's); and a level whose fixed part
does not fit is reported with the sample's price. Within a sample fewer successors coincide than
within the whole level, so its rates are upper bounds in practice (n = 7's first level: 1.9x the
distinct successors, 2x the new states; exact when the sample is the whole frontier). The old rule,
a level as large as the frontier at 40 bytes a candidate, refused n = 8's first level at ~19G; the
watch priced it at 7.2G, 1.15x what the process's peak grew (6.3G), and n = 7's levels at 1.1-1.9x
(docs/scale.md).

Neither the watch nor the sample changes the search: a stopped level keeps nothing and the sample's
expansion keeps no state, so states, ids, parents and summaries are the same under any budget that
lets the search finish (tests compare them).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..resources import PEAK_FACTOR
from . import keys as keyset

if TYPE_CHECKING:
    from .search import ShardPool

SAMPLE_MIN = 4096
"""Frontier states expanded to measure a level at least (all of them in a smaller frontier)."""

SAMPLE_SHARE = 256
"""And one in this many of a larger frontier (n = 8's first level: 450 thousand of 114 million)."""

CONSOLIDATE = 1 << 23
"""Candidate successors a level gathers before folding them into its sorted set (bounds the peak;
:meth:`.shard.Shard.expand`)."""

CONSOLIDATE_MIN = 1 << 20
"""And it folds them sooner, as soon as they outnumber the set and this (a fold's peak is per
candidate: a small level's all at once measured as the peak of a whole search at n = 6)."""

TRANSITION_BYTES = 256
"""A batch's peak bytes a transition (measured with tracemalloc: 228 at n = 5 on the paper's model,
182-205 at n = 7 on the SPIN reading)."""

FIRST_SAMPLE = 1024
"""Frontier states expanded to price the first level's first batch (no level expanded yet)."""

PRESUMED_MARGIN = 2.0
"""The pessimistic rate that spares a sample: this times the most transitions a state had on average
at any earlier level, every one of them a distinct new state."""


@dataclass(frozen=True, slots=True)
class Rates:
    """Per frontier state: the level's distinct followed successors (``candidates``) and, of them, the
    states not visited before (``new``); ``measured`` when a sample gave them."""

    candidates: float
    new: float
    measured: bool
    transitions: float = 0.0
    """Transitions per state (the sample's, or the most of an earlier level's)."""


def sample_size(frontier: int) -> int:
    """States of a frontier of ``frontier`` expanded to measure it."""
    return min(frontier, SAMPLE_MIN + frontier // SAMPLE_SHARE)


def measure(
    pool: ShardPool, levels: list[np.ndarray], frontier: np.ndarray, frontier_ids: np.ndarray, size: int | None = None
) -> Rates:
    """The rates of the level that expands ``frontier`` (ids ``frontier_ids``), measured on an evenly
    spaced sample of it (``size`` states, by default :func:`sample_size`), expanded by the pool's shards
    (a share each); ``levels`` are the visited levels' keys, each sorted."""
    size = sample_size(len(frontier)) if size is None else min(size, len(frontier))
    pick = np.unique(np.linspace(0, len(frontier) - 1, size).round().astype(np.int64))
    keys, ids = np.asarray(frontier[pick]), np.asarray(frontier_ids[pick])
    shares = np.array_split(np.arange(len(pick)), pool.count)
    got = pool.map("transitions", [(keys[s], ids[s]) for s in shares])
    successors = np.concatenate([t.key for t in got]) if got else keys[:0]
    distinct, _ = keyset.unique_first(successors)
    seen = np.zeros(len(distinct), dtype=bool)
    for level in levels:
        if len(level) and len(distinct):
            pos = np.minimum(keyset.searchsorted(level, distinct), len(level) - 1)
            seen |= np.asarray(level[pos]) == distinct
    transitions = sum(len(t.src) for t in got)
    return Rates(len(distinct) / len(pick), int((~seen).sum()) / len(pick), True, transitions / len(pick))


def presumed(summaries: list[np.ndarray], expanded: list[int]) -> Rates | None:
    """The pessimistic rates (:data:`PRESUMED_MARGIN`) from the earlier levels' transitions per expanded
    state; ``None`` before the first expansion."""
    most = per_state(summaries, expanded)
    if most is None:
        return None
    return Rates(PRESUMED_MARGIN * most, PRESUMED_MARGIN * most, False, most)


def expansion_bytes(frontier: int, candidates: int, key: int, batch: int = 0) -> int:
    """Bytes a level's expansion adds at its peak, having gathered ``candidates`` successors, with a
    batch's temporaries of ``batch`` bytes (:func:`batch_bytes`): per frontier state its id (4), enabled
    and goal (1 each), as batches and joined (x2); then the larger of the next batch beside the gathered
    candidates (key, source, action) and their consolidation (:func:`.shard._first_of`): per candidate
    the gathered columns, the joined keys, sources (8) and actions (4), ``np.unique``'s copy, sort order
    (8), merge buffer (4), sorted copy and mask (``4 key + 33``), and the result (``key + 8``, at most
    one per candidate)."""
    return frontier * 2 * (4 + 1 + 1) + max(candidates * (5 * key + 41), candidates * (key + 8) + batch)


def batch_bytes(transitions: int) -> int:
    """A batch's temporaries (the engine's expansion, the lemmas' flags, the compacted columns) for
    ``transitions`` transitions: :data:`TRANSITION_BYTES` each."""
    return transitions * TRANSITION_BYTES


def merge_bytes(frontier: int, distinct: int, new: int, visited: int, key: int, shards: int = 1) -> int:
    """Bytes the merge of a level adds at its peak (:meth:`.shard.Shard.merge`): the expansion's columns
    (6 a frontier state), the ``distinct`` routed candidates and their look-up in the visited set
    (``2 key + 25``), the ``new`` ones and their places (``key + 24``), the merged visited set of
    ``visited + new`` keys with its mask (``key + 1``); with more than one shard, the coordinator's
    numbering of the new states (``key + 40`` each)."""
    coordinator = new * (key + 40) if shards > 1 else 0
    return frontier * 6 + distinct * (2 * key + 25) + new * (key + 24) + (visited + new) * (key + 1) + coordinator


def level_bytes(frontier: int, rates: Rates, visited: int, key: int, shards: int = 1) -> int:
    """Bytes one level adds at its peak over what the search holds, for ``U = candidates * F`` distinct
    successors and ``N = min(U, new * F)`` new states: the larger of :func:`expansion_bytes` (its last
    consolidation gathering ``U`` plus at most :data:`CONSOLIDATE` pending ones) and
    :func:`merge_bytes`."""
    u = math.ceil(rates.candidates * frontier)
    n = min(u, math.ceil(rates.new * frontier))
    expansion = expansion_bytes(frontier, u + min(u, CONSOLIDATE), key)
    return max(expansion, merge_bytes(frontier, u, n, visited, key, shards))


def first_batch(frontier: int, batch: int, transitions: float) -> int:
    """What a level's first batch (``batch`` states of the frontier's) is priced at before it runs, for
    ``transitions`` a state (:func:`per_state`, or a small sample's: :func:`measure`)."""
    return batch_bytes(math.ceil(min(batch, frontier) * transitions))


def per_state(summaries: list[np.ndarray], expanded: list[int]) -> float | None:
    """The most transitions a state had on average at any earlier level (``None`` before the first)."""
    rates = [float(s[0]) / e for s, e in zip(summaries, expanded, strict=True) if e]
    return max(rates) if rates else None


def projected(held: int, frontier: int, rates: Rates, visited: int, key: int, shards: int = 1) -> int:
    """The level's projected peak: held bytes plus :func:`level_bytes`, times the peak factor."""
    return int((held + level_bytes(frontier, rates, visited, key, shards)) * PEAK_FACTOR)


@dataclass(slots=True)
class Watch:
    """A shard's level under a budget of ``room`` bytes (its share of what the search may add): before
    each step that spends memory in proportion to what the level has gathered, the step's peak is
    computed from the real figures (:meth:`fits`). When it would pass ``room``, ``spill`` (in the
    search's own process) moves the levels to disk and gives back a share of what that freed; when even
    then it does not fit, the level stops, and :attr:`needed` says what the whole level would have
    added, extrapolated from the share done."""

    room: int
    frontier: int
    visited: int
    key: int
    shards: int = 1
    spill: Callable[[], int] | None = None
    batch: int = 0
    """The largest batch's temporaries so far (:func:`batch_bytes`)."""
    needed: int = 0

    def fits(self, done: int, gathered: int, final: bool = False, transitions: int = 0) -> bool:
        """Whether the next step fits: after ``done`` frontier states, ``gathered`` candidates (at most
        that many distinct) and a batch of ``transitions`` transitions (the largest so far prices the
        next), another batch or a consolidation or, when ``final``, the merge (its new states at most
        the distinct candidates)."""
        self.batch = max(self.batch, batch_bytes(transitions))
        if final:
            peak = merge_bytes(self.frontier, gathered, gathered, self.visited, self.key, self.shards)
        else:
            peak = expansion_bytes(self.frontier, gathered, self.key, self.batch)
        if peak > self.room and self.spill is not None:
            self.room += self.spill()
            self.spill = None
        if peak <= self.room:
            return True
        whole = math.ceil(gathered * self.frontier / max(1, done))  # the rate so far, over the whole frontier
        self.needed = max(
            expansion_bytes(self.frontier, whole, self.key, self.batch),
            merge_bytes(self.frontier, whole, whole, self.visited, self.key, self.shards),
        )
        return False


def _mapped(a: np.ndarray) -> bool:
    """Whether ``a``'s memory is a memory map (a level on disk), through any chain of views."""
    while isinstance(a, np.ndarray):
        if isinstance(a, np.memmap):
            return True
        a = a.base  # type: ignore[assignment]
    return type(a).__name__ == "mmap"


def held_bytes(arrays: list[np.ndarray]) -> int:
    """Bytes of the distinct in-memory buffers behind ``arrays``: two arrays over the same bytes (the
    same address and size: one shard's frontier is the last level's keys) count once; memory maps (the
    levels on disk) not at all."""
    seen: dict[tuple[int, int], int] = {}
    for a in arrays:
        if len(a) and not _mapped(a):
            seen[(a.__array_interface__["data"][0], int(a.nbytes))] = int(a.nbytes)
    return sum(seen.values())


__all__ = [
    "CONSOLIDATE",
    "CONSOLIDATE_MIN",
    "FIRST_SAMPLE",
    "PRESUMED_MARGIN",
    "SAMPLE_MIN",
    "SAMPLE_SHARE",
    "TRANSITION_BYTES",
    "Rates",
    "Watch",
    "batch_bytes",
    "expansion_bytes",
    "first_batch",
    "held_bytes",
    "level_bytes",
    "measure",
    "merge_bytes",
    "per_state",
    "presumed",
    "projected",
    "sample_size",
]
