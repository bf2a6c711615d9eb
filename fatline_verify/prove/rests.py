"""What a lemma-level PROVED rests on (:attr:`fatline_verify.prove.coverage.LemmaVerdict.rests_on`): its
obligation rows by form and basis, the facts about the code it assumes and how each is checked (as Pactole
lists the assumptions of each final theorem), the lattice it was proved on, the rounds, the rule set and
the solver with its version."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..model.config import Model
from ..rules import registry
from .basis import counts_text


@dataclass(frozen=True)
class Fact:
    """A fact about the rules' code that a lemma's argument uses and no obligation of its proves: what it
    says and how it is checked (exhaustively over every view at q = 1, by a test, by inspection)."""

    name: str
    says: str
    checked: str


_LATTICE = re.compile(r"lattice q ?= ?(\d+)")


def lattices(rows: Sequence[dict[str, Any]]) -> str:
    """Where PROVED ``rows`` were proved: over the reals (every real configuration), on the lattice
    q = k (a per-lattice argument: the verdict is for that lattice only), or both."""
    qs = sorted({int(m.group(1)) for r in rows if (m := _LATTICE.search(str(r.get("reason", ""))))})
    reals = any(not _LATTICE.search(str(r.get("reason", ""))) for r in rows)
    parts = (["over the reals (every lattice)"] if reals else []) + [f"on the lattice q = {q} only" for q in qs]
    return "; ".join(parts) or "no rows"


def solver() -> str:
    """The solver the rows were decided by, with its version (read without importing it)."""
    from importlib import metadata

    try:
        return f"z3 {metadata.version('z3-solver')}"
    except metadata.PackageNotFoundError:  # pragma: no cover - z3 is a dependency
        return "z3 (version unknown)"


def rests_on(
    model: Model, rows: Sequence[dict[str, Any]], facts: Sequence[Fact] = (), more: Sequence[str] = ()
) -> tuple[str, ...]:
    """What a lemma-level PROVED rests on: its obligation rows (by form and basis), the facts assumed and
    how each is checked, the lattice, the scheduler and motion, the solver, and ``more`` (other lemmas)."""
    forms = ", ".join(f"{n} {f}" for f, n in _form_counts(rows).items())
    split = f"; {counts_text(list(rows))}" if any(r.get("basis") for r in rows) else ""
    out = [f"obligations: {len(rows)} PROVED ({forms}{split})"]
    out += [f"assumed: {f.name}: {f.says} (checked: {f.checked})" for f in facts]
    out += list(more)
    out += [
        f"lattice: {lattices(rows)}",
        f"rounds: scheduler {model.options.scheduler}, motion {model.options.motion}, timing {model.options.timing}; "
        "one shared snapshot per round, exact arithmetic, unit discs",
        f"rule set: {model.rules} ({registry.of(model).summary.rstrip('.')})",
        f"solver: {solver()}",
    ]
    return tuple(out)


def _form_counts(rows: Sequence[dict[str, Any]]) -> dict[str, int]:
    out: dict[str, int] = {}
    for r in rows:
        out[str(r.get("form"))] = out.get(str(r.get("form")), 0) + 1
    return out


__all__ = ["Fact", "lattices", "rests_on", "solver"]
