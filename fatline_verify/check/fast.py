"""The vectorised engine: a whole batch of states at once, with numpy.

Two facts make it fast without giving up the executable model as the single source of truth:

- A robot's decision depends only on its snapshot. Snapshots are packed into int64 keys (sorted
  lattice cell codes of the visible robots), de-duplicated with ``np.unique``, and only snapshots
  never seen before go through the model's own ``decide``; results are cached for the whole search.
- Whether two robots collide in a round depends only on their offset and on each one's relative
  path (or rest). Per state and pair there are three cases (i moves, j moves, both); these are
  keyed the same way and only new keys go through :func:`fatline_verify.schedulers.round.closest_dist2`.

Subset enumeration, positions after, connectivity, the RMA and the goal are plain array code.
"""

from __future__ import annotations

from functools import partial
from math import isqrt
from typing import Any

import numpy as np

from ..goals.registry import judge_batch
from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.lattice import KeyTable, connected
from ..rules.registry import decider
from ..schedulers.base import Expansion
from ..schedulers.round import closest_dist2, collides
from .offlattice import lattice_move

_CORNER_NONE, _CORNER_H, _CORNER_V = 0, 1, 2


def snapshot_cells(key: int, n: int, cell_bits: int, side: int, reach: int) -> list[tuple[int, int]]:
    """The visible offsets packed in a snapshot key (``n - 1`` cell codes of ``cell_bits`` bits, the
    sentinel ``side * side`` for an unseen robot); both vectorised engines pack snapshots this way."""
    sentinel = side * side
    mask = (1 << cell_bits) - 1
    out = []
    for k in range(n - 1):
        code = (key >> (cell_bits * (n - 2 - k))) & mask
        if code != sentinel:
            out.append((code // side - reach, code % side - reach))
    return out


def relative_path(dest: tuple[int, int], corner: int) -> tuple[tuple[int, int], ...]:
    """A robot's path from the origin to ``dest``: straight, or L-shaped with its corner kind."""
    if dest == (0, 0):
        return ((0, 0),)
    if corner == _CORNER_H:
        return ((0, 0), (dest[0], 0), dest)
    if corner == _CORNER_V:
        return ((0, 0), (0, dest[1]), dest)
    return ((0, 0), dest)


def pair_collides(key: int, model: Model) -> int:
    """The exact collision answer for a packed pair situation: the offset of robot j from robot i, each
    one's relative move (8 bits a field, offset by 128) and corner kinds (2 bits each)."""
    cb, key = key & 3, key >> 2
    ca, key = key & 3, key >> 2
    vals = []
    for _ in range(6):
        vals.append((key & 0xFF) - 128)
        key >>= 8
    bdy, bdx, ady, adx, oy, ox = vals
    pi = None if (adx, ady) == (0, 0) else relative_path((adx, ady), ca)
    pj = None if (bdx, bdy) == (0, 0) else tuple((x + ox, y + oy) for x, y in relative_path((bdx, bdy), cb))
    return int(collides(closest_dist2(pi, pj, (0, 0), (ox, oy), model), model))


class FastEngine:
    """Vectorised engine of the round systems; produces exactly the scalar engine's expansion."""

    name = "fast"

    def __init__(self, system: Any) -> None:
        self.system = system
        self.model: Model = system.model
        model = self.model
        self.rounds = system.rounds
        self.rule = decider(model)
        self.reach = isqrt(model.view2)
        self.side = 2 * self.reach + 1
        self.cell_bits = int(self.side * self.side).bit_length()
        self.decisions = KeyTable(3)  # dx, dy, corner kind
        self.pairs = KeyTable(1)  # collides?

    # --- decisions --------------------------------------------------------------------------
    def _snapshot_keys(self, states: np.ndarray) -> np.ndarray:
        m, n, _ = states.shape
        rel = states[:, None, :, :] - states[:, :, None, :]  # rel[s, i, j] = p_j - p_i
        d2 = (rel * rel).sum(axis=-1)
        visible = d2 <= self.model.view2
        visible[:, np.arange(n), np.arange(n)] = False
        sentinel = self.side * self.side
        codes = np.where(visible, (rel[..., 0] + self.reach) * self.side + rel[..., 1] + self.reach, sentinel)
        codes = np.sort(codes, axis=2)[:, :, : n - 1] if n > 1 else np.zeros((m, n, 0), dtype=np.int64)
        if self.cell_bits * max(n - 1, 1) > 63:
            raise ValueError(f"view radius {self.reach} with {n} robots does not pack snapshots into 63 bits")
        key = np.zeros((m, n), dtype=np.int64)
        for k in range(n - 1):
            key = (key << self.cell_bits) | codes[:, :, k]
        return key

    def _decode_snapshot(self, key: int, n: int) -> list[tuple[int, int]]:
        return snapshot_cells(key, n, self.cell_bits, self.side, self.reach)

    def _destinations(self, states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        n = states.shape[1]
        keys = self._snapshot_keys(states).ravel()

        def decide_new(first: np.ndarray) -> np.ndarray:
            rows = np.zeros((len(first), 3), dtype=np.int64)
            for r, key in enumerate(keys[first].tolist()):
                d = self.rule(self._decode_snapshot(key, n), self.model)
                dest = lattice_move("fast", d)
                corner = _CORNER_NONE
                if len(d.path) == 3:
                    corner = _CORNER_H if d.path[1][1] == 0 else _CORNER_V
                rows[r] = (dest[0], dest[1], corner)
            return rows

        got = self.decisions.lookup(keys, decide_new).reshape(*states.shape[:2], 3)
        return got[..., :2], got[..., 2]

    # --- collisions -------------------------------------------------------------------------
    def _case_table(self, n: int) -> np.ndarray:
        """(2^n, P): for each activation mask and pair i<j, the case that applies (-1: neither moves)."""
        ii, jj = np.triu_indices(n, 1)
        masks = np.arange(1 << n, dtype=np.int64)
        a_i = (masks[:, None] >> ii[None, :]) & 1 == 1
        a_j = (masks[:, None] >> jj[None, :]) & 1 == 1
        return np.where(a_i & a_j, 2, np.where(a_i, 0, np.where(a_j, 1, -1)))

    def _collision_words(self, states: np.ndarray, dest: np.ndarray, corner: np.ndarray) -> np.ndarray:
        """(m,) uint64: bit ``mask`` is set when activating ``mask`` makes some pair collide (n <= 6)."""
        n = states.shape[1]
        pairs = self._pair_collisions(states, dest, corner)  # (m, P, 3)
        case = self._case_table(n)
        weights = np.uint64(1) << np.arange(1 << n, dtype=np.uint64)
        word = np.zeros(len(states), dtype=np.uint64)
        for p in range(case.shape[1]):
            for c in range(3):
                masks_here = np.bitwise_or.reduce(weights[case[:, p] == c]) if (case[:, p] == c).any() else 0
                word |= np.where(pairs[:, p, c], np.uint64(masks_here), np.uint64(0))
        return word

    def _collisions_by_mask(self, states: np.ndarray, dest: np.ndarray, corner: np.ndarray) -> np.ndarray:
        """(m, 2^n) bool: whether activating ``mask`` makes some pair collide.

        Built from the per-pair cases with a static table saying, for each mask and pair, which
        case applies (-1: neither robot of the pair is active)."""
        m, n, _ = states.shape
        pairs = self._pair_collisions(states, dest, corner)  # (m, P, 3)
        case = self._case_table(n)
        out = np.zeros((m, 1 << n), dtype=bool)
        for c in range(3):
            sel = case == c  # (2^n, P)
            out |= (pairs[:, None, :, c] & sel[None, :, :]).any(axis=2)
        return out

    def _pair_collisions(self, states: np.ndarray, dest: np.ndarray, corner: np.ndarray) -> np.ndarray:
        """(m, P, 3) bool for the pairs i<j: collides when only i moves [0], only j [1], both [2]."""
        m, n, _ = states.shape
        ii, jj = np.triu_indices(n, 1)
        off = states[:, jj, :] - states[:, ii, :]  # (m, p, 2)
        di, dj = dest[:, ii, :], dest[:, jj, :]
        ci, cj = corner[:, ii], corner[:, jj]
        zero = np.zeros_like(di)
        cases = [(di, ci, zero, 0 * cj), (zero, 0 * ci, dj, cj), (di, ci, dj, cj)]
        out = np.zeros((m, len(ii), 3), dtype=bool)
        for c, (a, ca, b, cb) in enumerate(cases):
            fields = [off[..., 0], off[..., 1], a[..., 0], a[..., 1], b[..., 0], b[..., 1]]
            if any(f.size and (f.min() < -128 or f.max() > 127) for f in fields):
                raise ValueError("a pair offset or move exceeds 127 lattice units; the fast engine packs 8 bits each")
            key = np.zeros(off.shape[:2], dtype=np.int64)
            for f in fields:
                key = (key << 8) | (f + 128)
            key = (key << 2 | ca) << 2 | cb
            flat = key.ravel()
            rows = self.pairs.lookup(flat, partial(self._pair_rows, flat))
            out[:, :, c] = rows.reshape(key.shape).astype(bool)
        return out

    def _pair_rows(self, keys: np.ndarray, first: np.ndarray) -> np.ndarray:
        """Collision answers (one-column rows) for ``keys[first]``."""
        return np.array([[self._pair_from_key(int(k))] for k in keys[first]], dtype=np.int64).reshape(-1, 1)

    def _pair_from_key(self, key: int) -> int:
        return pair_collides(key, self.model)

    # --- goal -------------------------------------------------------------------------------
    def _goal(self, states: np.ndarray) -> np.ndarray:
        return judge_batch(states, self.model)

    # --- the expansion ----------------------------------------------------------------------
    def expand(self, states: np.ndarray) -> Expansion:
        n = states.shape[1]
        states = states.astype(np.int64)
        dest, corner = self._destinations(states)
        moves = (dest != 0).any(axis=-1)
        bits = 1 << np.arange(n, dtype=np.int64)
        enabled = (moves * bits).sum(axis=1)
        goal = self._goal(states)

        all_masks = np.arange(1, 1 << n, dtype=np.int64)
        valid = self.rounds.valid(all_masks, enabled)
        src, col = np.nonzero(valid)
        mask = all_masks[col]
        active = (mask[:, None] & bits[None, :]) != 0  # (t, n)
        after = states[src] + dest[src] * active[..., None]

        flags = np.zeros(len(src), dtype=np.int64)
        if n <= 6:  # one bit per activation mask fits an unsigned 64-bit word
            table = self._collision_words(states, dest, corner)
            hit = (table[src] >> mask.astype(np.uint64)) & np.uint64(1) == 1
        else:
            hit = self._collisions_by_mask(states, dest, corner)[src, mask]
        flags |= np.where(hit, Lemma.NO_COLLISION.flag, 0)

        before_ok = connected(states, self.model)
        lost = before_ok[src] & ~connected(after, self.model)
        flags |= np.where(lost, Lemma.CONNECTIVITY.flag, 0)

        rma = states[..., 0].max(axis=1)[src]
        xb, xa = states[src][..., 0], after[..., 0]
        crossed = (xa > rma[:, None]) | ((xb == rma[:, None]) & (xa != rma[:, None]))
        flags |= np.where(crossed.any(axis=1), Lemma.RMA_FIXED.flag, 0)
        return Expansion(enabled, goal, src.astype(np.int64), mask, after, flags, np.ones(len(src), dtype=bool))
