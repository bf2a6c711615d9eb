"""Every initial configuration of ``n`` robots in a ``w x h`` lattice window, up to translation.

"Initially the robots are stationary and the mutual distance between two robots is at least
delta > 2 units" and "Initially, the graph G is assumed to be connected". Robots agree on the axes
but not on an origin, so translation is the symmetry: each configuration is listed once, in its
canonical form (translated to min x = min y = 0, robots sorted).

Enumeration is Redelmeier's algorithm for connected sets of a graph, here the visibility graph of
the window's lattice points: each connected set is generated exactly once, from its least point
(the anchor). A point too close to the set built so far is skipped for good in that branch, which is
sound because every superset holding both points breaks the initial condition too. Anchors lie on
x = 0, so every set has min x = 0; sets with min y > 0 are translates of others and are dropped.

:func:`initial_keys` (what the checker uses; :func:`initial_array` decodes it) runs the same algorithm
as a numba kernel with one anchor instead of ``h``: the anchor is the origin, the lattice is the
half-plane of points after it in (x, y) order, ``0 <= x < w`` and ``|y| < h``, and a point that would
make the set taller than ``h`` is skipped for good like a point too close (every superset is taller
too). So every configuration is generated exactly once and none is dropped; shifting it up by its
least y gives the canonical form, whose key is written straight into the output.

The Python enumerations it is tested against (and falls back on without numba) are in
:mod:`.initial_reference`, and are importable from here too.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from math import isqrt
from typing import Any

import numpy as np

from ..model.config import Model
from ..model.lattice import KeyCodec
from .initial_reference import count_by_brute_force, initial_array_by_levels, initial_configurations

try:
    from numba import get_num_threads, njit, prange, types
    from numba.extending import intrinsic

    HAVE_NUMBA = True
except ImportError:  # pragma: no cover - without numba, initial_keys falls back to initial_array_by_levels
    HAVE_NUMBA = False

    def njit(*args: Any, **kwargs: Any) -> Any:  # type: ignore[no-redef]
        return args[0] if args and callable(args[0]) else (lambda f: f)

    def intrinsic(f: Any) -> Any:  # type: ignore[no-redef]
        return f

    prange = range  # type: ignore[misc,assignment]

    def get_num_threads() -> int:  # type: ignore[misc]
        return 1


# --- initial_keys: Redelmeier's algorithm as a numba kernel ------------------------------------------

FRONTIER_DEPTH = 3
"""Sets of this many robots are the parallel tasks: each is the root of an independent subtree."""

_KERNEL_LOCK = threading.Lock()
"""One parallel kernel launch at a time: numba's workqueue threading layer (used when neither TBB nor
OpenMP loads) aborts the process when two Python threads launch parallel kernels at once."""


class _Lattice:
    """The anchored half-plane lattice of a window, with its point sets as bitsets, in numpy.

    Points are numbered in (x, y) order, so the anchor (the origin) is point 0 and comparing numbers
    compares points; ``x`` in ``[0, w)``, ``y`` in ``(-h, h)``, and ``x = 0`` only for ``y >= 0``.
    ``w``, ``h``: the window, cropped to ``(n - 1) * isqrt(view2) + 1``: no connected set of ``n``
    points reaches further from its anchor, and none is wider or taller (so cropping keeps every set,
    and the lattice small however large the window).
    A set of points is ``words`` uint64 words, point ``p`` bit ``p % 64`` of word ``p // 64``.
    ``nbr[p]``: the points other than the origin that ``p`` sees (squared distance <= ``model.view2``).
    ``near[p]``: the points breaking the initial condition with ``p`` (``not model.initially_apart``).
    ``y_ge[i]`` / ``y_le[i]``: the points with ``y >= i - (h - 1)`` / ``y <= i - (h - 1)``.
    """

    def __init__(self, n: int, window: tuple[int, int], model: Model) -> None:
        reach = (n - 1) * isqrt(model.view2) + 1
        self.w, self.h = w, h = min(window[0], reach), min(window[1], reach)
        xs, ys = np.meshgrid(np.arange(w), np.arange(-(h - 1), h), indexing="ij")
        keep = (xs > 0) | (ys >= 0)
        index = np.full(xs.shape, -1, dtype=np.int64)
        index[keep] = np.arange(int(keep.sum()))  # "ij" order ravels in (x, y) order
        self.px = xs[keep].astype(np.int64)
        self.py = ys[keep].astype(np.int64)
        self.words = (len(self.px) + 63) // 64
        self.nbr = self._offsets(index, lambda d2: 0 < d2 <= model.view2, isqrt(model.view2))
        self.nbr[:, 0] &= ~np.uint64(1)  # the anchor is in every set already
        self.near = self._offsets(index, lambda d2: d2 > 0 and not model.initially_apart(d2), isqrt(model.apart2))
        ylev = np.arange(-(h - 1), h)
        self.y_ge = self.pack(self.py[None, :] >= ylev[:, None])
        self.y_le = self.pack(self.py[None, :] <= ylev[:, None])

    def _offsets(self, index: np.ndarray, related: Callable[[int], bool], r: int) -> np.ndarray:
        """Bitsets ``(points, words)``: per point, the points at an offset ``(dx, dy)``, ``|dx|, |dy| <= r``,
        whose squared length ``d2`` is ``related``."""
        out = np.zeros((len(self.px), self.words), dtype=np.uint64)
        x, y = self.px, self.py + (self.h - 1)
        r = min(r, max(self.w, 2 * self.h))  # no further offset joins two points
        for dx in range(-r, r + 1):
            for dy in range(-r, r + 1):
                if not related(dx * dx + dy * dy):
                    continue
                tx, ty = x + dx, y + dy
                inside = (tx >= 0) & (tx < index.shape[0]) & (ty >= 0) & (ty < index.shape[1])
                src = np.flatnonzero(inside)
                dst = index[tx[inside], ty[inside]]
                src, dst = src[dst >= 0], dst[dst >= 0]
                np.bitwise_or.at(out, (src, dst >> 6), np.left_shift(np.uint64(1), (dst & 63).astype(np.uint64)))
        return out

    def pack(self, member: np.ndarray) -> np.ndarray:
        """Bitsets ``(rows, words)`` of a boolean membership matrix ``(rows, points)``."""
        padded = np.zeros((len(member), self.words * 64), dtype=bool)
        padded[:, : member.shape[1]] = member
        return np.packbits(padded, axis=1, bitorder="little").view("<u8").astype(np.uint64)

    def members(self, bitset: np.ndarray) -> list[int]:
        """The points of one bitset, in increasing order."""
        bits = np.unpackbits(bitset.astype("<u8").view(np.uint8), bitorder="little")
        return np.flatnonzero(bits).tolist()  # type: ignore[no-any-return]

    def frontier(self, depth: int) -> list[tuple[list[int], list[int], list[int]]]:
        """Redelmeier's nodes holding ``depth`` points: (chosen, untried, seen). The subtrees under
        them partition the search, whatever order each node tries its untried points in."""
        first = self.members(self.nbr[0])
        root = ([0], first, [0, *first])
        if depth <= 1:
            return [root]
        out: list[tuple[list[int], list[int], list[int]]] = []
        py, h = self.py.tolist(), self.h
        near = [set(self.members(self.near[p])) for p in range(len(self.px))]

        def grow(chosen: list[int], untried: list[int], seen: set[int]) -> None:
            untried = list(untried)
            lo, hi = min(py[c] for c in chosen), max(py[c] for c in chosen)
            while untried:
                c = untried.pop()
                if any(c in near[d] for d in chosen) or max(hi, py[c]) - min(lo, py[c]) >= h:
                    continue
                fresh = [d for d in self.members(self.nbr[c]) if d not in seen]
                if len(chosen) + 1 == depth:
                    out.append(([*chosen, c], untried + fresh, [*seen, *fresh]))
                else:
                    grow([*chosen, c], untried + fresh, seen | set(fresh))

        grow(*root[:2], set(root[2]))
        return out


def _ctpop(typingctx: Any, x: Any) -> Any:
    """``_popcount(x)``: the number of set bits of a uint64 (LLVM ctpop)."""
    if x != types.uint64:
        return None

    def codegen(context: Any, builder: Any, sig: Any, args: Any) -> Any:
        return builder.ctpop(args[0])

    return types.uint64(types.uint64), codegen


def _cttz(typingctx: Any, x: Any) -> Any:
    """``_lowest(x)``: the index of the lowest set bit of a non-zero uint64 (LLVM cttz)."""
    if x != types.uint64:
        return None

    def codegen(context: Any, builder: Any, sig: Any, args: Any) -> Any:
        from llvmlite import ir

        return builder.cttz(args[0], ir.Constant(ir.IntType(1), 1))

    return types.uint64(types.uint64), codegen


_popcount: Any = intrinsic(_ctpop)
_lowest: Any = intrinsic(_cttz)


@njit(cache=True)  # type: ignore[misc]
def _subtree(
    n: int,
    h: int,
    ch: int,
    bits: int,
    px: np.ndarray,
    py: np.ndarray,
    nbr: np.ndarray,
    near: np.ndarray,
    y_ge: np.ndarray,
    y_le: np.ndarray,
    chosen0: np.ndarray,
    untried0: np.ndarray,
    seen0: np.ndarray,
    fill: bool,
    out: np.ndarray,
    pos: int,
) -> int:
    """Redelmeier's search below one node of ``s0`` points (``chosen0``, ``untried0``, ``seen0``),
    with a stack of bitsets: row ``L`` is the node of ``L + 1`` points ``chosen[:L+1]``: ``seen[L]``
    the points ever offered on its path, ``blk[L]`` those too close to one of its points, ``lo[L]`` /
    ``hi[L]`` its least / greatest y, ``unt[L]`` its untried points not tried yet (lowest first).
    Untried points that are blocked or would make the set taller than ``h`` are dropped as the node
    is made, for good: so would every superset be. Returns the number of sets of ``n`` points; with
    ``fill``, writes their keys (codec height ``ch``, ``bits`` a robot) at ``out[pos:]``."""
    nw = nbr.shape[1]
    s0 = len(chosen0)
    unt = np.zeros((n, nw), dtype=np.uint64)
    seen = np.zeros((n, nw), dtype=np.uint64)
    blk = np.zeros((n, nw), dtype=np.uint64)
    lo = np.zeros(n, dtype=np.int64)
    hi = np.zeros(n, dtype=np.int64)
    chosen = np.zeros(n, dtype=np.int64)
    srt = np.zeros(n, dtype=np.int64)
    raw = np.zeros(n, dtype=np.int64)
    place = np.zeros(n + 1, dtype=np.int64)  # the weight of each rank in a key, and their sum
    for k in range(n):
        place[k] = np.int64(1) << (bits * (n - 1 - k))
        place[n] += place[k]
    level = s0 - 1
    for i in range(s0):
        c = chosen0[i]
        chosen[i] = c
        lo[level] = min(lo[level], py[c])  # the origin is chosen: lo <= 0 <= hi
        hi[level] = max(hi[level], py[c])
        for k in range(nw):
            blk[level, k] |= near[c, k]
    for k in range(nw):
        seen[level, k] = seen0[k]
        unt[level, k] = _allowed(untried0[k], blk[level, k], y_ge, y_le, lo[level], hi[level], h, k)
    if s0 == n - 1:  # the node's untried points complete it
        return _complete(n, ch, px, py, chosen, unt, level, lo[level], fill, place, srt, raw, out, pos)
    count = 0
    while True:
        k = 0
        while k < nw and unt[level, k] == 0:
            k += 1
        if k == nw:  # node done
            if level == s0 - 1:
                break
            level -= 1
            continue
        word = unt[level, k]
        c = k * 64 + np.int64(_lowest(word))
        unt[level, k] = word & (word - np.uint64(1))
        up = level + 1
        chosen[up] = c
        a = lo[up] = min(lo[level], py[c])
        b = hi[up] = max(hi[level], py[c])
        for k in range(nw):
            fresh = nbr[c, k] & ~seen[level, k]
            seen[up, k] = seen[level, k] | fresh
            blk[up, k] = blk[level, k] | near[c, k]
            unt[up, k] = _allowed(unt[level, k] | fresh, blk[up, k], y_ge, y_le, a, b, h, k)
        if up == n - 2:  # a node of n - 1 points: each untried point completes it
            count += _complete(n, ch, px, py, chosen, unt, up, a, fill, place, srt, raw, out, pos + count)
        else:
            level = up
    return count


@njit(cache=True, inline="always")  # type: ignore[misc]
def _allowed(
    word: np.uint64, blocked: np.uint64, y_ge: np.ndarray, y_le: np.ndarray, lo: int, hi: int, h: int, k: int
) -> np.uint64:
    """Word ``k`` of the points in ``word`` not ``blocked`` and with y in ``[hi - h + 1, lo + h - 1]``
    (row ``i`` of ``y_ge`` / ``y_le`` is ``y = i - h + 1``)."""
    return word & ~blocked & y_ge[hi, k] & y_le[lo + 2 * h - 2, k]


@njit(cache=True)  # type: ignore[misc]
def _complete(
    n: int,
    ch: int,
    px: np.ndarray,
    py: np.ndarray,
    chosen: np.ndarray,
    unt: np.ndarray,
    row: int,
    lo: int,
    fill: bool,
    place: np.ndarray,
    srt: np.ndarray,
    raw: np.ndarray,
    out: np.ndarray,
    pos: int,
) -> int:
    """The sets completing a node of ``n - 1`` points ``chosen[:n-1]`` (least y ``lo``) with one of
    its untried points ``unt[row]``: count them, and if ``fill`` write their keys at ``out[pos:]``.

    The key of the set with ``c`` at rank ``r`` among the chosen (point order = (x, y) order = the
    canonical robot order), shifted up by ``-a`` (its least y), is
    ``raw[r] + code(c) * place[r] - a * place[n]``, with ``code(p) = px[p] * ch + py[p]`` (linear, so
    negative y are fine). ``srt`` and ``raw`` are scratch."""
    nw = unt.shape[1]
    cnt = 0
    if not fill:
        for k in range(nw):
            cnt += int(_popcount(unt[row, k]))
        return cnt
    for i in range(n - 1):  # insertion sort of the chosen points
        v = chosen[i]
        j = i - 1
        while j >= 0 and srt[j] > v:
            srt[j + 1] = srt[j]
            j -= 1
        srt[j + 1] = v
    acc = 0
    for k in range(n - 1):
        acc += (px[srt[k]] * ch + py[srt[k]]) * place[k + 1]
    raw[0] = acc
    for k in range(n - 1):
        raw[k + 1] = raw[k] + (px[srt[k]] * ch + py[srt[k]]) * (place[k] - place[k + 1])
    r = 0
    for k in range(nw):
        word = unt[row, k]
        while word:
            c = k * 64 + np.int64(_lowest(word))
            word &= word - np.uint64(1)
            while r < n - 1 and srt[r] < c:  # candidates come in increasing order
                r += 1
            out[pos + cnt] = raw[r] + (px[c] * ch + py[c]) * place[r] - min(lo, py[c]) * place[n]
            cnt += 1
    return cnt


@njit(cache=True, parallel=True)  # type: ignore[misc]
def _run(
    n: int,
    h: int,
    ch: int,
    bits: int,
    px: np.ndarray,
    py: np.ndarray,
    nbr: np.ndarray,
    near: np.ndarray,
    y_ge: np.ndarray,
    y_le: np.ndarray,
    t_chosen: np.ndarray,
    t_untried: np.ndarray,
    t_seen: np.ndarray,
    workers: int,
    fill: bool,
    offsets: np.ndarray,
    out: np.ndarray,
    counts: np.ndarray,
) -> None:
    """Every task's subtree: worker ``w`` takes tasks ``w, w + workers, ...``; task ``t`` writes
    ``counts[t]`` and (with ``fill``) its keys at ``out[offsets[t]:]``, so the output does not depend
    on the scheduling."""
    for wk in prange(workers):
        for t in range(wk, len(t_chosen), workers):
            counts[t] = _subtree(
                n,
                h,
                ch,
                bits,
                px,
                py,
                nbr,
                near,
                y_ge,
                y_le,
                t_chosen[t],
                t_untried[t],
                t_seen[t],
                fill,
                out,
                offsets[t],
            )


def initial_keys(n: int, window: tuple[int, int], model: Model, codec: KeyCodec) -> np.ndarray:
    """The sorted int64 keys, in ``codec``, of the canonical initial configurations of ``n`` robots
    in ``window``: the configurations of :func:`initial_configurations` and :func:`initial_array`.

    The paper's initial condition: "the mutual distance between two robots is at least delta > 2
    units" (:meth:`Model.initially_apart`) and "Initially, the graph G is assumed to be connected"
    (visibility: squared distance at most ``model.view2``). ``codec`` may have a larger window than
    ``window``; it must hold ``window`` and ``n`` robots. Memory: the keys (8 bytes a configuration),
    sorted in place; a count pass sizes the output and a fill pass writes it, both in parallel over
    the subtrees below the sets of :data:`FRONTIER_DEPTH` points.
    """
    w, h = window
    if n < 1:
        raise ValueError(f"robots={n}: expected at least 1 robot")
    if codec.n != n:
        raise ValueError(f"codec packs {codec.n} robots, not {n}: expected KeyCodec({n}, ...)")
    if codec.w < w or codec.h < h:
        raise ValueError(
            f"codec window {codec.w}x{codec.h} cannot hold window {w}x{h}: expected a codec window at least as large"
        )
    if w < 1 or h < 1:
        return np.zeros(0, dtype=np.int64)
    if n == 1:
        return np.zeros(1, dtype=np.int64)  # the one robot at the origin: code 0
    if not HAVE_NUMBA:  # pragma: no cover
        return np.sort(codec.encode(initial_array_by_levels(n, window, model)))
    lat = _Lattice(n, window, model)
    tasks = lat.frontier(min(FRONTIER_DEPTH, n - 1))
    if not tasks:
        return np.zeros(0, dtype=np.int64)
    t_chosen = np.array([c for c, _, _ in tasks], dtype=np.int64)
    member = np.zeros((2, len(tasks), len(lat.px)), dtype=bool)
    for t, (_, untried, seen) in enumerate(tasks):
        member[0, t, untried] = True
        member[1, t, seen] = True
    t_untried, t_seen = lat.pack(member[0]), lat.pack(member[1])
    workers = max(1, int(get_num_threads()))
    counts = np.zeros(len(tasks), dtype=np.int64)
    offsets = np.zeros(len(tasks) + 1, dtype=np.int64)
    args = (n, lat.h, codec.h, codec.bits, lat.px, lat.py, lat.nbr, lat.near, lat.y_ge, lat.y_le)
    targs = (t_chosen, t_untried, t_seen, workers)
    with _KERNEL_LOCK:
        _run(*args, *targs, False, offsets, np.zeros(0, dtype=np.int64), counts)
        np.cumsum(counts, out=offsets[1:])
        keys = np.empty(int(offsets[-1]), dtype=np.int64)
        _run(*args, *targs, True, offsets, keys, counts)
    keys.sort()
    return keys


def count_initial(n: int, window: tuple[int, int], model: Model, cap: int | None = None) -> int:
    """How many configurations :func:`initial_keys` would return, counted without keeping any (the
    count pass alone); with ``cap``, the count stops as soon as it passes ``cap`` and returns what it
    reached (so a guard refusing more than ``cap`` costs little however many there are)."""
    from math import comb

    w, h = window
    if n < 1 or w < 1 or h < 1:
        return 0
    if n == 1:
        return 1
    if cap is not None and comb(w * h, n) <= cap:
        return 0  # fewer than cap whatever the count: nothing to guard
    if not HAVE_NUMBA:  # pragma: no cover
        return len(initial_array_by_levels(n, window, model))
    codec = KeyCodec(n, window)
    lat = _Lattice(n, window, model)
    tasks = lat.frontier(min(FRONTIER_DEPTH, n - 1))
    if not tasks:
        return 0
    t_chosen = np.array([c for c, _, _ in tasks], dtype=np.int64)
    member = np.zeros((2, len(tasks), len(lat.px)), dtype=bool)
    for t, (_, untried, seen) in enumerate(tasks):
        member[0, t, untried] = True
        member[1, t, seen] = True
    t_untried, t_seen = lat.pack(member[0]), lat.pack(member[1])
    workers = max(1, int(get_num_threads()))
    args = (n, lat.h, codec.h, codec.bits, lat.px, lat.py, lat.nbr, lat.near, lat.y_ge, lat.y_le)
    chunk = len(tasks) if cap is None else max(4 * workers, len(tasks) // 64)
    total = 0
    with _KERNEL_LOCK:
        for lo in range(0, len(tasks), chunk):
            hi = min(lo + chunk, len(tasks))
            counts = np.zeros(hi - lo, dtype=np.int64)
            offsets = np.zeros(hi - lo + 1, dtype=np.int64)
            targs = (t_chosen[lo:hi], t_untried[lo:hi], t_seen[lo:hi], workers)
            _run(*args, *targs, False, offsets, np.zeros(0, dtype=np.int64), counts)
            total += int(counts.sum())
            if cap is not None and total > cap:
                break
    return total


def initial_array(n: int, window: tuple[int, int], model: Model) -> np.ndarray:
    """The same configurations as :func:`initial_configurations`, as canonical states ``(m, n, 2)``
    sorted by key (in ``KeyCodec(n, window)``): :func:`initial_keys`, decoded (as
    :meth:`KeyCodec.decode` does, with no temporaries the size of the output)."""
    codec = KeyCodec(n, window)
    keys = initial_keys(n, window, model, codec)
    if not HAVE_NUMBA:  # pragma: no cover
        return codec.decode(keys)
    out = np.empty((len(keys), n, 2), dtype=np.int64)
    _decode(keys, codec.h, codec.bits, out)
    return out


@njit(cache=True)  # type: ignore[misc]
def _decode(keys: np.ndarray, h: int, bits: int, out: np.ndarray) -> None:
    """:meth:`KeyCodec.decode` into ``out`` ``(m, n, 2)``: robot ``k``'s code is the ``k``-th ``bits``-bit
    field from the top, ``x * h + y``."""
    n = out.shape[1]
    mask = (np.int64(1) << bits) - 1
    for i in range(len(keys)):
        key = keys[i]
        for k in range(n - 1, -1, -1):
            code = key & mask
            key >>= bits
            out[i, k, 0] = code // h
            out[i, k, 1] = code % h


__all__ = [
    "FRONTIER_DEPTH",
    "HAVE_NUMBA",
    "count_by_brute_force",
    "count_initial",
    "initial_array",
    "initial_array_by_levels",
    "initial_configurations",
    "initial_keys",
]
