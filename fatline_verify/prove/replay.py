"""A solver's answer replayed by the executable model (:func:`replay`): the same case, the claim
broken, from an initial configuration or not; and an earlier run's counterexample replayed before
any search (:func:`replay_known`). Nothing is reported VIOLATED without this replay."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Any

from ..errors import InvalidTrace
from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.geometry import dist2
from ..model.numbers import Point, show_point
from ..model.options import Scheduler
from ..model.swarm import initial_problems
from ..rules.decision import Decision
from ..rules.paper.algorithm import Band
from ..rules.paper.cases import case_of
from ..schedulers.activation import scheduler_for
from ..schedulers.round import Collision, decide_all, lost_edges, play_round
from ..trace.simulate import Outcome, Run, outcome_after
from ..trace.traces import initial_radii, replayed_document
from .smt.claims import (
    CLOSER,
    ON_RMA,
    ONE_MOVER,
    SEEN,
    TWO_MOVERS,
    X_NONDECREASING,
    Spec,
)


@dataclass
class Replayed:
    """A solver answer turned into a configuration and checked by the executable model."""

    state: tuple[Point, ...]
    """Lattice units, r first."""
    focus: int | None
    initial: bool
    problems: list[str]
    doc: dict[str, Any] | None
    what: str


def _state(model: Model, positions: dict[str, tuple[Fraction, Fraction]], focus: str) -> tuple[list[Point], int | None]:
    """The distinct robots named (equal centres are one robot), r first, and the focus's index."""
    points: list[Point] = []
    for name in ["r", *[n for n in positions if n != "r"]]:
        p = model.to_lattice(positions[name])
        if p not in points:
            points.append(p)
    index = points.index(model.to_lattice(positions[focus])) if focus else None
    return points, index


def replay(model: Model, spec: Spec, positions: dict[str, tuple[Fraction, Fraction]], focus: str) -> Replayed | str:
    """Replay a solution: the state, r's case, the claim; or why it does not reproduce."""
    points, j = _state(model, positions, focus)
    state = tuple(points)
    decisions = decide_all(state, model)
    got = case_of(decisions[0], model)
    if got not in spec.mine:
        return f"r decides {got.name}, not {spec.name}"
    problems = initial_problems(state, model)
    initial = not problems
    form = spec.form
    if form in (SEEN, ON_RMA, X_NONDECREASING, CLOSER):
        dec = decisions[0]
        if spec.repair:
            moved = _repair_destination(model, spec.repair, state, dec)
            if isinstance(moved, str):
                return moved
            dec = replace(dec, destination=moved)
        what = _claim_fails(model, spec, state, dec, j)
        if what is None:
            return "the claim holds on the replayed configuration"
        return Replayed(state, j, initial, problems, None, what)
    assert j is not None
    other = case_of(decisions[j], model)
    fsync = model.options.scheduler is Scheduler.FSYNC
    if form == TWO_MOVERS and other not in spec.other:
        return f"the second robot decides {other.name}, not one of {spec.other_name}"
    if form == ONE_MOVER and fsync and other not in spec.other:
        return f"the robot at rest decides {other.name}, and moves"
    active = list(range(len(state))) if fsync else [0, j] if form == TWO_MOVERS else [0]
    if scheduler_for(model).forbids(tuple(active), len(state)) is not None:
        return f"activation {active} is not a round of the scheduler"
    result = play_round(state, active, model, decisions)
    if spec.lemma is Lemma.NO_COLLISION:
        hit = [v for v in result.violations if isinstance(v, Collision) and v.robots == (0, j)]
        if not hit:
            return f"r and robot {j} do not collide in the replayed round"
        focus_lemma, what = Lemma.NO_COLLISION, "collision"
    else:
        if not any(pair == (0, j) for pair, _ in lost_edges(result.before, result.after, model)):
            return f"r and robot {j} keep their edge in the replayed round"
        split = any(v.lemma == Lemma.CONNECTIVITY for v in result.violations)
        focus_lemma = Lemma.CONNECTIVITY if split else Lemma.CONNECTIVITY_EDGE
        what = "an edge is lost and the graph splits" if split else "an edge is lost (the graph stays connected)"
    run = Run(model, state, (result,), outcome_after(result.after, result, model) or Outcome.ROUND_LIMIT)
    origin = {"tool": "fatline prove", "lemma": spec.lemma, "form": form, "case": spec.name}
    if spec.other_name:
        origin["other"] = spec.other_name
    doc = replayed_document(run, origin, focus_lemma)
    return Replayed(state, j, initial, problems, doc, what)


def _repair_destination(model: Model, repair: str, state: Sequence[Point], dec: Decision) -> Point | str:
    """Where the repaired rules' own destination takes r in ``state`` (r deciding ``dec`` by the paper's
    rules), by the rules' own functions; or why it does not move r."""
    from ..rules.repaired.algorithm import align_destination, approach_destination
    from ..schedulers.round import snapshot

    if repair == "align":
        got = align_destination(snapshot(state, 0, model))
    elif repair == "approach":
        got = approach_destination(dec, model)
    else:
        return f"the repair {repair}'s moves are not replayed on their own (they depend on the legs allowed)"
    return f"the repair {repair} does not move r in the replayed configuration" if got is None else got


Known = tuple[str, dict[str, Any]]
"""A counterexample to replay before any search: where it was found (as the reason will say), and its
trace, or for a claim without a trace ``{"configuration": [...]}``."""


def replay_known(model: Model, spec: Spec, doc: dict[str, Any], *, initial: bool = True) -> Replayed | None:
    """An earlier run's counterexample of ``spec`` (its trace file, or for a claim without a trace its
    results row's ``configuration``), replayed by the executable model as the search would replay a
    solver's answer: the same case, the same claim broken, from an initial configuration; ``None`` if
    it does not (the readings changed, say), and the search runs. ``initial=False`` also returns a
    violation from a configuration that is not initial (an earlier INCONCLUSIVE row's trace)."""
    if "configuration" in doc:
        return _replay_configuration(model, spec, doc["configuration"], doc.get("focus"))
    try:
        state = initial_radii(doc)
        j = int(doc["violation"]["robots"][1])
    except (KeyError, IndexError, TypeError, ValueError, InvalidTrace):
        return None
    if not 0 < j < len(state):
        return None
    focus = "s" if spec.form == TWO_MOVERS else "o"
    positions = {"r": state[0], **{f"x{k}": p for k, p in enumerate(state[1:], 1) if k != j}, focus: state[j]}
    got = replay(model, spec, {k: (Fraction(x), Fraction(y)) for k, (x, y) in positions.items()}, focus)
    return got if isinstance(got, Replayed) and (got.initial or not initial) and got.doc is not None else None


def _replay_configuration(model: Model, spec: Spec, configuration: Any, focus: Any = None) -> Replayed | None:
    """A trace-less counterexample (``x,y`` strings in lattice units, r first) replayed; for ``closer``
    each other robot is tried as the one r does not get closer to (``focus``, its index, first if
    given: the replay puts it last, so a configuration replayed with its last robot first keeps its order)."""
    try:
        raw = [tuple(Fraction(v) for v in str(p).split(",")) for p in configuration]
    except (TypeError, ValueError, ZeroDivisionError):
        return None
    if not raw or any(len(p) != 2 for p in raw):
        return None
    points = [model.from_lattice((p[0], p[1])) for p in raw]
    r = points[0]
    others = {f"x{k}": (Fraction(p[0] - r[0]), Fraction(p[1] - r[1])) for k, p in enumerate(points[1:], 1)}
    focuses = list(others) if spec.form == CLOSER else [""]
    first = f"x{focus}" if isinstance(focus, int) and not isinstance(focus, bool) else ""
    if first in focuses:
        focuses.remove(first)
        focuses.insert(0, first)
    for focus in focuses:
        positions = {"r": (Fraction(0), Fraction(0)), **others}
        if focus:
            positions["o"] = positions.pop(focus)
        got = replay(model, spec, positions, "o" if focus else "")
        if isinstance(got, Replayed) and got.initial:
            return got
    return None


def _claim_fails(model: Model, spec: Spec, state: Sequence[Point], dec: Decision, j: int | None) -> str | None:
    """How r's decision breaks a per-rule claim on ``state`` (``None`` if it does not)."""
    dx, dy = dec.destination
    dest = show_point(model.from_lattice(dec.destination))
    if spec.form == X_NONDECREASING:
        return f"r moves to {dest}: x decreases" if dx < 0 else None
    if spec.form == ON_RMA:
        right_most = all(p[0] <= state[0][0] for p in state)
        leaves = right_most and dx != 0
        return f"r is on the right-most axis and moves to {dest}: it leaves the axis" if leaves else None
    if spec.form == SEEN:
        seen = [c for c, _ in dec.classification]
        if dx > 0 and all(c[0] < dx for c in seen):
            return f"r moves to {dest}, right of itself and of every robot it sees"
        return None
    assert j is not None
    rel = (state[j][0] - state[0][0], state[j][1] - state[0][1])
    bands = dict(dec.classification).get(rel, frozenset())
    if bands & {Band.B, Band.C, Band.D} and dist2(rel, (dx, dy)) >= dist2(rel, (0, 0)):
        where = show_point(model.from_lattice(rel))
        return f"r moves to {dest} and is not closer to the robot at {where} in {'/'.join(sorted(bands))}"
    return None
