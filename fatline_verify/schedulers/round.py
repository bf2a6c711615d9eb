"""One round: a shared snapshot, the active robots' decisions, rigid moves, and what went wrong.

"The robots execute this cycle in semi-synchronous scheduling where an arbitrary set of robots
look, compute and move simultaneously. This scheduling assures that when a robot is moving no
other robot is observing it." So every active robot Looks at the same state, and a state's
decisions are computed once; activating a robot whose destination is its position changes nothing.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import ClassVar

from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.geometry import Path, path_point_dist2, paths_any_speed_dist2, paths_lockstep_dist2
from ..model.numbers import Number, Point
from ..model.options import Contact, Timing
from ..model.swarm import State, components, is_connected
from ..rules import registry
from ..rules.decision import Decision
from ..rules.registry import decider


@dataclass(frozen=True, slots=True)
class Collision:
    """Two discs came closer than allowed during the round (``contact``: below 2, or at most 2)."""

    robots: tuple[int, int]
    closest_dist2: Number
    """The exact squared closest centre distance in lattice units."""
    both_moved: bool

    lemma: ClassVar[Lemma] = Lemma.NO_COLLISION


@dataclass(frozen=True, slots=True)
class Disconnection:
    """The visibility graph was connected before the round and is not after it."""

    components: tuple[tuple[int, ...], ...]
    lost_edges: tuple[tuple[int, int], ...]

    lemma: ClassVar[Lemma] = Lemma.CONNECTIVITY


@dataclass(frozen=True, slots=True)
class RmaMoved:
    """A robot ended right of the right-most axis, or a robot on it left it."""

    robot: int
    rma_x: Number
    x_after: Number

    lemma: ClassVar[Lemma] = Lemma.RMA_FIXED


Violation = Collision | Disconnection | RmaMoved


@dataclass(frozen=True, slots=True)
class RoundResult:
    """A round: who was active, what each decided, the states before and after, the violations."""

    active: tuple[int, ...]
    decisions: dict[int, Decision] = field(repr=False)
    before: State = field(repr=False)
    after: State
    violations: tuple[Violation, ...] = ()

    @property
    def source(self) -> State:
        """The state before the round (a round system's state is the positions)."""
        return self.before

    @property
    def target(self) -> State:
        """The state after the round."""
        return self.after


def snapshot(state: Sequence[Point], i: int, model: Model) -> tuple[Point, ...]:
    """What robot ``i`` Looks at: the robots it sees, relative to itself (itself excluded)."""
    ox, oy = state[i]
    out = []
    for j, (x, y) in enumerate(state):
        if j != i:
            rel = (x - ox, y - oy)
            if model.sees(rel[0] * rel[0] + rel[1] * rel[1]):
                out.append(rel)
    return tuple(out)


def decide_all(state: Sequence[Point], model: Model, robots: Iterable[int] | None = None) -> dict[int, Decision]:
    """Every (or the given) robot's decision on ``state``."""
    indices = range(len(state)) if robots is None else robots
    rule = decider(model)
    return {i: rule(snapshot(state, i, model), model) for i in indices}


def enabled(decisions: dict[int, Decision]) -> tuple[int, ...]:
    """The robots whose destination differs from their position."""
    return tuple(sorted(i for i, d in decisions.items() if d.moves))


def global_path(origin: Point, decision: Decision) -> Path:
    """The decision's path translated to global coordinates."""
    ox, oy = origin
    return tuple((x + ox, y + oy) for x, y in decision.path)


def collides(d2: Number, model: Model) -> bool:
    """Whether squared centre distance ``d2`` is a collision under the ``contact`` option."""
    limit = model.contact2
    return d2 < limit or (model.options.contact is Contact.STRICT and d2 == limit)


def closest_dist2(pi: Path | None, pj: Path | None, ci: Point, cj: Point, model: Model) -> Number:
    """Closest squared centre distance of two robots during a round; ``None`` for a robot at rest at
    its centre ``c``. Two movers are timed per the ``timing`` option."""
    if pi is not None and pj is not None:
        if model.options.timing is Timing.LOCKSTEP:
            return paths_lockstep_dist2(pi, pj)
        return paths_any_speed_dist2(pi, pj)
    if pi is not None:
        return path_point_dist2(pi, cj)
    if pj is not None:
        return path_point_dist2(pj, ci)
    dx, dy = ci[0] - cj[0], ci[1] - cj[1]
    return dx * dx + dy * dy


def collisions(state: Sequence[Point], paths: dict[int, Path], model: Model) -> list[Collision]:
    """Pairs of discs that collide while the robots in ``paths`` move (the others rest)."""
    found = []
    n = len(state)
    for i in range(n):
        for j in range(i + 1, n):
            pi, pj = paths.get(i), paths.get(j)
            if pi is None and pj is None:
                continue
            d2 = closest_dist2(pi, pj, state[i], state[j], model)
            if collides(d2, model):
                found.append(Collision((i, j), d2, pi is not None and pj is not None))
    return found


def claimed(violations: Sequence[Violation], model: Model) -> tuple[Violation, ...]:
    """The violations of lemmas ``model``'s rule set claims (:meth:`fatline_verify.rules.registry.RuleSet.applies`):
    a step that breaks only a lemma it does not claim is no violation of it (it neither ends a simulation nor
    stops a search)."""
    if not violations:
        return ()
    applies = registry.applies(model)
    return tuple(v for v in violations if v.lemma in applies)


def rma_violations(before: Sequence[Point], after: Sequence[Point]) -> list[RmaMoved]:
    """Robots that crossed the right-most axis, or left it ("once on RMA, r cannot leave it")."""
    rma = max(p[0] for p in before)
    return [
        RmaMoved(i, rma, a[0])
        for i, (b, a) in enumerate(zip(before, after, strict=True))
        if a[0] > rma or (b[0] == rma and a[0] != rma)
    ]


def lost_edges(before: Sequence[Point], after: Sequence[Point], model: Model) -> list[tuple[tuple[int, int], Number]]:
    """Pairs ``i < j`` that saw each other before the round and do not after it, with their squared
    distance after, in pair order."""
    out = []
    for i in range(len(before)):
        for j in range(i + 1, len(before)):
            d_before = (before[i][0] - before[j][0]) ** 2 + (before[i][1] - before[j][1]) ** 2
            d_after = (after[i][0] - after[j][0]) ** 2 + (after[i][1] - after[j][1]) ** 2
            if model.sees(d_before) and not model.sees(d_after):
                out.append(((i, j), d_after))
    return out


def disconnection(before: Sequence[Point], after: Sequence[Point], model: Model) -> Disconnection | None:
    """The lost connectivity, when the graph was connected before and is not after."""
    lost = tuple(pair for pair, _ in lost_edges(before, after, model))
    if not lost:  # every edge before is an edge after: connected after if it was before
        return None
    if is_connected(after, model) or not is_connected(before, model):
        return None
    comps = sorted(components(after, model))
    return Disconnection(tuple(comps), lost)


def play_round(
    state: State, active: Iterable[int], model: Model, decisions: dict[int, Decision] | None = None
) -> RoundResult:
    """Activate ``active`` on ``state``: all Look at ``state``, Compute, and move rigidly."""
    act = tuple(sorted(set(active)))
    if decisions is None:
        decisions = decide_all(state, model, act)
    chosen = {i: decisions[i] for i in act}
    paths = {i: global_path(state[i], d) for i, d in chosen.items() if d.moves}
    after = tuple(
        (p[0] + chosen[i].destination[0], p[1] + chosen[i].destination[1]) if i in chosen else p
        for i, p in enumerate(state)
    )
    violations: list[Violation] = list(collisions(state, paths, model))
    lost = disconnection(state, after, model)
    if lost is not None:
        violations.append(lost)
    violations.extend(rma_violations(state, after))
    return RoundResult(act, chosen, state, after, claimed(violations, model))
