"""Can *any* rule set of the repaired family bring a swarm to a line? Reachability over every leg.

The checker judges one rule set: from each initial configuration, every activation of *its*
decisions. When liveness fails there, two different things may be wrong: the rules chose badly
(another rule set could do better), or the safety mechanism itself leaves no way to the line. This
module tells them apart. The **family** is the moves of the classes the repaired rule set's safety
proof covers (:mod:`fatline_verify.rules.repaired.family`), on the lattice and never across the RMA (Lemma 3): a
robot that sees no robot strictly left of it (``repair_lock``)
makes one leg of a proved class that :func:`fatline_verify.rules.repaired.algorithm.allowed` passes (clear of every
robot it sees, every edge kept or bridged), ``k`` lattice units long, ``1 <= k <= q`` (one radius
at most):

- ``right`` (the ``horizontal`` class): not past the greatest x it sees, so never across the RMA;
- ``vertical`` (the ``top`` and ``bottom`` classes): up or down, seeing no robot above it on its
  vertical; or up, seeing robots above it there and none below, ending at least 3 radii below each.

Whatever a rule set of the family decides, each of its moves is one of these legs. So the family's
**round graph** (from a state, every set of robots each taking any of its legs at once) holds every
execution of every such rule set, oblivious or not, even one with memory, or a planner choosing
each robot's leg knowing the whole swarm. An initial configuration from which no state on one
vertical is reachable in that graph is one that **no rule set of the family** brings to a line:
an exact, rule-free statement, found by exhaustive search. (The converse does not hold: a line
that can be reached still needs a rule set that finds the way from what each robot sees.)

*What-if* kinds (:class:`Kind`) add legs the shipped safety proof does **not** cover, to ask which kind of
leg a live repair would need: ``left`` (one radius or less left, by a robot that sees one right of
it, so never off the RMA), ``left-alone`` (``left`` guarded: only by a robot that sees no other robot
on its own vertical, and no longer than :func:`left_alone_reach` allows; ``fatline prove repaired
--with left-alone`` decides its obligations) and ``corner`` (right and
vertically at once, as ``repair_progress = corner``: its edge tests are used).

The search runs in two phases. Rounds with one mover are a subgraph of the round graph and far
cheaper: an initial configuration that reaches a line there reaches one in the round graph. Only
the others are searched again with every set of movers at once. States are kept up to translation;
the legs keep the swarm connected (proved), so finitely many states are reachable and nothing is cut
off. Every round is also played through the executable model's own checks (collisions along the
paths, the graph, the RMA: :mod:`fatline_verify.schedulers.round`) before it is followed; one that fails them
is counted and not followed (none is expected of the proved legs; with what-if legs it keeps the
search to safe rounds). The search is :mod:`.search`'s. Each stuck configuration is searched again on its own
(:func:`.search.confirm_stuck`), and with ``witnesses`` a shortest way to a line from every other one is
played again by :func:`fatline_verify.schedulers.round.play_round` (:func:`.search.replay_witness`).

*Deadlocks for every algorithm* (:func:`universal_deadlock`) need neither the family nor the search:
a configuration where each robot, alone with the robots it sees, can make no move of at most one
radius without a collision or a split is left as it is by every safe algorithm of such moves.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import replace
from enum import StrEnum
from itertools import combinations, product

from ..check.initial import initial_array
from ..model.config import Model
from ..model.numbers import Point
from ..model.options import Goal
from ..rules.decision import ORIGIN
from ..rules.family.lang import Ground, holds
from ..rules.repaired.options import RepairProgress
from ..rules.repaired.whatif import left_alone_reach, legs_family, shapes
from ..schedulers.activation import scheduler_for
from ..schedulers.round import closest_dist2, collides, collisions, disconnection, rma_violations, snapshot

State = tuple[Point, ...]
Leg = tuple[Point, str]
"""A leg's end relative to the robot, and its class in the family (:func:`.legs_family`)."""
Moves = tuple[tuple[int, Point], ...]
"""One round: each mover's index in the state and the end of its leg, relative to it."""


class Kind(StrEnum):
    """A kind of leg the family may take."""

    RIGHT = "right"
    """Proved: the ``horizontal`` class."""
    VERTICAL = "vertical"
    """Proved: the ``top`` and ``bottom`` classes."""
    LEFT = "left"
    """What-if: one radius or less left, by a robot that sees one right of it (no leg obligation covers it)."""
    LEFT_ALONE = "left-alone"
    """What-if, guarded: a ``left`` leg by a robot that sees no other robot on its own vertical, at most
    :func:`left_alone_reach` units long (visibility is symmetric: two robots of one vertical that see
    each other never move in one round with one of them stepping left; a robot the mover does not see
    cannot reach its path by any leg of the family)."""
    CORNER = "corner"
    """What-if: right and vertically at once, as ``repair_progress = corner`` (up to sqrt(2) radii long)."""


PROVED = frozenset({Kind.RIGHT, Kind.VERTICAL})
WHAT_IF = (Kind.LEFT, Kind.LEFT_ALONE, Kind.CORNER)
EXCLUSIVE = frozenset({Kind.LEFT, Kind.LEFT_ALONE})
"""At most one of these in a family: ``left-alone`` is ``left`` with a guard (:func:`check_kinds`)."""


def check_kinds(kinds: Iterable[str]) -> None:
    """Refuse (one line) a family with both ``left`` and ``left-alone``: the guarded kind is a part of the other."""
    from ..errors import InvalidInput

    both = sorted(str(k) for k in kinds if k in EXCLUSIVE)
    if len(both) > 1:
        raise InvalidInput(
            f"with={','.join(both)}: {Kind.LEFT_ALONE} is {Kind.LEFT} with a guard; expected one of them"
        )


def what_if_text(kinds: frozenset[Kind], model: Model) -> str:
    """`` + what-if ...``: the what-if kinds of a family as ``reach`` and ``synth`` print them, with the
    command that decides their safety obligations (not the shipped rows; nothing is claimed here)."""
    extra = [k for k in Kind if k in kinds and k not in PROVED]
    if not extra:
        return ""
    names = []
    for k in extra:
        longest = left_alone_reach(model, kinds) if k is Kind.LEFT_ALONE else model.radius
        names.append(
            k.value
            + (f" (at most {longest} lattice unit{'s' if longest > 1 else ''})" if longest < model.radius else "")
        )
    return (
        f" + what-if {', '.join(names)} (no shipped obligation covers them; their own: fatline prove "
        f"{model.name} --with {','.join(k.value for k in extra)} --q {model.parameters.q})"
    )


def family_model(model: Model, kinds: frozenset[Kind]) -> Model:
    """The model whose ``repairs.allowed`` judges the legs: with ``corner``, its edge tests allow for
    each robot on r's vertical being on a corner leg (``repair_progress = corner``)."""
    if Kind.CORNER in kinds and model.options.repair_progress is not RepairProgress.CORNER:
        return replace(model, options=model.options.with_(repair_progress=RepairProgress.CORNER))
    return model


def family_legs(snap: tuple[Point, ...], model: Model, kinds: frozenset[Kind] = PROVED) -> tuple[Leg, ...]:
    """Every leg of ``kinds`` that a robot seeing ``snap`` may make: each lattice end of a class's shape whose
    guard holds there (:func:`.legs_family`, read by the concrete interpreter), unless the family holds the
    robot; in lattice units of ``model`` (one radius is ``model.radius`` units), each end once with the
    first class admitting it."""
    family = legs_family(model, kinds)
    if family.held(snap, model):
        return ()
    out: list[Leg] = []
    taken: set[Point] = set()
    for end, cls in shapes(family, model):
        if end not in taken and holds(cls.guard, Ground(model, snap, {"me": ORIGIN, "end": end})):
            taken.add(end)
            out.append((end, cls.name))
    return tuple(out)


def canonical(state: Iterable[Point]) -> State:
    """``state`` translated to min x = min y = 0, robots sorted: the form states are kept in."""
    pts = list(state)
    x0 = min(p[0] for p in pts)
    y0 = min(p[1] for p in pts)
    return tuple(sorted((x - x0, y - y0) for x, y in pts))


def moved(state: State, moves: Moves) -> State:
    """``state`` after ``moves`` (not canonical)."""
    ends = dict(moves)
    return tuple((x + ends[i][0], y + ends[i][1]) if i in ends else (x, y) for i, (x, y) in enumerate(state))


class Family:
    """The family's rounds on lattice states of ``model``; each view's legs are computed once."""

    def __init__(self, model: Model, kinds: frozenset[Kind] = PROVED) -> None:
        self.kinds = kinds
        self.model = family_model(model, kinds)
        self._legs: dict[tuple[Point, ...], tuple[Leg, ...]] = {}

    def legs(self, state: State, i: int) -> tuple[Leg, ...]:
        snap = snapshot(state, i, self.model)
        got = self._legs.get(snap)
        if got is None:
            got = self._legs[snap] = family_legs(snap, self.model, self.kinds)
        return got

    def safe(self, state: State, moves: Moves) -> bool:
        """Whether a round collides nobody, keeps the graph connected and nobody crosses the RMA, by the
        executable model's own checks (:mod:`fatline_verify.schedulers.round`). Pairs too far apart to meet
        (more than two radii plus both legs) are not measured."""
        m = self.model
        ends = dict(moves)
        after = moved(state, moves)
        reach2 = 24 * m.radius * m.radius  # (2 + 2 sqrt(2))^2 < 24 radii^2: the longest legs are corners
        for i, j in combinations(range(len(state)), 2):
            if i not in ends and j not in ends:
                continue
            (xi, yi), (xj, yj) = state[i], state[j]
            if (xi - xj) ** 2 + (yi - yj) ** 2 > reach2:
                continue
            pi = (state[i], after[i]) if i in ends else None
            pj = (state[j], after[j]) if j in ends else None
            if collides(closest_dist2(pi, pj, state[i], state[j], m), m):
                return False
        return disconnection(state, after, m) is None and not rma_violations(state, after)

    def one_mover(self, state: State) -> Iterator[Moves]:
        """Rounds with exactly one mover."""
        for i in range(len(state)):
            for end, _ in self.legs(state, i):
                yield ((i, end),)

    def any_movers(self, state: State) -> Iterator[Moves]:
        """Rounds with any non-empty set of movers, each taking any of its legs."""
        options = [[ORIGIN, *(end for end, _ in self.legs(state, i))] for i in range(len(state))]
        for ends in product(*options):
            round_ = tuple((i, e) for i, e in enumerate(ends) if e != ORIGIN)
            if round_:
                yield round_


Rounds = Callable[[State], Iterable[Moves]]
Tick = Callable[[str, int, int, str, str], None]
"""Progress, as :meth:`fatline_verify.progress.Progress.follow` hears it: ``(what, done, total, note,
unit)``, ``total`` 0 when not known (the engine never prints)."""


def starts(model: Model, n: int, window: tuple[int, int]) -> list[State]:
    """Every initial configuration of ``n`` robots in ``window``, canonical (the checker's own list)."""
    return [canonical(tuple((int(x), int(y)) for x, y in row)) for row in initial_array(n, window, model)]


def unit_legs(model: Model) -> tuple[Point, ...]:
    """Every move of at most one radius that ends on ``model``'s lattice (at ``q = 1``: one unit along an
    axis), in any direction."""
    rho = model.radius
    span = range(-rho, rho + 1)
    return tuple((a, b) for a in span for b in span if (a, b) != ORIGIN and a * a + b * b <= rho * rho)


def alone(model: Model) -> bool:
    """Whether the model's scheduler may activate one robot alone (what :func:`universal_deadlock` needs):
    SSYNC and centralized, not FSYNC (the scheduler object says: :attr:`RoundScheduler.alone`)."""
    return scheduler_for(model).alone


def universal_deadlock(state: State, model: Model) -> list[tuple[int, Point, str]] | None:
    """Whether ``state`` is a deadlock for **every** algorithm of oblivious robots that do not know how many
    they are, whose moves are straight and at most one radius long and stay on the lattice, and that
    never lets a swarm collide or split under a scheduler that may activate one robot alone (SSYNC,
    centralized: :func:`alone`); lock, rules and family aside.

    The argument: a robot decides on what it sees. Take robot i and only the robots it sees: a legal
    swarm (a star around i, so connected), where i sees exactly what it sees in ``state``, so it makes
    the same decision. If each of its moves there, i alone active, collides or splits that swarm
    (:func:`fatline_verify.schedulers.round.collisions`, ``disconnection``), a safe algorithm has i stay; if that
    holds for every robot, none moves in ``state``. Returns one row per robot and move, ``(robot, move,
    what breaks)``, or ``None`` when some move is safe there."""
    rows = []
    for i in range(len(state)):
        seen = snapshot(state, i, model)
        star = (ORIGIN, *seen)
        for end in unit_legs(model):
            hits = collisions(star, {0: (ORIGIN, end)}, model)
            split = disconnection(star, (end, *seen), model)
            if not hits and split is None:
                return None
            rows.append((i, end, "collides" if hits else "splits the swarm"))
    return rows


def refuse(model: Model) -> None:
    """Bad input, before any work: a model without the repairs the family's legs are proved under, one
    ``fatline prove`` refuses (ASYNC, corner legs), or another goal than one vertical."""
    from ..errors import InvalidInput
    from ..prove.tasks import check_encoded
    from ..rules.repaired.family import missing as missing_repairs

    missing = missing_repairs(model)
    if missing:
        raise InvalidInput(
            f"model={model.name!r}: the family's legs are those the repaired rule set's proof covers; "
            f"expected a model with {', '.join(missing)} (e.g. repaired)"
        )
    check_encoded(model)  # what fatline prove refuses (ASYNC, corner legs) has no proved legs to search
    if model.options.goal is not Goal.VERTICAL_LINE:
        raise InvalidInput(
            f"goal={model.options.goal}: the family's search looks for the robots on one vertical; expected "
            f"goal={Goal.VERTICAL_LINE}"
        )


__all__ = [
    "PROVED",
    "WHAT_IF",
    "Family",
    "Kind",
    "canonical",
    "check_kinds",
    "family_legs",
    "left_alone_reach",
    "refuse",
    "starts",
    "what_if_text",
]
