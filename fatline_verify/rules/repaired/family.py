"""The repaired rule set's move family: its three leg classes and the guard ``repairs.allowed`` enforces.

With ``repair_lock``, ``repair_step``, ``repair_clear`` and ``repair_edges`` on, a repaired robot that
moves makes one leg (:mod:`fatline_verify.rules.repaired.algorithm`), whatever rule chose it:

- ``horizontal``: ``(dx, 0)``, ``0 < dx <= 1`` — a leg toward a destination whose x never decreases;
- ``top``: ``(0, dy)``, ``0 < |dy| <= 1``, seeing no robot above it on its own vertical;
- ``bottom``: ``(0, dy)``, ``0 < dy <= 1``, every robot on its vertical above it and the leg ending at
  least 3 below each (the bottom's contraction).

It stays when it sees a robot strictly left of it (``repair_lock = left-first``: :attr:`at_rest`). Every
robot c it sees is clear of its swept disc (``repair_clear``), and its edge to c is **kept** (it ends within
view of c, and of c one radius right when the leg is vertical and c is on its vertical: c may move
right) or **bridged** by a witness b right of it that it sees, that sees its end and c wherever c's move
may take it (``repair_edges``). ``repair_progress = corner`` adds diagonal legs this family does not have:
a model with it has no family (the checker's evidence only).
"""

from __future__ import annotations

from typing import Any

from ..family.family import LegClass, MoveFamily
from ..family.lang import (
    TRUE,
    Cond,
    Pt,
    all_of,
    clear,
    clear_of,
    distinct,
    end,
    exists,
    forall,
    implies,
    me,
    point,
    sees,
)
from .options import RepairClear, RepairEdges, RepairLock, RepairProgress, RepairStep

dx = end.x - me.x
dy = end.y - me.y


def _on_vertical(c: Pt) -> Cond:
    return c.x == me.x


def _kept(c: Pt, vertical: bool) -> Cond:
    """r ends within view of ``c`` wherever c may be after the round, as far as this edge goes
    (``repairs._wherever``)."""
    if not vertical:
        return sees(end, c)
    return sees(end, c) & implies(_on_vertical(c), sees(end, c.moved(1, 0)))


def _places(c: Pt, corners: bool) -> list[tuple[Cond, Pt]]:
    """Where a robot ``c`` that r sees may be after the round (``repairs._anywhere``), each place with the
    condition under which it is listed: at rest; on r's vertical also one radius right, and above r one
    up or down. With ``corners`` (``repair_progress = corner``): above r only if r sees no robot above c
    on its vertical (then also right and down); below r by more than 3 with none seen below it, up
    (ending at most 3 below r), straight or right."""
    on = _on_vertical(c)
    out: list[tuple[Cond, Pt]] = [(TRUE, c), (on, c.moved(1, 0))]
    if not corners:
        above = on & (c.y > me.y)
        return [*out, (above, c.moved(0, 1)), (above, c.moved(0, -1))]
    top = on & (c.y > me.y) & forall(lambda d: ~(_on_vertical(d) & (d.y > c.y)))
    out += [(top, c.moved(0, 1)), (top, c.moved(0, -1)), (top, c.moved(1, -1))]
    bottom = on & (c.y < me.y - 3) & forall(lambda d: ~(_on_vertical(d) & (d.y < c.y)))
    near = c.y + 1 <= me.y - 3  # repairs._anywhere's min(y + 1, -3), as two cases
    for rise, up in ((near, c.moved(0, 1)), (~near, point(c.x, me.y - 3))):
        out += [(bottom & rise, up), (bottom & rise, up.moved(1, 0))]
    return out


def _anywhere(b: Pt, c: Pt, corners: bool = False) -> Cond:
    """``b`` sees ``c`` wherever c's own move may take it (:func:`_places`)."""
    if not corners:
        up_down = sees(b, c.moved(0, 1)) & sees(b, c.moved(0, -1))
        return sees(b, c) & implies(_on_vertical(c), sees(b, c.moved(1, 0)) & implies(c.y > me.y, up_down))
    return all_of(*(implies(cond, sees(b, p)) for cond, p in _places(c, corners)))


def _edge(c: Pt, vertical: bool, corners: bool = False) -> Cond:
    """``repairs._edge_kept``: the edge to ``c`` kept, or bridged by a robot right of r (held by the lock);
    with ``corners`` also by a robot on r's vertical, wherever its own move and c's may take them."""
    bridge = exists(lambda b: distinct(b, c) & (b.x > me.x) & sees(end, b) & _anywhere(b, c, corners), role="bridge")
    if not corners:
        return _kept(c, vertical) | bridge

    def along(b: Pt) -> Cond:
        mine, theirs = _places(b, True), _places(c, True)
        parts = [implies(cb, sees(pb, end)) for cb, pb in mine]
        parts += [implies(cb & cc, sees(pb, pc)) for cb, pb in mine for cc, pc in theirs]
        return distinct(b, c) & _on_vertical(b) & all_of(*parts)

    return _kept(c, vertical) | bridge | exists(along, role="vertical")


def _guard(vertical: bool, extra: Any = None, corners: bool = False, corner_leg: bool = False) -> Cond:
    """``repairs.allowed`` for every robot c seen: not strictly left (the lock), clear of the swept disc (a
    corner leg also of c's move right when c is on r's vertical), ``extra``, and the edge kept or bridged."""

    def each(c: Pt) -> Cond:
        parts = [c.x >= me.x, clear(c)]
        if corner_leg:
            parts.append(implies(_on_vertical(c), clear_of(me, end, c, c.moved(1, 0))))
        parts.append(_edge(c, vertical, corners))
        if extra is not None:
            parts.append(extra(c))
        return all_of(*parts)

    return forall(each)


def _not_above(c: Pt) -> Cond:
    """The top's condition: ``c`` is not above r on its vertical."""
    return ~(_on_vertical(c) & (c.y > me.y))


def _below_each(c: Pt) -> Cond:
    """The bottom's condition: a robot on r's vertical is above it, and the leg ends at least 3 below it."""
    return implies(_on_vertical(c), (c.y > me.y) & (end.y <= c.y - 3))


HORIZONTAL = LegClass(
    "horizontal",
    (dy == 0) & (dx > 0) & (dx <= 1),
    _guard(False),
    "(dx, 0) with 0 < dx <= 1",
)
TOP = LegClass(
    "top",
    (dx == 0) & (dy != 0) & (dy >= -1) & (dy <= 1),
    _guard(True, _not_above),
    "(0, dy) with 0 < |dy| <= 1, no robot seen above on its vertical",
)
BOTTOM = LegClass(
    "bottom",
    (dx == 0) & (dy > 0) & (dy <= 1),
    _guard(True, _below_each),
    "(0, dy) with 0 < dy <= 1, every robot seen on its vertical above it, ending >= 3 below each",
)

LEGS = MoveFamily(
    "repaired-legs",
    (HORIZONTAL, TOP, BOTTOM),
    max_step=1,
    at_rest=~forall(lambda c: c.x >= me.x),
    says="the repaired rules' legs: one radius or less along one axis, under the lock, clear paths and kept edges",
    witnesses={"bridge": "a robot right of the mover that sees its end and the robot whose edge it bridges"},
)
"""The family of the repaired rule set with the lock, unit steps, clear paths and kept edges."""

NEEDED = {
    "repair_lock": RepairLock.LEFT_FIRST,
    "repair_step": RepairStep.UNIT,
    "repair_clear": RepairClear.ON,
    "repair_edges": RepairEdges.ON,
}
"""The repairs the family rests on (the others only choose destinations)."""


def missing(model: Any) -> list[str]:
    """The repairs of :data:`NEEDED` ``model`` does not have, as ``name=reading`` to set."""
    return [f"{name}={want}" for name, want in NEEDED.items() if getattr(model.options, name) is not want]


def family(model: Any) -> MoveFamily | None:
    """:data:`LEGS` for a model with every repair of :data:`NEEDED` and no corner legs; else ``None``."""
    if missing(model) or model.options.repair_progress is RepairProgress.CORNER:
        return None
    return LEGS


__all__ = ["LEGS", "NEEDED", "family", "missing"]
