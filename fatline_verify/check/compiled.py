"""The compiled engine: the round systems' successor function as numba kernels, in two passes.

It computes exactly what :class:`~fatline_verify.check.fast.FastEngine` computes (same transitions,
same order, same flags) and keeps the same principle: **the executable model decides**. The kernels
never decide a move or a collision themselves; they only look answers up in caches that Python fills
from the model:

- a robot's decision depends only on its snapshot, packed into an int64 key exactly as the fast engine
  packs it (sorted lattice cell codes of the visible robots); a snapshot never seen goes through the
  model's own ``decide`` (``model.algorithm`` when set) and its ``(dx, dy, corner)`` is cached;
- whether two robots collide in a round depends only on their offset and each one's relative path (or
  rest); per pair there are three cases (only i moves, only j, both), keyed as the fast engine keys
  them; a key never seen goes through :func:`~fatline_verify.schedulers.round.closest_dist2` and
  :func:`~fatline_verify.schedulers.round.collides` and its answer is cached.

Both caches are open-addressing int64 hash tables in plain numpy arrays (linear probing, Fibonacci
hashing, each slot's key and values side by side, load at most 1/2, grown by rehash), so a cache hit
is a few memory reads inside a kernel and never a Python call. A call runs in two passes:

1. **analyse** (:func:`_analyse`): per state, the snapshot keys and their decisions, the enabled robots,
   the pair keys of the cases some offered activation set uses and their answers, connectivity and the
   goal. Keys missing from a cache are reported; Python asks the model about them (each distinct key
   once), inserts the answers and re-runs the pass on the states that had misses only (decisions
   first, then the pair keys that depend on them).
2. **expand** (:func:`_expand`): per state and offered activation set (a table of valid masks per
   enabled mask, from the scheduler's own ``valid`` once per robot count), the positions after, the
   collision flag from the per-pair answers, lost connectivity, the RMA flag, and either the successor
   itself (:meth:`CompiledEngine.expand`) or its canonical form's key in a codec, with the bound check
   (:meth:`CompiledEngine.expand_keys`, which never materialises the successors).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import isqrt
from typing import Any

import numpy as np
from numba import njit

from ..goals.registry import NO_KERNEL, judge_batch, kernel_of
from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.lattice import KeyCodec, RankedCodec
from ..rules.registry import decider
from ..schedulers.base import Expansion, KeyExpansion
from .compiled_common import Events, Rows, at_goal, connected, settle
from .fast import pair_collides, snapshot_cells
from .hashtable import HashTable, distinct, find
from .keys import snapshot_key
from .offlattice import lattice_move

_CORNER_NONE, _CORNER_H, _CORNER_V = 0, 1, 2


# --- per-state analysis -------------------------------------------------------------------------
@njit(cache=True)
def _decode_ranked(keys: np.ndarray, n: int, h: int, cum: np.ndarray) -> np.ndarray:
    """Canonical states ``(m, n, 2)`` of ranked keys (as :meth:`RankedCodec.decode`)."""
    out = np.empty((len(keys), n, 2), dtype=np.int64)
    top = cum.shape[1] - 1
    for s in range(len(keys)):
        rest = keys[s]
        prev = 0
        for i in range(n):
            target = rest + cum[i, prev]
            lo, hi = prev, top  # the largest d with cum[i, d] <= target
            while lo < hi:
                mid = (lo + hi + 1) // 2
                if cum[i, mid] <= target:
                    lo = mid
                else:
                    hi = mid - 1
            rest -= cum[i, lo] - cum[i, prev]
            code = lo - i
            out[s, i, 0] = code // h
            out[s, i, 1] = code % h
            prev = lo + 1
    return out


@njit(cache=True)
def _decode(keys: np.ndarray, n: int, bits: int, h: int) -> np.ndarray:
    """Canonical states ``(m, n, 2)`` of codec keys (as :meth:`KeyCodec.decode`)."""
    out = np.empty((len(keys), n, 2), dtype=np.int64)
    mask = (1 << bits) - 1
    for s in range(len(keys)):
        key = keys[s]
        for k in range(n - 1, -1, -1):
            code = key & mask
            key >>= bits
            out[s, k, 0] = code // h
            out[s, k, 1] = code % h
    return out


@njit(cache=True)
def _pair_key(ox: int, oy: int, ax: int, ay: int, ca: int, bx: int, by: int, cb: int) -> int:
    """The fast engine's relative-motion key: six 8-bit fields (offset, move a, move b), two corner kinds."""
    key = ox + 128
    key = (key << 8) | (oy + 128)
    key = (key << 8) | (ax + 128)
    key = (key << 8) | (ay + 128)
    key = (key << 8) | (bx + 128)
    key = (key << 8) | (by + 128)
    return ((key << 2 | ca) << 2) | cb


@njit(cache=True)
def _analyse(
    states: np.ndarray,
    view2: int,
    reach: int,
    side: int,
    cell_bits: int,
    dtab: np.ndarray,
    dshift: int,
    ptab: np.ndarray,
    pshift: int,
    pi: np.ndarray,
    pj: np.ndarray,
    need: np.ndarray,
    goal_kind: int,
    width: int,
    dest: np.ndarray,
    corner: np.ndarray,
    enabled: np.ndarray,
    coll: np.ndarray,
    conn: np.ndarray,
    goal: np.ndarray,
    status: np.ndarray,
    miss_snap: np.ndarray,
    miss_pair: np.ndarray,
) -> tuple[int, int, int]:
    """Pass 1 over ``states``: fills ``dest``/``corner``/``enabled``/``coll``/``conn``/``goal`` and
    ``status`` (0 complete, 1 a decision missing, 2 a pair answer missing); returns the numbers of
    missing snapshot and pair keys written to ``miss_snap``/``miss_pair`` and 1 when a pair field
    exceeds the 8-bit packing (else 0)."""
    m, n = states.shape[0], states.shape[1]
    n_pairs = len(pi)
    codes = np.empty(max(n - 1, 1), dtype=np.int64)
    nbrs = np.empty(n, dtype=np.int64)
    n_snap, n_pair, err = 0, 0, 0
    for s in range(m):
        st = 0
        for i in range(n):
            key = snapshot_key(states[s], i, view2, reach, side, cell_bits, codes)
            slot = find(dtab, dshift, key)
            if slot < 0:
                miss_snap[n_snap] = key
                n_snap += 1
                st = 1
            else:
                dest[s, i, 0] = dtab[slot, 1]
                dest[s, i, 1] = dtab[slot, 2]
                corner[s, i] = dtab[slot, 3]
        conn[s] = connected(states[s], view2, nbrs)
        goal[s] = at_goal(states[s], goal_kind, width)
        if st == 0:
            e = 0
            for i in range(n):
                if dest[s, i, 0] != 0 or dest[s, i, 1] != 0:
                    e |= 1 << i
            enabled[s] = e
            for p in range(n_pairs):
                i, j = pi[p], pj[p]
                ox = states[s, j, 0] - states[s, i, 0]
                oy = states[s, j, 1] - states[s, i, 1]
                ax, ay, ca = dest[s, i, 0], dest[s, i, 1], corner[s, i]
                bx, by, cb = dest[s, j, 0], dest[s, j, 1], corner[s, j]
                if max(ox, oy, ax, ay, bx, by) > 127 or min(ox, oy, ax, ay, bx, by) < -128:
                    err = 1
                    st = 3
                    break
                for cs in range(3):
                    coll[s, p, cs] = -1
                    if not need[e, p, cs]:
                        continue
                    ua, ub = cs != 1, cs != 0  # i moves (cases 0, 2), j moves (cases 1, 2)
                    key = _pair_key(
                        ox, oy, ax if ua else 0, ay if ua else 0, ca if ua else 0, bx if ub else 0, by if ub else 0,
                        cb if ub else 0,
                    )  # fmt: skip
                    slot = find(ptab, pshift, key)
                    if slot < 0:
                        miss_pair[n_pair] = key
                        n_pair += 1
                        st = 2
                    else:
                        coll[s, p, cs] = ptab[slot, 1]
        status[s] = st
    return n_snap, n_pair, err


# --- expansion ----------------------------------------------------------------------------------
@njit(cache=True)
def _expand(
    states: np.ndarray,
    dest: np.ndarray,
    enabled: np.ndarray,
    coll: np.ndarray,
    conn: np.ndarray,
    vstart: np.ndarray,
    vmasks: np.ndarray,
    offsets: np.ndarray,
    pi: np.ndarray,
    pj: np.ndarray,
    view2: int,
    flag_collision: int,
    flag_connectivity: int,
    flag_rma: int,
    want_after: bool,
    want_keys: bool,
    w: int,
    h: int,
    bits: int,
    cum: np.ndarray,
    src: np.ndarray,
    action: np.ndarray,
    flags: np.ndarray,
    after: np.ndarray,
    keys: np.ndarray,
    fits: np.ndarray,
) -> None:
    """Pass 2: every offered activation set of every state, in (state, mask) order from ``offsets``."""
    m, n = states.shape[0], states.shape[1]
    n_pairs = len(pi)
    a = np.empty((n, 2), dtype=np.int64)
    nbrs = np.empty(n, dtype=np.int64)
    codes = np.empty(n, dtype=np.int64)
    for s in range(m):
        e = enabled[s]
        t = offsets[s]
        rma = states[s, 0, 0]
        for i in range(1, n):
            rma = max(rma, states[s, i, 0])
        for q in range(vstart[e], vstart[e + 1]):
            mask = vmasks[q]
            f = 0
            crossed = False
            for i in range(n):
                xb = states[s, i, 0]
                if (mask >> i) & 1:
                    a[i, 0] = xb + dest[s, i, 0]
                    a[i, 1] = states[s, i, 1] + dest[s, i, 1]
                else:
                    a[i, 0] = xb
                    a[i, 1] = states[s, i, 1]
                xa = a[i, 0]
                if xa > rma or (xb == rma and xa != rma):
                    crossed = True
            for p in range(n_pairs):
                ai = (mask >> pi[p]) & 1
                aj = (mask >> pj[p]) & 1
                if ai and aj:
                    cs = 2
                elif ai:
                    cs = 0
                elif aj:
                    cs = 1
                else:
                    continue
                if coll[s, p, cs] == 1:
                    f |= flag_collision
                    break
            if conn[s] and not connected(a, view2, nbrs):
                f |= flag_connectivity
            if crossed:
                f |= flag_rma
            src[t] = s
            action[t] = mask
            flags[t] = f
            if want_after:
                for i in range(n):
                    after[t, i, 0] = a[i, 0]
                    after[t, i, 1] = a[i, 1]
            if want_keys:
                mnx, mny, mxx, mxy = a[0, 0], a[0, 1], a[0, 0], a[0, 1]
                for i in range(1, n):
                    mnx = min(mnx, a[i, 0])
                    mny = min(mny, a[i, 1])
                    mxx = max(mxx, a[i, 0])
                    mxy = max(mxy, a[i, 1])
                if mxx - mnx < w and mxy - mny < h:
                    for i in range(n):
                        code = (a[i, 0] - mnx) * h + (a[i, 1] - mny)
                        k = i
                        while k > 0 and codes[k - 1] > code:
                            codes[k] = codes[k - 1]
                            k -= 1
                        codes[k] = code
                    key = 0
                    if cum.shape[0]:  # ranked (:class:`RankedCodec`): the lexicographic rank of the codes
                        prev = 0
                        for i in range(n):
                            d = codes[i] + i
                            key += cum[i, d] - cum[i, prev]
                            prev = d + 1
                    else:
                        for i in range(n):
                            key = (key << bits) | codes[i]
                    keys[t] = key
                    fits[t] = True
                else:
                    keys[t] = 0
                    fits[t] = False
            t += 1


# --- the engine ---------------------------------------------------------------------------------
@dataclass(slots=True)
class _Tables:
    """What depends only on the robot count: pairs, offered masks per enabled mask, needed pair cases."""

    pi: np.ndarray
    pj: np.ndarray
    vstart: np.ndarray
    vmasks: np.ndarray
    vcount: np.ndarray
    need: np.ndarray


@dataclass(slots=True)
class _Analysis(Rows):
    """Pass 1's per-state results: decisions, enabled robots, pair answers (``coll[s, p, case]``: 1
    collides, 0 not, -1 not needed or not known yet), connectivity, goal, and what is still missing."""

    dest: np.ndarray
    corner: np.ndarray
    enabled: np.ndarray
    coll: np.ndarray
    conn: np.ndarray
    goal: np.ndarray
    status: np.ndarray

    @classmethod
    def empty(cls, m: int, n: int, n_pairs: int) -> _Analysis:
        return cls(
            np.zeros((m, n, 2), dtype=np.int64),
            np.zeros((m, n), dtype=np.int64),
            np.zeros(m, dtype=np.int64),
            np.full((m, n_pairs, 3), -1, dtype=np.int8),
            np.zeros(m, dtype=np.bool_),
            np.zeros(m, dtype=np.bool_),
            np.zeros(m, dtype=np.int8),
        )


class CompiledEngine:
    """Compiled engine of the round systems; produces exactly the fast (and scalar) engine's expansion."""

    name = "compiled"

    def __init__(self, system: Any) -> None:
        self.system = system
        self.model: Model = system.model
        model = self.model
        self.rounds = system.rounds
        self.rule = decider(model)
        self.view2 = model.view2
        self.reach = isqrt(self.view2)
        self.side = 2 * self.reach + 1
        self.cell_bits = int(self.side * self.side).bit_length()
        self.goal_kind = kernel_of(model)
        self.width = 2 * model.radius
        self.decisions = HashTable(3)  # dx, dy, corner kind
        self.pairs = HashTable(1)  # collides?
        self._tables: dict[int, _Tables] = {}
        self._counts: set[int] = set()
        self._kept = (0, 0)

    # --- answers kept between runs (:mod:`.answers`) ---------------------------------------------
    def _remember(self, n: int) -> None:
        """On the first batch: the answers an earlier run for this model and robot count kept."""
        from .answers import answers_path, load_answers

        self._counts.add(n)
        got = load_answers(answers_path(self.model, n)) if len(self._counts) == 1 and not len(self.decisions) else None
        if got is not None:
            for table, rows in ((self.decisions, got["decisions"]), (self.pairs, got["pairs"])):
                if len(rows):
                    table.insert(rows[:, 0], rows[:, 1:])
        self._kept = (len(self.decisions), len(self.pairs))

    def save_answers(self) -> None:
        """Keep the answers for the next run (one robot count per file; nothing new, nothing written)."""
        from .answers import answers_path, save_answers

        if len(self._counts) != 1 or (len(self.decisions), len(self.pairs)) == self._kept:
            return
        (n,) = self._counts
        d, p = self.decisions.slots, self.pairs.slots
        save_answers(answers_path(self.model, n), d[d[:, 0] != -1], p[p[:, 0] != -1])
        self._kept = (len(self.decisions), len(self.pairs))

    # --- per robot count -----------------------------------------------------------------------
    def _tables_for(self, n: int) -> _Tables:
        got = self._tables.get(n)
        if got is not None:
            return got
        ii, jj = np.triu_indices(n, 1)
        masks = np.arange(1, 1 << n, dtype=np.int64)
        every = np.arange(1 << n, dtype=np.int64)
        valid = np.asarray(self.rounds.valid(masks, every), dtype=bool)  # (2^n, 2^n - 1)
        vcount = valid.sum(axis=1).astype(np.int64)
        vstart = np.concatenate([[0], np.cumsum(vcount)]).astype(np.int64)
        _, cols = np.nonzero(valid)  # row-major: by enabled mask, then mask ascending
        vmasks = masks[cols].astype(np.int64)
        a_i = (masks[:, None] >> ii[None, :]) & 1 == 1  # (2^n - 1, P)
        a_j = (masks[:, None] >> jj[None, :]) & 1 == 1
        case = np.where(a_i & a_j, 2, np.where(a_i, 0, np.where(a_j, 1, -1)))
        need = np.zeros((1 << n, len(ii), 3), dtype=np.bool_)
        for c in range(3):
            need[:, :, c] = (valid.astype(np.int64) @ (case == c).astype(np.int64)) > 0
        got = _Tables(ii.astype(np.int64), jj.astype(np.int64), vstart, vmasks, vcount, need)
        self._tables[n] = got
        return got

    # --- the model's answers, for keys never seen ----------------------------------------------
    def _decode_snapshot(self, key: int, n: int) -> list[tuple[int, int]]:
        return snapshot_cells(key, n, self.cell_bits, self.side, self.reach)

    def _learn_decisions(self, keys: np.ndarray, n: int) -> None:
        keys = distinct(keys)
        rows = np.zeros((len(keys), 3), dtype=np.int64)
        for r, key in enumerate(keys.tolist()):
            d = self.rule(self._decode_snapshot(key, n), self.model)
            dest = lattice_move("compiled", d)
            kind = _CORNER_NONE
            if len(d.path) == 3:
                kind = _CORNER_H if d.path[1][1] == 0 else _CORNER_V
            rows[r] = (dest[0], dest[1], kind)
        self.decisions.insert(keys, rows)

    def _pair_answer(self, key: int) -> int:
        return pair_collides(key, self.model)

    def _learn_pairs(self, keys: np.ndarray) -> None:
        keys = distinct(keys)
        rows = np.array([self._pair_answer(k) for k in keys.tolist()], dtype=np.int64).reshape(-1, 1)
        self.pairs.insert(keys, rows)

    # --- pass 1 ---------------------------------------------------------------------------------
    def _run_analyse(self, states: np.ndarray, tables: _Tables) -> tuple[_Analysis, tuple[np.ndarray, np.ndarray, int]]:
        m, n, _ = states.shape
        out = _Analysis.empty(m, n, len(tables.pi))
        miss_snap = np.empty(m * n, dtype=np.int64)
        miss_pair = np.empty(m * len(tables.pi) * 3, dtype=np.int64)
        d, p = self.decisions, self.pairs
        n_snap, n_pair, err = _analyse(
            states, self.view2, self.reach, self.side, self.cell_bits,
            d.slots, d.shift, p.slots, p.shift,
            tables.pi, tables.pj, tables.need, self.goal_kind, self.width,
            out.dest, out.corner, out.enabled, out.coll, out.conn, out.goal, out.status,
            miss_snap, miss_pair,
        )  # fmt: skip
        return out, (miss_snap[:n_snap], miss_pair[:n_pair], int(err))

    def _analyse(self, states: np.ndarray) -> tuple[_Analysis, _Tables]:
        """Pass 1 to completion: every decision and needed pair answer known (the model asked for the
        keys never seen), or the fast engine's error."""
        n = states.shape[1]
        if self.cell_bits * max(n - 1, 1) > 63:
            raise ValueError(f"view radius {self.reach} with {n} robots does not pack snapshots into 63 bits")
        if n not in self._counts:
            self._remember(n)
        tables = self._tables_for(n)

        def learn(misses: tuple[np.ndarray, np.ndarray, int]) -> None:
            snaps, pairs, err = misses
            if len(snaps):
                self._learn_decisions(snaps, n)
            if err:
                raise ValueError(
                    "a pair offset or move exceeds 127 lattice units; the compiled engine packs 8 bits each"
                )
            if len(pairs):
                self._learn_pairs(pairs)

        # decisions, then the pair keys that depend on them, then complete
        result = settle(states, lambda s: self._run_analyse(s, tables), learn, 3, "compiled")
        if self.goal_kind == NO_KERNEL:  # a goal without a kernel: its own checks (fallback_note says so)
            result.goal[:] = judge_batch(states, self.model)
        return result, tables

    # --- pass 2 ---------------------------------------------------------------------------------
    def _run_expand(self, states: np.ndarray, an: _Analysis, tables: _Tables, codec: KeyCodec | None) -> Events:
        n = states.shape[1]
        want_keys = codec is not None
        ev = Events.empty(tables.vcount[an.enabled], (n, 2), None, want_keys)
        w, h, bits = (codec.w, codec.h, codec.bits) if codec is not None else (0, 0, 0)
        cum = codec.cum if isinstance(codec, RankedCodec) else np.zeros((0, 1), dtype=np.int64)
        _expand(
            states, an.dest, an.enabled, an.coll, an.conn, tables.vstart, tables.vmasks, ev.offsets,
            tables.pi, tables.pj, self.view2,
            Lemma.NO_COLLISION.flag, Lemma.CONNECTIVITY.flag, Lemma.RMA_FIXED.flag,
            not want_keys, want_keys, w, h, bits, cum,
            ev.src, ev.action, ev.flags, ev.after, ev.keys, ev.fits,
        )  # fmt: skip
        return ev

    # --- the engine interface -------------------------------------------------------------------
    def expand(self, states: np.ndarray) -> Expansion:
        """The expansion of a batch of array states ``(m, n, 2)``, equal to the fast engine's."""
        states = np.ascontiguousarray(states, dtype=np.int64)
        an, tables = self._analyse(states)
        ev = self._run_expand(states, an, tables, None)
        return Expansion(an.enabled, an.goal, ev.src, ev.action, ev.after, ev.flags, np.ones(len(ev.src), dtype=bool))

    def expand_keys(self, keys: np.ndarray, codec: KeyCodec) -> KeyExpansion:
        """The expansion of the canonical states with keys ``keys`` in ``codec``, successors as canonical
        keys in ``codec``: ``expand(codec.decode(keys))`` followed by canonical form, bound check and
        encoding, without materialising the successors."""
        keys = np.ascontiguousarray(keys, dtype=np.int64)
        if isinstance(codec, RankedCodec):
            states = _decode_ranked(keys, codec.n, codec.h, codec.cum)
        else:
            states = _decode(keys, codec.n, codec.bits, codec.h)
        an, tables = self._analyse(states)
        ev = self._run_expand(states, an, tables, codec)
        exact = np.ones(len(ev.src), dtype=bool)
        return KeyExpansion(an.enabled, an.goal, ev.src, ev.action, ev.keys, ev.flags, ev.fits, exact)


__all__ = ["CompiledEngine", "HashTable", "KeyExpansion", "distinct"]
