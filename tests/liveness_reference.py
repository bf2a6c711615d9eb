"""The fair-cycle search as it was before the numba kernels (networkx over every edge on a cycle): the
reference tests/test_liveness.py holds :mod:`fatline_verify.check.liveness` to.

Liveness over the explored graph: deadlocks, terminal states off the RMA, and fair cycles.

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
"""

from __future__ import annotations

from itertools import pairwise
from typing import TYPE_CHECKING

import numpy as np

from fatline_verify.check.exploration import Exploration
from fatline_verify.check.liveness import Lasso

if TYPE_CHECKING:
    import networkx as nx

Labels = tuple[int, ...]
Node = tuple[int, Labels]


def _trim(src: np.ndarray, dst: np.ndarray, n_nodes: int) -> np.ndarray:
    """Edges that can lie on a cycle: repeatedly drop edges at nodes without in- or out-edges."""
    keep = np.ones(len(src), dtype=bool)
    while True:
        outdeg = np.bincount(src[keep], minlength=n_nodes)
        indeg = np.bincount(dst[keep], minlength=n_nodes)
        ok = keep & (outdeg[dst] > 0) & (indeg[src] > 0)
        if ok.sum() == keep.sum():
            return keep
        keep = ok


def _permutation(ex: Exploration, state_id: int, code: int) -> tuple[int, ...]:
    """For the step ``code`` from ``state_id``: ``perm[k]`` = the source index now at canonical index k."""
    system = ex.system
    state = system.from_array(ex.state_array(state_id))
    target = system.play(state, system.action(code, range(ex.n), state)).target
    _, order = system.canonical(system.to_array(target)[None])
    return tuple(int(i) for i in order[0])


def fair_cycles(ex: Exploration, nodes: np.ndarray) -> list[Lasso]:
    """One fair cycle per product SCC that has one, among explored states with ``nodes[id]`` true.

    Only edges between such states count, and only edges the search follows (non-violating unless
    ``after_violation == "continue"``).
    """
    src, dst, mask = ex.followed_edges(nodes)  # recomputed: the search keeps no transitions
    keep = _trim(src, dst, ex.n_states)
    src, dst, mask = src[keep], dst[keep], mask[keep]
    if not len(src):
        return []
    import networkx as nx  # imported when there is a cycle to look at: a check's start-up does not pay for it

    graph = nx.MultiDiGraph()
    for s, d, k in zip(src.tolist(), dst.tolist(), mask.tolist(), strict=True):
        graph.add_edge(s, d, mask=k)
    found = []
    identity = tuple(range(ex.n))
    for component in nx.strongly_connected_components(graph):
        sub = graph.subgraph(component)
        if len(component) == 1 and not sub.number_of_edges():
            continue
        start = min(component)
        product = _product(ex, sub, start, identity)
        for pcomp in nx.strongly_connected_components(product):
            lasso = _fair_cycle(ex, product.subgraph(pcomp))
            if lasso is not None:
                found.append(lasso)
    return sorted(found, key=lambda lasso: (int(ex.depth[lasso.start]), lasso.start, len(lasso.cycle)))


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
