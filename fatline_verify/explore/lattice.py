"""Array encodings of lattice states: canonical form, packed int64 keys, vectorised predicates.

A batch of states is an int64 array ``(m, n, 2)``. The canonical form of a state translates it to
min x = min y = 0 and sorts its robots by (x, y); robots are anonymous and agree on axes, so two
states with the same canonical form behave the same. A canonical state inside a ``w x h`` window packs
into one int64: robot code ``x * h + y`` in ``bits`` bits each, in sorted order.
"""

from __future__ import annotations

import numpy as np

from ..config import Model


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


def connected(states: np.ndarray, model: Model) -> np.ndarray:
    """Per state, whether its visibility graph is connected: a flood fill over int64 bitmasks."""
    m, n, _ = states.shape
    if n <= 1:
        return np.ones(m, dtype=bool)
    x = states[..., 0].astype(np.int32)
    y = states[..., 1].astype(np.int32)
    dx = x[:, :, None] - x[:, None, :]
    dy = y[:, :, None] - y[:, None, :]
    adj = dx * dx + dy * dy <= model.view2
    bits = np.zeros((m, n), dtype=np.int64)
    for j in range(n):
        bits |= adj[:, :, j].astype(np.int64) << j  # (m, n) neighbour sets
    reach = np.ones(m, dtype=np.int64)
    for _ in range(n - 1):
        grown = reach.copy()
        for i in range(n):
            grown |= np.where((reach >> i) & 1 == 1, bits[:, i], 0)
        reach = grown
    return reach == (1 << n) - 1
