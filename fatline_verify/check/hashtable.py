"""An open-addressing hash table of int64 keys and small int64 rows, for numba kernels.

The compiled engine caches the executable model's decisions (by snapshot key) and pair-collision
answers (by relative-motion key) in two of these: kernels look keys up without returning to Python,
and Python inserts the rows of keys never seen, a batch at a time. One int64 array holds each slot's
key (``-1``: free) and row side by side; linear probing from a Fibonacci hash; the load stays at most
one half and the table grows by rehashing.
"""

from __future__ import annotations

import numpy as np
from numba import njit

_EMPTY = -1
"""The free slot of a hash table (every stored key is non-negative)."""
_GOLDEN = np.uint64(0x9E3779B97F4A7C15)


def distinct(keys: np.ndarray) -> np.ndarray:
    """The distinct values of an int64 array, sorted. (``np.unique`` on a plain int64 array takes a hash
    path in numpy 2.4 that measures 50-80x slower than sorting on these packed keys.)"""
    out = np.sort(keys)
    if len(out) > 1:
        keep = np.empty(len(out), dtype=bool)
        keep[0] = True
        np.not_equal(out[1:], out[:-1], out=keep[1:])
        out = out[keep]
    return out


# --- hash tables --------------------------------------------------------------------------------
@njit(cache=True)
def _slot(key: int, shift: int) -> int:
    return int(np.int64((np.uint64(key) * _GOLDEN) >> np.uint64(shift)))


@njit(cache=True)
def find(table: np.ndarray, shift: int, key: int) -> int:
    """The row of ``table`` (column 0 the key) holding ``key``, or -1."""
    mask = len(table) - 1
    i = _slot(key, shift)
    while True:
        k = table[i, 0]
        if k == key:
            return i
        if k == _EMPTY:
            return -1
        i = (i + 1) & mask


@njit(cache=True)
def _insert(table: np.ndarray, shift: int, rows: np.ndarray) -> None:
    """Insert ``rows`` (column 0 the key, distinct and not present)."""
    mask = len(table) - 1
    for r in range(len(rows)):
        key = rows[r, 0]
        i = _slot(key, shift)
        while table[i, 0] != _EMPTY and table[i, 0] != key:
            i = (i + 1) & mask
        for c in range(table.shape[1]):
            table[i, c] = rows[r, c]


class HashTable:
    """A growing int64 -> int64-row map for the kernels: open addressing in one numpy array.

    ``slots`` has a power-of-two number of rows, each the key (``-1``: free) followed by its ``width``
    values, so a probe reads one cache line; the load stays at most 1/2. Kernels look keys up with
    :func:`_find`; Python inserts whole batches, growing the table by rehashing."""

    def __init__(self, width: int, capacity: int = 1 << 12) -> None:
        self.width = width
        self.count = 0
        self._allocate(capacity)

    def _allocate(self, capacity: int) -> None:
        self.slots = np.zeros((capacity, 1 + self.width), dtype=np.int64)
        self.slots[:, 0] = _EMPTY
        self.shift = 64 - (capacity.bit_length() - 1)

    def __len__(self) -> int:
        return self.count

    @property
    def keys(self) -> np.ndarray:
        """The key column (``-1``: a free slot)."""
        return self.slots[:, 0]

    @property
    def vals(self) -> np.ndarray:
        """The value columns."""
        return self.slots[:, 1:]

    def insert(self, keys: np.ndarray, rows: np.ndarray) -> None:
        """Add distinct ``keys`` not yet present, with their ``rows`` of ``width`` values."""
        need = self.count + len(keys)
        capacity = len(self.slots)
        if 2 * need > capacity:
            while 2 * need > capacity:
                capacity *= 2
            old = self.slots[self.slots[:, 0] != _EMPTY]
            self._allocate(capacity)
            _insert(self.slots, self.shift, old)
        new = np.empty((len(keys), 1 + self.width), dtype=np.int64)
        new[:, 0] = keys
        new[:, 1:] = np.asarray(rows, dtype=np.int64).reshape(-1, self.width)
        _insert(self.slots, self.shift, new)
        self.count = need


__all__ = ["HashTable", "distinct", "find"]
