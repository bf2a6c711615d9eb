"""Array encodings of lattice states: canonical form, packed int64 keys, vectorised predicates.

A batch of states is an int64 array ``(m, n, 2)``. The canonical form of a state translates it to
min x = min y = 0 and sorts its robots by (x, y); robots are anonymous and agree on axes, so two
states with the same canonical form behave the same. A canonical state inside a ``w x h`` window packs
into one int64: robot code ``x * h + y`` in ``bits`` bits each, in sorted order.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .config import Model
from .options import Goal


def canonical(states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Canonical forms of a batch ``(m, n, 2)`` and, per state, the robot order:
    ``canon[i, k] = translated[i, order[i, k]]``."""
    shifted = states - states.min(axis=1, keepdims=True)
    span = int(shifted[..., 1].max()) + 1 if shifted.size else 1
    codes = shifted[..., 0] * span + shifted[..., 1]
    order = np.argsort(codes, axis=1, kind="stable")
    canon = np.take_along_axis(shifted, order[..., None], axis=1)
    return canon, order


def extent(canon: np.ndarray) -> np.ndarray:
    """Per canonical state, its bounding box ``(width, height)`` in lattice points."""
    return canon.max(axis=1) + 1


class KeyCodec:
    """Packs canonical states of ``n`` robots inside a ``w x h`` window into int64 keys and back."""

    dtype = np.dtype(np.int64)

    def __init__(self, n: int, window: tuple[int, int]) -> None:
        self.n, (self.w, self.h) = n, window
        self.bits = max(1, int(self.w * self.h - 1).bit_length())
        if self.bits * n > 63:
            raise ValueError(f"window={self.w}x{self.h} with {n} robots does not pack into 63 bits")

    def fits(self, canon: np.ndarray) -> np.ndarray:
        """Which canonical states lie inside the window."""
        ext = extent(canon)
        return (ext[:, 0] <= self.w) & (ext[:, 1] <= self.h)

    def encode(self, canon: np.ndarray) -> np.ndarray:
        """Keys of canonical states that fit the window (the caller filters with :meth:`fits`)."""
        codes = canon[..., 0].astype(np.int64) * self.h + canon[..., 1]
        codes = np.sort(codes, axis=1)
        key = np.zeros(len(canon), dtype=np.int64)
        for k in range(self.n):
            key = (key << self.bits) | codes[:, k]
        return key

    def decode(self, keys: np.ndarray) -> np.ndarray:
        """Canonical states ``(m, n, 2)`` from keys."""
        keys = np.asarray(keys, dtype=np.int64)
        mask = (1 << self.bits) - 1
        codes = np.empty((len(keys), self.n), dtype=np.int64)
        for k in range(self.n - 1, -1, -1):
            codes[:, k] = keys & mask
            keys = keys >> self.bits
        return np.stack([codes // self.h, codes % self.h], axis=-1)


def rank_table(n: int, cells: int) -> np.ndarray:
    """``cum[i, x]``: how many sorted code tuples ``c`` of ``n`` codes in ``[0, cells)`` (repetition
    allowed) have, position ``i`` on and the positions before it fixed, ``c[i] + i`` below ``x`` (so
    ``d = c + (0, 1, ..., n - 1)`` is a strictly increasing tuple in ``[0, cells + n - 1)`` and its
    lexicographic rank is ``sum(cum[i, d[i]] - cum[i, d[i - 1] + 1])``, ``d[-1] = -1``). Exact integers
    (Python's, then int64: :class:`RankedCodec` checks the total fits)."""
    from math import comb

    m = cells + n - 1
    cum = np.zeros((n, m + 1), dtype=np.int64)
    for i in range(n):
        total = 0
        for x in range(m + 1):
            cum[i, x] = total
            if x < m:
                total += comb(m - 1 - x, n - 1 - i)
    return cum


class RankedCodec(KeyCodec):
    """Canonical states whose packed codes pass 63 bits (8 robots in 20x20: 72), as the lexicographic
    rank of their sorted cell codes among all sorted code tuples: the same order as packed keys would
    have (so state ids, parents and witnesses are the same as with :class:`KeyCodec` wherever both
    apply), in at most 63 bits (8 robots in 20x20: 54)."""

    def __init__(self, n: int, window: tuple[int, int]) -> None:
        from math import comb

        self.n, (self.w, self.h) = n, window
        self.bits = max(1, int(self.w * self.h - 1).bit_length())
        cells = self.w * self.h
        if comb(cells + n - 1, n) >= 2**63:
            raise ValueError(f"window={self.w}x{self.h} with {n} robots does not rank into 63 bits")
        self.cum = rank_table(n, cells)

    def encode(self, canon: np.ndarray) -> np.ndarray:
        codes = np.sort(canon[..., 0].astype(np.int64) * self.h + canon[..., 1], axis=1)
        key = np.zeros(len(canon), dtype=np.int64)
        prev = np.zeros(len(canon), dtype=np.int64)  # d[i - 1] + 1
        for i in range(self.n):
            d = codes[:, i] + i
            key += self.cum[i, d] - self.cum[i, prev]
            prev = d + 1
        return key

    def decode(self, keys: np.ndarray) -> np.ndarray:
        rest = np.asarray(keys, dtype=np.int64).copy()
        codes = np.empty((len(rest), self.n), dtype=np.int64)
        prev = np.zeros(len(rest), dtype=np.int64)
        for i in range(self.n):
            target = rest + self.cum[i, prev]
            d = np.searchsorted(self.cum[i], target, side="right") - 1
            rest -= self.cum[i, d] - self.cum[i, prev]
            codes[:, i] = d - i
            prev = d + 1
        return np.stack([codes // self.h, codes % self.h], axis=-1)


def key_codec(n: int, window: tuple[int, int]) -> KeyCodec:
    """The packed codec where ``n`` codes fit 63 bits, else the ranked one (ValueError past that)."""
    try:
        return KeyCodec(n, window)
    except ValueError:
        return RankedCodec(n, window)


class KeyTable:
    """A growing table of small integer rows keyed by int64 or fixed-width byte keys, looked up with
    ``searchsorted``; rows for new keys are computed on demand. Both fast engines cache decisions
    (by snapshot key) and collision answers (by relative-motion key) in one."""

    def __init__(self, width: int) -> None:
        self.width = width
        self.keys: np.ndarray | None = None
        self.rows = np.zeros((0, width), dtype=np.int64)

    def __len__(self) -> int:
        return len(self.rows)

    def lookup(self, keys: np.ndarray, compute: Callable[[np.ndarray], np.ndarray]) -> np.ndarray:
        """Rows of ``keys`` (1-D); ``compute(first)`` gives the rows of the keys not seen yet, from the
        index of each one's first occurrence in ``keys``."""
        if not len(keys):
            return np.zeros((0, self.width), dtype=np.int64)
        uniq, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
        if self.keys is None or not len(self.keys):
            new = np.ones(len(uniq), dtype=bool)
        else:
            pos = np.minimum(np.searchsorted(self.keys, uniq), len(self.keys) - 1)
            new = self.keys[pos] != uniq
        if new.any():
            rows = np.asarray(compute(first[new]), dtype=np.int64).reshape(-1, self.width)
            allk = uniq[new] if self.keys is None else np.concatenate([self.keys, uniq[new]])
            allr = np.concatenate([self.rows, rows])
            order = np.argsort(allk, kind="stable")
            self.keys, self.rows = allk[order], allr[order]
        assert self.keys is not None
        return self.rows[np.searchsorted(self.keys, uniq)][inverse.ravel()]  # type: ignore[no-any-return]


def connected(states: np.ndarray, model: Model) -> np.ndarray:
    """Per state, whether its visibility graph is connected."""
    return connected_within(states, model.view2)


def connected_within(pos: np.ndarray, view2: int) -> np.ndarray:
    """Per state ``(m, n, 2)``, whether the graph of pairs at squared distance at most ``view2`` is
    connected (int64 throughout: positions may be in a fine unit)."""
    m, n, _ = pos.shape
    if n <= 1:
        return np.ones(m, dtype=bool)
    d = pos[:, :, None, :] - pos[:, None, :, :]
    adj = (d * d).sum(axis=-1) <= view2  # (m, n, n)
    nbrs = (adj.astype(np.int64) << np.arange(n, dtype=np.int64)).sum(axis=2)  # (m, n) neighbour sets
    reach = np.ones(m, dtype=np.int64)
    for _ in range(n - 1):
        grown = reach.copy()
        for i in range(n):
            grown |= np.where((reach >> i) & 1 == 1, nbrs[:, i], 0)
        reach = grown
    return reach == (1 << n) - 1  # type: ignore[no-any-return]


def goal_positions(pos: np.ndarray, goal: Goal, width: int) -> np.ndarray:
    """Per state ``(m, n, 2)`` (integer positions in any unit), whether it forms the goal line;
    ``width`` is the strip width of ``line-meets-discs`` in that unit."""
    m, n, _ = pos.shape
    if goal is Goal.VERTICAL_LINE:
        x = pos[..., 0]
        return (x == x[:, :1]).all(axis=1)  # type: ignore[no-any-return]
    if n <= 2:
        return np.ones(m, dtype=bool)
    a = pos[:, :, None, :]  # the line through robots a and b, every robot c tested against it
    ab = pos[:, None, :, :] - a  # (m, n, n, 2)
    ac = pos[:, None, None, :, :] - a[:, :, :, None, :]  # (m, n, 1, n, 2)
    crossv = ab[..., None, 0] * ac[..., 1] - ab[..., None, 1] * ac[..., 0]  # (m, n, n, n)
    distinct = (ab != 0).any(axis=-1)
    uniq = np.sort(pos[..., 0] * 1_000_003 + pos[..., 1], axis=1)
    few = (np.diff(uniq, axis=1) != 0).sum(axis=1) + 1 < 3
    if goal is Goal.ANY_LINE:
        line = (crossv == 0).all(axis=-1) & distinct
        return line.any(axis=(1, 2)) | few  # type: ignore[no-any-return]
    limit = width * width * (ab * ab).sum(axis=-1)
    one_side = (crossv >= 0).all(axis=-1) | (crossv <= 0).all(axis=-1)
    fits = one_side & (crossv * crossv <= limit[..., None]).all(axis=-1) & distinct
    return fits.any(axis=(1, 2)) | few  # type: ignore[no-any-return]
