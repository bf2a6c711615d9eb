"""What ``fatline synth`` prints and writes (:mod:`.encode` searches, :mod:`.certificate` checks)."""

from __future__ import annotations

from typing import Any

from ..integrity import seal
from ..model.config import Model, model_to_mapping
from ..model.numbers import format_number
from ..outputs import Kind as OutputKind
from ..repair.reach import PROVED, Kind, State, what_if_text
from .certificate import Certificate
from .encode import SynthResult


def radii(model: Model, state: State) -> str:
    """A configuration as ``--init`` text, in radii."""
    return " ".join(",".join(str(format_number(v)) for v in model.from_lattice(p)) for p in state)


def counts_text(r: SynthResult) -> str:
    """``3`` or ``2..4``: the robot counts one table was searched for."""
    c = r.counts
    return str(r.n) if len(c) == 1 else f"{c.start}..{r.n}"


def kinds_text(kinds: frozenset[Kind], model: Model) -> str:
    proved = [k.value for k in Kind if k in PROVED]
    return ", ".join(proved) + what_if_text(kinds, model)


def synth_lines(
    model: Model, ref: str, results: list[tuple[SynthResult, Certificate]], *, shown: int = 10
) -> list[str]:
    """One row per robot count, then each unsat core replayed and each sat table's replay."""
    if not results:
        return []
    first = results[0][0]
    w, h = first.window
    lines = [
        f"model {model.describe()}",
        "tables: a robot's view (what it sees within rad_v, relative to it) -> one leg of "
        f"{kinds_text(first.kinds, model)} (fatline reach's family, under its lock), or stay",
        f"scheduler: {first.scheduler.value}; initial configurations: every one in a {w}x{h} window of lattice "
        f"points; live: every execution the scheduler allows (no fairness assumed) reaches one vertical, every "
        f"round safe; solver {first.solver} (python-sat)",
        "",
        "one table for every robot count of a row (a robot does not know how many there are)",
        "",
        f"{'robots':>6}  {'initial':>8}  {'answer':<6}  {'states':>7}  {'views':>6}  {'vars':>7}  {'clauses':>8}  "
        f"{'refined':>7}  {'seconds':>7}",
    ]
    for r, _ in results:
        s = r.stats
        lines.append(
            f"{counts_text(r):>6}  {r.initial:>8,}  {'SAT' if r.sat else 'UNSAT':<6}  {s.states:>7,}  {s.views:>6,}  "
            f"{s.variables:>7,}  {s.clauses:>8,}  {s.refinements:>7,}  {s.seconds:>7.1f}"
        )
    q = f" --q {model.parameters.q}" if model.parameters.q != 1 else ""
    for r, cert in results:
        lines.append("")
        if r.sat:
            assert r.table is not None and cert.replay is not None
            rp = cert.replay
            verdict = (
                "replayed: every round safe, every execution on a line"
                if not rp.problems
                else (f"REPLAY FAILED: {rp.problems[0]}")
            )
            moving = sum(e != (0, 0) for e in r.table.legs.values())
            lines.append(
                f"{counts_text(r)} robots: SAT, a table of {moving:,} moving views (of {len(r.table.legs):,} the "
                f"table's own executions meet); {verdict} (executable model: {rp.states:,} configurations, "
                f"{rp.rounds_played:,} rounds played, at most {rp.rounds} rounds to a line)"
            )
            continue
        which = (
            "this initial configuration"
            if len(r.core) == 1
            else f"these {len(r.core)} initial configurations together (each is needed)"
        )
        lines.append(f"{counts_text(r)} robots: UNSAT -- no table of these legs is safe and live from {which}:")
        for row in cert.core[:shown]:
            planner = (
                f"a line in {row.planner} rounds by the family (replayed)"
                if row.planner is not None
                else "no line reachable by any rounds of the family"
            )
            alone = "a table exists for it alone" if row.alone else "no table for it alone"
            lines.append(f'  fatline simulate {ref}{q} --init "{radii(model, row.state)}"   # {planner}; {alone}')
        if cert.again:
            lines.append(f"  the core solved again from a fresh encoding by {cert.again}: UNSAT")
    return lines


def synth_to_json(model: Model, results: list[tuple[SynthResult, Certificate]]) -> dict[str, Any]:
    """The results as plain data (``--json``), sealed with their digest: each sat table's moving views in
    lattice units (``q`` and ``rad_v`` given), each unsat core in lattice units and radii."""
    first = results[0][0]
    out: dict[str, Any] = {
        "format": OutputKind.SYNTH.value,
        "model": model_to_mapping(model),
        "q": model.parameters.q,
        "rad_v": str(format_number(model.parameters.rad_v)),
        "legs": sorted(k.value for k in first.kinds),
        "scheduler": first.scheduler.value,
        "window": list(first.window),
        "solver": first.solver,
        "searches": [],
    }
    for r, cert in results:
        s = r.stats
        row: dict[str, Any] = {
            "robots": [r.counts.start, r.n],
            "initial": r.initial,
            "answer": "sat" if r.sat else "unsat",
            "states": s.states,
            "views": s.views,
            "variables": s.variables,
            "clauses": s.clauses,
            "refinements": s.refinements,
            "cycle_clauses": s.cycles,
            "several_mover_rounds": s.multi,
            "seconds": round(s.seconds, 2),
        }
        if r.table is not None and cert.replay is not None:
            row["table"] = r.table.to_json()
            row["replay"] = {
                "configurations": cert.replay.states,
                "rounds_played": cert.replay.rounds_played,
                "most_rounds_to_line": cert.replay.rounds,
                "problems": cert.replay.problems,
            }
        else:
            row["core"] = [
                {
                    "lattice": [list(p) for p in c.state],
                    "radii": radii(model, c.state),
                    "planner_rounds": c.planner,
                    "table_alone": c.alone,
                }
                for c in cert.core
            ]
            row["core_again"] = cert.again
        out["searches"].append(row)
    return seal(out)


__all__ = ["radii", "synth_lines", "synth_to_json"]
