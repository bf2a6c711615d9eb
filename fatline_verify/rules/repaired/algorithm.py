"""Named repairs: changes to the paper's algorithm, each removing one class of counterexample.

The paper's ``LineForm()`` (:func:`fatline_verify.rules.paper.algorithm.decide`) is left as it is; a repair
acts on its decision, after it, and only on a robot that would move. Each repair is an option
(``repair_*`` in ``options.py``, ``off`` by default: the paper); an option at ``off`` is left out
of a model's data, so it changes no fingerprint of the paper's models. ``models/repaired.toml``
picks them.

The repairs and the counterexample class each one removes:

- ``repair_stack = align``: *a deadlock of robots in each other's A/I bands.* Under bands=disc the
  bands are 4 radii wide, so robots at (0, 0) and (1, 2) each see only A u I and stay ("NoMovement"),
  though they are not on one vertical. A robot that sees only A u I, some of it right of its
  vertical, moves horizontally to the greatest x it sees.
- ``repair_lock = left-first``: *two movers collide or drift apart.* Under SSYNC any set of robots
  may move at once, and a robot cannot know what a neighbour decides (the neighbour sees robots it
  does not). A robot moves only if it sees no robot strictly left of it, and moves vertically only
  if it sees no robot above it on its own vertical. Two movers that see each other are then on one
  vertical, at most one of them (the upper) moving vertically and the others horizontally, away
  from the vertical, so their distance does not shrink below 2; any other two movers are farther
  apart than ``rad_v``. With ``repair_edges``, the top robot moving vertically keeps each robot
  below it on its vertical in view wherever that robot's one-radius move right may take it.
- ``repair_approach = on``: *Scenario 4's drop, which leaves the swarm (2 robots 4 apart on a
  horizontal: r drops 3 and loses the other).* When psi_right has no vacant point within view and r
  would drop, r moves right instead, to 2 radii short of psi_right (never touching a robot on it),
  if that is right of r; the search is tried again from there.
- ``repair_step = unit``: *a move so long that robots r cannot see are in its way, or that two far
  movers meet.* A robot moves at most one radius a round, along one axis: horizontally toward its
  destination by ``min(|dx|, 1)``, or, if that leg is not allowed, vertically by ``min(|dy|, 1)``.
  Every disc that can meet such a path has its centre within 3 < ``rad_v`` of r: r sees it. Two
  movers farther apart than ``rad_v`` = 4 each move at most 1: they stay more than 2 apart.
- ``repair_clear = on``: *r's path crosses a robot it sees* (the paper's vacancy tests look at the
  destination only, and Scenario 1 at none). A leg is allowed only if no visible robot comes closer
  than 2 to it (contact per the ``contact`` option): r's swept disc meets no disc it sees.
- ``repair_edges = on``: *r walks out of a neighbour's view* (Scenario 4's drop by ``rad_v - 1``, a
  far vacancy). A leg is allowed only if, for every robot c r sees, r ends within ``rad_v`` of c,
  or (under the lock) of a robot b right of r that sees c wherever c may move: b is held by the
  lock, so an edge r-c that goes is bridged by r-b-c, and the swarm stays connected.

- ``repair_progress = detour`` (with the lock, unit steps, clearance and edges): *a deadlock where the
  unlocked robot's legs toward its destination are all refused* (``(0, 1) (1, 4) (2, 0)``: right is
  refused by clearance with (2, 0), down by the edge to (1, 4)). It tries other legs of the same
  three classes, in a fixed order (:func:`_progress`): right (Scenario 4's drop first steps right, at
  most to the greatest x r sees), then along its vertical toward the nearest height, reachable by
  allowed legs, from which that step would pass, then the leg toward its destination, the top's
  contraction, one radius up, then down. Every move it makes passes :func:`allowed` and is a leg of
  :class:`Leg`: the leg obligations (:mod:`fatline_verify.rules.repaired.family`) cover it unchanged. What it
  cannot remove: configurations where no robot has any such leg (the square ``(0, 0) (0, 4) (4, 0)
  (4, 4)`` of side ``rad_v``; at ``q = 2`` three robots, ``(0, 3/2)`` between ``(3/2, 0)`` and
  ``(3/2, 3)``).
- ``repair_progress = corner`` (the detour, then): *the square of side ``rad_v``*, where each robot on
  the left vertical holds an edge of length ``rad_v`` along it and one to the right. A *corner* leg
  moves one radius right and one vertically at once (:func:`_corner`): the top of a vertical with a
  robot below it there, right and down ((0, 4) to (1, 3) keeps both edges); the bottom, right and up,
  ending 3 below each robot above. It must clear the move right of each robot on r's vertical too,
  r allows for each robot on its vertical being on a corner leg (:func:`_anywhere`), and an edge may
  also be bridged by a robot on r's vertical. A corner leg is up to sqrt(2) long: the unit-step
  argument for far movers does not cover it, nor do the leg obligations (``fatline prove`` refuses
  it); the checker and the random-round tests are its evidence.

``repair_stack = align`` also contracts a vertical: a robot that sees only robots on its own vertical
above it (the bottom) moves one radius up, ending at least 3 below the nearest (which may come down
one radius), and the top (robots below only) moves down, ending at least 2 above the nearest: the
bottom's margin keeps the two apart when both move, and only these two robots of a vertical ever
move vertically. A robot whose every leg is refused stays (``repair-blocked``), or, on top of its
vertical, contracts it; one the lock holds stays (``repair-lock``). What is left for the checker to
judge is whether the repaired robots still make progress: most repairs remove moves or shorten them.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from enum import StrEnum
from fractions import Fraction
from typing import Any

from ...model.config import Model
from ...model.geometry import Path, dist2, path_point_dist2, segment_segment_dist2
from ...model.numbers import Number, Point
from ...model.options import Contact
from ..decision import ORIGIN, Decision
from ..paper.algorithm import Rule, _path, _stay
from ..paper.options import PathShape
from .options import (
    RepairApproach,
    RepairClear,
    RepairEdges,
    RepairLock,
    RepairProgress,
    RepairStack,
    RepairStep,
)

SCENARIO_4 = (Rule.SCENARIO_4_I_EMPTY, Rule.SCENARIO_4_I_NONEMPTY)


class Leg(StrEnum):
    """The class of a repaired move (``repair_step = unit``), whatever rule chose it: what
    ``fatline prove`` reasons about for the repaired rule set (:mod:`fatline_verify.rules.repaired.family`)."""

    HORIZONTAL = "horizontal"
    """One radius or less along the x axis."""
    TOP = "top"
    """One radius or less along the y axis, seeing no robot above on its own vertical (a vertical leg
    of a paper rule, or the top's contraction)."""
    BOTTOM = "bottom"
    """One radius or less up, seeing robots above on its own vertical and none below, ending at least 3
    radii below each (the bottom's contraction)."""
    TOP_CORNER = "top-corner"
    """``repair_progress = corner``: one radius or less right and down at once, seeing no robot above on
    its own vertical and one below."""
    BOTTOM_CORNER = "bottom-corner"
    """``repair_progress = corner``: one radius or less right and up at once, seeing robots above on its
    own vertical and none below, ending at least 3 radii below each."""


CORNERS = (Leg.TOP_CORNER, Leg.BOTTOM_CORNER)


def leg_of(destination: Point, snapshot: Sequence[Point]) -> Leg:
    """The class of a repaired move to ``destination`` (relative, one axis) from ``snapshot``."""
    dx, dy = destination
    if not dy:
        return Leg.HORIZONTAL
    if dx:
        return Leg.BOTTOM_CORNER if below_another(snapshot) else Leg.TOP_CORNER
    return Leg.BOTTOM if below_another(snapshot) else Leg.TOP


def locked(snapshot: Sequence[Point]) -> bool:
    """``repair_lock = left-first``: r sees a robot strictly left of it."""
    return any(c[0] < 0 for c in snapshot)


def below_another(snapshot: Sequence[Point]) -> bool:
    """``repair_lock = left-first``: r sees a robot above it on its own vertical. Robots on one vertical
    may move in the same round (neither is left of the other); only the top one r sees may move
    vertically, the others horizontally, away from the vertical."""
    return any(c[0] == 0 and c[1] > 0 for c in snapshot)


def _toward(v: Number, rho: int) -> Number:
    """At most one radius of ``v``, with its sign."""
    return max(-rho, min(v, rho)) if isinstance(v, int) else max(Fraction(-rho), min(v, Fraction(rho)))


def legs(destination: Point, model: Model) -> list[tuple[Point, Path]]:
    """The moves r may make toward ``destination``, in the order tried: ``(end, path)``.

    Without ``repair_step``, the paper's own move (path per the ``path`` option). With it, one
    radius along one axis: the horizontal leg first (the paper: "its horizontal movement must be
    followed by a vertical movement"), unless the path option puts the vertical leg first."""
    opts = model.options
    if opts.repair_step is RepairStep.OFF:
        return [(destination, _path(destination, opts.path))]
    rho = model.radius
    dx, dy = destination
    horizontal: list[Point] = [(_toward(dx, rho), 0)] if dx else []
    vertical: list[Point] = [(0, _toward(dy, rho))] if dy else []
    order = vertical + horizontal if opts.path is PathShape.VERTICAL_THEN_HORIZONTAL else horizontal + vertical
    return [(end, (ORIGIN, end)) for end in order]


def allowed(end: Point, path: Path, snapshot: Sequence[Point], model: Model, *, bottom_up: bool = False) -> bool:
    """Whether a leg passes ``repair_lock`` (no vertical leg below another robot on r's vertical, but
    the bottom's contraction, ``bottom_up``), ``repair_clear`` and ``repair_edges`` (each only when on)."""
    opts = model.options
    lock = opts.repair_lock is RepairLock.LEFT_FIRST
    if lock and end[1] != 0 and below_another(snapshot) and not bottom_up:
        return False
    if opts.repair_clear is RepairClear.ON:
        limit = model.contact2
        strict = opts.contact is Contact.STRICT
        for c in snapshot:
            d2 = path_point_dist2(path, c)
            if d2 < limit or (strict and d2 == limit):
                return False
            if end[0] != 0 and end[1] != 0 and c[0] == 0:  # a corner leg: clear of c's move right too
                d2 = segment_segment_dist2(ORIGIN, end, c, (c[0] + model.radius, c[1]))
                if d2 < limit or (strict and d2 == limit):
                    return False
    if opts.repair_edges is RepairEdges.OFF:
        return True
    return all(_edge_kept(c, end, snapshot, lock, model) for c in snapshot)


def _edge_kept(c: Point, end: Point, snapshot: Sequence[Point], lock: bool, model: Model) -> bool:
    """``repair_edges``: r ends within view of ``c`` wherever ``c`` may be (:func:`_wherever`), or,
    under the lock, r ends within view of a robot ``b`` right of it (held by the lock: it sees r,
    which is left of it) that sees ``c`` wherever ``c``'s own move may take it: the edge r-c may
    go, r and c stay connected through b. With ``repair_progress = corner``, b may also be on r's
    vertical, wherever its own move may take it."""
    rho = model.radius
    if all(model.sees(dist2(after, end)) for after in _wherever(c, end, lock, rho)):
        return True
    if not lock:
        return False
    corners = model.options.repair_progress is RepairProgress.CORNER
    moves = _anywhere(c, rho, snapshot, corners=corners)
    if any(
        b != c and b[0] > 0 and model.sees(dist2(b, end)) and all(model.sees(dist2(b, after)) for after in moves)
        for b in snapshot
    ):
        return True
    return corners and any(
        b != c
        and b[0] == 0
        and all(model.sees(dist2(bb, end)) for bb in _anywhere(b, rho, snapshot, corners=True))
        and all(model.sees(dist2(bb, cc)) for bb in _anywhere(b, rho, snapshot, corners=True) for cc in moves)
        for b in snapshot
    )


def _anywhere(c: Point, rho: int, snapshot: Sequence[Point] = (), *, corners: bool = False) -> tuple[Point, ...]:
    """Every place a visible robot ``c`` may be after this round under the lock (the corners of a region
    holding them all: distance is convex): at rest if it is off r's vertical (right of r, so held; left
    of r cannot be, or r would be held); on it, one radius right, and one radius up or down if it is
    above r (it may be the top).

    With ``corners`` (``repair_progress = corner``), from what r sees in ``snapshot``: above r, it may be
    the top only if r sees no robot above it there (that robot would be closer to it than to r): then
    also up, down, and right and down; below r, it may be the bottom only if r sees none below it there,
    and then moves up only if more than 3 below r, ending 3 below r: up, or right and up."""
    x, y = c
    if x != 0:
        return (c,)
    if not corners:
        return (c, (x + rho, y), *(((x, y + rho), (x, y - rho)) if y > 0 else ()))
    out = [c, (x + rho, y)]
    if y > 0 and not any(d[0] == 0 and d[1] > y for d in snapshot):
        out += [(x, y + rho), (x, y - rho), (x + rho, y - rho)]
    if y < -3 * rho and not any(d[0] == 0 and d[1] < y for d in snapshot):
        up = min(y + rho, -3 * rho)
        out += [(x, up), (x + rho, up)]
    return tuple(out)


def _wherever(c: Point, end: Point, lock: bool, rho: int) -> tuple[Point, ...]:
    """Where a visible robot ``c`` may be after this round, as far as r's edge to it goes.

    At rest, except under the lock when r's leg has a vertical part (the top of its vertical, or its
    bottom contracting it; or a corner leg) and ``c`` is on r's vertical: ``c`` may move one radius
    right. The other pairs on one vertical are covered by the other robot's own test (the robot
    moving vertically tests r's move right) or need none (two moves right: the distance is at most the larger of the two
    tested; a move toward r only shortens the edge). Distance is convex along a move, so its ends
    are enough."""
    if lock and end[1] != 0 and c[0] == 0:
        return (c, (c[0] + rho, c[1]))
    return (c,)


def _contract(decision: Decision, snapshot: Sequence[Point], model: Model) -> Decision:
    """``repair_stack = align``, for a robot that sees only A u I and none right of its vertical: the
    bottom of its vertical (robots above it, none below) moves one radius up, ending at least 3
    radii below the robot above (which may come down one radius); the top (robots below, none above)
    moves one radius down, ending at least 2 above the robot below. Otherwise, or if the move is
    not allowed, r stays as the paper says."""
    rho = model.radius
    above = [c[1] for c in snapshot if c[0] == 0 and c[1] > 0]
    below = [c[1] for c in snapshot if c[0] == 0 and c[1] < 0]
    if above and not below and min(above) > 3 * rho:
        end: Point = (0, min(rho, min(above) - 3 * rho))
    elif below and not above and max(below) < -2 * rho:
        end = (0, max(-rho, max(below) + 2 * rho))
    else:
        return decision
    path = (ORIGIN, end)
    if model.options.repair_lock is RepairLock.LEFT_FIRST and locked(snapshot):
        return decision
    if not allowed(end, path, snapshot, model, bottom_up=end[1] > 0):
        return decision
    return Decision(Rule.REPAIR_CONTRACT, end, path, decision.classification)


def align_destination(snapshot: Sequence[Point]) -> Point | None:
    """``repair_stack = align``'s destination for a robot that sees only A u I: the greatest x it sees,
    if right of it ("r moves right to the greatest x it sees"); else ``None`` (r does not move by it)."""
    right = max(c[0] for c in snapshot)
    return (right, 0) if right > 0 else None


def approach_destination(decision: Decision, model: Model) -> Point | None:
    """``repair_approach = on``'s destination for a Scenario 4 decision: 2 radii short of psi_right,
    if right of r; else ``None`` (Scenario 4 as the paper says)."""
    assert decision.psi is not None
    x = decision.psi - 2 * model.radius
    return (x, 0) if x > 0 else None


def repair(decision: Decision, snapshot: Sequence[Point], model: Model) -> Decision:
    """The repaired decision: the paper's ``decision`` if it stays; else held by the lock, or the
    first allowed leg toward its destination, or a stay when no leg is allowed."""
    if decision.rule is Rule.ONLY_AI and model.options.repair_stack is RepairStack.ALIGN:
        aligned = align_destination(snapshot)
        if aligned is not None:
            destination = aligned
            decision = Decision(
                Rule.REPAIR_ALIGN, destination, _path(destination, model.options.path), decision.classification
            )
    if decision.rule in SCENARIO_4 and model.options.repair_approach is RepairApproach.ON:
        approached = approach_destination(decision, model)
        if approached is not None:
            destination = approached
            decision = replace(
                decision,
                rule=Rule.REPAIR_APPROACH,
                destination=destination,
                path=_path(destination, model.options.path),
            )
    if decision.rule is Rule.ONLY_AI and model.options.repair_stack is RepairStack.ALIGN and not decision.moves:
        return _contract(decision, snapshot, model)
    if not decision.moves:
        return decision
    kw = {"psi": decision.psi, "r_psi": decision.r_psi, "candidates": decision.candidates, "case": decision.case}
    if model.options.repair_lock is RepairLock.LEFT_FIRST and locked(snapshot):
        return _stay(Rule.REPAIR_LOCK, decision.classification, **kw)
    if _detour_on(model):
        return _progress(decision, snapshot, model, kw)
    for end, path in legs(decision.destination, model):
        if allowed(end, path, snapshot, model):
            return replace(decision, destination=end, path=path)
    if model.options.repair_stack is RepairStack.ALIGN and not below_another(snapshot):
        below = [c[1] for c in snapshot if c[0] == 0 and c[1] < 0]
        if below:  # the top of a vertical contracts it: one radius down toward the robot below
            end = (0, max(-model.radius, max(below) + 2 * model.radius))
            path = (ORIGIN, end)
            if end[1] < 0 and allowed(end, path, snapshot, model):
                return Decision(Rule.REPAIR_CONTRACT, end, path, decision.classification, **kw)  # type: ignore[arg-type]
    return _stay(Rule.REPAIR_BLOCKED, decision.classification, **kw)


def _detour_on(model: Model) -> bool:
    """``repair_progress = detour``, and the repairs its legs rest on (lock, unit steps, clearance, edges)."""
    opts = model.options
    return (
        opts.repair_progress is not RepairProgress.OFF
        and opts.repair_lock is RepairLock.LEFT_FIRST
        and opts.repair_step is not RepairStep.OFF
        and opts.repair_clear is not RepairClear.OFF
        and opts.repair_edges is not RepairEdges.OFF
        and opts.path is not PathShape.VERTICAL_THEN_HORIZONTAL
    )


def _sign(v: Number) -> int:
    return (v > 0) - (v < 0)


def _vertical(way: int, snapshot: Sequence[Point], model: Model) -> tuple[Point, bool] | None:
    """One radius along r's vertical in ``way`` (1 up, -1 down) as a leg of its class, ``(end, bottom_up)``:
    ``top`` if r sees no robot above it on its vertical; else ``bottom`` (up only, none below, ending at
    least 3 below each robot above); else none (a middle robot does not move vertically)."""
    rho = model.radius
    above = [c[1] for c in snapshot if c[0] == 0 and c[1] > 0]
    if not above:
        return (0, way * rho), False
    below = any(c[0] == 0 and c[1] < 0 for c in snapshot)
    if way < 0 or below:
        return None
    up = min(rho, min(above) - 3 * rho)
    return ((0, up), True) if up > 0 else None


def _seen_from(h: Number, snapshot: Sequence[Point], model: Model) -> list[Point]:
    """The robots r sees that it would still see from ``(0, h)``, relative to that point."""
    moved = [(c[0], c[1] - h) for c in snapshot]
    return [c for c in moved if model.sees(c[0] * c[0] + c[1] * c[1])]


def _free_way(step: Point, prefer: int, snapshot: Sequence[Point], model: Model) -> int:
    """The way (1 up, -1 down, 0 none) to the nearest height, whole radii along r's vertical and within
    view, that r could walk to by legs that pass :func:`allowed` and from which the horizontal leg
    ``step`` would pass it, the robots r sees staying where they are; at equal distance ``prefer``'s
    way, else down. Stable as r walks there: that height gets nearer, every other one farther."""
    rho = model.radius
    best: tuple[int, int] | None = None
    for rank, w in enumerate((prefer, -prefer) if prefer else (-1, 1)):
        h: Number = 0
        for i in range(1, model.view // rho + 1):
            here = _seen_from(h, snapshot, model)
            leg = _vertical(w, here, model)
            if leg is None or not allowed(leg[0], (ORIGIN, leg[0]), here, model, bottom_up=leg[1]):
                break
            h += leg[0][1]
            if allowed(step, (ORIGIN, step), _seen_from(h, snapshot, model), model):
                if best is None or (i, rank) < best:
                    best = (i, rank)
                break
    if best is None:
        return 0
    return ((prefer, -prefer) if prefer else (-1, 1))[best[1]]


def _shorter(end: Point) -> list[Point]:
    """``end`` and the lattice points short of it on its axis, longest first (one lattice unit is
    ``1/q`` radius; at ``q = 1`` only ``end``)."""
    dx, dy = end
    if not isinstance(dx, int) or not isinstance(dy, int):
        return [end]
    if dx and dy:  # a corner leg: both parts shortened together, each at most its own length
        most = max(abs(dx), abs(dy))
        return [(_sign(dx) * min(k, abs(dx)), _sign(dy) * min(k, abs(dy))) for k in range(most, 0, -1)]
    return [(_sign(dx) * k, _sign(dy) * k) for k in range(abs(dx) + abs(dy), 0, -1)]


def _corner(snapshot: Sequence[Point], model: Model) -> Point | None:
    """``repair_progress = corner``: one radius right (at most to the greatest x r sees) and one radius
    vertically at once. The top of a vertical with a robot below it there: right and down. The
    bottom (robots above it there, none below): right and up, ending at least 3 below each above."""
    rho = model.radius
    right = max(c[0] for c in snapshot)
    if right <= 0:
        return None
    above = [c[1] for c in snapshot if c[0] == 0 and c[1] > 0]
    below = [c[1] for c in snapshot if c[0] == 0 and c[1] < 0]
    if below and not above:
        return (min(rho, right), -rho)
    if above and not below and min(above) - 3 * rho > 0:
        return (min(rho, right), min(rho, min(above) - 3 * rho))
    return None


def _progress(decision: Decision, snapshot: Sequence[Point], model: Model, kw: dict[str, Any]) -> Decision:
    """``repair_progress = detour`` for an unlocked robot that would move (every leg one of the classes
    of :class:`Leg`, passing :func:`allowed`), trying in this order:

    1. the horizontal leg toward its destination; for a vertical destination (Scenario 4's drop), one
       radius right (at most to the greatest x r sees, so never past the RMA) instead;
    2. one radius along its vertical toward the nearest height from which that horizontal leg would
       pass (:func:`_free_way`), around what refuses it;
    3. the vertical leg toward its destination;
    4. the top of a vertical down toward the robot below (the contraction of ``repair_stack``);
    5. one radius up its vertical (``top``, or ``bottom`` keeping 3 below the robot above), then down;
    each leg, if refused, also shorter, by whole lattice units (``q > 1``); else it stays (``repair-blocked``)."""
    rho = model.radius
    dx, dy = decision.destination
    right = max((c[0] for c in snapshot), default=0)
    tries: list[tuple[Rule, Point, bool]] = []
    step: Point | None = None
    if dx > 0:
        step = (_toward(dx, rho), 0)
        tries.append((decision.rule, step, False))
    elif right > 0:
        step = (min(rho, right), 0)
        tries.append((Rule.REPAIR_DETOUR, step, False))
    if step is not None and not allowed(step, (ORIGIN, step), snapshot, model):
        way = _free_way(step, _sign(dy), snapshot, model)
        leg = _vertical(way, snapshot, model) if way else None
        if leg is not None:
            tries.append((Rule.REPAIR_DETOUR, *leg))
    if dy:
        leg = _vertical(_sign(dy), snapshot, model)
        if leg is not None and leg[0][1] == _sign(dy) * rho:
            tries.append((decision.rule, (0, _toward(dy, rho)), leg[1]))
        elif leg is not None:
            tries.append((decision.rule, *leg))
    below = [c[1] for c in snapshot if c[0] == 0 and c[1] < 0]
    if below and not below_another(snapshot):
        down = max(-rho, max(below) + 2 * rho)
        if down < 0:
            tries.append((Rule.REPAIR_CONTRACT, (0, down), False))
    for way in (1, -1):  # last: any leg along r's vertical, up first
        leg = _vertical(way, snapshot, model)
        if leg is not None:
            tries.append((Rule.REPAIR_DETOUR, *leg))
    if model.options.repair_progress is RepairProgress.CORNER:
        corner = _corner(snapshot, model)
        if corner is not None:
            tries.append((Rule.REPAIR_DETOUR, corner, corner[1] > 0))
    for rule, end, bottom_up in tries:
        for short in _shorter(end):
            path = (ORIGIN, short)
            if allowed(short, path, snapshot, model, bottom_up=bottom_up):
                return replace(decision, rule=rule, destination=short, path=path)
    return _stay(Rule.REPAIR_BLOCKED, decision.classification, **kw)  # type: ignore[arg-type]


__all__ = ["Leg", "allowed", "leg_of", "legs", "locked", "repair"]
