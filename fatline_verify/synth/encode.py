"""Is some oblivious table of the family's legs safe and live for ``n`` robots? SAT, refined lazily.

The question
------------
A *table* maps each view (:mod:`.table`) to one of the legs :func:`fatline_verify.repair.reach.family_legs`
offers a robot seeing it (the repaired family's, under its lock; with ``left``/``corner`` the what-if
legs too), or to staying. Under a scheduler (centralized: one robot a round; SSYNC: any non-empty set of
robots) the table is **safe and live** for ``n`` robots in a window when, from every initial configuration
of the checker's (connected, apart, in the window), every execution reaches a line (one vertical, the
``vertical-line`` goal) without a round that collides, splits the swarm or crosses the RMA: every
reachable configuration off a line has a robot the table moves, every round the scheduler allows is
safe, and no execution cycles (a rank over the reachable configurations that every round lowers exists
exactly when the reachable round graph is acyclic). No fairness is assumed: every execution the scheduler
allows counts, so the checker's ``termination`` (weakly fair cycles only) follows from a table found here,
and an unsat answer says no table ends *every* execution on a line (a table live only under fairness is
not ruled out). States are kept up to translation; a line is a sink (every leg keeps a line a line: no
robot on it sees one right of it).

The encoding (python-sat)
-------------------------
Variables: ``a[v, k]`` (view ``v`` takes action ``k``, exactly one per view; ``k = 0`` stays) and
``R[s]`` (configuration ``s`` is reached). Clauses, each a necessary condition of a safe, live table:

* ``R[s]`` for each initial configuration (passed as assumptions, so an unsat core names them);
* enabledness: ``R[s] -> OR a[v_i, k]`` over each robot ``i`` of ``s`` off a line and each leg ``k >= 1``;
* rounds of one mover (every scheduler here may activate one robot alone): ``R[s] & a[v_i, k] -> R[s']``,
  or ``-> false`` when the executable model's checks fail the round or it leads back to ``s``;
* found lazily (*refinement*): rounds of several movers under SSYNC (``R[s] & a[..] & a[..] -> R[s']`` or
  ``-> false``), and cycles: ``R[s_0] -> NOT(all the choices along the cycle)``.

Each candidate table the solver returns is played exactly (:meth:`Encoder.refine`): every round the scheduler
allows from every initial configuration. A round the formula does not yet hold, or a cycle, adds its
clause and the solver runs again; a table whose play needs no new clause is safe and live (acyclic,
every state off a line enabled, every round safe) and is returned. Every clause holds of every safe,
live table (its ``R`` read as "reachable"), so **unsat is exact**: no table of those legs is safe and live
for those initial configurations; the core of initial configurations is shrunk by deletion until each
is needed.
"""

from __future__ import annotations

import time
from collections.abc import Iterable
from dataclasses import dataclass
from itertools import combinations

from pysat.solvers import Solver

from ..model.config import Model
from ..model.numbers import Point
from ..model.options import Scheduler
from ..model.swarm import is_goal
from ..repair.reach import PROVED, Family, Kind, Moves, State, Tick, canonical, family_legs, moved, starts
from .table import ORIGIN, Table, View, view_of

SCHEDULERS = (Scheduler.CENTRALIZED, Scheduler.SSYNC)
"""Schedulers the encoding covers: both may activate one robot alone (the eager rounds of one mover)."""
SOLVERS = ("cadical153", "glucose4", "minisat22")
"""SAT solvers of python-sat offered; the first is the default."""


@dataclass
class Stats:
    """The size of the search."""

    states: int = 0
    views: int = 0
    variables: int = 0
    clauses: int = 0
    refinements: int = 0
    """Solver calls that returned a table needing new clauses."""
    cycles: int = 0
    """Cycle clauses added."""
    multi: int = 0
    """Rounds of several movers added (SSYNC)."""
    seconds: float = 0.0


@dataclass(frozen=True)
class SynthResult:
    """What :func:`synthesise` found for swarms of ``smallest`` to ``n`` robots (one table for them all)."""

    n: int
    window: tuple[int, int]
    scheduler: Scheduler
    kinds: frozenset[Kind]
    initial: int
    table: Table | None
    """A safe, live table (``None``: unsat)."""
    core: tuple[State, ...]
    """Unsat: initial configurations from which no table is safe and live, each needed (deletion-minimal)."""
    stats: Stats
    rounds: int = 0
    """Sat: the most rounds any execution of the table takes to a line."""
    reached: int = 0
    """Sat: configurations the table reaches."""
    solver: str = SOLVERS[0]
    smallest: int = 0
    """The fewest robots searched with the same table (``0``: ``n`` only)."""

    @property
    def counts(self) -> range:
        """The robot counts the table is searched for."""
        return range(self.smallest or self.n, self.n + 1)

    @property
    def sat(self) -> bool:
        return self.table is not None


class Encoder:
    """The incremental formula of the module docstring over the configurations met so far."""

    def __init__(self, model: Model, kinds: frozenset[Kind], scheduler: Scheduler, solver: str = SOLVERS[0]) -> None:
        self.family = Family(model, kinds)
        self.model = self.family.model
        self.kinds = kinds
        self.scheduler = scheduler
        self.solver = Solver(name=solver)
        self.top = 0
        self.clauses = 0
        self.reach: dict[State, int] = {}
        self.views: dict[View, tuple[tuple[int, ...], tuple[Point, ...]]] = {}
        """Each view's action variables (stay first) and leg ends (stay first)."""
        self.robot_views: dict[State, tuple[View, ...]] = {}
        self.multi: set[tuple[State, tuple[int, ...]]] = set()
        self.cycles = 0
        self.keep: list[list[int]] | None = None
        """When a list, every clause added is kept there too (bench/synth.py solves the formula again)."""

    def _var(self) -> int:
        self.top += 1
        return self.top

    def add(self, clause: Iterable[int]) -> None:
        c = list(clause)
        self.solver.add_clause(c)
        self.clauses += 1
        if self.keep is not None:
            self.keep.append(c)

    def view(self, v: View) -> tuple[tuple[int, ...], tuple[Point, ...]]:
        got = self.views.get(v)
        if got is None:
            ends: tuple[Point, ...] = (ORIGIN, *(end for end, _ in family_legs(v, self.model, self.kinds)))
            lits = tuple(self._var() for _ in ends)
            self.add(lits)
            for x, y in combinations(lits, 2):
                self.add((-x, -y))
            got = self.views[v] = (lits, ends)
        return got

    def goal(self, s: State) -> bool:
        return is_goal(s, self.model)

    def state(self, s: State) -> int:
        """``R[s]``, adding ``s`` and every configuration its rounds of one mover reach (their clauses too)."""
        if s in self.reach:
            return self.reach[s]
        self.reach[s] = self._var()
        todo = [s]
        while todo:
            cur = todo.pop()
            r = self.reach[cur]
            if self.goal(cur):
                continue
            views = tuple(view_of(cur, i, self.model) for i in range(len(cur)))
            self.robot_views[cur] = views
            enabled = []
            for i, v in enumerate(views):
                lits, ends = self.view(v)
                for lit, end in zip(lits[1:], ends[1:], strict=True):
                    enabled.append(lit)
                    moves: Moves = ((i, end),)
                    nxt = canonical(moved(cur, moves))
                    if nxt == cur or not self.family.safe(cur, moves):
                        self.add((-r, -lit))
                        continue
                    if nxt not in self.reach:
                        self.reach[nxt] = self._var()
                        todo.append(nxt)
                    self.add((-r, -lit, self.reach[nxt]))
            self.add((-r, *enabled))
        return self.reach[s]

    def choice(self, s: State, i: int, end: Point) -> int:
        lits, ends = self.views[self.robot_views[s][i]]
        return lits[ends.index(end)]

    def table(self, model_lits: set[int]) -> Table:
        legs: dict[View, Point] = {}
        for v, (lits, ends) in self.views.items():
            for lit, end in zip(lits, ends, strict=True):
                if lit in model_lits:
                    legs[v] = end
        return Table(int(self.model.parameters.q), int(self.model.parameters.rad_v), legs)

    def rounds(self, s: State, table: Table) -> list[Moves]:
        """Every round the scheduler allows from ``s`` under ``table`` (its enabled robots' legs)."""
        movers = [(i, table.action(v)) for i, v in enumerate(self.robot_views[s]) if table.action(v) != ORIGIN]
        if self.scheduler is Scheduler.CENTRALIZED:
            return [(m,) for m in movers]
        return [tuple(c) for k in range(1, len(movers) + 1) for c in combinations(movers, k)]

    def refine(self, starts_: list[State], table: Table) -> tuple[bool, int, int]:
        """Play ``table`` from ``starts_`` (every round its scheduler allows); add the clauses it lacks.
        Returns whether none was missing, the longest way to a line and the configurations reached."""
        edges: dict[State, list[tuple[State, Moves]]] = {}
        added = False
        seen = set(starts_)
        todo = list(starts_)
        while todo:
            s = todo.pop()
            edges[s] = []
            if self.goal(s):
                continue
            for moves in self.rounds(s, table):
                nxt = canonical(moved(s, moves))
                if len(moves) > 1:
                    key = (s, tuple(self.choice(s, i, e) for i, e in moves))
                    if key not in self.multi:
                        self.multi.add(key)
                        guard = [-g for g in key[1]]
                        if nxt == s or not self.family.safe(s, moves):
                            self.add((-self.reach[s], *guard))
                            added = True
                            continue
                        self.add((-self.reach[s], *guard, self.state(nxt)))
                        added = True
                    elif nxt == s or not self.family.safe(s, moves):  # pragma: no cover - the clause forbids it
                        continue
                edges[s].append((nxt, moves))
                if nxt not in seen:
                    seen.add(nxt)
                    todo.append(nxt)
        if added:
            return False, 0, len(seen)
        cycles = find_cycles(edges)
        for cycle in cycles:
            lits = {-self.choice(s, i, e) for s, moves in cycle for i, e in moves}
            self.add((-self.reach[cycle[0][0]], *sorted(lits)))
            self.cycles += 1
        if cycles:
            return False, 0, len(seen)
        return True, longest(edges, starts_), len(seen)

    def stats(self, seconds: float) -> Stats:
        return Stats(len(self.reach), len(self.views), self.top, self.clauses, 0, self.cycles, len(self.multi), seconds)


def find_cycles(edges: dict[State, list[tuple[State, Moves]]]) -> list[list[tuple[State, Moves]]]:
    """One cycle (its ``(state, round)`` steps) per non-trivial strongly connected component of ``edges``."""
    index: dict[State, int] = {}
    low: dict[State, int] = {}
    comp: dict[State, int] = {}
    stack: list[State] = []
    on: set[State] = set()
    count = 0
    ncomp = 0
    for root in edges:
        if root in index:
            continue
        work = [(root, iter(edges[root]))]
        index[root] = low[root] = count
        count += 1
        stack.append(root)
        on.add(root)
        while work:
            node, it = work[-1]
            for nxt, _ in it:
                if nxt not in index:
                    index[nxt] = low[nxt] = count
                    count += 1
                    stack.append(nxt)
                    on.add(nxt)
                    work.append((nxt, iter(edges.get(nxt, []))))
                    break
                if nxt in on:
                    low[node] = min(low[node], index[nxt])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    while True:
                        w = stack.pop()
                        on.discard(w)
                        comp[w] = ncomp
                        if w == node:
                            break
                    ncomp += 1
    members: dict[int, list[State]] = {}
    for s, c in comp.items():
        members.setdefault(c, []).append(s)
    out = []
    for group in members.values():
        inside = set(group)
        start = group[0]
        if len(group) == 1 and not any(n == start for n, _ in edges.get(start, [])):
            continue
        # breadth-first from start back to start inside the component
        prev: dict[State, tuple[State, Moves]] = {}
        frontier = [start]
        found = None
        while frontier and found is None:
            nxt_frontier = []
            for s in frontier:
                for n, moves in edges.get(s, []):
                    if n not in inside:
                        continue
                    if n == start:
                        found = (s, moves)
                        break
                    if n not in prev:
                        prev[n] = (s, moves)
                        nxt_frontier.append(n)
                if found:
                    break
            frontier = nxt_frontier
        assert found is not None
        steps = [found]
        s = found[0]
        while s != start:
            steps.append(prev[s])
            s = prev[s][0]
        out.append(list(reversed(steps)))
    return out


def longest(edges: dict[State, list[tuple[State, Moves]]], roots: list[State]) -> int:
    """The most rounds of any way from ``roots`` in the acyclic ``edges``."""
    depth: dict[State, int] = {}
    for root in roots:
        work = [(root, iter(edges.get(root, [])))]
        while work:
            node, it = work[-1]
            for n, _ in it:
                if n not in depth:
                    work.append((n, iter(edges.get(n, []))))
                    break
            else:
                work.pop()
                depth[node] = 1 + max((depth[n] for n, _ in edges.get(node, [])), default=-1)
    return max((depth[r] for r in roots), default=0)


def search(
    enc: Encoder, starts_: list[State], stats: Stats, tick: Tick | None = None, label: str = ""
) -> tuple[Table | None, list[State], int, int]:
    """The refinement loop on ``starts_``: a safe, live table, or ``None`` and the starts in the core.
    ``tick`` hears the initial configurations encoded (each with every configuration one mover reaches from
    it), then each solve and refinement (``label`` begins each stage's name)."""
    lits = {}
    for k, s in enumerate(starts_):
        if tick is not None and k % TICK_EVERY == 0:
            met = f"{len(enc.reach):,} states"
            tick(f"{label}encoding initial configurations", k, len(starts_), met, "configurations")
        lits[enc.state(s)] = s
    while True:
        if tick is not None:
            tick(f"{label}solving and refining", stats.refinements, 0, f"{enc.clauses:,} clauses", "refinements")
        if not enc.solver.solve(assumptions=list(lits)):
            core = enc.solver.get_core() or []
            return None, [lits[c] for c in core if c in lits], 0, 0
        table = enc.table({x for x in enc.solver.get_model() if x > 0})
        done, rounds, reached = enc.refine(starts_, table)
        if done:
            kept = _reached_views(enc, starts_, table)
            return Table(table.q, table.rad_v, {v: e for v, e in table.legs.items() if v in kept}), [], rounds, reached
        stats.refinements += 1


TICK_EVERY = 16
"""Initial configurations encoded between two progress calls."""


def _reached_views(enc: Encoder, starts_: list[State], table: Table) -> set[View]:
    seen = set(starts_)
    todo = list(starts_)
    views: set[View] = set()
    while todo:
        s = todo.pop()
        if enc.goal(s):
            continue
        views.update(enc.robot_views[s])
        for moves in enc.rounds(s, table):
            n = canonical(moved(s, moves))
            if n not in seen:
                seen.add(n)
                todo.append(n)
    return views


def synthesise(
    model: Model,
    n: int,
    window: tuple[int, int],
    kinds: frozenset[Kind] = PROVED,
    *,
    scheduler: Scheduler = Scheduler.CENTRALIZED,
    solver: str = SOLVERS[0],
    minimise: bool = True,
    only: list[State] | None = None,
    keep: list[list[int]] | None = None,
    smallest: int | None = None,
    progress: Tick | None = None,
) -> SynthResult:
    """A safe, live table for ``n`` robots of ``model`` in ``window`` (module docstring), or the proof that
    none exists: an unsat core of initial configurations (deletion-minimal with ``minimise``). ``only``:
    these initial configurations instead of the checker's list; ``keep``: a list that receives every clause
    (the last formula, for solving it again elsewhere); ``smallest``: one table for every count from
    ``smallest`` to ``n`` (a robot does not know how many there are: its view is the same in all of them).
    ``progress`` hears the configurations encoded, each solve, and the core's configurations tried out."""
    t0 = time.perf_counter()
    lo = n if smallest is None else smallest
    first = list(only) if only is not None else [s for k in range(lo, n + 1) for s in starts(model, k, window)]
    enc = Encoder(model, kinds, scheduler, solver)
    enc.keep = keep
    stats = Stats()
    label = f"{lo}..{n} robots: " if lo != n else f"{n} robots: "
    table, core, rounds, reached = search(enc, first, stats, progress, label)
    if table is None and minimise:
        core = sorted(set(core))
        for k, s in enumerate(list(core)):
            if progress is not None:
                progress(f"{label}minimising the core", k, len(core), f"{len(core):,} left", "configurations")
            rest = [c for c in core if c != s]
            if rest and search(enc, rest, stats)[0] is None:
                core = rest
    got = enc.stats(time.perf_counter() - t0)
    got.refinements = stats.refinements
    enc.solver.delete()
    return SynthResult(
        n, window, scheduler, kinds, len(first), table, tuple(sorted(core)), got, rounds, reached, solver, lo
    )


def schedulers_text() -> str:
    return ", ".join(s.value for s in SCHEDULERS)


def independent_check(model: Model, result: SynthResult, solver: str) -> bool:
    """An unsat answer solved again from its core alone with a fresh encoding and another solver: whether
    it is unsat again."""
    again = synthesise(
        model,
        result.n,
        result.window,
        result.kinds,
        scheduler=result.scheduler,
        solver=solver,
        minimise=False,
        only=list(result.core),
    )
    return not again.sat


__all__ = ["SCHEDULERS", "SOLVERS", "Encoder", "Stats", "SynthResult", "independent_check", "search", "synthesise"]
