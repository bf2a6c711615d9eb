"""A move family: the moves a rule set may make, and the guard each must pass, declared once.

A rule set that declares a family may decide by any Python it likes (a table, a planner, an ordering):
its *policy* is free. What it declares is the family every decision must lie in:

- :class:`LegClass` — a class of straight moves: its **shape** (a condition on :data:`~.lang.end`, the
  move's end relative to the robot: ``(end.y == 0) & (end.x > 0) & (end.x <= 1)`` is one radius or
  less to the right) and its **guard** (a condition on what the robot sees);
- :attr:`MoveFamily.at_rest` — the condition under which a robot must stay (a lock);
- :attr:`MoveFamily.max_step` — the longest move of any class, in radii (what a robot it does not see
  can do to it).

A decision is **admitted** when it stays, or it is a straight move from the origin, the robot is not
held by :attr:`~MoveFamily.at_rest`, and some class's shape and guard hold (:meth:`MoveFamily.admit`).
The checker judges every decision against the family as it runs (the step lemma ``in-family``,
:mod:`fatline_verify.rules.family.enforce`), and the prover derives its no-collision and connectivity
obligations from the family alone (:mod:`fatline_verify.prove.smt.family`): what is proved is what runs.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from ...model.geometry import dist2
from ...model.numbers import Point
from .lang import FALSE, Cond, Ground, chain_roles, holds, roles

REST = "rest"
"""The class name of a robot that does not move."""


@dataclass(frozen=True, eq=False)
class LegClass:
    """One class of straight moves: which ends belong (``shape``, over :data:`~.lang.end`), and the guard
    each must pass (over :data:`~.lang.me`, :data:`~.lang.end` and the robots seen)."""

    name: str
    shape: Cond
    guard: Cond
    says: str = ""
    """The class in words (written in each obligation's header)."""

    def __post_init__(self) -> None:
        if not self.name or self.name == REST or not all(ch.isalnum() or ch in "-_" for ch in self.name):
            raise ValueError(f"leg class {self.name!r}: expected a name of letters, digits, '-' or '_', not {REST!r}")
        for what in (self.shape, self.guard):
            if not isinstance(what, Cond):
                raise TypeError(f"leg class {self.name!r}: {what!r} is not a condition of the guard language")


@dataclass(frozen=True, eq=False)
class MoveFamily:
    """The moves a rule set may make: its leg classes, the condition under which a robot stays, and the
    longest move (radii)."""

    name: str
    classes: tuple[LegClass, ...]
    max_step: Fraction
    at_rest: Cond = FALSE
    says: str = ""
    rests_on: str = ""
    """What the family takes from outside itself (written in each obligation's header): empty when nothing."""
    witnesses: dict[str, str] = field(default_factory=dict)
    """What each witness role of the guards stands for, in words."""
    lattice: bool = False
    """Whether the prover decides the family's obligations on the model's lattice (integers, exact: PROVED for
    every swarm size on that lattice) rather than over the reals (every position): for legs whose lengths the
    reals' nonlinear arithmetic does not decide in time (a sqrt(2)-long diagonal)."""
    rules_out: dict[str, str] = field(default_factory=dict)
    """``role -> class``: witness roles that speak of the robot ``o`` a guard's ``forall`` is instantiated at
    and show that o cannot move by ``class`` (a robot whose own guard forbids that leg: one in its path, say).
    The prover splits on each such existential only where o moves by that class (false, or its witness named:
    the ``.by.ROLE`` obligations) and takes it as unknown elsewhere (:mod:`fatline_verify.prove.smt.family`).
    Empty: every role is a bridge, as before."""
    order: tuple[Fraction, Fraction] | None = None
    """``(a, b)``: an order ``a x + b y`` (radii) of the robots, needed by a family whose guards have a
    :func:`~.lang.chain`: the prover's connectivity argument inducts over it (an edge with a mover above r is
    answered by the induction; :mod:`fatline_verify.prove.smt.family`)."""

    def __post_init__(self) -> None:
        if not self.classes:
            raise ValueError(f"move family {self.name!r}: expected at least one leg class")
        names = [c.name for c in self.classes]
        if len(set(names)) != len(names):
            raise ValueError(f"move family {self.name!r}: leg classes named twice in {names}")
        if Fraction(self.max_step) <= 0:
            raise ValueError(f"move family {self.name!r}: max_step={self.max_step!r}: expected a positive length")
        if roles(self.at_rest):
            raise ValueError(f"move family {self.name!r}: at_rest names a witness; expected a condition without one")
        chains = sorted({r for c in self.classes for r in chain_roles(c.guard)})
        if chains and (self.order is None or not any(Fraction(k) for k in self.order)):
            raise ValueError(
                f"move family {self.name!r}: its guards have chains {chains} but no order; expected order=(a, b), "
                "not both 0 (the induction of the connectivity argument)"
            )
        for role, cls in self.rules_out.items():
            if cls not in names:
                raise ValueError(
                    f"move family {self.name!r}: rules_out[{role!r}]={cls!r}: expected the name of one of its classes"
                )

    def get(self, name: str) -> LegClass:
        for c in self.classes:
            if c.name == name:
                return c
        raise KeyError(name)

    def held(self, seen: Sequence[Point], model: Any) -> bool:
        """Whether a robot seeing ``seen`` must stay."""
        return holds(self.at_rest, Ground(model, seen, {"me": (0, 0), "end": (0, 0)}))

    def classify(self, seen: Sequence[Point], destination: Point, model: Any) -> str | None:
        """The first class whose shape and guard admit a straight move to ``destination`` (relative) by a
        robot seeing ``seen``; :data:`REST` for a stay; ``None`` when no class admits it."""
        if destination == (0, 0):
            return REST
        g = Ground(model, seen, {"me": (0, 0), "end": destination})
        if holds(self.at_rest, g) or not self.within_step(destination, model):
            return None
        for c in self.classes:
            if holds(c.shape, g) and holds(c.guard, g):
                return c.name
        return None

    def admit(self, seen: Sequence[Point], decision: Any, model: Any) -> str | None:
        """Why ``decision`` (by a robot seeing ``seen``) leaves the family, or ``None`` when it is admitted."""
        if not decision.moves:
            return None
        path = tuple(decision.path)
        dest = decision.destination
        if path != ((0, 0), dest):
            return f"its path {list(path)} is not one straight leg from (0, 0) to {dest}"
        if self.classify(seen, dest, model) is not None:
            return None
        g = Ground(model, seen, {"me": (0, 0), "end": dest})
        if holds(self.at_rest, g):
            return "it must stay (the family's at_rest holds)"
        if not self.within_step(dest, model):
            return f"a move to {dest} is longer than the family's max_step ({self.max_step} radii)"
        shaped = [c.name for c in self.classes if holds(c.shape, g)]
        if not shaped:
            return f"no leg class has the shape of a move to {dest}"
        return f"a move to {dest} fails the guard of {', '.join(shaped)}"

    def longest(self, model: Any) -> int:
        """:attr:`max_step` squared, in lattice units squared."""
        v = Fraction(self.max_step) * model.radius
        return int(v * v) if (v * v).denominator == 1 else v * v  # type: ignore[return-value]

    def within_step(self, destination: Point, model: Any) -> bool:
        return dist2((0, 0), destination) <= self.longest(model)


FamilyOf = MoveFamily | Callable[[Any], MoveFamily | None]
"""What a rule set declares: a family, or a function of the model giving one (``None``: this model's
options leave the rule set without a family)."""


def family_of(declared: FamilyOf | None, model: Any) -> MoveFamily | None:
    """The family ``declared`` gives ``model``."""
    if declared is None or isinstance(declared, MoveFamily):
        return declared
    got = declared(model)
    if got is not None and not isinstance(got, MoveFamily):
        raise TypeError(f"family function {declared!r} gave {got!r}; expected a MoveFamily or None")
    return got


__all__ = ["REST", "FamilyOf", "LegClass", "MoveFamily", "family_of"]
