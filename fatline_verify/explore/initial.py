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
"""

from __future__ import annotations

from collections.abc import Iterator
from math import isqrt

import numpy as np

from ..config import Model
from ..swarm import State, is_connected
from .lattice import KeyCodec, canonical


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


def initial_array(n: int, window: tuple[int, int], model: Model) -> np.ndarray:
    """The same configurations as :func:`initial_configurations`, built level by level with numpy.

    Every connected graph has a vertex whose removal leaves it connected, so every canonical
    (k+1)-configuration extends some canonical k-configuration by one visible point; each level
    extends every k-configuration by every visible, non-conflicting point, re-canonicalises, keeps
    what fits the window and de-duplicates by packed key. Rows are sorted by key.
    """
    codec = KeyCodec(n, window)
    r = isqrt(model.view2)
    disc = np.array(
        [(dx, dy) for dx in range(-r, r + 1) for dy in range(-r, r + 1) if dx * dx + dy * dy <= model.view2]
    )
    level = np.zeros((1, 1, 2), dtype=np.int64)
    for k in range(1, n):
        if not len(level):
            return np.zeros((0, n, 2), dtype=np.int64)
        # every member + every disc offset: (m, k * |disc|, 2) candidates
        cand = (level[:, :, None, :] + disc[None, None, :, :]).reshape(len(level), -1, 2)
        diff = cand[:, :, None, :] - level[:, None, :, :]
        ok = ((diff * diff).sum(axis=-1) >= model.apart2).all(axis=2)
        rows, cols = np.nonzero(ok)
        grown = np.concatenate([level[rows], cand[rows, cols][:, None, :]], axis=1)
        canon, _ = canonical(grown)
        sub = KeyCodec(k + 1, window)
        canon = canon[sub.fits(canon)]
        keys, first = np.unique(sub.encode(canon), return_index=True)
        level = canon[first]
    keys = codec.encode(level) if n > 1 else np.zeros(1, dtype=np.int64)
    order = np.argsort(keys)
    return level[order]
