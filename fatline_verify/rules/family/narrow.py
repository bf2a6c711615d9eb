"""A family narrowed to a finite policy: each class's guard also names the views the policy moves by it.

A policy given as a finite map from views to moves (a table ``fatline synth`` found, or a plug-in's own) lies
inside a wider family whose guards speak of any view. The family's obligations are then about every move the
guards admit, most of which the policy never makes: a connectivity obligation can fail on a configuration the
policy does not play, and the prover can neither prove nor refute it (INCONCLUSIVE). :func:`narrowed` keeps
the classes and their guards and adds, to the guard of each class, "the robot sees what one of the views in
which the policy moves by this class shows, and moves to that view's end": for every robot seen, it is at
one of that view's points. Every move of the policy meets it (a view's robots are at its points), so the
narrowed family is still implied by the policy and what the prover proves of it holds for the policy; the
named robots of each obligation are then held to the views' points, which is what a proof of the policy
needs.

Not said: that each point of the view holds a robot (an existential per point, with a witness role the
obligations would split on); the guard is weaker for it, so still implied, and no obligation of the shipped
tables needed it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import Any

from ...model.numbers import Point
from .family import LegClass, MoveFamily
from .lang import Cond, Ground, all_of, any_of, end, forall, holds, me


def at(c: Any, p: Point, radius: int) -> Cond:
    """The point ``c`` (a robot seen, or ``end``) at ``p`` (relative to the deciding robot, lattice units)."""
    return (c.x == me.x + Fraction(p[0], radius)) & (c.y == me.y + Fraction(p[1], radius))


def in_view(view: Sequence[Point], radius: int) -> Cond:
    """Every robot seen is at one of ``view``'s points (relative, lattice units)."""
    return forall(lambda c: any_of(*(at(c, p, radius) for p in view)))


def narrowed(base: MoveFamily, moves: Mapping[tuple[Point, ...], Point], model: Any, name: str) -> MoveFamily:
    """``base`` with each class's guard also requiring one of the views ``moves`` moves by that class (to that
    view's end); a class the policy never moves by is left out. ``moves``: view -> end (lattice units; a stay,
    ``(0, 0)``, is no move)."""
    rho = model.radius
    classes: list[LegClass] = []
    for cls in base.classes:
        mine = [
            (view, e)
            for view, e in sorted(moves.items())
            if e != (0, 0) and holds(cls.shape, Ground(model, (), {"me": (0, 0), "end": e}))
        ]
        if not mine:
            continue
        table = any_of(*(at(end, e, rho) & in_view(v, rho) for v, e in mine))
        says = f"{cls.says or cls.name}; only in the {len(mine)} view(s) {name} moves by it"
        classes.append(LegClass(cls.name, cls.shape, all_of(table, cls.guard), says))
    if not classes:
        raise ValueError(f"{name}: the policy makes no move of the family {base.name}; nothing to narrow to")
    says = f"{base.says or base.name}; each class narrowed to the views {name} moves by it"
    return dataclasses.replace(base, name=f"{base.name}/{name}", classes=tuple(classes), says=says)


__all__ = ["at", "in_view", "narrowed"]
