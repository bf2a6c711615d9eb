"""A table played through the executable model, apart from the encoding that found it.

From every initial configuration, every round the scheduler allows (centralized: each enabled robot
alone; SSYNC: each non-empty set of enabled robots) is played by
:func:`fatline_verify.schedulers.round.play_round` (collisions along the paths, the graph, the RMA), each
robot deciding by the table from what it sees; every leg must be one the family offers that view. A
table passes when no round breaks a check, no configuration off a line has no enabled robot, and the
graph of configurations reached (up to translation) has no cycle: then every execution reaches a line
within :attr:`Replay.rounds` rounds.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations

from ..model.config import Model
from ..model.options import Scheduler
from ..model.swarm import is_goal
from ..repair.reach import Family, Kind, State, canonical, family_legs, starts
from ..rules.decision import ORIGIN, Decision
from ..rules.paper.algorithm import Rule
from ..schedulers.round import play_round
from .table import Table, view_of


@dataclass
class Replay:
    """What :func:`replay` found."""

    initial: int = 0
    states: int = 0
    rounds_played: int = 0
    rounds: int = 0
    """The most rounds of any execution to a line (when there is no problem)."""
    problems: list[str] = field(default_factory=list)


def replay(
    table: Table,
    model: Model,
    counts: range | int,
    window: tuple[int, int],
    kinds: frozenset[Kind],
    scheduler: Scheduler,
    only: list[State] | None = None,
) -> Replay:
    """Play ``table`` from every initial configuration of each robot count of ``counts`` in ``window``
    (module docstring)."""
    m = Family(model, kinds).model
    out = Replay()
    ns = range(counts, counts + 1) if isinstance(counts, int) else counts
    first = list(only) if only is not None else [s for k in ns for s in starts(model, k, window)]
    out.initial = len(first)
    edges: dict[State, list[State]] = {}
    todo = list(dict.fromkeys(first))
    seen = set(todo)
    while todo and len(out.problems) < 10:
        s = todo.pop()
        edges[s] = []
        if is_goal(s, m):
            continue
        decisions: dict[int, Decision] = {}
        for i in range(len(s)):
            v = view_of(s, i, m)
            end = table.action(v)
            if end == ORIGIN:
                continue
            if end not in {e for e, _ in family_legs(v, m, kinds)}:
                out.problems.append(f"{s}: robot {i} at {s[i]} takes {end}, not a leg of its view")
            decisions[i] = Decision(Rule.REPAIR_DETOUR, end, (ORIGIN, end), ())
        if not decisions:
            out.problems.append(f"{s}: off a line and no robot moves (stuck)")
            continue
        movers = sorted(decisions)
        if scheduler is Scheduler.CENTRALIZED:
            sets: list[tuple[int, ...]] = [(i,) for i in movers]
        else:
            sets = [c for k in range(1, len(movers) + 1) for c in combinations(movers, k)]
        for active in sets:
            result = play_round(s, active, m, decisions)
            out.rounds_played += 1
            if result.violations:
                out.problems.append(f"{s}: robots {active} break a check: {result.violations[0]}")
                continue
            nxt = canonical(result.after)
            edges[s].append(nxt)
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    out.states = len(seen)
    if out.problems:
        return out
    depth: dict[State, int] = {}
    for root in first:
        path: set[State] = {root}
        work = [(root, iter(edges[root]))]
        while work:
            node, it = work[-1]
            for nxt in it:
                if nxt in path:
                    out.problems.append(f"{nxt}: an execution comes back to it (a cycle)")
                    return out
                if nxt not in depth:
                    path.add(nxt)
                    work.append((nxt, iter(edges[nxt])))
                    break
            else:
                work.pop()
                path.discard(node)
                depth[node] = 1 + max((depth[x] for x in edges[node]), default=-1)
    out.rounds = max((depth[r] for r in first), default=0)
    return out


__all__ = ["Replay", "replay"]
