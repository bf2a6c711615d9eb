"""Predicates over a whole swarm state: the visibility graph, the goal, the initial condition.

A *state* is a tuple of robot centres in global lattice coordinates; robot ``i`` is index ``i``.
The robots do not know these coordinates: only the engine does, to apply the scheduler.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..errors import InvalidInput
from .config import Model
from .geometry import dist2
from .numbers import Point, show, show_point

if TYPE_CHECKING:
    import networkx as nx

State = tuple[Point, ...]


def visibility_graph(state: Sequence[Point], model: Model) -> nx.Graph:
    """ "There exists an edge ... between the robots r_i and r_j if and only if they can see each
    other." Visibility is symmetric under every reading (it depends on the distance only)."""
    import networkx as nx  # imported when used: a check's start-up does not pay for it

    graph = nx.Graph()
    graph.add_nodes_from(range(len(state)))
    for i in range(len(state)):
        for j in range(i + 1, len(state)):
            if model.sees(dist2(state[i], state[j])):
                graph.add_edge(i, j)
    return graph


def components(state: Sequence[Point], model: Model) -> list[tuple[int, ...]]:
    """The connected components of the visibility graph (robot indices, each sorted; by least index)."""
    seen: set[int] = set()
    out = []
    for start in range(len(state)):
        if start in seen:
            continue
        seen.add(start)
        todo, comp = [start], [start]
        while todo:
            i = todo.pop()
            for j in range(len(state)):
                if j not in seen and model.sees(dist2(state[i], state[j])):
                    seen.add(j)
                    comp.append(j)
                    todo.append(j)
        out.append(tuple(sorted(comp)))
    return out


def is_connected(state: Sequence[Point], model: Model) -> bool:
    """Whether the visibility graph is connected (a single robot is)."""
    return len(state) <= 1 or len(components(state, model)) == 1


def is_goal(state: Sequence[Point], model: Model) -> bool:
    """Whether ``state`` is at the model's goal ("the robots in R will form a straight line", per the
    ``goal`` option, or another registered goal: :mod:`fatline_verify.goals`), exactly."""
    from ..goals import registry

    return registry.holds(state, model)


def initial_problems(state: Sequence[Point], model: Model) -> list[str]:
    """Why ``state`` breaks the paper's initial condition (empty when it meets it).

    "Initially the robots are stationary and the mutual distance between two robots is at least
    delta > 2 units" (distance exactly delta meets it) and "Initially, the graph G is assumed to be connected".
    """
    problems: list[str] = []
    points = model.points
    for i in range(len(state)):
        for j in range(i + 1, len(state)):
            d2 = dist2(state[i], state[j])
            pi, pj = show_point(model.from_lattice(state[i])), show_point(model.from_lattice(state[j]))
            where = f"robots {i} {pi} and {j} {pj}"
            if points:  # point robots: distinct positions are the whole condition
                if d2 == 0:
                    problems.append(f"{where} share a point (point robots start at distinct positions)")
            elif d2 < model.contact2:
                problems.append(f"{where} overlap (centre distance below 2)")
            elif not model.initially_apart(d2):
                problems.append(f"{where} are closer than delta")
    if not problems and not is_connected(state, model):
        problems.append("the visibility graph is not connected")
    return problems


def require_initial(state: Sequence[Point], model: Model) -> None:
    """Raise :class:`InvalidInput` naming the first way ``state`` breaks the initial condition."""
    if not state:
        raise InvalidInput("init='': expected at least one robot position")
    problems = initial_problems(state, model)
    if problems:
        apart = "distinct positions" if model.points else f"pairwise distance >= delta={show(model.parameters.delta)}"
        raise InvalidInput(f"init: {problems[0]}; expected {apart} and a connected swarm")
