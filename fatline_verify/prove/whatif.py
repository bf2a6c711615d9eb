"""``fatline prove MODEL --with left,corner``: the what-if legs' obligations
(:mod:`fatline_verify.prove.smt.whatif`), decided on the model's lattice and replayed by ``reach``.

Not the shipped obligations: ``fatline prove repaired`` without ``--with`` is unchanged, and these
rows go to their own file (``OUT/MODEL/whatif-KINDS-qQ.json``, the ``.smt2`` files under
``OUT/MODEL/whatif-KINDS-qQ/``).

1. **Vacuity**: if the two legs cannot occur together, PROVED ("never occur together").
2. ``unsat``: PROVED for every swarm size on the lattice (the header's argument).
3. ``sat``: the named robots at the answer's lattice points are a swarm; the answer is a
   counterexample (VIOLATED) only if, replayed by the family of ``fatline reach --with`` with these
   legs (:class:`fatline_verify.repair.reach.Family`: each mover's leg one of the legs its own view
   allows, the round played by :func:`fatline_verify.schedulers.round.play_round`), the swarm was
   connected and collision-free before and the round breaks the claim. Otherwise INCONCLUSIVE,
   with what the replay found (the obligation's conditions are weaker than the family's tests).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.numbers import Point
from ..model.swarm import initial_problems, is_connected
from ..repair.reach import PROVED as PROVED_KINDS
from ..repair.reach import Family, Kind, left_alone_reach
from ..rules.decision import ORIGIN, Decision
from ..rules.paper.algorithm import Rule
from ..rules.repaired.options import RepairProgress
from ..schedulers.round import closest_dist2, collides, disconnection, lost_edges, play_round, snapshot
from .search import Budget, rounds, rounds_text
from .smt.whatif import BRIDGES, KEPT, REST, VERTICAL_BRIDGE, WhatIfSpec, argument, arith, build, whatif_specs

VACUITY_SHARE = 0.05
PROVED_ON = "unsat on the lattice q = {q}: holds for swarms of every size on it (the header's argument)"
WITNESSED = (
    ", once the robot each mover's leg needs it to see is named (below a top-corner, above a bottom, right of a "
    "left or horizontal leg)"
)
EXTRA = 2
WITNESS_SHARE = 0.6
"""The share of what is left of the budget, once an answer is not replayed, for the obligation with each
mover's witness named (a proof); the rest goes to the searches for a counterexample the replay accepts."""
"""Robots at rest added to the named ones when looking for a counterexample the replay accepts."""


@dataclass
class WhatIfResult:
    """One what-if obligation's verdict."""

    spec: WhatIfSpec
    verdict: Verdict
    reason: str
    seconds: float
    smt2: str = ""
    state: tuple[Point, ...] = ()
    """The replayed swarm (lattice units; r, o, b), when the solver found an assignment."""
    moves: tuple[tuple[int, Point], ...] = ()
    """The replayed round: each mover's index and its leg's end, relative (lattice units)."""
    header: str = field(default="", repr=False)

    def row(self) -> dict[str, Any]:
        s = self.spec
        return {
            "key": s.key,
            "lemma": str(s.lemma),
            "form": s.form,
            "case": s.mine,
            "other": s.other,
            "q": s.q,
            "with": sorted(s.kinds),
            "verdict": str(self.verdict),
            "reason": self.reason,
            "seconds": round(self.seconds, 3),
            "smt2": self.smt2,
            "state": [list(p) for p in self.state],
            "moves": [[i, list(end)] for i, end in self.moves],
            **({"left_alone_units": s.left_units} if "left-alone" in s.kinds else {}),
        }


def prove_whatif(model: Model, spec: WhatIfSpec, *, timeout: float, out: Path | None) -> WhatIfResult:
    """Decide one what-if obligation; write its lattice form (with its argument) under ``out``."""
    from .smt.solving import write

    full = build(arith(spec), model, spec)
    full.comment = argument(model, spec, full)
    path = ""
    if out is not None:
        target = out / str(spec.lemma) / f"{spec.key.split('/', 1)[1].replace('@', '.')}.smt2"
        write(full, target)
        path = target.as_posix()
    spend = Budget(timeout)
    t0 = time.monotonic()
    fires, last = False, "budget exhausted"

    def result(verdict: Verdict, reason: str, state: tuple[Point, ...] = (), moves: Any = ()) -> WhatIfResult:
        return WhatIfResult(spec, verdict, reason, time.monotonic() - t0, path, state, tuple(moves), full.comment)

    for budget in rounds(timeout):
        if not fires:
            ans = spend.solve(build(arith(spec), model, spec, vacuity=True), budget * VACUITY_SHARE)
            if ans.status == "unsat":
                return result(Verdict.PROVED, "these legs never occur together (vacuous)")
            fires = ans.status == "sat"
        ans = spend.solve(full, budget * (1 - (0 if fires else VACUITY_SHARE)))
        if ans.status == "unsat":
            return result(Verdict.PROVED, PROVED_ON.format(q=spec.q))
        if ans.status == "sat":
            verdict, reason, state, moves = replay_whatif(model, spec, ans.positions)
            if verdict is Verdict.VIOLATED:
                return result(verdict, reason, state, moves)
            named = spend.solve(build(arith(spec), model, spec, witnesses=True), spend.left() * WITNESS_SHARE)
            if named.status == "unsat":
                return result(Verdict.PROVED, PROVED_ON.format(q=spec.q) + WITNESSED)
            tried = []
            for extra in range(EXTRA + 1):
                share = spend.left() / (EXTRA + 1 - extra)
                closed = spend.solve(build(arith(spec), model, spec, closed=True, extra=extra), share)
                if closed.status == "sat":
                    again = replay_whatif(model, spec, closed.positions)
                    if again[0] is Verdict.VIOLATED:
                        return result(*again)
                    tried.append(f"{extra} more: sat, not replayed")
                else:
                    tried.append(f"{extra} more: {closed.status}")
            return result(
                Verdict.INCONCLUSIVE,
                f"{reason}; searched again with the named robots and 0 to {EXTRA} more at rest as the whole swarm "
                f"({'; '.join(tried)}): no counterexample",
                state,
                moves,
            )
        last = ans.reason
    return result(Verdict.INCONCLUSIVE, f"solver: {last} {rounds_text(timeout)}; rerun with a larger --timeout")


def family_kinds(spec: WhatIfSpec) -> frozenset[Kind]:
    """The kinds of ``reach``'s family the obligation is about: the proved ones and its what-ifs."""
    return PROVED_KINDS | {Kind(k) for k in spec.kinds}


def obligations(model: Model, kinds: frozenset[str], lemmas: tuple[Lemma, ...]) -> list[WhatIfSpec]:
    """The what-if obligations of ``kinds`` on ``model``'s lattice, the ``left-alone`` legs as long as
    ``reach``'s family makes them (:func:`fatline_verify.repair.reach.left_alone_reach`): the one way the
    command and the tests ask for them, so the prover and the family agree on the legs."""
    family = PROVED_KINDS | {Kind(k) for k in kinds}
    reach = left_alone_reach(model, family) if Kind.LEFT_ALONE in family else None
    return whatif_specs(kinds, model.parameters.q, lemmas, reach)


def replay_whatif(
    model: Model, spec: WhatIfSpec, positions: dict[str, tuple[Fraction, Fraction]]
) -> tuple[Verdict, str, tuple[Point, ...], tuple[tuple[int, Point], ...]]:
    """The solver's named robots as a swarm of ``reach``'s family with the spec's kinds: VIOLATED only if
    the swarm is connected and collision-free, each mover's leg is one its own view allows there, and
    the executable model's round breaks the claim."""
    names = ["r", "o", *(["b"] if spec.form in BRIDGES else [])]
    names += sorted(n for n in positions if n.startswith("e") and not n.endswith("'"))
    m = model.with_q(spec.q) if model.parameters.q != spec.q else model
    state = tuple(_lattice(m, positions[n]) for n in names)
    movers = [0] if spec.other == REST else [0, 1]
    if spec.form == VERTICAL_BRIDGE and spec.via != REST:
        movers.append(2)
    moves = tuple((i, _minus(_lattice(m, positions[f"{names[i]}'"]), state[i])) for i in movers)
    shown = f"robots {list(state)} (lattice units, q = {spec.q}; {', '.join(names)}), round {list(moves)}"
    family = Family(m, family_kinds(spec))
    fm = family.model
    if not is_connected(state, fm):
        return (Verdict.INCONCLUSIVE, f"the legs' conditions admit a violation at {shown}, but those robots are not a "
                "connected swarm: not a counterexample", state, moves)  # fmt: skip
    for i, end in moves:
        if end not in {e for e, _ in family.legs(state, i)}:
            return (Verdict.INCONCLUSIVE, f"the legs' conditions admit a violation at {shown}, but the family's own "
                    f"tests do not allow robot {names[i]}'s leg there: not a counterexample", state, moves)  # fmt: skip
    if spec.form in BRIDGES and not _bridge_used(fm, state, moves[0][1], spec.form == VERTICAL_BRIDGE):
        return (Verdict.INCONCLUSIVE, f"the legs' conditions admit a violation at {shown}, but there r's edge test "
                "for o passes by keeping it, or b is not a bridge by the family's own test: not a counterexample",
                state, moves)  # fmt: skip
    if spec.form == KEPT and not all(_kept(fm, state, i, end, 1 - i) for i, end in moves):
        return (Verdict.INCONCLUSIVE, f"the legs' conditions admit a violation at {shown}, but there a mover's "
                "edge test for the other does not keep the edge (it is bridged): not a counterexample",
                state, moves)  # fmt: skip
    ends = dict(moves)
    after = tuple((p[0] + ends[i][0], p[1] + ends[i][1]) if i in ends else p for i, p in enumerate(state))
    if spec.lemma is Lemma.NO_COLLISION:
        pr = (state[0], after[0])
        po = (state[1], after[1]) if 1 in ends else None
        broken = collides(closest_dist2(pr, po, state[0], state[1], fm), fm)
        what = "r and o collide"
    else:
        gone = {pair for pair, _ in lost_edges(state, after, fm)}
        lost = sorted(gone & {(0, 1)}) + sorted(gone & {(0, 2), (1, 2)} if spec.form in BRIDGES else set())
        broken = (0, 1) in gone and (spec.form not in BRIDGES or bool(gone & {(0, 2), (1, 2)}))
        split = disconnection(state, after, fm)
        what = "lost: " + ", ".join("-".join(names[i] for i in pair) for pair in lost)
        what += "; the swarm splits" if split is not None else "; the swarm stays connected through the others"
    if not broken:
        return (Verdict.INCONCLUSIVE, f"the replayed round of {shown} keeps the claim", state, moves)
    decisions = {i: Decision(Rule.REPAIR_DETOUR, end, (ORIGIN, end), ()) for i, end in moves}
    played = play_round(state, list(decisions), fm, decisions)
    seen = f"; the executable model's round: {played.violations[0]}" if played.violations else ""
    initial = "an initial configuration" if not initial_problems(state, fm) else "a connected swarm (not initial)"
    return (
        Verdict.VIOLATED,
        f"{what}: {shown}, from {initial}, each leg allowed by the family's tests (reach --with "
        f"{','.join(sorted(spec.kinds))}){seen}",
        state,
        moves,
    )


def _kept(model: Model, state: tuple[Point, ...], i: int, end: Point, j: int) -> bool:
    """Whether robot ``i``'s edge test for robot ``j`` passes by keeping it (``repairs._edge_kept``'s first
    test, ``_wherever``), its leg to ``end``."""
    from ..rules.repaired.algorithm import _wherever

    c = _minus(state[j], state[i])
    return all(model.sees(_d2(p, end)) for p in _wherever(c, end, True, model.radius))


def _bridge_used(model: Model, state: tuple[Point, ...], end: Point, vertical: bool) -> bool:
    """Whether, by ``repairs._edge_kept``'s own tests from r's view (robot 0, leg to ``end``), r's edge to
    o (robot 1) is not kept and b (robot 2) bridges it (``vertical``: as a robot on r's vertical)."""
    from ..rules.repaired.algorithm import _anywhere, _wherever

    rho = model.radius
    snap = snapshot(state, 0, model)
    rel = [_minus(p, state[0]) for p in state]
    c, b = rel[1], rel[2]
    if all(model.sees(_d2(p, end)) for p in _wherever(c, end, True, rho)):
        return False
    corners = model.options.repair_progress is RepairProgress.CORNER
    places = _anywhere(c, rho, snap, corners=corners)
    if vertical:
        mine = _anywhere(b, rho, snap, corners=True)
        return (
            corners
            and b[0] == 0
            and all(model.sees(_d2(p, end)) for p in mine)
            and all(model.sees(_d2(p, cc)) for p in mine for cc in places)
        )
    return b[0] > 0 and model.sees(_d2(b, end)) and all(model.sees(_d2(b, p)) for p in places)


def _d2(a: Point, b: Point) -> int:
    return int((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)


def _minus(a: Point, b: Point) -> Point:
    return (a[0] - b[0], a[1] - b[1])


def _lattice(model: Model, p: tuple[Fraction, Fraction]) -> Point:
    x, y = model.to_lattice(p)
    return (int(x), int(y))


__all__ = ["WhatIfResult", "family_kinds", "obligations", "prove_whatif", "replay_whatif"]
