"""What ``fatline reach`` prints and writes (:mod:`fatline_verify.repair.reach` computes it)."""

from __future__ import annotations

from typing import Any

from ..model.config import Model, model_to_mapping
from ..model.numbers import format_number
from ..outputs import Kind as OutputKind
from ..text import plural
from .reach import PROVED, Kind, State, alone, what_if_text
from .search import ReachResult


def _radii(model: Model, state: State) -> str:
    """A state as ``--init`` text, in radii."""
    return " ".join(",".join(str(format_number(v)) for v in model.from_lattice(p)) for p in state)


def _point_list(model: Model, state: State) -> list[list[str]]:
    return [[str(format_number(v)) for v in model.from_lattice(p)] for p in state]


def _kinds_text(kinds: frozenset[Kind], model: Model) -> str:
    proved = ", ".join(k.value for k in Kind if k in PROVED)
    text = f"{proved} (the classes fatline prove proves safe: fatline_verify/rules/repaired/family.py)"
    return text + what_if_text(kinds, model)


def _simulate(model: Model, ref: str, state: State) -> str:
    q = f" --q {model.parameters.q}" if model.parameters.q != 1 else ""
    return f'fatline simulate {ref}{q} --init "{_radii(model, state)}"'


def reach_lines(
    model: Model,
    ref: str,
    kinds: frozenset[Kind],
    window: tuple[int, int],
    results: list[ReachResult],
    *,
    shown: int,
) -> list[str]:
    """The table, then the stuck configurations (the first ``shown`` per robot count, each as a
    ``fatline simulate`` command on ``ref``, the model as the user named it), then what was checked."""
    w, h = window
    q = model.parameters.q
    radii = (
        f"{format_number(model.from_lattice((w - 1, h - 1))[0])}x{format_number(model.from_lattice((w - 1, h - 1))[1])}"
    )
    lines = [
        f"model {model.describe()}",
        f"legs: {_kinds_text(kinds, model)}, each {'one lattice unit' if q == 1 else f'1 to {q} lattice units'} "
        "long per axis (one radius at most), right no farther than the greatest x the mover sees; in a round, any "
        "set of robots the lock lets move, each any of its legs",
        f"initial configurations: every one in a {w}x{h} window of lattice points ({radii} radii), up to translation",
        "",
        f"{'robots':>6}  {'initial':>9}  {'line, 1 mover':>13}  {'line, any':>9}  {'stuck':>7}  "
        f"{'every algorithm':>15}  states",
    ]
    for r in results:
        lines.append(
            f"{r.n:>6}  {r.initial:>9,}  {r.one_mover:>13,}  {r.reached:>9,}  {len(r.stuck):>7,}  "
            f"{len(r.universal) if alone(model) else '-':>15}  {r.states[0]:,} + {r.states[1]:,}"
        )
    stuck = [r for r in results if r.stuck]
    if stuck:
        lines += [
            "",
            "STUCK: from these initial configurations no state on one vertical is reachable by any rounds of these "
            "legs, so no rule set whose moves are these legs on this lattice (oblivious or not) brings them to a "
            "line:",
        ]
        for r in stuck:
            more = f" (first {shown}; --json lists all)" if len(r.stuck) > shown else ""
            configurations = plural(len(r.stuck), "configuration")
            lines.append(f"  {r.n} robots, {configurations}{more}:")
            lines += [f"    {_simulate(model, ref, s)}" for s in r.stuck[:shown]]
    else:
        lines += ["", "every initial configuration reaches a line by some rounds of these legs"]
    universal = [r for r in results if r.universal]
    if universal:
        lines += [
            "",
            "DEADLOCKED FOR EVERY ALGORITHM of oblivious robots that do not know their number, whose moves are "
            f"straight, at most one radius long and on this lattice, under {model.options.scheduler} (whatever its "
            "lock, rules or legs): each robot sees what it would see alone with the robots it sees (a legal swarm), "
            "and there every such move of it, it alone active, collides or splits the swarm; an algorithm that never "
            "does either keeps every robot of these still:",
        ]
        for r in universal:
            lines += [f"  {r.n} robots: {_simulate(model, ref, s)}" for s in r.universal[:shown]]
    elif not alone(model):
        lines += [
            "",
            f"deadlocks for every algorithm: not looked for under {model.options.scheduler}, where no robot "
            "is ever activated alone",
        ]
    unsafe = sum(r.unsafe for r in results)
    lines += [
        "",
        f"every round was first played through the executable model's collision, connectivity and RMA checks: "
        f"{unsafe:,} failed them (counted, not followed)",
    ]
    if stuck:
        confirmed = sum(r.confirmed for r in results)
        again = sum(r.confirmed_configurations for r in results)
        total = sum(len(r.stuck) for r in results)
        which = (
            "each stuck configuration was"
            if again == total
            else f"{again:,} of the {total:,} stuck configurations (evenly spread; --verify: all) were"
        )
        lines.append(
            f"{which} searched again on its own with every set of movers ({confirmed:,} states, no line among them)"
        )
    replayed = [r.replayed for r in results if r.replayed is not None]
    if replayed:
        rounds = plural(sum(replayed), "round")
        lines.append(
            f"a shortest way to a line from every other configuration was replayed by fatline_verify.schedulers.round."
            f"play_round ({rounds}: every leg one of the mover's, no collision, the graph connected, the RMA kept)"
        )
    lines.append(
        "Bounds: the initial configurations of the window; the rounds are not bounded (the legs keep the swarm "
        "connected, so finitely many states are reachable up to translation)."
    )
    return lines


def reach_to_json(
    model: Model, kinds: frozenset[Kind], window: tuple[int, int], results: list[ReachResult]
) -> dict[str, Any]:
    """The results as plain data (``--json``): every stuck configuration in radii."""
    return {
        "format": OutputKind.REACH.value,
        "model": model_to_mapping(model),
        "legs": sorted(k.value for k in kinds),
        "window": list(window),
        "searches": [
            {
                "robots": r.n,
                "initial": r.initial,
                "line_one_mover": r.one_mover,
                "line_any_movers": r.reached,
                "states": list(r.states),
                "confirmed_states": r.confirmed,
                "confirmed_configurations": r.confirmed_configurations,
                "unsafe_rounds": r.unsafe,
                **({"replayed_rounds": r.replayed} if r.replayed is not None else {}),
                "stuck": [_point_list(model, s) for s in r.stuck],
                **(
                    {
                        "deadlocked_for_every_algorithm_of_one_radius_lattice_moves": [
                            _point_list(model, s) for s in r.universal
                        ]
                    }
                    if alone(model)
                    else {}
                ),
            }
            for r in results
        ],
    }
