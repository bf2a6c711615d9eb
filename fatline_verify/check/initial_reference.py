"""The Python enumerations of initial configurations: Redelmeier's algorithm over the window's lattice
points (:func:`initial_configurations`), a level-by-level numpy build (:func:`initial_array_by_levels`,
the fallback of :func:`~fatline_verify.check.initial.initial_keys` without numba) and a count by brute
force over every subset. The checker's kernel (:mod:`.initial`) is tested against them.

"Initially the robots are stationary and the mutual distance between two robots is at least
delta > 2 units" and "Initially, the graph G is assumed to be connected".
"""

from __future__ import annotations

from collections.abc import Iterator
from math import isqrt

import numpy as np

from ..model.config import Model
from ..model.lattice import KeyCodec, canonical
from ..model.swarm import State, is_connected


def _neighbours(cells: list[tuple[int, int]], model: Model) -> dict[tuple[int, int], list[tuple[int, int]]]:
    view2 = model.view2
    out: dict[tuple[int, int], list[tuple[int, int]]] = {c: [] for c in cells}
    for a in cells:
        for b in cells:
            if a != b and (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 <= view2:
                out[a].append(b)
    return out


def initial_configurations(n: int, window: tuple[int, int], model: Model) -> Iterator[State]:
    """Canonical initial configurations, in a deterministic order (by anchor, then search order)."""
    w, h = window
    cells = [(x, y) for x in range(w) for y in range(h)]
    if n == 1:
        yield ((0, 0),)
        return
    nbrs = _neighbours(cells, model)

    for anchor in [(0, y) for y in range(h)]:
        first = [d for d in nbrs[anchor] if d > anchor]
        yield from _grow(first, [anchor], {anchor, *first}, anchor, n, nbrs, model)


def _grow(
    untried: list[tuple[int, int]],
    chosen: list[tuple[int, int]],
    seen: set[tuple[int, int]],
    anchor: tuple[int, int],
    n: int,
    nbrs: dict[tuple[int, int], list[tuple[int, int]]],
    model: Model,
) -> Iterator[State]:
    """One level of Redelmeier's recursion: try each untried point in turn, never again after."""
    untried = list(untried)
    while untried:
        c = untried.pop()
        if not all(model.initially_apart((c[0] - d[0]) ** 2 + (c[1] - d[1]) ** 2) for d in chosen):
            continue
        chosen.append(c)
        if len(chosen) == n:
            if min(p[1] for p in chosen) == 0:
                yield tuple(sorted(chosen))
        else:
            fresh = [d for d in nbrs[c] if d > anchor and d not in seen]
            seen.update(fresh)
            yield from _grow(untried + fresh, chosen, seen, anchor, n, nbrs, model)
            seen.difference_update(fresh)
        chosen.pop()


def count_by_brute_force(n: int, window: tuple[int, int], model: Model) -> int:
    """The same count by brute force over all n-subsets (the reference for tests; small windows only)."""
    from itertools import combinations

    w, h = window
    cells = [(x, y) for x in range(w) for y in range(h)]
    found = set()
    for combo in combinations(cells, n):
        if min(p[0] for p in combo) or min(p[1] for p in combo):
            continue
        ok = all(model.initially_apart((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) for a, b in combinations(combo, 2))
        if ok and is_connected(combo, model):
            found.add(combo)
    return len(found)


def initial_array_by_levels(n: int, window: tuple[int, int], model: Model) -> np.ndarray:
    """The same configurations as :func:`initial_configurations`, built level by level with numpy
    (the checker's enumeration before :func:`initial_keys`; kept as an independent reference for tests:
    it allocates (configurations x grid) arrays per level, so it is slow and memory-hungry beyond n = 5).

    Every connected graph has a vertex whose removal leaves it connected, so every canonical
    (k+1)-configuration extends some canonical k-configuration by one visible point. Each level marks,
    per k-configuration, on a grid around it, the points some member sees, unmarks those too close to
    a member or that would make the bounding box outgrow the window, adds each remaining point,
    re-canonicalises and de-duplicates by packed key. Rows are sorted by key.
    """
    w, h = window
    r = isqrt(model.view2)
    offsets = [(dx, dy) for dx in range(-r, r + 1) for dy in range(-r, r + 1)]
    seen_off = [o for o in offsets if o[0] * o[0] + o[1] * o[1] <= model.view2]
    near_off = [o for o in offsets if o[0] * o[0] + o[1] * o[1] < model.apart2]
    level = np.zeros((1, 1, 2), dtype=np.int64)
    gx, gy = w + 2 * r, h + 2 * r  # grid cell (i, j) is the point (i - r, j - r)
    for k in range(1, n):
        if not len(level):
            return np.zeros((0, n, 2), dtype=np.int64)
        m = len(level)
        rows = np.arange(m)
        visible = np.zeros((m, gx, gy), dtype=bool)
        blocked = np.zeros((m, gx, gy), dtype=bool)
        for j in range(k):
            x, y = level[:, j, 0] + r, level[:, j, 1] + r
            for dx, dy in seen_off:
                visible[rows, x + dx, y + dy] = True
            for dx, dy in near_off:
                blocked[rows, x + dx, y + dy] = True
        lo, hi = level.min(axis=1), level.max(axis=1)  # (m, 2)
        xs, ys = np.arange(gx) - r, np.arange(gy) - r
        fit_x = (xs[None, :] >= hi[:, :1] - (w - 1)) & (xs[None, :] <= lo[:, :1] + (w - 1))
        fit_y = (ys[None, :] >= hi[:, 1:] - (h - 1)) & (ys[None, :] <= lo[:, 1:] + (h - 1))
        cand = visible & ~blocked & fit_x[:, :, None] & fit_y[:, None, :]
        row, cx, cy = np.nonzero(cand)
        point = np.stack([cx - r, cy - r], axis=-1)[:, None, :]
        grown = np.concatenate([level[row], point], axis=1)
        canon, _ = canonical(grown)
        codec = KeyCodec(k + 1, window)
        _, first = np.unique(codec.encode(canon), return_index=True)
        level = canon[first]
    if n == 1:
        return level
    order = np.argsort(KeyCodec(n, window).encode(level))
    return level[order]


__all__ = ["count_by_brute_force", "initial_array_by_levels", "initial_configurations"]
