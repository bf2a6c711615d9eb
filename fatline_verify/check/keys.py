"""Packed keys for the numba kernels: a robot's snapshot key, shared by the compiled engines of the
round systems (:mod:`.compiled`) and of ASYNC (:mod:`.compiled_async`), so both pack a snapshot the
way the vectorised engines do (:func:`fatline_verify.check.fast.snapshot_cells` reads it back).

A snapshot is the set of robots a robot sees, as offsets from it; each visible offset ``(dx, dy)``
(``dx^2 + dy^2 <= view2``, in the engine's unit) is the cell code ``(dx + reach) * side + dy + reach``;
the codes are sorted ascending, padded with the sentinel ``side^2`` to ``n - 1`` codes and packed
``cell_bits`` bits each, first code highest, into one non-negative int64.
"""

from __future__ import annotations

import sys

import numpy as np
from numba import njit


@njit(cache=True)
def snapshot_key(pos: np.ndarray, i: int, view2: int, reach: int, side: int, cell_bits: int, codes: np.ndarray) -> int:
    """Robot ``i``'s snapshot key among the positions ``pos`` ``(n, 2)`` (``codes``: scratch of at
    least ``n - 1`` int64). The caller checks ``cell_bits * (n - 1) <= 63``."""
    n = pos.shape[0]
    c = 0
    for j in range(n):
        if j == i:
            continue
        dx = pos[j, 0] - pos[i, 0]
        dy = pos[j, 1] - pos[i, 1]
        if dx * dx + dy * dy <= view2:
            code = (dx + reach) * side + dy + reach
            k = c
            while k > 0 and codes[k - 1] > code:
                codes[k] = codes[k - 1]
                k -= 1
            codes[k] = code
            c += 1
    sentinel = side * side
    key = 0
    for k in range(n - 1):
        key = (key << cell_bits) | (codes[k] if k < c else sentinel)
    return key


# --- sets of multi-word keys ----------------------------------------------------------------------
# A state key wider than 63 bits is a fixed-width byte string (numpy void) of big-endian 64-bit words
# (:class:`~fatline_verify.schedulers.asynchronous.AsyncCodec`), ordered as its bytes compare. numpy
# sorts and searches void arrays through a generic byte comparison, which measured half of an n = 5
# ASYNC search; these functions do the same on the 64-bit words in numba kernels and give exactly
# numpy's answers. Plain int64 keys go to numpy unchanged.

_SWAP = sys.byteorder == "little"
"""Whether a key's big-endian words read as native integers need their bytes swapped."""
_M32 = np.uint64(0x00000000FFFFFFFF)
_M16 = np.uint64(0x0000FFFF0000FFFF)
_M8 = np.uint64(0x00FF00FF00FF00FF)
_S32, _S16, _S8 = np.uint64(32), np.uint64(16), np.uint64(8)
_DIGIT = 11
"""Bits per pass of the radix sort."""


def _raw(keys: np.ndarray) -> np.ndarray:
    """Byte-string keys ``(m,)`` as their 64-bit words ``(m, w)`` in native integers, without a copy
    (bytes still big-endian: compare through :func:`_word`)."""
    keys = np.ascontiguousarray(keys)
    return keys.view(np.uint64).reshape(len(keys), keys.dtype.itemsize // 8)


def words(keys: np.ndarray) -> np.ndarray:
    """Byte-string keys ``(m,)`` as native unsigned words ``(m, w)``, in the same lexicographic order."""
    return np.ascontiguousarray(keys).view(">u8").reshape(len(keys), keys.dtype.itemsize // 8).astype(np.uint64)


@njit(cache=True, inline="always")
def _word(x: np.uint64, swap: bool) -> np.uint64:
    """The big-endian word ``x`` (read as a native integer) as the number it stands for."""
    if not swap:
        return x
    x = ((x & _M32) << _S32) | (x >> _S32)
    x = ((x & _M16) << _S16) | ((x >> _S16) & _M16)
    return ((x & _M8) << _S8) | ((x >> _S8) & _M8)


@njit(cache=True)
def _cmp(a: np.ndarray, i: int, sa: bool, b: np.ndarray, j: int, sb: bool) -> int:
    """-1, 0 or 1 as row ``i`` of ``a`` is below, equal to or above row ``j`` of ``b`` (``sa``, ``sb``:
    whether that array's words need :func:`_word`)."""
    for q in range(a.shape[1]):
        x, y = _word(a[i, q], sa), _word(b[j, q], sb)
        if x != y:
            return -1 if x < y else 1
    return 0


@njit(cache=True)
def _argsort(w: np.ndarray) -> np.ndarray:
    """Stable argsort of the rows of the native words ``w`` (most significant word first): a least
    significant digit radix sort, ``_DIGIT`` bits a pass, that moves the rows with their indices and
    skips a pass whose digit every row shares."""
    m, nw = w.shape
    a = w.copy()
    ai = np.arange(m)
    b = np.empty_like(a)
    bi = np.empty(m, dtype=np.int64)
    buckets = 1 << _DIGIT
    mask = np.uint64(buckets - 1)
    count = np.empty(buckets + 1, dtype=np.int64)
    for q in range(nw - 1, -1, -1):
        for shift in range(0, 64, _DIGIT):
            sh = np.uint64(shift)
            count[:] = 0
            for r in range(m):
                count[((a[r, q] >> sh) & mask) + 1] += 1
            if count.max() == m:
                continue  # every row has this digit
            for d in range(buckets):
                count[d + 1] += count[d]
            for r in range(m):
                d = (a[r, q] >> sh) & mask
                k = count[d]
                count[d] = k + 1
                for c in range(nw):
                    b[k, c] = a[r, c]
                bi[k] = ai[r]
            a, b = b, a
            ai, bi = bi, ai
    return ai


@njit(cache=True)
def _ascending(w: np.ndarray, sw: bool) -> bool:
    """Whether the rows of ``w`` are in ascending order."""
    r = 1
    while r < w.shape[0] and _cmp(w, r - 1, sw, w, r, sw) <= 0:
        r += 1
    return r >= w.shape[0]


@njit(cache=True)
def _bisect(s: np.ndarray, ss: bool, q: np.ndarray, sq: bool) -> np.ndarray:
    """``np.searchsorted(s, q)`` (side left) on rows, one binary search each."""
    out = np.empty(q.shape[0], dtype=np.int64)
    for r in range(q.shape[0]):
        lo, hi = 0, s.shape[0]
        while lo < hi:
            mid = (lo + hi) // 2
            if _cmp(s, mid, ss, q, r, sq) < 0:
                lo = mid + 1
            else:
                hi = mid
        out[r] = lo
    return out


@njit(cache=True)
def _walk(s: np.ndarray, ss: bool, q: np.ndarray, sq: bool, order: np.ndarray) -> np.ndarray:
    """``np.searchsorted(s, q)`` (side left) for the rows of ``q`` visited in ascending ``order``: one
    merge walk through ``s``."""
    out = np.empty(q.shape[0], dtype=np.int64)
    lo = 0
    for r in range(q.shape[0]):
        t = order[r]
        while lo < s.shape[0] and _cmp(s, lo, ss, q, t, sq) < 0:
            lo += 1
        out[t] = lo
    return out


def _wide(keys: np.ndarray) -> bool:
    return keys.dtype.kind == "V"


def argsort(keys: np.ndarray) -> np.ndarray:
    """``np.argsort(keys, kind="stable")``."""
    if not _wide(keys):
        return np.argsort(keys, kind="stable")
    return _argsort(words(keys))  # type: ignore[no-any-return]


def sort(keys: np.ndarray) -> np.ndarray:
    """``np.sort(keys)``."""
    if not _wide(keys):
        return np.sort(keys, kind="stable")
    return keys[_argsort(words(keys))]  # type: ignore[no-any-return]


def unique_first(keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(keys, return_index=True)``: the distinct keys, sorted, and each one's first index."""
    if not _wide(keys):
        return np.unique(keys, return_index=True)  # type: ignore[no-any-return]
    w = words(keys)
    order = _argsort(w)
    ws = w[order]
    first = np.ones(len(keys), dtype=bool)
    first[1:] = (ws[1:] != ws[:-1]).any(axis=1)
    return keys[order[first]], order[first]


def searchsorted(sorted_keys: np.ndarray, queries: np.ndarray) -> np.ndarray:
    """``np.searchsorted(sorted_keys, queries)``."""
    if not _wide(sorted_keys):
        return np.searchsorted(sorted_keys, queries)
    s, q = _raw(sorted_keys), _raw(queries)
    if len(q) * 8 < len(s):  # few queries: a binary search each
        return _bisect(s, _SWAP, q, _SWAP)  # type: ignore[no-any-return]
    order = np.arange(len(q)) if _ascending(q, _SWAP) else _argsort(words(queries))
    return _walk(s, _SWAP, q, _SWAP, order)  # type: ignore[no-any-return]


def merge_sorted(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The sorted union (with repeats) of the sorted ``a`` and ``b``: ``np.sort(np.concatenate([a, b]))``."""
    if not _wide(a):
        return np.sort(np.concatenate([a, b]), kind="stable")
    return np.insert(a, searchsorted(a, b), b)


__all__ = ["argsort", "merge_sorted", "searchsorted", "snapshot_key", "sort", "unique_first", "words"]
