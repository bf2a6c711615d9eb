"""Moves off the lattice in the packed engines: what ``fast`` and ``compiled`` do with a rule set's
rational destination (:class:`OffLattice`: the checker hands the robot count to the ``scalar`` engine,
:func:`fatline_verify.check.checker.explore_robots`)."""

from __future__ import annotations

from fractions import Fraction
from typing import Any


class OffLattice(Exception):
    """A decision whose destination is off the model's lattice, met by an engine that packs moves as
    lattice integers (``fast``, ``compiled``). Not an error of the run: the checker hands the robot count
    to the ``scalar`` engine, which follows the executable model exactly (an off-lattice successor is
    judged on its step and counted, not explored), and says so in one line."""

    def __init__(self, engine: str, destination: object, rule: object) -> None:
        self.engine, self.destination, self.rule = engine, destination, rule
        super().__init__(
            f"rule {rule} decided {destination}, off the lattice: the {engine} engine packs lattice moves only"
        )


def lattice_move(engine: str, decision: Any) -> tuple[int, int]:
    """``decision``'s destination as lattice integers (an integral ``Fraction`` is one), or :class:`OffLattice`."""
    dest = decision.destination
    out = []
    for v in dest:
        if isinstance(v, int):
            out.append(v)
        elif isinstance(v, Fraction) and v.denominator == 1:
            out.append(int(v))
        else:
            raise OffLattice(engine, dest, decision.rule)
    return out[0], out[1]


__all__ = ["OffLattice", "lattice_move"]
