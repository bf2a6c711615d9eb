"""A synthesised rule table: a robot's view to the leg it takes (or staying), and its file form.

A *view* is what a robot sees (:func:`fatline_verify.schedulers.round.snapshot`: the robots within
``rad_v``, relative to itself, lattice units), sorted, so two robots that see the same set of robots
decide the same: the robots are oblivious and anonymous. A view missing from a table stays.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from ..model.numbers import Point
from ..schedulers.round import snapshot

View = tuple[Point, ...]
ORIGIN: Point = (0, 0)
FORMAT = "fatline-synth-table"


def view_of(state: Sequence[Point], i: int, model: Any) -> View:
    """Robot ``i``'s view of ``state``: the robots it sees relative to it, sorted (its canonical form)."""
    return tuple(sorted(snapshot(state, i, model)))


@dataclass(frozen=True)
class Table:
    """The end of each view's leg (relative to the robot, lattice units); views not listed stay."""

    q: int
    rad_v: int
    legs: dict[View, Point] = field(default_factory=dict)

    def action(self, view: View) -> Point:
        """Where a robot seeing ``view`` goes, relative to itself (``(0, 0)``: it stays)."""
        return self.legs.get(view, ORIGIN)

    def to_json(self) -> dict[str, str]:
        """The moving views as ``{"x,y x,y ...": "dx,dy"}`` (lattice units; the view's robots sorted)."""
        return {view_text(v): f"{end[0]},{end[1]}" for v, end in sorted(self.legs.items()) if end != ORIGIN}

    @classmethod
    def from_json(cls, q: int, rad_v: int, rows: dict[str, str]) -> Table:
        """The inverse of :meth:`to_json`."""
        return cls(q, rad_v, {parse_view(v): parse_view(end)[0] for v, end in rows.items()})


def view_text(view: View) -> str:
    """``"x,y x,y"``: a view as text (its points in order)."""
    return " ".join(f"{x},{y}" for x, y in view)


def parse_view(text: str) -> View:
    """The inverse of :func:`view_text` (``""``: the empty view)."""
    return tuple((int(a), int(b)) for a, b in (tok.split(",") for tok in text.split()))


__all__ = ["FORMAT", "Table", "View", "parse_view", "view_of", "view_text"]
