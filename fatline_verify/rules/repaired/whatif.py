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

from ..family.family import LegClass, MoveFamily
from ..family.lang import FALSE, Cond, Pt, end, exists, forall, me
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


__all__ = ["BOTTOM_CORNER", "CORNER", "KINDS", "LEFT", "LEFT_ALONE", "SHIPPED", "TOP_CORNER", "classes", "family"]
