"""The what-if families: the repaired family's legs and the legs ``fatline reach --with`` adds, one guard each.

``fatline reach`` and ``fatline synth`` search every rule set of a family of legs (not one rule set's
choice); ``fatline prove repaired --with KINDS`` proves the family's safety; a table ``fatline synth``
found declares it as its family. All three read the family :func:`family` returns, whose guards are those
``repairs.allowed`` enforces (:mod:`.family`), with ``repair_progress = corner``'s edge tests when the
kinds include ``corner``, and what a leg of the search needs its mover to see:

- ``horizontal``: ``(dx, 0)``, ``0 < dx <= 1``, never past the greatest x the robot sees (Lemma 3: a robot
  seen at least as far right, role ``ahead``);
- ``top``, ``bottom``: as the repaired family's;
- ``left`` (what-if): ``(-dx, 0)``, ``0 < dx <= 1``, by a robot that sees one strictly right of it (so never
  off the RMA);
- ``left-alone`` (what-if, the guarded left leg): ``left`` by a robot that sees **no other robot on its own
  vertical** (every robot it sees strictly right of it), at most ``left_units`` lattice units long
  (:func:`fatline_verify.repair.reach.left_alone_reach`: no robot it does not see reaches its path by a
  leg of the family);
- ``top-corner`` / ``bottom-corner`` (what-if, ``corner``): ``(dx, -dy)`` by a robot that sees a robot
  below it on its vertical and none above, ``(dx, dy)`` by one that sees robots above it there and none
  below, ending at least 3 radii below each; ``0 < dx, dy <= 1`` (up to sqrt(2) radii), ``dx`` not past
  the greatest x it sees; the path clear also of each robot on the mover's vertical moving one radius
  right.

A robot stays when it sees a robot strictly left of it (the lock) or sees none. The corner legs are
sqrt(2) radii long, which the reals' nonlinear arithmetic does not decide in time: the family is proved
on the model's lattice (:attr:`~fatline_verify.rules.family.family.MoveFamily.lattice`).
"""

from __future__ import annotations

from collections.abc import Iterable
from fractions import Fraction
from typing import Any

from ...model.numbers import Point
from ..family.family import LegClass, MoveFamily
from ..family.lang import FALSE, Cond, Ground, Pt, end, exists, forall, holds, me
from .family import BOTTOM, HORIZONTAL, LEGS, TOP, _below_each, _guard, _not_above, _on_vertical, dx, dy

LEFT, LEFT_ALONE, CORNER = "left", "left-alone", "corner"
KINDS = (LEFT, LEFT_ALONE, CORNER)
"""The what-if kinds, as ``--with`` names them (``fatline reach``, ``synth``, ``prove``)."""

TOP_CORNER, BOTTOM_CORNER = "top-corner", "bottom-corner"
SHIPPED = tuple(c.name for c in LEGS.classes)
"""The repaired family's classes (proved by ``fatline prove repaired``)."""


def _ahead() -> Cond:
    """A robot seen at least as far right as the leg ends (never past the greatest x seen: Lemma 3)."""
    return exists(lambda w: w.x >= end.x, role="ahead")


def _right_of_me(w: Pt) -> Cond:
    return w.x > me.x


def _on_vertical_below(w: Pt) -> Cond:
    return _on_vertical(w) & (w.y < me.y)


def _on_vertical_above(w: Pt) -> Cond:
    return _on_vertical(w) & (w.y > me.y)


def _alone(c: Pt) -> Cond:
    """The left-alone guard: ``c`` is strictly right of the mover (not on its vertical, not left: the lock)."""
    return c.x > me.x


def classes(kinds: Iterable[str], q: int, left_units: int | None = None) -> tuple[LegClass, ...]:
    """The leg classes of the family with the what-if ``kinds`` on the lattice ``q`` (``left_units``: the
    longest ``left-alone`` leg, lattice units; ``None``: one radius)."""
    kinds = frozenset(kinds)
    corners = CORNER in kinds
    horizontal = LegClass(
        HORIZONTAL.name,
        HORIZONTAL.shape,
        _guard(False, corners=corners) & _ahead(),
        HORIZONTAL.says + ", not past the greatest x seen",
    )
    top = LegClass(TOP.name, TOP.shape, _guard(True, _not_above, corners), TOP.says)
    bottom = LegClass(BOTTOM.name, BOTTOM.shape, _guard(True, _below_each, corners), BOTTOM.says)
    out = [horizontal, top, bottom]
    left_shape = (dy == 0) & (dx < 0) & (dx >= -1)
    if LEFT in kinds:
        out.append(
            LegClass(
                LEFT,
                left_shape,
                _guard(False, corners=corners) & exists(_right_of_me, role="ahead"),
                "(-dx, 0) with 0 < dx <= 1, seeing a robot right of it",
            )
        )
    if LEFT_ALONE in kinds:
        units = q if left_units is None else left_units
        out.append(
            LegClass(
                LEFT_ALONE,
                (dy == 0) & (dx < 0) & (dx >= -Fraction(units, q)),
                _guard(False, _alone, corners),
                f"(-dx, 0) with 0 < dx <= {Fraction(units, q)}, every robot seen strictly right of it",
            )
        )
    if corners:
        diagonal = (dx > 0) & (dx <= 1)
        out.append(
            LegClass(
                TOP_CORNER,
                diagonal & (dy < 0) & (dy >= -1),
                _guard(True, _not_above, True, True) & _ahead() & exists(_on_vertical_below, role="below"),
                "(dx, -dy) with 0 < dx, dy <= 1, not past the greatest x seen, a robot seen below on its "
                "vertical and none above",
            )
        )
        out.append(
            LegClass(
                BOTTOM_CORNER,
                diagonal & (dy > 0) & (dy <= 1),
                _guard(True, _below_each, True, True) & _ahead() & exists(_on_vertical_above, role="above"),
                "(dx, dy) with 0 < dx, dy <= 1, not past the greatest x seen, robots seen above on its "
                "vertical, none below, ending >= 3 below each",
            )
        )
    return tuple(out)


def family(kinds: Iterable[str], q: int, left_units: int | None = None) -> MoveFamily:
    """The family of the repaired legs and the what-if ``kinds`` on the lattice ``q`` (module docstring)."""
    kinds = frozenset(kinds)
    corners = CORNER in kinds
    named = ",".join(k for k in KINDS if k in kinds)
    return MoveFamily(
        f"repaired-legs+{named}" if named else "repaired-legs-searched",
        classes(kinds, q, left_units),
        max_step=Fraction(3, 2) if corners else Fraction(1),
        at_rest=~forall(lambda c: c.x >= me.x) | forall(lambda c: FALSE),
        says="the repaired legs"
        + (f" and the what-if {named} legs" if named else "")
        + ", under the lock, clear paths and kept edges"
        + (" (repair_progress = corner's edge tests)" if corners else ""),
        witnesses={
            "bridge": "a robot right of the mover that sees its end and the robot whose edge it bridges",
            "vertical": "a robot on the mover's vertical that sees its end and the robot whose edge it bridges, "
            "wherever their own moves take them",
            "ahead": "a robot the mover sees at least as far right as its leg ends (or right of it, for a left leg)",
            "below": "a robot below the mover on its vertical",
            "above": "a robot above the mover on its vertical",
        },
        lattice=True,
    )


def legs_family(model: Any, kinds: Iterable[str] = ()) -> MoveFamily:
    """:func:`family` of the what-if ``kinds`` among ``kinds`` (others, such as ``fatline reach``'s ``right`` and
    ``vertical``, are the repaired classes, always there) on ``model``'s lattice, the ``left-alone`` legs as long
    as :func:`left_alone_reach` allows: the family ``fatline reach``, ``synth`` and ``prove --with`` read, and a
    table's. Made once per lattice, view and kinds."""
    what = frozenset(str(k) for k in kinds if str(k) in KINDS)
    key = (model.radius, model.view2, model.options.timing, model.options.contact, what)
    got = _FAMILIES.get(key)
    if got is None:
        units = left_alone_reach(model, what) if LEFT_ALONE in what else None
        got = _FAMILIES[key] = family(what, model.radius, units)
    return got


_FAMILIES: dict[tuple[object, ...], MoveFamily] = {}


def shapes(family: MoveFamily, model: Any) -> tuple[tuple[Point, LegClass], ...]:
    """Every lattice end of ``model`` of each class's shape (at most ``max_step``), in the order legs are tried:
    class by class, shortest first (the concrete interpreter on the shape alone: it speaks of ``end`` only)."""
    key = (id(family), model.radius)
    got = _SHAPES.get(key)
    if got is None or got[0] is not family:
        rho = model.radius
        box = int(Fraction(family.max_step) * rho) + 1
        ends = [(a, b) for a in range(-box, box + 1) for b in range(-box, box + 1) if (a, b) != (0, 0)]
        out: list[tuple[Point, LegClass]] = []
        for cls in family.classes:
            mine = [
                e
                for e in ends
                if family.within_step(e, model) and holds(cls.shape, Ground(model, (), {"me": (0, 0), "end": e}))
            ]
            out += [(e, cls) for e in sorted(mine, key=lambda e: (abs(e[0]), e[1] if not e[0] else abs(e[1])))]
        got = _SHAPES[key] = (family, tuple(out))
    return got[1]


_SHAPES: dict[tuple[int, int], tuple[MoveFamily, tuple[tuple[Point, LegClass], ...]]] = {}
_REACH: dict[tuple[object, ...], int] = {}


def left_alone_reach(model: Any, kinds: Iterable[str]) -> int:
    """The longest ``left-alone`` leg, in lattice units (at most one radius): the greatest ``K`` such that no
    robot the mover does not see (squared distance beyond ``rad_v``), taking any leg of the family of ``kinds``
    in the same round (every end of its shapes, whatever it sees: a stronger test), comes within a collision
    of the mover's path to ``(-k, 0)`` for any ``k <= K``; by the model's own ``closest_dist2`` and ``collides``
    (exact integers). A robot it does not see may be beyond ``2 + k + |leg|`` radii of the mover only, so the
    search covers the robots within 5 radii (a leg is at most sqrt(2) < 2 radii).

    With the proved legs and left legs the answer is one radius (unit legs: ``d > rad_v >= 4`` radii minus two
    legs of at most one radius each is more than two radii); with corner legs (sqrt(2) radii) it is the
    lattice's own answer: one radius at ``q = 1``, half a radius at ``q = 2`` (the collision ``fatline prove
    repaired --with left,corner --q 2`` found: ``leg-left.and.top-corner``)."""
    from ...schedulers.round import closest_dist2, collides

    rho = model.radius
    what = frozenset(str(k) for k in kinds if str(k) in KINDS)
    key = (rho, model.view2, model.options.timing, model.options.contact, what)
    got = _REACH.get(key)
    if got is not None:
        return got
    legs = sorted({e for e, _ in shapes(family(what, rho), model)})  # left-alone one radius long
    far = 25 * rho * rho  # (2 + 1 + 2)^2 radii^2: beyond it no leg of at most 2 radii meets one of 1 radius
    box = 5 * rho
    around = [
        (x, y)
        for x in range(-box, box + 1)
        for y in range(-box, box + 1)
        if not model.sees(x * x + y * y) and x * x + y * y <= far
    ]
    best = 0
    for k in range(1, rho + 1):
        mine = ((0, 0), (-k, 0))
        if any(
            collides(closest_dist2(mine, ((x, y), (x + a, y + b)), (0, 0), (x, y), model), model)
            for x, y in around
            for a, b in legs
        ):
            break
        best = k
    _REACH[key] = best
    return best


__all__ = [
    "BOTTOM_CORNER",
    "CORNER",
    "KINDS",
    "LEFT",
    "LEFT_ALONE",
    "SHIPPED",
    "TOP_CORNER",
    "classes",
    "family",
    "left_alone_reach",
    "legs_family",
    "shapes",
]
