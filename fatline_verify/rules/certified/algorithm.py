"""The certified rule set: what one robot decides from what it sees (lattice units, exact integers).

Not the paper's algorithm: a rule set designed for issue 32 to be safe by a local argument and live by a
measure, then judged by the checker (``fatline check certified``). Each robot decides from the robots
within ``rad_v`` of it only (:func:`decide`), relative to itself; nothing is remembered, nothing is sent.

Moves (``rho`` = one radius = ``q`` lattice units)
--------------------------------------------------
``right`` one radius or less (never past the greatest x the robot sees); ``up-right`` and ``down-right``
one lattice unit along each axis; ``down`` and ``up`` one radius or less. No move goes left: a robot
on the right-most vertical (RMA) never moves off it, and one that sees nothing right of it (it may be
on the RMA) moves only vertically.

The rules, in the order tried
-----------------------------
A robot that sees a robot right of it (a *pusher*) tries ``right`` (longest first), ``down-right``,
``up-right``, and, when a robot ahead of it is within two radii of its height (in its way), a ``fall``
straight down, to two radii below the lowest such robot at most.

A robot that sees nothing right of it tries, in order: ``close-in`` (down toward a robot left of it
more than two radii below it, ending two radii above it); ``contract-down`` (toward the robot below it
on its vertical, to a gap of ``DOWN_GAP`` radii, unless a robot left of it waits between the two);
``contract-up`` (only a robot that sees nothing but its own vertical: up toward the robot above it,
to a gap of ``UP_GAP`` radii, the gap below staying at most ``DOWN_GAP``; it *parks* under the robot
above, so that robot can tell it will not cross its way); ``make-room`` (one lattice unit down, when it
sees a robot left of it at or above its height that would meet it on a step right or diagonally right,
or that it sees while it carries a robot resting on it from above; never while a robot left of it
waits lower).

Who may move, and what it must check (safety)
---------------------------------------------
A robot estimates, for each robot it sees, the *region* of moves that robot might make
(:func:`region`): every move of the list above that is clear of every robot both see (at rest), that
keeps the edge to the observer when no robot both see could carry it, and ``up`` only if the robot
sees nothing off its vertical as far as the observer can tell. The region is a superset of what the
robot will do: every test below is a necessary condition of that robot's own rules.

* **Left neighbours** (strictly left): if all their regions are empty they stay (r is *free*);
  otherwise r must be clear of, and keep its edge to, every end of every non-empty region (and the
  contractions wait). A robot right of a robot that moves sees that robot's move in its region, so
  it is never free: it takes the pair on itself, and r may treat the robots right of it as at rest.
* **Column-mates** (same x): each pair of moves of a lower and an upper robot is ranked (:data:`RANK`);
  r is clear of, and keeps its edge to, every move of higher rank of each column-mate; the other side
  checks the rest.
* **Every robot r sees**: the path clears it at rest (contact per the model), and after the move r
  either sees it wherever the moves r must allow put it, or reaches it through edges that hold
  whatever the robots concerned do (:func:`allowed`).
* **A fall** (any ``down``) never leaves r seeing its own vertical only.

Two movers that do not see each other are more than ``rad_v`` apart; each moves at most one radius
along an axis or one lattice unit along each: on the lattice q = 1 no two such moves come closer than
2 (checked exhaustively in ``tests/test_certified.py``), and for q >= 2 every move is at most one
radius long. No collision and no lost connectivity at any swarm size then rest on the obligations the
prover will have to discharge (``docs/certified.md``, "What is left for the prover").

The measure (for the prover)
----------------------------
``A = sum_i (x_max - x_i)`` (lattice units; ``x_max`` never changes: no robot passes the RMA or leaves
it) and ``B = sum_i y_i``. ``right``, ``up-right`` and ``down-right`` lower A by at least 1 and no move
raises it (no move goes left); every ``down`` leaves A and lowers B by at least 1. So ``(A, B)``
decreases lexicographically on every round in which some robot moves, except by ``contract-up``,
which raises B: it is made only by a robot that sees nothing but its own vertical, closing a gap above it
of more than ``UP_GAP`` radii; a fall never leaves the faller seeing (at their places before the round)
nothing but its own vertical.
A is bounded (``0 <= A <= n (n - 1) rad_v q``: the swarm is connected and one robot is on the RMA).
Left to prove: that B is bounded below on every execution (no endless fall of the whole swarm) and
that parkings do not alternate with falls forever; within the checker's bounds neither happens (no
execution leaves a 20x20 bound, no fair cycle).

What the checker finds (SSYNC, FSYNC and centralized alike; 9x9 window, 20x20 bound)
------------------------------------------------------------------------------------
Every lemma holds for 2 to 4 robots at q = 1 and 2 to 3 at q = 2. Liveness fails at 5 robots, q = 1
(5 reachable deadlocks, none initial) and 4 robots, q = 2 (2 reachable deadlocks, none initial):
each is a robot held by a move another robot could make as far as it can see, but cannot make for a
reason it cannot see (a robot out of its view). ``docs/certified.md`` lists them, with the figures.
Under ASYNC it collides (2 robots, 8 events: a stale snapshot of a contracting vertical).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from fractions import Fraction

from ...model.config import Model
from ...model.geometry import dist2, path_point_dist2, segment_segment_dist2
from ...model.numbers import Point
from ...model.options import Contact
from ..decision import ORIGIN, Decision

DOWN_GAP = 3
"""Radii: a robot that sees nothing right of it contracts down to this gap above the robot below it."""
UP_GAP = 2
"""Radii: a robot that sees only its own vertical parks this far under the robot above it (touching)."""

R, UR, DR, DN, UP = "right", "up-right", "down-right", "down", "up"
KINDS = (R, UR, DR, DN, UP)

RANK = {
    ("lower", UR): 20, ("lower", UP): 19, ("upper", DR): 18, ("upper", DN): 17, ("lower", DN): 16,
    ("upper", R): 15, ("lower", R): 14, ("upper", UR): 13, ("upper", UP): 12, ("lower", DR): 11,
}  # fmt: skip
"""Two robots on one vertical, both moving: the move of lower rank gives way (its robot checks the other's
move; the other does not). Every value differs, so of any two moves exactly one robot checks."""

LABELS = {
    "alone": "sees no robot: stays",
    "lock": "a robot left of it may move, and every move it has meets one of those moves: stays",
    "blocked": "every move it has meets a robot or loses an edge: stays",
    "right": "right, toward the greatest x it sees",
    "down-right": "one lattice unit right and one down",
    "up-right": "one lattice unit right and one up",
    "fall": "down, out of the way of a robot ahead",
    "close-in": "down toward a robot left of it, to two radii above it",
    "contract-down": f"down toward the robot below on its vertical, to {DOWN_GAP} radii",
    "contract-up": f"up under the robot above on its vertical, to {UP_GAP} radii (it sees only its vertical)",
    "make-room": "one lattice unit down, out of the way of a robot left of it",
}
"""The rule labels :func:`decide` returns, read aloud."""


def _stay(rule: str) -> Decision:
    return Decision(rule, ORIGIN, (ORIGIN,), ())  # type: ignore[arg-type]


def _collide(d2: int | Fraction, model: Model) -> bool:
    """Whether squared centre distance ``d2`` is a collision under the model's ``contact``."""
    limit = model.contact2
    return d2 < limit or (model.options.contact is Contact.STRICT and d2 == limit)


def _hits(a: Point, b: Point, c: Point, model: Model) -> bool:
    """Whether a move from a to b meets a robot at rest at c."""
    return _collide(path_point_dist2((a, b), c), model)


def vectors(kind: str, rho: int) -> list[Point]:
    """The lattice steps of a kind of move, longest first."""
    if kind == R:
        return [(s, 0) for s in range(rho, 0, -1)]
    if kind == UR:
        return [(1, 1)]
    if kind == DR:
        return [(1, -1)]
    if kind == UP:
        return [(0, s) for s in range(rho, 0, -1)]
    return [(0, -s) for s in range(rho, 0, -1)]


def region(c: Point, snapshot: Sequence[Point], model: Model) -> list[tuple[str, Point]]:
    """Every move (kind, end) the robot at ``c`` might make this round, as far as r (at the origin) can
    tell: a superset of what its own rules give it, from the robots both see (and r itself)."""
    sees = model.sees
    rho = model.radius
    both = [ORIGIN] + [d for d in snapshot if d != c and sees(dist2(d, c))]
    above = [d[1] for d in both if d[0] == c[0] and d[1] > c[1]]
    vertical_only = all(d[0] == c[0] for d in both)
    out = []
    for kind in KINDS:
        if kind == UP and not vertical_only:
            continue
        for m in vectors(kind, rho):
            end = (c[0] + m[0], c[1] + m[1])
            if kind == UP and any(end[1] > y - UP_GAP * rho for y in above):
                continue
            if len(both) == 1 and not sees(dist2(end, ORIGIN)):
                continue  # no robot both see could carry the edge c-r: c keeps it
            if all(not _hits(c, end, d, model) for d in both):
                out.append((kind, end))
    return out


def blocks(a: Point, b: Point, model: Model) -> bool:
    """Whether the robot at b is in the way of a move right, down-right or up-right of the robot at a."""
    return any(_hits(a, (a[0] + m[0], a[1] + m[1]), b, model) for m in ((1, 0), (1, -1), (1, 1)))


def allowed(
    kind: str,
    u: Point,
    snapshot: Sequence[Point],
    model: Model,
    mates: dict[Point, list[tuple[str, Point]]],
    left: dict[Point, list[Point]],
) -> bool:
    """Whether r may move to ``u`` (a move of ``kind``): clear of every robot at rest, of every end of
    ``left`` (the robots left of r that may move) and of the column-mates' moves of higher rank
    (``mates``: their regions); and every robot r sees stays in view of r's end wherever those moves put
    it, or reachable from it through edges that hold whatever the robots concerned do."""
    sees = model.sees
    if any(_hits(ORIGIN, u, c, model) for c in snapshot):
        return False
    side = [c for c in snapshot if c[0] != 0]
    if kind == DN and side and not any(sees(dist2(u, c)) for c in side):
        return False  # a fall never leaves r seeing its own vertical only
    for c, ends in left.items():
        if any(_collide(segment_segment_dist2(ORIGIN, u, c, e), model) for e in ends):
            return False
    ranked: dict[Point, list[Point]] = {}
    for c, reg in mates.items():
        theirs = "upper" if c[1] > 0 else "lower"
        mine = RANK[("lower" if c[1] > 0 else "upper", kind)]
        ends = [e for k, e in reg if RANK[(theirs, k)] > mine]
        if any(_collide(segment_segment_dist2(ORIGIN, u, c, e), model) for e in ends):
            return False
        ranked[c] = ends
    where = [[c] + [e for _, e in mates.get(c, ())] + left.get(c, []) for c in snapshot]

    def sure(a: list[Point], b: list[Point]) -> bool:
        return all(sees(dist2(p, q)) for p in a for q in b)

    n = len(snapshot)
    reach = [sure([u], where[i]) for i in range(n)]
    todo = [i for i in range(n) if reach[i]]
    while todo:
        i = todo.pop()
        for j in range(n):
            if not reach[j] and sure(where[i], where[j]):
                reach[j] = True
                todo.append(j)
    for i, c in enumerate(snapshot):
        if reach[i]:
            continue
        if c in ranked and all(sees(dist2(u, e)) for e in [c] + ranked[c]):
            continue
        if c in left and all(sees(dist2(u, e)) for e in [c] + left[c]):
            continue
        return False
    return True


def candidates(snapshot: Sequence[Point], model: Model) -> list[tuple[str, str, Point]]:
    """The moves r tries, in order: (rule, kind, step). Steps are whole lattice units; positions seen may be
    exact fractions (a trace from a finer lattice replayed under this rule set)."""
    rho = model.radius
    right = max(0, *(c[0] for c in snapshot))
    below = [c[1] for c in snapshot if c[0] == 0 and c[1] < 0]
    above = [c[1] for c in snapshot if c[0] == 0 and c[1] > 0]
    tries: list[tuple[str, str, Point]] = []
    if right > 0:
        tries += [("right", R, (s, 0)) for s in range(min(rho, math.floor(right)), 0, -1)]
        tries += [("down-right", DR, (1, -1)), ("up-right", UR, (1, 1))]
        ahead = [c[1] for c in snapshot if c[0] > 0 and -2 * rho < c[1] < 2 * rho]
        if ahead:
            floor = min(ahead) - 2 * rho
            tries += [("fall", DN, (0, -s)) for s in range(rho, 0, -1) if -s >= floor]
        return tries
    lower_left = [c[1] for c in snapshot if c[0] < 0 and c[1] < -2 * rho]
    if lower_left:
        floor = max(lower_left) + 2 * rho
        tries += [("close-in", DN, (0, -s)) for s in range(rho, 0, -1) if -s >= floor]
    if below and not any(c[0] < 0 and max(below) < c[1] < 0 for c in snapshot):
        floor = max(below) + DOWN_GAP * rho
        tries += [("contract-down", DN, (0, -s)) for s in range(rho, 0, -1) if -s >= floor]
    if above and all(c[0] == 0 for c in snapshot):
        room = min(above) - UP_GAP * rho
        if below:
            room = min(room, max(below) + DOWN_GAP * rho)
        tries += [("contract-up", UP, (0, s)) for s in range(rho, 0, -1) if s <= room]
    pressed = any(y == 2 * rho for y in above)
    lowest = max(below) if below else None
    waiting = any(c[0] < 0 and c[1] < 0 and (lowest is None or c[1] > lowest) for c in snapshot)
    if not waiting and any(c[0] < 0 and c[1] >= 0 and (pressed or blocks(c, ORIGIN, model)) for c in snapshot):
        tries.append(("make-room", DN, (0, -1)))
    return tries


def propose(snapshot: Sequence[Point], model: Model) -> Iterator[Decision]:
    """Every move the certified rules allow the robot at the origin that sees ``snapshot`` (relative, lattice
    units), in the order tried, then the stay they give when no move is taken."""
    if not snapshot:
        yield _stay("alone")
        return
    regions = {c: region(c, snapshot, model) for c in snapshot if c[0] < 0}
    left = {c: [e for _, e in reg] for c, reg in regions.items() if reg}
    mates = {c: region(c, snapshot, model) for c in snapshot if c[0] == 0}
    for rule, kind, u in candidates(snapshot, model):
        if left and rule in ("contract-down", "contract-up"):
            continue  # contractions wait for the robots left of r
        if rule == "make-room" and any(k == DN for reg in regions.values() for k, _ in reg):
            continue  # a robot on the left that may fall itself: making room too could follow it down
        if allowed(kind, u, snapshot, model, mates, left):
            yield Decision(rule, u, (ORIGIN, u), ())  # type: ignore[arg-type]
    yield _stay("lock" if left else "blocked")


def decide(snapshot: Sequence[Point], model: Model) -> Decision:
    """The certified rules for the robot at the origin that sees ``snapshot``: the first move they allow (the
    rule set runs :func:`.family.decide`, which also holds each to the move family)."""
    return next(iter(propose(snapshot, model)))


__all__ = [
    "DOWN_GAP",
    "KINDS",
    "LABELS",
    "RANK",
    "UP_GAP",
    "allowed",
    "blocks",
    "candidates",
    "decide",
    "propose",
    "region",
]
