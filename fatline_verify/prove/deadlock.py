"""Reachable deadlocks as counterexamples to the liveness obligations.

Lemma 2 reads "There exists always a robot which will move unless the robots in R forms a straight
line"; the enabledness obligations (:mod:`fatline_verify.prove.smt.liveness`) claim it of every
*connected* configuration that is not a goal: its named robot (on the left-most vertical, seeing a
robot right of it) moves. A configuration reached from an initial one by rounds the executable model
replays, in which no robot moves, which is connected and not a goal, breaks that claim where it
matters (the run is stuck short of the goal, so termination fails too): its named robot stays, and
with its case's witnesses and the robot it sees right of it it is a solution of the enabledness
obligation of the case it decides. A deadlock reached after no rounds is a stuck initial
configuration (:func:`fatline_verify.prove.live.replay_stuck`); one reached after some rounds is just
as much a counterexample, and :class:`Deadlock` carries either kind with its replayed trace.

The named robot's case is the one the live cases (:func:`~fatline_verify.prove.smt.live_rules.live_cases`)
give its decision: for the paper's rules :func:`fatline_verify.rules.paper.cases.case_of`; for another
rule set, every declared case whose encoding holds on the whole configuration, with the decision's
destination (z3 on the concrete points: each witness one of the robots, the universal conditions over
every robot).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.numbers import Point, show_point
from ..model.swarm import is_connected, is_goal
from ..rules.decision import Decision
from ..schedulers.round import decide_all
from ..trace.simulate import Outcome, Run


def named_robots(state: Sequence[Point], model: Model) -> list[int]:
    """The enabledness obligations' named robots of ``state``: on its left-most vertical, each seeing a
    robot right of it (every connected swarm that is not on one vertical has one)."""
    left = min(p[0] for p in state)
    return [
        i
        for i, p in enumerate(state)
        if p[0] == left and any(o[0] > p[0] and model.sees((o[0] - p[0]) ** 2 + (o[1] - p[1]) ** 2) for o in state)
    ]


def named_cases(model: Model, state: Sequence[Point], decisions: Mapping[int, Decision]) -> dict[str, int]:
    """Each live case a named robot of ``state`` decides, with the first such robot (in robot order)."""
    found: dict[str, int] = {}
    from .tasks import encoding_name

    paper = encoding_name(model) == "paper"  # the paper's rules: case_of names the case (no solver)
    for i in named_robots(state, model):
        if paper:
            from ..rules.paper.cases import case_of

            names = [case_of(decisions[i], model).name]
        else:
            names = matching_cases(model, state, i, decisions[i])
        for name in names:
            found.setdefault(name, i)
    return found


def matching_cases(model: Model, state: Sequence[Point], i: int, decision: Decision) -> list[str]:
    """The declared live cases whose encoding robot ``i`` of ``state`` meets with ``decision``'s
    destination: each witness one of the robots (or ``i`` itself), the universal conditions over every
    other robot; on the model's own lattice, exactly."""
    import z3

    from .smt.cases import Arith, same
    from .smt.live_rules import live_cases

    out = []
    me_at = state[i]
    for case in live_cases(model):
        ar = Arith(model.parameters.q)
        me = ar.origin()
        universe = [
            (z3.IntVal(p[0] - me_at[0], ar.ctx), z3.IntVal(p[1] - me_at[1], ar.ctx))
            for j, p in enumerate(state)
            if j != i
        ]
        roles = {name: ar.point(name) for name in case.roles}
        cs, dest = case.encode(ar, model, me, roles, universe)
        cs = list(cs)
        for p in roles.values():
            cs.append(ar.any([same(p, o) for o in [me, *universe]]))
        cs += [dest[0] == z3.IntVal(int(decision.destination[0]), ar.ctx)]
        cs += [dest[1] == z3.IntVal(int(decision.destination[1]), ar.ctx)]
        solver = z3.Solver(ctx=ar.ctx)
        solver.add(*cs)
        if solver.check() == z3.sat:
            out.append(case.name)
    return out


@dataclass(frozen=True)
class Deadlock:
    """A replayed run of ``model`` from an initial configuration that ends stuck: no robot moves, the
    swarm is connected and not a goal. ``cases``: each live case a named robot decides there, with that
    robot; ``doc``: the run's trace, replayed."""

    source: str
    """Where it came from, as a reason names it (``given with --known FILE``, ``found among the small swarms``)."""
    rounds: int
    initial: tuple[Point, ...]
    final: tuple[Point, ...]
    cases: dict[str, int]
    rules: tuple[str, ...]
    """The rules every robot's decision in the final configuration came from."""
    doc: dict[str, Any] = field(repr=False)

    def shown(self, model: Model, state: Sequence[Point]) -> str:
        """``state`` in radii, as a reason shows it."""
        return ", ".join(show_point(model.from_lattice(p)) for p in state)

    def reason(self, model: Model, case: str) -> str:
        """Why the enabledness row of ``case`` is VIOLATED by this deadlock."""
        i = self.cases[case]
        where = self.shown(model, self.final)
        if self.rounds:
            start = (
                f"a deadlock reached after {self.rounds} round{'s' if self.rounds > 1 else ''} from the initial "
                f"configuration {self.shown(model, self.initial)} ({self.source}, replayed): no robot of {where}"
            )
        else:
            start = f"stuck: no robot of the initial configuration {where} ({self.source}, replayed)"
        return (
            f"{start} ({len(self.final)} robots, connected, not a line) moves (rules {', '.join(self.rules)}); "
            f"robot {i} {show_point(model.from_lattice(self.final[i]))}, on the left-most vertical and seeing a "
            f"robot right of it, decides {case}: Lemma 2 and termination fail"
        )

    def configuration(self, model: Model, case: str) -> tuple[str, ...]:
        """The final configuration, the named robot of ``case`` first, as exact ``x,y`` radii."""
        i = self.cases[case]
        ordered = [self.final[i], *(p for j, p in enumerate(self.final) if j != i)]
        return tuple(f"{x},{y}" for x, y in (model.from_lattice(p) for p in ordered))


def deadlock_problem(model: Model, run: Run) -> str:
    """Why the replayed ``run`` is no counterexample to progress (``""`` when it is one): it does not
    end in a deadlock, its last configuration is not connected, or no named robot's decision there
    falls in a declared case."""
    if run.outcome is not Outcome.DEADLOCK:
        return f"its run ends in outcome {run.outcome}, not a deadlock"
    final = run.final
    if not is_connected(final, model):
        where = ", ".join(show_point(model.from_lattice(p)) for p in final)
        return (
            f"its deadlock {where} is not connected (the enabledness obligations read connected configurations; "
            "a split swarm is connectivity's counterexample)"
        )
    if not named_cases(model, final, decide_all(final, model)):
        return (
            f"no robot of the left-most vertical that sees a robot right of it decides one of rule set "
            f"{model.rules!r}'s declared cases there (the declaration does not cover that decision, so no "
            "enabledness row can take it)"
        )
    return ""


def deadlock_of(model: Model, run: Run, source: str, origin: Mapping[str, Any]) -> Deadlock | None:
    """``run`` (replayed by the executable model under ``model``) as a :class:`Deadlock`, its trace
    re-derived with progress as its focus; ``None`` if :func:`deadlock_problem` finds a problem."""
    from ..trace.traces import replayed_document

    if deadlock_problem(model, run):
        return None
    assert not is_goal(run.final, model)  # a deadlock outcome is never a goal
    decisions = decide_all(run.final, model)
    doc = replayed_document(run, dict(origin), Lemma.PROGRESS)
    return Deadlock(
        source,
        len(run.rounds),
        tuple(run.initial),
        tuple(run.final),
        named_cases(model, run.final, decisions),
        tuple(sorted({str(d.rule) for d in decisions.values()})),
        doc,
    )


__all__ = ["Deadlock", "deadlock_of", "deadlock_problem", "matching_cases", "named_cases", "named_robots"]
