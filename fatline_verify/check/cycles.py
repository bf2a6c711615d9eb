"""Graph kernels of the fair-cycle search (:mod:`.liveness`), in numba: strongly connected components of
a graph of tens of millions of edges, and the product of a component with the robots' labellings.

A graph is given as edge arrays ``(src, dst)`` over nodes ``0..n-1``; :func:`csr` groups the edges by
source, keeping their order (the order the liveness module's walks depend on).
"""

from __future__ import annotations

import numpy as np
from numba import njit


def csr(src: np.ndarray, dst: np.ndarray, n_nodes: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(indptr, indices, edge)``: node ``v``'s out-edges are ``edge[indptr[v]:indptr[v + 1]]`` (edge
    numbers, in their given order) going to ``indices[...]``."""
    edge = np.argsort(src, kind="stable")
    indptr = np.zeros(n_nodes + 1, dtype=np.int64)
    np.cumsum(np.bincount(src, minlength=n_nodes), out=indptr[1:])
    return indptr, np.ascontiguousarray(dst[edge], dtype=np.int64), edge


@njit(cache=True)
def _tarjan(indptr: np.ndarray, indices: np.ndarray) -> tuple[np.ndarray, int]:
    n = len(indptr) - 1
    index = np.full(n, -1, dtype=np.int64)
    low = np.zeros(n, dtype=np.int64)
    comp = np.full(n, -1, dtype=np.int64)
    stack = np.empty(n, dtype=np.int64)
    call_v = np.empty(n, dtype=np.int64)
    call_e = np.empty(n, dtype=np.int64)
    sp = 0
    counter = 0
    count = 0
    for root in range(n):
        if index[root] >= 0:
            continue
        index[root] = counter
        low[root] = counter
        counter += 1
        stack[sp] = root
        sp += 1
        call_v[0] = root
        call_e[0] = indptr[root]
        depth = 1
        while depth > 0:
            v = call_v[depth - 1]
            e = call_e[depth - 1]
            if e < indptr[v + 1]:
                call_e[depth - 1] = e + 1
                w = indices[e]
                if index[w] < 0:
                    index[w] = counter
                    low[w] = counter
                    counter += 1
                    stack[sp] = w
                    sp += 1
                    call_v[depth] = w
                    call_e[depth] = indptr[w]
                    depth += 1
                elif comp[w] < 0 and index[w] < low[v]:  # w is on the stack
                    low[v] = index[w]
            else:
                depth -= 1
                if low[v] == index[v]:
                    while True:
                        sp -= 1
                        w = stack[sp]
                        comp[w] = count
                        if w == v:
                            break
                    count += 1
                if depth > 0:
                    u = call_v[depth - 1]
                    if low[v] < low[u]:
                        low[u] = low[v]
    return comp, count


def strong_components(indptr: np.ndarray, indices: np.ndarray) -> tuple[np.ndarray, int]:
    """Each node's strongly connected component (numbered in reverse topological order: an edge
    between two components goes to a lower number), and the number of components."""
    comp, count = _tarjan(np.asarray(indptr, dtype=np.int64), np.asarray(indices, dtype=np.int64))
    return comp, int(count)


@njit(cache=True)
def _trim(src: np.ndarray, dst: np.ndarray, n_nodes: int, rounds: int) -> np.ndarray:
    keep = np.ones(len(src), dtype=np.bool_)
    for _ in range(rounds):
        has_out = np.zeros(n_nodes, dtype=np.bool_)
        has_in = np.zeros(n_nodes, dtype=np.bool_)
        for e in range(len(src)):
            if keep[e]:
                has_out[src[e]] = True
                has_in[dst[e]] = True
        changed = False
        for e in range(len(src)):
            if keep[e] and not (has_in[src[e]] and has_out[dst[e]]):
                keep[e] = False
                changed = True
        if not changed:
            break
    return keep


def cyclic_edges(src: np.ndarray, dst: np.ndarray, n_nodes: int, rounds: int = 64) -> tuple[np.ndarray, np.ndarray]:
    """``(keep, comp)``: which edges lie on a cycle (both ends in one strongly connected component), and
    each node's component (-1 for a node on no such edge). Edges at nodes without in- or out-edges are
    dropped first (up to ``rounds`` times, until none is), so the components are computed on what
    remains."""
    keep = _trim(src, dst, n_nodes, rounds)
    comp = np.full(n_nodes, -1, dtype=np.int64)
    inside = np.flatnonzero(keep)
    if not len(inside):
        return keep, comp
    s, d = src[inside], dst[inside]
    nodes = np.unique(np.concatenate([s, d]))
    ls, ld = np.searchsorted(nodes, s), np.searchsorted(nodes, d)
    indptr, indices, _ = csr(ls, ld, len(nodes))
    sub, _ = strong_components(indptr, indices)
    same = sub[ls] == sub[ld]
    keep[inside[~same]] = False
    comp[nodes] = sub
    on = np.zeros(n_nodes, dtype=bool)
    on[s[same]] = True
    comp[~on] = -1
    return keep, comp


# --- the product with labellings ------------------------------------------------------------------
@njit(cache=True)
def _grow(a: np.ndarray, size: int) -> np.ndarray:
    if size <= a.shape[0]:
        return a
    b = np.empty((max(2 * a.shape[0], size),) + a.shape[1:], dtype=a.dtype)  # noqa: RUF005 (numba)
    b[: a.shape[0]] = a
    return b


@njit(cache=True)
def _pack(lab: np.ndarray, bits: int) -> int:
    key = 0
    for i in range(lab.shape[0]):
        key = (key << bits) | lab[i]
    return key


@njit(cache=True)
def _product(
    indptr: np.ndarray, indices: np.ndarray, perm: np.ndarray, starts: np.ndarray, n: int, bits: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    seen = dict()
    seen[(-1, -1)] = -1  # types the dict: (graph node, packed labelling) -> product node
    node_state = np.empty(1024, dtype=np.int64)
    node_lab = np.empty((1024, n), dtype=np.int64)
    eu = np.empty(1024, dtype=np.int64)
    ev = np.empty(1024, dtype=np.int64)
    ej = np.empty(1024, dtype=np.int64)
    todo = np.empty(1024, dtype=np.int64)
    nodes = 0
    edges = 0
    lab = np.empty(n, dtype=np.int64)
    for s0 in starts:
        node_state = _grow(node_state, nodes + 1)
        node_lab = _grow(node_lab, nodes + 1)
        node_state[nodes] = s0
        for i in range(n):
            node_lab[nodes, i] = i
        seen[(s0, _pack(node_lab[nodes], bits))] = nodes
        todo[0] = nodes
        top = 1
        nodes += 1
        while top > 0:
            top -= 1
            u = todo[top]
            s = node_state[u]
            for j in range(indptr[s], indptr[s + 1]):
                d = indices[j]
                for i in range(n):
                    lab[i] = node_lab[u, perm[j, i]]
                key = (d, _pack(lab, bits))
                v = seen.get(key, -1)
                if v < 0:
                    v = nodes
                    node_state = _grow(node_state, nodes + 1)
                    node_lab = _grow(node_lab, nodes + 1)
                    node_state[v] = d
                    node_lab[v] = lab
                    seen[key] = v
                    nodes += 1
                    todo = _grow(todo, top + 1)
                    todo[top] = v
                    top += 1
                eu = _grow(eu, edges + 1)
                ev = _grow(ev, edges + 1)
                ej = _grow(ej, edges + 1)
                eu[edges] = u
                ev[edges] = v
                ej[edges] = j
                edges += 1
    return node_state[:nodes].copy(), node_lab[:nodes].copy(), eu[:edges].copy(), ev[:edges].copy(), ej[:edges].copy()


def product(
    indptr: np.ndarray, indices: np.ndarray, perm: np.ndarray, starts: np.ndarray, n: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The product of a graph (CSR, ``perm[j]`` the permutation its edge ``j`` induces: ``perm[j][k]`` =
    the source index now at index ``k``) with the labellings of ``n`` robots, explored depth first from
    each node of ``starts`` labelled by the identity, as :func:`fatline_verify.check.liveness` defines it.

    Returns ``(node_state, node_labels, edge_u, edge_v, edge_j)``: product node ``p`` is graph node
    ``node_state[p]`` with robot ``node_labels[p, k]`` at index ``k``; product edge ``i`` goes from
    ``edge_u[i]`` to ``edge_v[i]`` along graph edge (CSR position) ``edge_j[i]``."""
    bits = max(1, (n - 1).bit_length())
    if bits * n > 63:
        raise ValueError(f"robots={n}: a labelling of more than 15 robots does not pack in 63 bits")
    return _product(  # type: ignore[no-any-return]
        np.asarray(indptr, dtype=np.int64),
        np.asarray(indices, dtype=np.int64),
        np.ascontiguousarray(perm, dtype=np.int64),
        np.asarray(starts, dtype=np.int64),
        n,
        bits,
    )


@njit(cache=True)
def _bfs_path(indptr: np.ndarray, indices: np.ndarray, inside: np.ndarray, source: int, target: int) -> np.ndarray:
    """The nodes of a shortest path from ``source`` to ``target`` through nodes with ``inside`` true
    (``[source]`` when they are one); empty when there is none."""
    if source == target:
        out = np.empty(1, dtype=np.int64)
        out[0] = source
        return out
    parent = dict()
    parent[source] = source
    queue = np.empty(1024, dtype=np.int64)
    queue[0] = source
    head, tail = 0, 1
    while head < tail:
        u = queue[head]
        head += 1
        for e in range(indptr[u], indptr[u + 1]):
            v = indices[e]
            if not inside[v] or v in parent:
                continue
            parent[v] = u
            if v == target:
                length = 1
                w = v
                while w != source:
                    w = parent[w]
                    length += 1
                out = np.empty(length, dtype=np.int64)
                w = v
                for i in range(length - 1, -1, -1):
                    out[i] = w
                    w = parent[w]
                return out
            queue = _grow(queue, tail + 1)
            queue[tail] = v
            tail += 1
    return np.empty(0, dtype=np.int64)


def bfs_path(indptr: np.ndarray, indices: np.ndarray, inside: np.ndarray, source: int, target: int) -> np.ndarray:
    """A shortest path (its nodes) from ``source`` to ``target`` among the nodes with ``inside`` true."""
    return _bfs_path(indptr, indices, inside, int(source), int(target))  # type: ignore[no-any-return]


# --- fairness of a component, without its product ----------------------------------------------------
@njit(cache=True)
def _find(parent: np.ndarray, c: int, i: int) -> int:
    while parent[c, i] != i:
        parent[c, i] = parent[c, parent[c, i]]
        i = parent[c, i]
    return i


@njit(cache=True)
def _fair_components(
    indptr: np.ndarray,
    indices: np.ndarray,
    perm: np.ndarray,
    action: np.ndarray,
    comp: np.ndarray,
    starts: np.ndarray,
    enabled: np.ndarray,
    n: int,
) -> np.ndarray:
    m = len(indptr) - 1
    count = len(starts)
    tree = np.full((m, n), -1, dtype=np.int64)
    queue = np.empty(m, dtype=np.int64)
    parent = np.empty((count, n), dtype=np.int64)
    for c in range(count):
        for i in range(n):
            parent[c, i] = i
    head, tail = 0, 0
    for c in range(count):  # a spanning tree of each component from its start, labelling its nodes
        s0 = starts[c]
        for i in range(n):
            tree[s0, i] = i
        queue[tail] = s0
        tail += 1
        while head < tail:
            u = queue[head]
            head += 1
            for j in range(indptr[u], indptr[u + 1]):
                v = indices[j]
                if tree[v, 0] < 0:
                    for i in range(n):
                        tree[v, i] = tree[u, perm[j, i]]
                    queue[tail] = v
                    tail += 1
    good = np.zeros((count, n), dtype=np.bool_)
    for u in range(m):
        c = comp[u]
        seen = ~enabled[u]
        for j in range(indptr[u], indptr[u + 1]):
            v = indices[j]
            seen |= action[j]
            for i in range(n):  # the edge relabels robot tree[v, i] as tree[u, perm[j, i]]: one orbit
                a = _find(parent, c, tree[v, i])
                b = _find(parent, c, tree[u, perm[j, i]])
                if a != b:
                    parent[c, a] = b
        for k in range(n):
            if seen >> k & 1:
                good[c, tree[u, k]] = True
    fair = np.ones(count, dtype=np.bool_)
    hit = np.zeros(n, dtype=np.bool_)
    for c in range(count):
        hit[:] = False
        for i in range(n):
            if good[c, i]:
                hit[_find(parent, c, i)] = True
        for i in range(n):
            if not hit[_find(parent, c, i)]:
                fair[c] = False
    return fair


def fair_components(
    indptr: np.ndarray,
    indices: np.ndarray,
    perm: np.ndarray,
    action: np.ndarray,
    comp: np.ndarray,
    starts: np.ndarray,
    enabled: np.ndarray,
    n: int,
) -> np.ndarray:
    """Whether each strongly connected component ``c`` (``comp[v]`` in ``0..len(starts)-1``; every edge
    inside one) has a fair cycle in its product with the labellings (:func:`product` from
    ``starts[c]``), without building the product.

    Every edge of that product lies on a cycle (lift a cycle of the component through it and repeat it
    until the labelling returns), so the part reached from ``(start, identity)`` is one SCC; with
    ``tree[v]`` the labelling a spanning tree reaches ``v`` with, its nodes at ``v`` are ``(v, h o
    tree[v])`` for ``h`` in the group generated by the relabellings the edges make
    (``tree[u] o perm o tree[v]^-1``). So the robots found at index ``k`` of ``v`` are the orbit of
    ``tree[v][k]`` under that group, and the SCC is fair iff every orbit holds a robot standing, in
    the tree's labelling, at an index disabled at a node or activated by an edge out of it."""
    return _fair_components(  # type: ignore[no-any-return]
        np.asarray(indptr, dtype=np.int64),
        np.asarray(indices, dtype=np.int64),
        np.ascontiguousarray(perm, dtype=np.int64),
        np.asarray(action, dtype=np.int64),
        np.asarray(comp, dtype=np.int64),
        np.asarray(starts, dtype=np.int64),
        np.asarray(enabled, dtype=np.int64),
        n,
    )


__all__ = ["bfs_path", "csr", "cyclic_edges", "fair_components", "product", "strong_components"]
