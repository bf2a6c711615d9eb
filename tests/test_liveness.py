"""The fair-cycle search (:mod:`fatline_verify.check.liveness`) against the networkx search it replaced
(tests/liveness_reference.py): the same lassos on random graphs and on explored models; and the lassos
its array walk builds for a large product (:func:`liveness._built`) are fair cycles of the product, one per
product SCC the reference finds one in, with the same start and length."""

from __future__ import annotations

from dataclasses import replace
from itertools import permutations as all_orders
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from fatline_verify.check import cycles, liveness
from fatline_verify.check.checker import CheckPlan, explore_robots
from fatline_verify.check.liveness import Lasso
from fatline_verify.check.witness import lasso_run
from fatline_verify.rules.paper.algorithm import Decision, Rule
from tests import liveness_reference as reference
from tests.conftest import make_model


class Graph:
    """A stand-in for an :class:`~fatline_verify.check.exploration.Exploration`: states, their enabled
    robots, edges in (source, action) order, and the permutation each edge induces."""

    def __init__(self, n: int, enabled: list[int], edges: dict[tuple[int, int], tuple[int, tuple[int, ...]]]):
        self.n = n
        self.n_states = len(enabled)
        self.enabled = np.array(enabled, dtype=np.uint8)
        self.expanded = np.ones(self.n_states, dtype=bool)
        self.goal = np.zeros(self.n_states, dtype=bool)
        self.depth = np.arange(self.n_states, dtype=np.int32) % 3
        self.perm = {key: perm for key, (_, perm) in edges.items()}
        rows = sorted((s, k, d) for (s, k), (d, _) in edges.items())
        self.src = np.array([r[0] for r in rows], dtype=np.int64)
        self.action = np.array([r[1] for r in rows], dtype=np.int32)
        self.dst = np.array([r[2] for r in rows], dtype=np.int64)
        self._cache: dict[str, Any] = {}

    def followed_edges(self, nodes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        ok = nodes[self.src] & nodes[self.dst] if len(self.src) else np.zeros(0, dtype=bool)
        return self.src[ok], self.dst[ok], self.action[ok]

    def memo(self, name: str, make: Any) -> Any:
        if name not in self._cache:
            self._cache[name] = make()
        return self._cache[name]

    def has_index(self) -> bool:
        return False

    def drop_index(self) -> None:
        pass


@pytest.fixture
def graph_perms(monkeypatch):
    """Both searches read a :class:`Graph`'s permutations instead of playing the model."""

    def one(ex, s, k):
        return ex.perm[(int(s), int(k))]

    def many(ex, src, action):
        return np.array([one(ex, s, k) for s, k in zip(src, action, strict=True)], dtype=np.int64).reshape(-1, ex.n)

    monkeypatch.setattr(liveness, "_permutation", one)
    monkeypatch.setattr(reference, "_permutation", one)
    monkeypatch.setattr(liveness, "permutations", many)


@st.composite
def graphs(draw: Any) -> Graph:
    n = draw(st.integers(1, 4))
    size = draw(st.integers(1, 9))
    orders = list(all_orders(range(n)))
    enabled = [draw(st.integers(0, (1 << n) - 1)) for _ in range(size)]
    edges = {}
    for s in range(size):
        for k in draw(st.sets(st.integers(1, (1 << n) - 1), max_size=3)):
            edges[(s, k)] = (draw(st.integers(0, size - 1)), draw(st.sampled_from(orders)))
    return Graph(n, enabled, edges)


def closes_fairly(ex: Graph, lasso: Lasso) -> bool:
    """The lasso is a cycle of the product (states and labelling return) on which every robot is disabled
    in a node or activated on a step."""
    state, lab, seen = lasso.start, tuple(range(ex.n)), 0
    for s, k in lasso.cycle:
        if s != state or (s, k) not in ex.perm:
            return False
        for i in range(ex.n):
            if not int(ex.enabled[s]) >> i & 1 or k >> i & 1:
                seen |= 1 << lab[i]
        perm = ex.perm[(s, k)]
        state, lab = int(ex.dst[(ex.src == s) & (ex.action == k)][0]), tuple(lab[perm[i]] for i in range(ex.n))
    return state == lasso.start and lab == tuple(range(ex.n)) and seen == (1 << ex.n) - 1


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(graphs(), st.booleans())
def test_random_graphs_give_the_reference_lassos(graph_perms, ex, goal_free):
    nodes = ex.expanded.copy()
    if goal_free:
        nodes[::2] = False
    want = reference.fair_cycles(ex, nodes)
    ex._cache.clear()
    assert liveness.fair_cycles(ex, nodes) == want


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(graphs())
def test_the_array_walk_builds_fair_cycles_where_the_reference_does(graph_perms, monkeypatch, ex):
    monkeypatch.setattr(liveness, "EXACT_PRODUCT", 0)
    want = reference.fair_cycles(ex, ex.expanded)
    got = liveness.fair_cycles(ex, ex.expanded)
    assert sorted((a.start, len(a.cycle)) for a in got) == sorted((a.start, len(a.cycle)) for a in want)
    assert all(closes_fairly(ex, lasso) for lasso in got)


def test_a_relabelling_cycle_is_fair_only_through_the_product(graph_perms, monkeypatch):
    # Two robots, one state, robot at canonical index 0 always the one activated, but each step swaps
    # the labels: in the product the cycle has two nodes and activates both robots.
    ex = Graph(2, [0b11], {(0, 0b01): (0, (1, 0))})
    for cap in (liveness.EXACT_PRODUCT, 0):
        monkeypatch.setattr(liveness, "EXACT_PRODUCT", cap)
        ex._cache.clear()
        got = liveness.fair_cycles(ex, ex.expanded)
        assert got == [Lasso(0, ((0, 1), (0, 1)))]
    unfair = Graph(2, [0b11], {(0, 0b01): (0, (0, 1))})
    assert liveness.fair_cycles(unfair, unfair.expanded) == []


def test_strong_components_match_networkx():
    import networkx as nx

    rng = np.random.default_rng(7)
    for _ in range(30):
        size = int(rng.integers(1, 40))
        src = rng.integers(0, size, int(rng.integers(0, 80)))
        dst = rng.integers(0, size, len(src))
        indptr, indices, _ = cycles.csr(src, dst, size)
        comp, count = cycles.strong_components(indptr, indices)
        graph = nx.DiGraph()
        graph.add_nodes_from(range(size))
        graph.add_edges_from(zip(src.tolist(), dst.tolist(), strict=True))
        want = {frozenset(c) for c in nx.strongly_connected_components(graph)}
        assert {frozenset(np.flatnonzero(comp == c).tolist()) for c in range(count)} == want
        keep, _ = cycles.cyclic_edges(src, dst, size)
        on_cycle = [bool(nx.has_path(graph, d, s)) for s, d in zip(src.tolist(), dst.tolist(), strict=True)]
        assert keep.tolist() == on_cycle


def slide(scheduler: str) -> Any:
    """Every robot that sees anything steps down 2: under any scheduler the swarm can slide forever."""

    def rule(snapshot, model):
        if not snapshot:
            return Decision(Rule.ALONE, (0, 0), ((0, 0),), ())
        return Decision(Rule.SCENARIO_4_I_EMPTY, (0, -2), ((0, 0), (0, -2)), ())

    return replace(make_model(scheduler=scheduler), algorithm=rule)


@pytest.mark.parametrize(
    ("scheduler", "n"),
    [
        *((s, n) for s in ("fsync", "ssync", "centralized") for n in (2, 3)),
        ("async", 2),
        pytest.param("async", 3, marks=pytest.mark.slow),  # 89 fair SCCs, each walked by both searches
    ],
)
def test_explored_models_give_the_reference_lassos_and_permutations(scheduler, n, monkeypatch):
    model = slide(scheduler)
    ex = explore_robots(CheckPlan.of(model, robots=(n, n), window=(7, 7), max_states=200_000, engine="fast"), n)
    src, _, action = ex.followed_edges(ex.expanded)
    got = liveness.permutations(ex, src, action)
    assert [tuple(p) for p in got.tolist()] == [
        liveness._permutation(ex, int(s), int(k)) for s, k in zip(src, action, strict=True)
    ]
    for nodes in (ex.expanded & ~ex.goal, ex.expanded):
        want = reference.fair_cycles(ex, nodes)
        assert liveness.fair_cycles(ex, nodes) == want
    assert want
    # The array walk (a large product's): the same starts and lengths, and every lasso replays.
    monkeypatch.setattr(liveness, "EXACT_PRODUCT", 0)
    built = liveness.fair_cycles(ex, ex.expanded)
    assert sorted((a.start, len(a.cycle)) for a in built) == sorted((a.start, len(a.cycle)) for a in want)
    for lasso in built:
        lasso_run(ex, lasso.start, lasso.cycle)
