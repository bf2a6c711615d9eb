"""The compiled engine of the asynchronous system: ASYNC's successor function as numba kernels, from
packed keys to packed keys.

It computes exactly what :class:`~fatline_verify.check.fast_async.FastAsyncEngine` computes (same
transitions, same order, same flags, same successors) and keeps its principle: **the executable model
decides**. The kernels never decide a move or a collision; they look answers up in two caches
(:class:`~fatline_verify.check.hashtable.HashTable`) that Python fills from the model, through the
fast engine's own questions to it (:meth:`FastAsyncEngine._decide`, :meth:`FastAsyncEngine._sweep_rows`):

- an idle robot's decision depends only on its snapshot of the current positions (units of ``1/K``),
  packed by :func:`~fatline_verify.check.keys.snapshot_key` as the fast engine packs it; the row is the
  fast engine's ``(dx, dy, corner, moves, on lattice)``;
- whether a move step hits a robot at rest depends only on that robot's offset from the mover's start,
  the mover's relative path and its steps done: the fast engine's sweep key.

A call runs in two passes over the batch. **analyse** (:func:`_analyse`): per state and robot, the
current position, the decision of an idle robot and the collision answer of a moving robot's next step;
keys missing from a cache are reported, Python asks the model about each distinct one and re-runs the
pass on the states that had misses. **expand** (:func:`_expand`): every event in the fast engine's
order (state, robot, move or look before stop), its flags, and either the successor in the source's
robot order (:meth:`CompiledAsyncEngine.expand`) or its canonical key in the search's
:class:`~fatline_verify.schedulers.asynchronous.AsyncCodec`, one int64 or several 64-bit words
(:meth:`CompiledAsyncEngine.expand_keys`), with the bound check, without materialising successors.

Shapes the kernels do not pack (a snapshot wider than 63 bits, a codec word of 64 bits) are delegated
whole to the fast engine, which gives the same answer.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numba import njit

from ..goals.registry import NO_KERNEL, judge_batch, kernel_of
from ..lemmas.properties import Lemma
from ..model.config import Model
from ..schedulers.asynchronous import AsyncCodec
from ..schedulers.base import Expansion, KeyExpansion
from .compiled_common import Events, Rows, at_goal, connected, settle
from .fast_async import _SWEEP_BITS, FastAsyncEngine
from .hashtable import HashTable, distinct, find
from .keys import snapshot_key


# --- one robot ----------------------------------------------------------------------------------
@njit(cache=True)
def _where(sx: int, sy: int, ex: int, ey: int, corner: int, k: int, K: int) -> tuple[int, int, bool]:
    """Where a robot is after ``k`` of ``K`` steps from ``(sx, sy)`` to ``(ex, ey)``, in the same unit,
    and whether that is exact (as :func:`~fatline_verify.schedulers.asynchronous.current_positions`)."""
    dx, dy = ex - sx, ey - sy
    if corner == 0:
        nx, ny = dx * k, dy * k
        return sx + nx // K, sy + ny // K, nx % K == 0 and ny % K == 0
    adx, ady = abs(dx), abs(dy)
    gx = 1 if dx > 0 else (-1 if dx < 0 else 0)
    gy = 1 if dy > 0 else (-1 if dy < 0 else 0)
    along = (adx + ady) * k
    dist = along // K
    exact = along % K == 0
    if corner == 1:  # horizontal first
        if dist <= adx:
            return sx + gx * dist, sy, exact
        return ex, sy + gy * (dist - adx), exact
    if dist <= ady:
        return sx, sy + gy * dist, exact
    return sx + gx * (dist - ady), ey, exact


@njit(cache=True)
def _decode(words: np.ndarray, n: int, bits: int, per_word: int, K: int, wf: int, hf: int) -> np.ndarray:
    """Canonical array states ``(m, n, 6)`` of codec keys given as int64 words ``(m, words)``."""
    m, nw = words.shape
    out = np.empty((m, n, 6), dtype=np.int64)
    mask = (1 << bits) - 1
    last = n - (nw - 1) * per_word
    w = np.empty(nw, dtype=np.int64)
    for s in range(m):
        for q in range(nw):
            w[q] = words[s, q]
        if nw > 1:
            w[nw - 1] >>= bits * (per_word - last)
        for r in range(n - 1, -1, -1):
            q = r // per_word if nw > 1 else 0
            code = w[q] & mask
            w[q] >>= bits
            out[s, r, 5] = code % K
            code //= K
            out[s, r, 4] = code % 3
            code //= 3
            out[s, r, 3] = code % hf
            code //= hf
            out[s, r, 2] = code % wf
            code //= wf
            out[s, r, 1] = code % hf
            out[s, r, 0] = code // hf
    return out


# --- pass 1 -------------------------------------------------------------------------------------
@njit(cache=True)
def _analyse(
    states: np.ndarray,
    K: int,
    view2: int,
    reach: int,
    side: int,
    cell_bits: int,
    near: int,
    dtab: np.ndarray,
    dshift: int,
    stab: np.ndarray,
    sshift: int,
    pos: np.ndarray,
    dec: np.ndarray,
    hit: np.ndarray,
    status: np.ndarray,
    miss_snap: np.ndarray,
    miss_sweep: np.ndarray,
) -> tuple[int, int, int]:
    """Per state: ``pos`` (current positions, units of ``1/K``), ``dec`` (an idle robot's decision row),
    ``hit`` (a moving robot's next step collides) and ``status`` (0 complete, 1 a key missing). Returns
    the numbers of missing snapshot and sweep keys and 1 when a sweep field exceeds its packing."""
    m, n = states.shape[0], states.shape[1]
    codes = np.empty(max(n - 1, 1), dtype=np.int64)
    half = 1 << (_SWEEP_BITS - 1)
    n_snap, n_sweep, err = 0, 0, 0
    for s in range(m):
        st = 0
        for i in range(n):
            x, y, _ = _where(
                states[s, i, 0], states[s, i, 1], states[s, i, 2], states[s, i, 3], states[s, i, 4],
                states[s, i, 5], K,
            )  # fmt: skip
            pos[s, i, 0] = x
            pos[s, i, 1] = y
        for i in range(n):
            sx, sy, ex, ey = states[s, i, 0], states[s, i, 1], states[s, i, 2], states[s, i, 3]
            hit[s, i] = 0
            if sx == ex and sy == ey:
                key = snapshot_key(pos[s], i, view2, reach, side, cell_bits, codes)
                slot = find(dtab, dshift, key)
                if slot < 0:
                    miss_snap[n_snap] = key
                    n_snap += 1
                    st = 1
                else:
                    for c in range(5):
                        dec[s, i, c] = dtab[slot, 1 + c]
                continue
            dx, dy = ex - sx, ey - sy
            lox, hix = min(dx, 0), max(dx, 0)
            loy, hiy = min(dy, 0), max(dy, 0)
            corner, k = states[s, i, 4], states[s, i, 5]
            for j in range(n):
                if j == i:
                    continue
                ox, oy = pos[s, j, 0] - sx, pos[s, j, 1] - sy
                if max(lox - ox, ox - hix, 0) > near or max(loy - oy, oy - hiy, 0) > near:
                    continue
                if min(ox, oy, dx, dy) < -half or max(ox, oy, dx, dy) >= half:
                    err = 1
                    continue
                key = ox + half
                key = (key << _SWEEP_BITS) | (oy + half)
                key = (key << _SWEEP_BITS) | (dx + half)
                key = (key << _SWEEP_BITS) | (dy + half)
                key = ((key << 2 | corner) << 4) | k
                slot = find(stab, sshift, key)
                if slot < 0:
                    miss_sweep[n_sweep] = key
                    n_sweep += 1
                    st = 1
                elif stab[slot, 1] != 0:
                    hit[s, i] = 1
        status[s] = st
    return n_snap, n_sweep, err


@njit(cache=True)
def _counts(states: np.ndarray, dec: np.ndarray, rigid: bool, enabled: np.ndarray, counts: np.ndarray) -> None:
    """Per state, the enabled robots (bitmask) and the number of events offered."""
    m, n = states.shape[0], states.shape[1]
    for s in range(m):
        e, c = 0, 0
        for i in range(n):
            moving = states[s, i, 0] != states[s, i, 2] or states[s, i, 1] != states[s, i, 3]
            if moving or dec[s, i, 3] != 0:
                e |= 1 << i
                c += 1
            if moving and not rigid and states[s, i, 5] >= 1:
                c += 1
        enabled[s] = e
        counts[s] = c


# --- pass 2 -------------------------------------------------------------------------------------
@njit(cache=True)
def _expand(
    states: np.ndarray,
    pos: np.ndarray,
    dec: np.ndarray,
    hit: np.ndarray,
    offsets: np.ndarray,
    K: int,
    rigid: bool,
    view2: int,
    goal_kind: int,
    width: int,
    flag_collision: int,
    flag_connectivity: int,
    flag_rma: int,
    want_after: bool,
    want_keys: bool,
    wf: int,
    hf: int,
    bits: int,
    per_word: int,
    goal: np.ndarray,
    src: np.ndarray,
    action: np.ndarray,
    flags: np.ndarray,
    exact: np.ndarray,
    after: np.ndarray,
    keys: np.ndarray,
    fits: np.ndarray,
) -> None:
    """Every offered event of every state, in the fast engine's order, from ``offsets``."""
    m, n = states.shape[0], states.shape[1]
    nw = keys.shape[1]
    row = np.empty((n, 6), dtype=np.int64)
    fine = np.empty((n, 2), dtype=np.int64)
    codes = np.empty(n, dtype=np.int64)
    nbrs = np.empty(n, dtype=np.int64)
    view2_fine = view2 * K * K
    for s in range(m):
        t = offsets[s]
        moving_any = False
        rma = pos[s, 0, 0]
        for i in range(n):
            rma = max(rma, pos[s, i, 0])
            if states[s, i, 0] != states[s, i, 2] or states[s, i, 1] != states[s, i, 3]:
                moving_any = True
        goal[s] = (not moving_any) and at_goal(states[s, :, 0:2], goal_kind, width)
        conn = connected(pos[s], view2, nbrs)
        rma *= K
        for i in range(n):
            moving = states[s, i, 0] != states[s, i, 2] or states[s, i, 1] != states[s, i, 3]
            for slot in range(2):
                if slot == 0 and not (moving or dec[s, i, 3] != 0):
                    continue
                if slot == 1 and not (moving and not rigid and states[s, i, 5] >= 1):
                    continue
                for r in range(n):
                    for c in range(6):
                        row[r, c] = states[s, r, c]
                ok = True
                f = 0
                hx, hy = pos[s, i, 0], pos[s, i, 1]
                if slot == 1:  # stop: idle where it is
                    row[i, 0], row[i, 1], row[i, 2], row[i, 3], row[i, 4], row[i, 5] = hx, hy, hx, hy, 0, 0
                elif not moving:  # look: a move starts from here
                    row[i, 0], row[i, 1] = hx, hy
                    row[i, 2], row[i, 3] = hx + dec[s, i, 0], hy + dec[s, i, 1]
                    row[i, 4], row[i, 5] = dec[s, i, 2], 0
                    ok = dec[s, i, 4] != 0
                else:  # move: one step, the new position in units of 1/K^2
                    k1 = states[s, i, 5] + 1
                    nx, ny, _ = _where(
                        states[s, i, 0] * K, states[s, i, 1] * K, states[s, i, 2] * K, states[s, i, 3] * K,
                        states[s, i, 4], k1, K,
                    )  # fmt: skip
                    ok = nx % K == 0 and ny % K == 0
                    row[i, 5] = k1
                    if k1 == K:
                        row[i, 0], row[i, 1], row[i, 4], row[i, 5] = states[s, i, 2], states[s, i, 3], 0, 0
                    if hit[s, i] != 0:
                        f |= flag_collision
                    if conn:
                        for r in range(n):
                            fine[r, 0] = pos[s, r, 0] * K
                            fine[r, 1] = pos[s, r, 1] * K
                        fine[i, 0], fine[i, 1] = nx, ny
                        if not connected(fine, view2_fine, nbrs):
                            f |= flag_connectivity
                    xb = pos[s, i, 0] * K
                    if nx > rma or (xb == rma and nx != rma):
                        f |= flag_rma
                src[t] = s
                action[t] = (1 << i) | ((1 << n) if slot == 1 else 0)
                flags[t] = f
                exact[t] = ok
                if want_after:
                    for r in range(n):
                        for c in range(6):
                            after[t, r, c] = row[r, c] if ok else 0
                if want_keys:
                    for q in range(nw):
                        keys[t, q] = 0
                    lx, ly = min(row[0, 0], row[0, 2]), min(row[0, 1], row[0, 3])
                    for r in range(1, n):
                        lx = min(lx, row[r, 0], row[r, 2])
                        ly = min(ly, row[r, 1], row[r, 3])
                    inside = ok
                    for r in range(n):
                        if max(row[r, 0], row[r, 2]) - lx >= wf or max(row[r, 1], row[r, 3]) - ly >= hf:
                            inside = False
                    fits[t] = inside
                    if inside:
                        for r in range(n):
                            code = (row[r, 0] - lx) * hf + row[r, 1] - ly
                            code = (code * wf + row[r, 2] - lx) * hf + row[r, 3] - ly
                            code = (code * 3 + row[r, 4]) * K + row[r, 5]
                            k = r
                            while k > 0 and codes[k - 1] > code:
                                codes[k] = codes[k - 1]
                                k -= 1
                            codes[k] = code
                        for r in range(n):
                            q = r // per_word if nw > 1 else 0
                            keys[t, q] = (keys[t, q] << bits) | codes[r]
                        if nw > 1:
                            keys[t, nw - 1] <<= bits * (per_word - (n - (nw - 1) * per_word))
                t += 1


# --- the engine ---------------------------------------------------------------------------------
@dataclass(slots=True)
class _Analysis(Rows):
    """Pass 1's per-state results: current positions (units of ``1/K``), an idle robot's decision row, a
    moving robot's next step collides, and what is still missing."""

    pos: np.ndarray
    dec: np.ndarray
    hit: np.ndarray
    status: np.ndarray


class CompiledAsyncEngine:
    """Compiled engine of the asynchronous system; produces exactly the fast (and scalar) engine's
    expansion, and the search step from keys to keys."""

    name = "compiled"

    def __init__(self, system: Any) -> None:
        self.system = system
        self.model: Model = system.model
        self.fast = FastAsyncEngine(system)
        """The model's answers for keys never seen, and the shapes the kernels do not pack."""
        self.K: int = system.K
        self.rigid: bool = system.rigid
        f = self.fast
        self.view2, self.reach, self.side, self.cell_bits, self.near = f.view2, f.reach, f.side, f.cell_bits, f.near
        self.goal_kind = kernel_of(self.model)
        self.width = 2 * self.model.radius * self.K
        self.decisions = HashTable(5)  # the fast engine's decision row
        self.sweeps = HashTable(1)  # collides?

    def packs(self, n: int, codec: AsyncCodec | None = None) -> bool:
        """Whether the kernels pack ``n`` robots' snapshots (and ``codec``'s keys) into int64 words."""
        if self.cell_bits * max(n - 1, 1) > 63:
            return False
        return codec is None or codec.bits * codec.per_word <= 63

    # --- the model's answers, for keys never seen ----------------------------------------------
    def _learn_decisions(self, keys: np.ndarray, n: int) -> None:
        keys = distinct(keys)
        mask = (1 << self.cell_bits) - 1
        codes = np.empty((len(keys), max(n - 1, 0)), dtype=np.int64)
        rest = keys.copy()
        for k in range(n - 2, -1, -1):
            codes[:, k] = rest & mask
            rest >>= self.cell_bits
        self.decisions.insert(keys, self.fast._decide(codes))

    def _learn_sweeps(self, keys: np.ndarray) -> None:
        keys = distinct(keys)
        half, fmask = 1 << (_SWEEP_BITS - 1), (1 << _SWEEP_BITS) - 1
        k, corner = keys & 15, (keys >> 4) & 3
        rest = keys >> 6
        dy = (rest & fmask) - half
        dx = ((rest >> _SWEEP_BITS) & fmask) - half
        oy = ((rest >> (2 * _SWEEP_BITS)) & fmask) - half
        ox = ((rest >> (3 * _SWEEP_BITS)) & fmask) - half
        self.sweeps.insert(keys, self.fast._sweep_rows(ox, oy, np.stack([dx, dy], axis=1), corner, k))

    # --- pass 1 ---------------------------------------------------------------------------------
    def _run_analyse(self, states: np.ndarray) -> tuple[_Analysis, tuple[np.ndarray, np.ndarray]]:
        m, n, _ = states.shape
        out = _Analysis(
            np.zeros((m, n, 2), dtype=np.int64),
            np.zeros((m, n, 5), dtype=np.int64),
            np.zeros((m, n), dtype=np.int8),
            np.zeros(m, dtype=np.int8),
        )
        miss_snap = np.empty(m * n, dtype=np.int64)
        miss_sweep = np.empty(m * n * n, dtype=np.int64)
        d, w = self.decisions, self.sweeps
        n_snap, n_sweep, err = _analyse(
            states, self.K, self.view2, self.reach, self.side, self.cell_bits, self.near,
            d.slots, d.shift, w.slots, w.shift, out.pos, out.dec, out.hit, out.status, miss_snap, miss_sweep,
        )  # fmt: skip
        if err:
            half = 1 << (_SWEEP_BITS - 1)
            raise ValueError(
                f"a move or offset exceeds {half - 1} units of 1/{self.K}; "
                f"the fast engine packs {_SWEEP_BITS} bits each"
            )
        return out, (miss_snap[:n_snap], miss_sweep[:n_sweep])

    def _analyse(self, states: np.ndarray) -> _Analysis:
        """Pass 1 to completion: every decision and sweep answer known (the model asked for the keys
        never seen)."""
        n = states.shape[1]

        def learn(misses: tuple[np.ndarray, np.ndarray]) -> None:
            snaps, sweeps = misses
            if len(snaps):
                self._learn_decisions(snaps, n)
            if len(sweeps):
                self._learn_sweeps(sweeps)

        # learn, then complete (decisions and sweeps do not depend on each other)
        return settle(states, self._run_analyse, learn, 2, "compiled ASYNC")

    # --- pass 2 ---------------------------------------------------------------------------------
    def _run(self, states: np.ndarray, codec: AsyncCodec | None) -> tuple[np.ndarray, ...]:
        m, n, _ = states.shape
        an = self._analyse(states)
        enabled = np.zeros(m, dtype=np.int64)
        counts = np.zeros(m, dtype=np.int64)
        _counts(states, an.dec, self.rigid, enabled, counts)
        want_keys = codec is not None
        ev = Events.empty(counts, (n, 6), codec.words if codec is not None else 1, want_keys)
        goal = np.zeros(m, dtype=np.bool_)
        exact = np.empty(len(ev.src), dtype=np.bool_)
        wf, hf, bits, per_word = (codec.wf, codec.hf, codec.bits, codec.per_word) if codec else (1, 1, 1, 1)
        _expand(
            states, an.pos, an.dec, an.hit, ev.offsets, self.K, self.rigid, self.view2, self.goal_kind, self.width,
            Lemma.NO_COLLISION.flag, Lemma.CONNECTIVITY.flag, Lemma.RMA_FIXED.flag,
            not want_keys, want_keys, wf, hf, bits, per_word,
            goal, ev.src, ev.action, ev.flags, exact, ev.after, ev.keys, ev.fits,
        )  # fmt: skip
        if self.goal_kind == NO_KERNEL:  # a goal without a kernel: its own checks, on the robots at rest
            idle = (states[..., 0:2] == states[..., 2:4]).all(axis=(1, 2))
            goal[idle] = judge_batch(states[idle, :, 0:2], self.model, self.K)
        return enabled, goal, ev.src, ev.action, ev.flags, exact, ev.after, ev.keys, ev.fits

    # --- the engine interface -------------------------------------------------------------------
    def expand(self, states: np.ndarray) -> Expansion:
        """The expansion of a batch of array states ``(m, n, 6)``, equal to the fast engine's."""
        states = np.ascontiguousarray(states, dtype=np.int64)
        if not self.packs(states.shape[1]):
            return self.fast.expand(states)
        enabled, goal, src, action, flags, exact, after, _, _ = self._run(states, None)
        return Expansion(enabled, goal, src, action, after, flags, exact)

    def expand_keys(self, keys: np.ndarray, codec: AsyncCodec) -> KeyExpansion:
        """The expansion of the canonical states with keys ``keys`` in ``codec``, successors as canonical
        keys in ``codec``: what decode, :meth:`expand`, canonical form, bound check and encoding give."""
        if not self.packs(codec.n, codec):
            from ..schedulers.base import expand_keys

            return expand_keys(self.system, self.fast, codec, keys)
        m = len(keys)
        if codec.words == 1:
            words = np.ascontiguousarray(keys, dtype=np.int64).reshape(m, 1)
        else:
            words = np.ascontiguousarray(keys).view(">u8").reshape(m, codec.words).astype(np.int64)
        states = _decode(words, codec.n, codec.bits, codec.per_word, self.K, codec.wf, codec.hf)
        enabled, goal, src, action, flags, exact, _, succ, fits = self._run(states, codec)
        key = succ[:, 0] if codec.words == 1 else succ.astype(">u8").view(codec.dtype).ravel()
        return KeyExpansion(enabled, goal, src, action, key, flags, fits, exact)


__all__ = ["CompiledAsyncEngine"]
