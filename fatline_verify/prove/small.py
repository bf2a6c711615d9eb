"""Small swarms, enumerated: a counterexample of a per-case obligation looked for among every initial
configuration of a few robots on a lattice, by the executable model alone (no solver).

The solver searches the obligation's named robots (r, its witnesses, the robot the claim is about),
up to a dozen of them, each anywhere; a counterexample where most roles fall on the same few robots
can lie beyond its budget though a handful of robots on a coarse lattice show it. This step is the
checker's idea applied to one decision case: every initial configuration of 2 to ``n`` robots in a
window of the lattices of :data:`SMALL` (:func:`fatline_verify.check.initial.initial_array`: up to
translation, each once), every robot of it as r; where r's decision falls in the obligation's case,
the claim is tested on that configuration, and a hit is replayed by :func:`~fatline_verify.prove.replay.replay`
exactly as a solver's answer would be. It finds nothing where the claim holds, whatever the size, so
it runs only for obligations the first round left open (:func:`fatline_verify.prove.search.prove_spec`).
What it searched is bounded and says so; only a find is a verdict.
"""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction

from ..errors import InvalidModel
from ..model.config import Model
from ..model.numbers import Point
from ..model.options import Scheduler
from ..rules.paper.cases import case_of
from ..schedulers.round import Collision, decide_all, lost_edges, play_round
from .replay import Replayed, replay
from .smt.claims import CLOSER, ONE_MOVER, TWO_MOVERS, Spec

SMALL: tuple[tuple[int, int, tuple[int, int]], ...] = ((1, 4, (9, 9)), (2, 4, (9, 9)))
"""``(q, robots, window)``: the lattice ``x = X / q``, the largest swarm, the window in lattice points.
Measured on ``paper`` (this machine): q = 1, 2-4 robots, about 0.3 s; q = 2, 2-4 robots in 9x9
(4 radii a side; 10,750 configurations of 4 robots), about 2 s. At q = 2 with 5 robots in 11x11
(636,204 configurations) it takes 3 minutes: beyond what one obligation should spend."""

SMALL_TEXT = " and ".join(f"2 to {n} robots in {w[0]}x{w[1]} at q={q}" for q, n, w in SMALL)
"""How a reason names what was enumerated."""


def _swarms(model: Model) -> Iterator[tuple[int, Model, tuple[Point, ...]]]:
    """Every initial configuration of :data:`SMALL`, lattice by lattice in its order and fewest robots
    first on each: ``(q, model at q, state)``; a lattice the model's ``rad_v`` is not whole on is left out."""
    from ..check.initial import initial_array

    for q, most, window in SMALL:
        try:
            mq = model.with_q(q)
        except InvalidModel:  # rad_v * q not an integer (rad_v = 7/2 at q = 1)
            continue
        for n in range(2, most + 1):
            for row in initial_array(n, window, mq):
                yield q, mq, tuple((int(x), int(y)) for x, y in row)


def _focuses(spec: Spec, mq: Model, state: tuple[Point, ...], i: int, decisions: dict) -> list[int]:  # type: ignore[type-arg]
    """The robots worth replaying as the claim's other robot when ``i`` is r (one-mover: those r's
    round alone collides with or loses; two movers: those deciding one of ``spec.other``), or
    ``[-1]`` for a claim about r alone."""
    others = [j for j in range(len(state)) if j != i]
    if spec.form == CLOSER:
        return others
    if spec.form == TWO_MOVERS:
        return [j for j in others if case_of(decisions[j], mq) in spec.other]
    if spec.form != ONE_MOVER:
        return [-1]
    if mq.options.scheduler is Scheduler.FSYNC:
        return others
    result = play_round(state, [i], mq, decisions)
    hit = {v.robots[0] + v.robots[1] - i for v in result.violations if isinstance(v, Collision) and i in v.robots}
    hit |= {a + b - i for (a, b), _ in lost_edges(result.before, result.after, mq) if i in (a, b)}
    return sorted(hit)


def in_state(model: Model, spec: Spec, at: Model, state: tuple[Point, ...]) -> Replayed | None:
    """A counterexample of ``spec`` in ``state`` (lattice units of ``at``, the same model on its own
    lattice): the first robot, as r, that decides ``spec``'s case and breaks its claim from an initial
    configuration, replayed under ``model``; ``None`` if none does."""
    q = at.parameters.q
    decisions = decide_all(state, at)
    for i, decision in decisions.items():
        if case_of(decision, at) not in spec.mine:
            continue
        r = state[i]
        rel = {j: (Fraction(p[0] - r[0]) / q, Fraction(p[1] - r[1]) / q) for j, p in enumerate(state) if j != i}
        for j in _focuses(spec, at, state, i, decisions):
            focus = "" if j < 0 else "s" if spec.form == TWO_MOVERS else "o"
            positions = {"r": (Fraction(0), Fraction(0)), **{f"x{k}": p for k, p in rel.items() if k != j}}
            if j >= 0:
                positions[focus] = rel[j]
            got = replay(model, spec, positions, focus)
            if isinstance(got, Replayed) and got.initial:
                return got
    return None


def small_swarm_counterexample(model: Model, spec: Spec) -> tuple[Replayed, int] | None:
    """The first configuration of :data:`SMALL` (in enumeration order) in which some robot, as r,
    decides ``spec``'s case and breaks its claim from an initial configuration, replayed under
    ``model``; with the lattice it was found on. ``None`` if there is none."""
    for q, mq, state in _swarms(model):
        got = in_state(model, spec, mq, state)
        if got is not None:
            return got, q
    return None


def given_counterexample(model: Model, spec: Spec, radii: tuple[Point, ...]) -> Replayed | None:
    """A configuration given by hand (``fatline prove --known``: a trace's initial positions, in radii),
    every robot tried as r, as :func:`in_state` does."""
    state = tuple(model.to_lattice(p) for p in radii)
    return in_state(model, spec, model, state)


__all__ = ["SMALL", "SMALL_TEXT", "given_counterexample", "in_state", "small_swarm_counterexample"]
