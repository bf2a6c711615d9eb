"""Lemma 1 in its global form over symbolic slots (the whole graph after one round), and the old
slot encoding's shared tools: solving, SMT-LIB2 output, re-checking a written file, and the
symbolic ``decide`` evaluated on a concrete snapshot (for differential tests).

The global form has no witness argument (the lemma is about the whole graph), so ``unsat`` holds
only for configurations of at most ``k + 1`` robots. The per-case obligations are in
:mod:`fatline_verify.prove.smt.claims`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...model.options import Contact, Scheduler
from ...rules.paper.algorithm import Rule
from .solving import exact_value, rlimit, unknown_reason
from .symbolic import Slot, decide, make_slots, real, sq, view_reach


@dataclass
class Obligation:
    """One SMT obligation, ready to write and solve."""

    lemma: Lemma
    form: str
    rule: Rule
    k: int
    any_size: bool
    comment: str
    assertions: list[z3.BoolRef] = field(repr=False)
    slots: list[Slot] = field(repr=False)
    flags: list[z3.BoolRef] = field(default_factory=list, repr=False)
    """Booleans whose values a sat answer reports (the global form's activation set: r, then each slot)."""

    @property
    def name(self) -> str:
        return "global" if self.form == "global" else f"{self.form}-{self.rule.value}"


@dataclass(frozen=True)
class Answer:
    """The solver's answer to one obligation."""

    status: str  # "sat" | "unsat" | "unknown"
    seconds: float
    reason: str = ""
    positions: tuple[tuple[Fraction, Fraction], ...] = ()
    """For sat: the present slot robots' centres (radii, relative to r), slot order."""
    rounded: bool = False
    flags: tuple[bool, ...] = ()
    """For sat: the obligation's flags, and for each slot whether it is present (flags first)."""


SymPoint = tuple[z3.ArithRef, z3.ArithRef]


def _apart(model: Model, d2: z3.ArithRef) -> z3.BoolRef:
    return d2 > 4 if model.options.contact is Contact.STRICT else d2 >= 4


def _connected(pos: list[SymPoint], present: list[z3.BoolRef], reach2: z3.ArithRef) -> z3.BoolRef:
    """Every present robot is reachable from robot 0 (present) in the visibility graph."""
    n = len(pos)

    def sees(i: int, j: int) -> z3.BoolRef:
        return z3.And(present[i], present[j], sq(pos[i][0] - pos[j][0]) + sq(pos[i][1] - pos[j][1]) <= reach2)

    reached = [z3.BoolVal(True)] + [sees(0, j) for j in range(1, n)]
    for _ in range(n):
        reached = [z3.Or(reached[i], *[z3.And(reached[j], sees(i, j)) for j in range(n) if j != i]) for i in range(n)]
    return z3.And(*[z3.Implies(present[i], reached[i]) for i in range(n)])


def build_global(model: Model, k: int, initial: bool = False) -> Obligation:
    """Lemma 1 in its global form for r and ``k`` slot robots: every robot decides from its own view of
    the others, a symbolic set of them is activated, the graph is connected before and not after."""
    slots = make_slots(k)
    everyone = [Slot(real(0), real(0), z3.BoolVal(True)), *slots]
    asserts: list[z3.BoolRef] = []
    for i, a in enumerate(everyone):
        for b in everyone[i + 1 :]:
            asserts.append(z3.Implies(z3.And(a.present, b.present), _apart(model, sq(a.x - b.x) + sq(a.y - b.y))))
    reach2 = real(view_reach(model) ** 2)
    after: list[SymPoint] = []
    actives = [z3.Bool(f"a{i}") for i in range(k + 1)]
    for i, me in enumerate(everyone):
        view = [other.minus(me.x, me.y) for j, other in enumerate(everyone) if j != i]
        dec = decide(view, model, f"g{i}")
        asserts += dec.side
        active = actives[i]
        after.append((me.x + z3.If(active, dec.dx, real(0)), me.y + z3.If(active, dec.dy, real(0))))
    scheduler = model.options.scheduler
    if scheduler is Scheduler.FSYNC:  # every robot is activated
        asserts += [a == c.present for a, c in zip(actives, everyone, strict=True)]
    elif scheduler is Scheduler.CENTRALIZED:  # one robot a round
        asserts.append(z3.PbEq([(a, 1) for a in actives], 1))
    present = [c.present for c in everyone]
    before = [(c.x, c.y) for c in everyone]
    asserts += [_connected(before, present, reach2), z3.Not(_connected(after, present, reach2))]
    if initial:
        asserts += initial_condition(model, slots)
    comment = "\n".join(
        [
            f"Obligation: {Lemma.CONNECTIVITY}, global form, r and {k} slot robots (each may be absent).",
            "Claim (Lemma 1): a connected configuration stays connected after one semi-synchronous round.",
            "Encoding: every present robot decides from its own view of the others (symbolic decide); a symbolic "
            "set of robots (a0, a1, ...) moves, as the scheduler allows (ssync: any set; centralized: exactly one; "
            "fsync: all); the visibility graph is connected before and not after.",
            f"unsat proves the claim for configurations of at most {k + 1} robots, not for every size: the lemma is "
            "about the whole graph, so no single-robot witness argument applies.",
            "Assumptions: exact real arithmetic; robots are non-overlapping unit discs; one shared snapshot.",
        ]
    )
    return Obligation(Lemma.CONNECTIVITY, "global", Rule.ALONE, k, False, comment, asserts, slots, actives)


def initial_condition(model: Model, slots: list[Slot]) -> list[z3.BoolRef]:
    """The paper's initial condition on r and the present slots, for the counterexample search:
    pairwise distance > delta (strictly inside "at least delta", so that a model rounded from
    algebraic numbers stays initial; every configuration found meets the paper's condition) and a
    connected visibility graph (reachability from r in at most k steps). No unsat answer of a search
    with this condition is reported: the verdicts that claim a lemma come from obligations without it."""
    delta2 = real(Fraction(model.parameters.delta) ** 2)
    reach2 = real(view_reach(model) ** 2)
    out = []
    for i, a in enumerate(slots):
        out.append(z3.Implies(a.present, sq(a.x) + sq(a.y) > delta2))
        for b in slots[i + 1 :]:
            out.append(z3.Implies(z3.And(a.present, b.present), sq(a.x - b.x) + sq(a.y - b.y) > delta2))
    reached = [z3.And(a.present, sq(a.x) + sq(a.y) <= reach2) for a in slots]
    for _ in range(len(slots)):
        reached = [
            z3.Or(
                reached[i],
                *[
                    z3.And(reached[j], b.present, sq(a.x - b.x) + sq(a.y - b.y) <= reach2)
                    for j, b in enumerate(slots)
                    if j != i
                ],
            )
            for i, a in enumerate(slots)
        ]
    out += [z3.Implies(a.present, r) for a, r in zip(slots, reached, strict=True)]
    return out


def smt2(ob: Obligation) -> str:
    """The obligation as a plain SMT-LIB2 script any solver reads."""
    solver = z3.Solver()
    solver.add(*ob.assertions)
    header = "\n".join(f"; {line}" for line in ob.comment.splitlines())
    body = solver.sexpr()
    return f"{header}\n(set-logic QF_NRA)\n{body}(check-sat)\n"


def write(ob: Obligation, path: Path) -> None:
    from ...outputs import write_text

    write_text(path, smt2(ob))  # atomic, never through a link


def solve(ob: Obligation, timeout_s: float) -> Answer:
    """Ask z3; for sat, decode the present robots to exact rationals (algebraic values rounded).

    The budget is z3's deterministic resource limit (``rlimit``), so an answer does not depend on
    the machine's load; the wall clock only stops a runaway check
    (:func:`~fatline_verify.prove.smt.solving.wall_ms`, as every other check).
    """
    from .solving import wall_ms

    solver = z3.Solver()
    solver.set("rlimit", rlimit(timeout_s))
    solver.set("timeout", wall_ms(timeout_s))
    solver.add(*ob.assertions)
    t0 = time.perf_counter()
    res = solver.check()
    seconds = time.perf_counter() - t0
    if res == z3.unsat:
        return Answer("unsat", seconds)
    if res == z3.unknown:
        return Answer("unknown", seconds, unknown_reason(solver, timeout_s))
    m = solver.model()
    points, rounded = [], False
    for slot in ob.slots:
        if z3.is_true(m.eval(slot.present, model_completion=True)):
            x, rx = exact_value(m.eval(slot.x, model_completion=True))
            y, ry = exact_value(m.eval(slot.y, model_completion=True))
            rounded = rounded or rx or ry
            points.append((x, y))
    flags = tuple(z3.is_true(m.eval(f, model_completion=True)) for f in ob.flags)
    present = tuple(z3.is_true(m.eval(s.present, model_completion=True)) for s in ob.slots)
    return Answer("sat", seconds, positions=tuple(points), rounded=rounded, flags=flags + present)


def recheck_file(path: Path, timeout_s: float = 30.0) -> str:
    """Re-check a written ``.smt2`` file with a fresh z3 solver: ``sat``, ``unsat`` or ``unknown``."""
    solver = z3.Solver()
    solver.set("timeout", int(timeout_s * 1000))
    solver.add(z3.parse_smt2_file(str(path)))
    return str(solver.check())


def solver_version() -> str:
    return f"z3 {z3.get_version_string()}"


def evaluate(model: Model, others: list[tuple[Fraction, Fraction]]) -> tuple[Rule, tuple[Fraction, Fraction]]:
    """The symbolic decision on a concrete snapshot (slots fixed): for differential tests."""
    slots = make_slots(len(others))
    dec = decide(slots, model, "e")
    solver = z3.Solver()
    solver.add(*dec.side)
    for s, (x, y) in zip(slots, others, strict=True):
        solver.add(s.present, s.x == real(x), s.y == real(y))
    if solver.check() != z3.sat:
        raise AssertionError("a concrete snapshot has no symbolic decision")
    m = solver.model()
    rule = Rule(list(Rule)[m.eval(dec.rule).as_long()])
    dx, _ = exact_value(m.eval(dec.dx, model_completion=True))
    dy, _ = exact_value(m.eval(dec.dy, model_completion=True))
    return rule, (dx, dy)
