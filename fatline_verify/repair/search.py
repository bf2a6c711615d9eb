"""``fatline reach``'s search (the module docstring of :mod:`.reach` says what it decides): the family's
round graph closed from every initial configuration, in two phases (one mover, then every set of movers),
a shortest way to a line replayed through the executable model, and each stuck configuration searched
again on its own. The family's legs and states are :mod:`.reach`'s.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from ..model.config import Model
from ..model.swarm import is_goal
from ..rules.decision import ORIGIN, Decision
from ..rules.paper.algorithm import Rule
from ..rules.repaired.algorithm import locked
from ..rules.repaired.options import RepairLock
from ..schedulers.round import play_round, snapshot
from .reach import PROVED, Family, Kind, Moves, Rounds, State, Tick, alone, canonical, moved, starts, universal_deadlock

TICK_EVERY = 256
"""States expanded between two progress calls of a closure."""

CONFIRM = 100
"""Stuck configurations searched again on their own per robot count, evenly spread (all with ``witnesses``):
each search starts afresh, so thousands of them cost far more than the search that found them."""


@dataclass
class _Graph:
    """The closure of some states under ``rounds``, kept as reverse edges (canonical states)."""

    rounds: Rounds
    safe: Callable[[State, Moves], bool]
    """Whether a round is safe; unsafe rounds are counted, not followed."""
    parents: dict[State, set[State]] = field(default_factory=dict)
    unsafe: int = 0

    def close(self, roots: Iterable[State], tick: Callable[[int, int], None] | None = None) -> None:
        """Add every state ``rounds`` reach from ``roots``; ``tick(expanded, known)`` every
        :data:`TICK_EVERY` states expanded (the states met so far as the note: the total is not known)."""
        queue = deque(s for s in roots if s not in self.parents)
        for s in queue:
            self.parents.setdefault(s, set())
        expanded = 0
        while queue:
            state = queue.popleft()
            expanded += 1
            if tick is not None and expanded % TICK_EVERY == 0:
                tick(expanded, len(self.parents))
            for moves in self.rounds(state):
                nxt = canonical(moved(state, moves))
                if nxt == state:
                    continue
                if not self.safe(state, moves):
                    self.unsafe += 1
                    continue
                fresh = nxt not in self.parents
                self.parents.setdefault(nxt, set()).add(state)
                if fresh:
                    queue.append(nxt)

    def distances(self, goal: Callable[[State], bool]) -> dict[State, int]:
        """Rounds to the nearest ``goal`` state, for every state of the closure that reaches one."""
        dist = {s: 0 for s in self.parents if goal(s)}
        queue = deque(dist)
        while queue:
            s = queue.popleft()
            for p in self.parents[s]:
                if p not in dist:
                    dist[p] = dist[s] + 1
                    queue.append(p)
        return dist


@dataclass(frozen=True)
class ReachResult:
    """What :func:`reach` found for ``n`` robots of ``model`` (at its ``q``) in ``window``."""

    model: Model
    kinds: frozenset[Kind]
    n: int
    window: tuple[int, int]
    initial: int
    """Initial configurations, up to translation."""
    one_mover: int
    """Of them, those that reach a line by rounds of one mover."""
    stuck: tuple[State, ...]
    """Those that reach no line by any rounds of the family: no rule set of the family is live there."""
    states: tuple[int, int]
    """States explored by each phase."""
    witnesses: dict[State, list[tuple[State, Moves]]] = field(repr=False)
    """For each initial configuration that reaches a line, a shortest way there (one phase's rounds)."""
    confirmed: int = 0
    """States of the searches that confirmed stuck configurations on their own (:func:`confirm_stuck`)."""
    confirmed_configurations: int = 0
    """How many stuck configurations were searched again (:data:`CONFIRM`, evenly spread; all with ``witnesses``)."""
    replayed: int | None = None
    """Rounds of the ways to a line replayed by :func:`replay_witness` (``None``: not asked)."""
    unsafe: int = 0
    """Rounds that would collide, split the swarm or cross the RMA (counted, not followed; none is
    expected of the proved legs)."""
    universal: tuple[State, ...] = ()
    """Initial configurations that are deadlocks for every algorithm of one-radius lattice moves
    (:func:`universal_deadlock`), whatever its legs, lock or rules."""

    @property
    def reached(self) -> int:
        return self.initial - len(self.stuck)


def _path(graph: _Graph, dist: dict[State, int], start: State) -> list[tuple[State, Moves]]:
    """A shortest way from ``start`` to a goal state, as ``(state, round)`` steps."""
    out = []
    state = start
    while dist[state]:
        for moves in graph.rounds(state):
            nxt = canonical(moved(state, moves))
            # an edge of the graph only: an unsafe round may lead to the same state
            if dist.get(nxt) == dist[state] - 1 and graph.safe(state, moves):
                out.append((state, moves))
                state = nxt
                break
        else:  # pragma: no cover - distances come from the same rounds
            raise AssertionError(f"no step down from {state}")
    return out


def reach(
    model: Model,
    n: int,
    window: tuple[int, int],
    kinds: frozenset[Kind] = PROVED,
    *,
    witnesses: bool = False,
    progress: Tick | None = None,
) -> ReachResult:
    """The two-phase search of the module docstring over every initial configuration of ``n`` robots in
    ``window``; with ``witnesses``, a shortest way to a line for each that has one. ``progress`` hears each
    phase: the states each closure expands (their number is not known ahead), then the stuck configurations
    searched again one by one, and the witnesses replayed (those two with their totals)."""
    family = Family(model, kinds)
    tell: Tick = progress if progress is not None else (lambda *_: None)

    def goal(s: State) -> bool:
        return is_goal(s, family.model)

    def closing(what: str) -> Callable[[int, int], None]:
        label = f"{n} robots: {what}"
        tell(label, 0, 0, "", "states")
        return lambda expanded, known: tell(label, expanded, 0, f"{known:,} met", "states")

    first = starts(model, n, window)
    single = _Graph(family.one_mover, family.safe)
    single.close(first, closing(f"states by one mover from {len(first):,} initial configurations"))
    dist1 = single.distances(goal)
    hard = [s for s in first if s not in dist1]
    full = _Graph(family.any_movers, family.safe)
    full.close(hard, closing(f"states by any movers from the {len(hard):,} configurations one mover leaves"))
    dist2 = full.distances(goal)
    paths: dict[State, list[tuple[State, Moves]]] = {}
    if witnesses:
        paths = {s: _path(single, dist1, s) for s in first if s in dist1}
        paths |= {s: _path(full, dist2, s) for s in hard if s in dist2}
    stuck = tuple(sorted(s for s in hard if s not in dist2))
    again = stuck if witnesses or len(stuck) <= CONFIRM else stuck[:: -(-len(stuck) // CONFIRM)]
    confirmed = 0
    for k, s in enumerate(again):
        tell(f"{n} robots: stuck configurations searched again", k, len(again), "", "configurations")
        confirmed += confirm_stuck(s, family)
    replayed = None
    if witnesses:
        replayed = 0
        for k, (s, steps) in enumerate(paths.items()):
            tell(f"{n} robots: ways to a line replayed", k, len(paths), "", "ways")
            problems = replay_witness(s, steps, family)
            if problems:
                raise AssertionError(f"the way to a line from {s} does not replay: {problems[0]}")
            replayed += len(steps)
    states = (len(single.parents), len(full.parents))
    return ReachResult(
        family.model,
        kinds,
        n,
        window,
        len(first),
        len(first) - len(hard),
        stuck,
        states,
        paths,
        confirmed,
        len(again),
        replayed,
        single.unsafe + full.unsafe,
        tuple(s for s in first if not goal(s) and universal_deadlock(s, family.model) is not None)
        if alone(model)
        else (),
    )


def replay_witness(start: State, steps: list[tuple[State, Moves]], family: Family) -> list[str]:
    """Problems with a way to a line (empty when it is one), checked apart from the search: each round
    is played by :func:`fatline_verify.schedulers.round.play_round` (collisions along the paths, the graph,
    the RMA), each mover's leg is one of its legs, and the last state is on one vertical."""
    m = family.model
    problems: list[str] = []
    state = start
    for k, (at, moves) in enumerate(steps):
        if canonical(state) != at:
            return [*problems, f"round {k}: starts from {canonical(state)}, not {at}"]
        state = at  # the round's robot indices are those of the canonical state
        for i, end in moves:
            snap = snapshot(state, i, m)
            if locked(snap) and m.options.repair_lock is RepairLock.LEFT_FIRST:
                problems.append(f"round {k}: robot {i} at {state[i]} is held by the lock")
            if end not in {e for e, _ in family.legs(state, i)}:
                problems.append(f"round {k}: robot {i} at {state[i]} has no leg to {end}")
        decisions = {i: Decision(Rule.REPAIR_DETOUR, end, (ORIGIN, end), ()) for i, end in moves}
        result = play_round(state, list(decisions), m, decisions)
        problems += [f"round {k}: {v}" for v in result.violations]
        state = result.after
    if not is_goal(state, m):
        problems.append(f"ends off a line: {state}")
    return problems


def way_to_line(start: State, family: Family, *, one_mover: bool = False) -> list[tuple[State, Moves]] | None:
    """A shortest way from ``start`` to a line by any rounds of ``family`` (rounds of one mover with
    ``one_mover``), as ``(state, round)`` steps for :func:`replay_witness`, or ``None`` when no state on a
    line is reachable (the search is exhaustive: the legs keep the swarm connected, so it is finite)."""
    graph = _Graph(family.one_mover if one_mover else family.any_movers, family.safe)
    graph.close([canonical(start)])
    dist = graph.distances(lambda s: is_goal(s, family.model))
    if canonical(start) not in dist:
        return None
    return _path(graph, dist, canonical(start))


def confirm_stuck(start: State, family: Family) -> int:
    """The number of states reachable from ``start`` by any rounds of ``family``, searched afresh;
    raises if one of them is on a line (the search's answer would be wrong)."""
    graph = _Graph(family.any_movers, family.safe)
    graph.close([start])
    on_line = [s for s in graph.parents if is_goal(s, family.model)]
    if on_line:
        raise AssertionError(f"{start} reaches the line {on_line[0]}")
    return len(graph.parents)


__all__ = ["CONFIRM", "TICK_EVERY", "ReachResult", "confirm_stuck", "reach", "replay_witness", "way_to_line"]
