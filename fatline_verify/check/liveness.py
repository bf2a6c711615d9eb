"""Liveness over the explored graph: deadlocks, terminal states off the RMA, and fair cycles.

Fairness (weak, per robot): a cycle is fair when no robot stays enabled in every state of it
without being activated in some round of it ("the robots do not stay idle for infinite time";
idle robots may be activated for free, a self-loop). Canonical states forget which robot is which,
but fairness is about a robot, so cycles are looked for in a product graph whose nodes are
``(state, labelling)``: the labelling says which robot stands at each canonical index, and an edge
carries the permutation its round induces. Relabelling robots is a symmetry of that graph, so
exploring it from one labelling per strongly connected component (SCC) of the state graph is
enough. A product SCC contains a fair cycle iff every robot is disabled in one of its nodes or
activated on one of its edges (weak fairness needs no refinement of the SCC); the cycle built then
visits, for each robot, such a node or edge, and returns.

How it is computed (the graphs reach a hundred million edges): the followed transitions are recomputed
once per exploration and only those on a cycle of the state graph are kept (:func:`_cyclic`,
:mod:`.cycles`: numba SCCs). The product from one labelling of a state SCC is a single SCC (each of its
edges lies on a cycle: a state cycle through it, repeated until the labelling returns), whose
labellings at a state are those of a spanning tree composed with one group of relabellings; so whether
it is fair is decided without building it (:func:`.cycles.fair_components`), and only a fair one is
built and walked: by networkx as before when small (:data:`EXACT_PRODUCT`), else on arrays.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise
from math import factorial
from typing import TYPE_CHECKING

import numpy as np

from . import cycles
from .exploration import Exploration

if TYPE_CHECKING:
    import networkx as nx

Labels = tuple[int, ...]
Node = tuple[int, Labels]


@dataclass(frozen=True, slots=True)
class Lasso:
    """A fair cycle: the state it starts from and its rounds as ``(state id, mask)`` steps."""

    start: int
    cycle: tuple[tuple[int, int], ...]


def _permutation(ex: Exploration, state_id: int, code: int) -> tuple[int, ...]:
    """For the step ``code`` from ``state_id``: ``perm[k]`` = the source index now at canonical index k."""
    system = ex.system
    state = system.from_array(ex.state_array(state_id))
    target = system.play(state, system.action(code, range(ex.n), state)).target
    _, order = system.canonical(system.to_array(target)[None])
    return tuple(int(i) for i in order[0])


EXACT_PRODUCT = 100_000
"""A state SCC's states times n! (a bound on its product's nodes) up to which its fair cycles are built by
the reference walk (networkx, as it always was); a larger one's by :func:`_built` on arrays."""


def fair_cycles(ex: Exploration, nodes: np.ndarray) -> list[Lasso]:
    """One fair cycle per product SCC that has one, among explored states with ``nodes[id]`` true.

    Only edges between such states count, and only edges the search follows (non-violating unless
    ``after_violation == "continue"``). The edges that lie on a cycle are found once per exploration
    (:func:`_cyclic`); each state SCC's product is explored from one labelling and its SCCs judged on
    arrays (:mod:`.cycles`); only the SCCs with a fair cycle are walked to build it.
    """
    src, dst, mask = _cyclic(ex, nodes)
    if not len(src):
        return []
    keep, comp = cycles.cyclic_edges(src, dst, ex.n_states)
    src, dst, mask = src[keep], dst[keep], mask[keep]
    if not len(src):
        return []
    states = np.unique(src)  # every state on a cycle has an edge out
    local_src, local_dst = np.searchsorted(states, src), np.searchsorted(states, dst)
    # state SCCs numbered 0, 1, ...; each one's least state (states ascend) starts its product
    _, starts, scc = np.unique(comp[states], return_index=True, return_inverse=True)
    indptr, indices, order = cycles.csr(local_src, local_dst, len(states))
    perms = permutations(ex, src[order], mask[order])
    action = mask[order].astype(np.int64)
    fair = cycles.fair_components(indptr, indices, perms, action, scc, starts, ex.enabled[states], ex.n)
    found: list[Lasso] = []
    for c in np.flatnonzero(fair).tolist():
        inside = scc[local_src] == c
        if int((scc == c).sum()) * factorial(ex.n) <= EXACT_PRODUCT:
            found += _reference(ex, src[inside], dst[inside], mask[inside])
            continue
        found += _product_lassos(ex, states, indptr, indices, perms, action, int(starts[c]))
    return sorted(found, key=lambda lasso: (int(ex.depth[lasso.start]), lasso.start, len(lasso.cycle)))


def _product_lassos(
    ex: Exploration,
    states: np.ndarray,
    indptr: np.ndarray,
    indices: np.ndarray,
    perms: np.ndarray,
    action: np.ndarray,
    start: int,
) -> list[Lasso]:
    """The fair cycles of the product of one state SCC (from its least state ``start``), built on arrays."""
    pstate, plab, pu, pv, pj = cycles.product(indptr, indices, perms, np.array([start]), ex.n)
    pptr, pidx, porder = cycles.csr(pu, pv, len(pstate))
    pcomp, count = cycles.strong_components(pptr, pidx)
    inner = pcomp[pu] == pcomp[pv]
    cover = np.zeros(count, dtype=np.int64)
    enabled = ex.enabled[states[pstate]].astype(np.int64)
    act = action[pj]
    for k in range(ex.n):
        np.bitwise_or.at(cover, pcomp, np.where((enabled >> k) & 1, 0, np.int64(1) << plab[:, k]))
        on = inner & ((act >> k) & 1).astype(bool)
        np.bitwise_or.at(cover, pcomp[pu[on]], np.int64(1) << plab[pu[on], k])
    fair = (cover == (1 << ex.n) - 1) & (np.bincount(pcomp[pu[inner]], minlength=count) > 0)
    graph = (pptr, pidx, porder, pu, pv, act)
    return [_built(ex, states, pstate, plab, pcomp, c, graph) for c in np.flatnonzero(fair).tolist()]


def _cyclic(ex: Exploration, nodes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The followed edges between states with ``nodes[id]`` true that may lie on a cycle: the edges on a
    cycle among all expanded states (recomputed once per exploration and kept), restricted to ``nodes``.
    A cycle among ``nodes`` is a cycle among the expanded states, and unexpanded states have no edges."""

    def make() -> tuple[np.ndarray, ...]:
        had_index = ex.has_index()
        src, dst, mask = ex.followed_edges(ex.expanded)  # recomputed: the search keeps no transitions
        if not had_index:
            ex.drop_index()  # about 24 bytes a state, not needed again
        keep, _ = cycles.cyclic_edges(src, dst, ex.n_states)
        return src[keep], dst[keep], mask[keep]

    got = ex.memo("cyclic_edges", make)
    src, dst, mask = got
    ok = nodes[src] & nodes[dst]
    return src[ok], dst[ok], mask[ok]


def permutations(ex: Exploration, src: np.ndarray, action: np.ndarray, batch: int = 50_000) -> np.ndarray:
    """``(m, n)``: row ``i`` is :func:`_permutation` of the step ``action[i]`` from state ``src[i]``
    (``perm[k]`` = the source index now at canonical index k), computed by the search's engine for a
    batch of states at a time."""
    out = np.zeros((len(src), ex.n), dtype=np.int64)
    sources, inverse = np.unique(src, return_inverse=True)
    engine = ex.expander_engine()
    for lo in range(0, len(sources), batch):
        rows = np.flatnonzero((inverse >= lo) & (inverse < lo + batch))
        got = engine.expand(ex.state_array(sources[lo : lo + batch]))
        have = got.src.astype(np.int64) * (1 << 32) + got.action.astype(np.int64)
        want = (inverse[rows] - lo).astype(np.int64) * (1 << 32) + action[rows].astype(np.int64)
        by = np.argsort(have, kind="stable")
        at = by[np.minimum(np.searchsorted(have, want, sorter=by), len(have) - 1)]
        if len(want) and not np.array_equal(have[at], want):
            raise RuntimeError("the engine no longer lists a step the search followed")
        _, order = ex.system.canonical(got.after[at])
        out[rows] = order
    return out


def _reference(ex: Exploration, src: np.ndarray, dst: np.ndarray, mask: np.ndarray) -> list[Lasso]:
    """The fair cycles of one state SCC (its edges, in (source, action) order), by the reference walk."""
    import networkx as nx  # imported when there is a fair cycle to build: a check's start-up does not pay for it

    sub = nx.MultiDiGraph()
    for s, d, k in zip(src.tolist(), dst.tolist(), mask.tolist(), strict=True):
        sub.add_edge(s, d, mask=k)
    product = _product(ex, sub, int(src.min()), tuple(range(ex.n)))
    found = []
    for pcomp in nx.strongly_connected_components(product):
        lasso = _fair_cycle(ex, product.subgraph(pcomp))
        if lasso is not None:
            found.append(lasso)
    return found


def _built(
    ex: Exploration,
    states: np.ndarray,
    pstate: np.ndarray,
    plab: np.ndarray,
    pcomp: np.ndarray,
    c: int,
    graph: tuple[np.ndarray, ...],
) -> Lasso:
    """The fair cycle of the product SCC ``c`` (one that has one), as :func:`_fair_cycle` builds it: per
    robot the least node where it is disabled, else the least edge that activates it, in turn from the
    least node and back, by shortest paths (ties between shortest paths broken otherwise)."""
    pptr, pidx, porder, pu, pv, action = graph
    members = np.flatnonzero(pcomp == c)
    sid = states[pstate[members]]
    # sorted(comp.nodes): by state id, then labelling
    rank_order = np.lexsort((*(plab[members, k] for k in range(ex.n - 1, -1, -1)), sid))
    ordered = members[rank_order]
    rank = np.full(len(pstate), -1, dtype=np.int64)
    rank[ordered] = np.arange(len(ordered))
    inside = pcomp == c
    edges = np.flatnonzero(inside[pu] & inside[pv])
    edges = edges[np.lexsort((action[edges], rank[pv[edges]], rank[pu[edges]]))]
    enabled = ex.enabled[states[pstate]].astype(np.int64)
    targets: list[tuple[int, tuple[int, int] | None]] = []
    for robot in range(ex.n):
        k_of = np.argmax(plab[ordered] == robot, axis=1)
        off = np.flatnonzero(((enabled[ordered] >> k_of) & 1) == 0)
        if len(off):
            targets.append((int(ordered[off[0]]), None))
            continue
        k_u = np.argmax(plab[pu[edges]] == robot, axis=1)
        on = np.flatnonzero((action[edges] >> k_u) & 1)
        e = int(edges[on[0]])  # the SCC is fair: some edge activates the robot
        targets.append((int(pu[e]), (int(pv[e]), int(action[e]))))
    start = int(ordered[0])
    steps: list[tuple[int, int]] = []
    here = start

    def step(u: int, v: int) -> None:
        out = porder[pptr[u] : pptr[u + 1]]
        k = int(action[out[pv[out] == v]].min())
        steps.append((int(states[pstate[u]]), k))

    def walk(to: int) -> None:
        nonlocal here
        path = cycles.bfs_path(pptr, pidx, inside, here, to).tolist()
        for u, v in pairwise(path):
            step(u, v)
        here = to

    for node, then in targets:
        walk(node)
        if then is not None:
            steps.append((int(states[pstate[node]]), then[1]))
            here = then[0]
    walk(start)
    if not steps:
        out = porder[pptr[start] : pptr[start + 1]]
        first = out[inside[pv[out]]][0]
        steps.append((int(states[pstate[start]]), int(action[first])))
        here = int(pv[first])
        walk(start)
    return Lasso(int(states[pstate[start]]), tuple(steps))


def _product(ex: Exploration, sub: nx.MultiDiGraph, start: int, labels: Labels) -> nx.MultiDiGraph:
    import networkx as nx

    product = nx.MultiDiGraph()
    todo = [(start, labels)]
    product.add_node(todo[0])
    perms: dict[tuple[int, int], tuple[int, ...]] = {}
    while todo:
        node = todo.pop()
        s, lab = node
        for _, d, data in sub.out_edges(s, data=True):
            k = data["mask"]
            perm = perms.get((s, k))
            if perm is None:
                perm = perms[(s, k)] = _permutation(ex, s, k)
            nxt = (d, tuple(lab[perm[i]] for i in range(ex.n)))
            if nxt not in product:
                todo.append(nxt)
            product.add_edge(node, nxt, mask=k)
    return product


def _fair_cycle(ex: Exploration, comp: nx.MultiDiGraph) -> Lasso | None:
    if comp.number_of_edges() == 0:
        return None
    # Per robot: a node to reach, then optionally an edge (to node, mask) to take from it.
    targets: list[tuple[Node, tuple[Node, int] | None]] = []
    for robot in range(ex.n):
        disabled = next(
            (node for node in sorted(comp.nodes) if not (int(ex.enabled[node[0]]) >> node[1].index(robot) & 1)), None
        )
        if disabled is not None:
            targets.append((disabled, None))
            continue
        edge = next(
            (
                (u, v, data["mask"])
                for u, v, data in sorted(comp.edges(data=True), key=lambda e: (e[0], e[1], e[2]["mask"]))
                if data["mask"] >> u[1].index(robot) & 1
            ),
            None,
        )
        if edge is None:
            return None
        targets.append((edge[0], (edge[1], edge[2])))
    import networkx as nx

    start = min(comp.nodes)
    steps: list[tuple[int, int]] = []
    here = start

    def walk(to: Node) -> None:
        nonlocal here
        path = nx.shortest_path(comp, here, to)
        for u, v in pairwise(path):
            k = min(data["mask"] for data in comp.get_edge_data(u, v).values())
            steps.append((u[0], k))
        here = to

    for node, then in targets:
        walk(node)
        if then is not None:
            steps.append((node[0], then[1]))
            here = then[0]
    walk(start)
    if not steps:  # the start node is a target of every robot; take its cheapest self-loop or cycle
        for u, v, data in comp.out_edges(start, data=True):
            steps.append((u[0], data["mask"]))
            here = v
            break
        walk(start)
    return Lasso(start[0], tuple(steps))
