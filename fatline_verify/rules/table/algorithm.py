"""A synthesised table as a rule set: a robot looks up what it sees and takes that leg, or stays.

Not the paper's algorithm: a table ``fatline synth`` found (fatline_verify/synth/, docs/synth.md), an
oblivious rule from a robot's view (the robots within ``rad_v``, relative to it, sorted) to one leg of the
repaired family (``fatline reach``'s, under its lock) or to staying: a policy inside that move family
(:func:`family`), which ``fatline prove`` proves safe. The table was searched, and replayed
through the executable model, for the lattice (``q``), ``rad_v``, window, robot counts and scheduler its
file names; a view it was not searched for stays (``unseen``): beyond those bounds nothing is claimed.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ...errors import InvalidModel
from ...integrity import sealed
from ...synth.table import Table, parse_view
from ..decision import ORIGIN, Decision
from ..family.family import MoveFamily
from ..family.narrow import narrowed
from ..repaired.whatif import legs_family

TABLES = Path(__file__).resolve().parent / "tables"
"""The shipped tables: ``fatline synth --json`` files (one rule set each, ``table-<file stem>``)."""

LABELS = {
    "table-move": "the table's leg for what it sees",
    "table-stay": "the table has it stay",
    "table-unseen": "a view the table was not searched for: stays",
}
"""The rule labels :func:`decide` returns, read aloud."""


@dataclass(frozen=True)
class Shipped:
    """A table file and what it was searched for."""

    name: str
    table: Table
    summary: str
    legs: tuple[str, ...] = ()
    """The leg kinds it was searched over (``fatline synth --with``'s family: ``right``, ``vertical``, and the
    what-if ``left``, ``left-alone``, ``corner``)."""


def load(path: Path) -> Shipped:
    """The table of the last sat search of a ``fatline synth --json`` file (the most robot counts)."""
    data = json.loads(path.read_text(encoding="utf-8"))
    sealed(data, path)  # a digest that does not match is refused, naming the file
    sat = [s for s in data["searches"] if s["answer"] == "sat"]
    if not sat:
        raise InvalidModel(f"table {path}: no sat search in it; expected a fatline synth --json file with a table")
    last = sat[-1]
    lo, hi = last["robots"]
    w, h = data["window"]
    summary = (
        f"Not the paper: a table fatline synth found (docs/synth.md) -- legs {', '.join(data['legs'])}; "
        f"searched and replayed for {lo}..{hi} robots in {w}x{h} at q = {data['q']}, rad_v = {data['rad_v']}, "
        f"{data['scheduler']}; unseen views stay."
    )
    table = Table.from_json(int(data["q"]), int(data["rad_v"]), last["table"])
    return Shipped(f"table-{path.stem}", table, summary, tuple(data["legs"]))


def family(shipped: Shipped) -> Any:
    """The table's move family: the one ``fatline synth`` searched (its leg kinds, on the model's lattice,
    :func:`fatline_verify.rules.repaired.whatif.legs_family`), each class narrowed to the views the table moves
    by it (:func:`fatline_verify.rules.family.narrow.narrowed`). Every leg of the table is one the family admits
    from its view, and a view the table does not list stays: a table is a policy inside the family, so the
    family's safety obligations are the table's (``fatline prove``), and the checker's ``in-family`` holds
    each run to it. Narrowed, the obligations speak of the views the table plays only: the wider family's
    connectivity has configurations the table never plays, which no proof or counterexample decides."""
    made: dict[tuple[object, ...], MoveFamily] = {}

    def of(model: Any) -> MoveFamily:
        base = legs_family(model, shipped.legs)
        key = (id(base), model.radius)
        got = made.get(key)
        if got is None or got.name != f"{base.name}/{shipped.name}":
            got = made[key] = narrowed(base, shipped.table.legs, model, shipped.name)
        return got

    return of


def decider(shipped: Shipped) -> Any:
    """The decision function of a table (``decide(snapshot, model)``, lattice units)."""
    table = shipped.table
    known = set(table.legs)

    def decide(snapshot: Sequence[Any], model: Any) -> Decision:
        p = model.parameters
        if p.q != table.q or p.rad_v != table.rad_v:
            raise InvalidModel(
                f"rules={shipped.name}: q={p.q}, rad_v={p.rad_v}; expected q={table.q}, rad_v={table.rad_v} "
                "(the lattice the table was searched on)"
            )
        view = tuple(sorted((int(x), int(y)) for x, y in snapshot))
        end = table.action(view)
        if end == ORIGIN:
            rule = "table-stay" if view in known or not snapshot else "table-unseen"
            return Decision(rule, ORIGIN, (ORIGIN,), ())  # type: ignore[arg-type]
        return Decision("table-move", end, (ORIGIN, end), ())  # type: ignore[arg-type]

    return decide


__all__ = ["LABELS", "TABLES", "Shipped", "decider", "family", "load", "parse_view"]
