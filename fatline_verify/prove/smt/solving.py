"""Ask z3 about a :class:`~fatline_verify.prove.smt.claims.Built` obligation; decode its answer exactly.

The budget is z3's deterministic resource limit (``rlimit``), so an answer does not depend on the
machine's load; the wall clock stops a check at 1.5 times the budget (nlsat does not always count resources).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction
from pathlib import Path

import z3

from .claims import Built

RLIMIT_PER_SECOND = 2_000_000
"""z3 resource units per second of budget. Measured here: 1 to 4 million units a second depending
on the obligation, so the deterministic limit normally stops a check before the clock does."""

WALL = 1.5
"""The wall clock stops a check at this many times its budget, plus :data:`WALL_SLACK` (a check without
resource counting, or z3 running slower than :data:`RLIMIT_PER_SECOND` on a busy machine). Only a
check stopped by its resource limit stops at the same point on every run; one stopped by the clock says
so in its reason."""

WALL_SLACK = 0.1
"""Seconds the wall clock adds to every check's limit, so that a check given a sliver of budget stops
at its resource limit (and says so) rather than at a clock limit of a few milliseconds."""


def wall_ms(seconds: float) -> int:
    """The wall-clock limit of a check with ``seconds`` of budget, in milliseconds (z3's ``timeout``)."""
    return int(1000 * (WALL * seconds + WALL_SLACK))


Positions = dict[str, tuple[Fraction, Fraction]]


@dataclass
class Answer:
    """The solver's answer: ``sat`` (with every named robot's centre, radii, relative to r),
    ``unsat`` or ``unknown`` (with z3's reason)."""

    status: str
    seconds: float
    reason: str = ""
    positions: Positions = field(default_factory=dict)
    rounded: bool = False
    budget: float = 0.0
    """The budget the check used, in seconds of :data:`RLIMIT_PER_SECOND`: z3's resource count for an
    answer, the whole budget given for ``unknown``. Deterministic, unlike :attr:`seconds` (the wall
    clock), so a search that spends its budget by it reaches the same verdicts on every run."""


def exact_value(value: z3.ExprRef, q: int | None = None) -> tuple[Fraction, bool]:
    """A model value as a fraction (an integer on the lattice x = X/q divided by ``q``), and whether it
    was rounded (an algebraic number, to 40 digits)."""
    if z3.is_int_value(value):
        return Fraction(value.as_long(), q or 1), False
    if z3.is_rational_value(value):
        return Fraction(value.numerator_as_long(), value.denominator_as_long()), False
    if z3.is_algebraic_value(value):
        approx = value.approx(40)
        return Fraction(approx.numerator_as_long(), approx.denominator_as_long()), True
    raise ValueError(f"unexpected model value {value}")


def rlimit(seconds: float) -> int:
    return max(1, int(RLIMIT_PER_SECOND * seconds))


def unknown_reason(solver: z3.Solver, seconds: float) -> str:
    """Why a check answered unknown: the budget, said in the user's terms (the resource limit, which
    is the same on every machine, or the wall clock, which is not), or z3's own reason."""
    reason = str(solver.reason_unknown())
    if "resource" in reason:
        return f"budget exhausted (rlimit {rlimit(seconds):,}, about {seconds:.1f} s)"
    if any(word in reason for word in ("timeout", "canceled")):
        return (
            f"stopped by the wall clock at {wall_ms(seconds) / 1000:.1f} s, before its resource limit (rlimit "
            f"{rlimit(seconds):,}): z3 ran slower than the budget assumes, so a less busy machine may decide it"
        )
    return reason


def _rlimit_count(solver: z3.Solver) -> int:
    """z3's resource count of the solver's context so far (cumulative over the context's checks)."""
    stats = solver.statistics()
    return int(stats.get_key_value("rlimit count")) if "rlimit count" in stats.keys() else 0  # noqa: SIM118


def solver_for(built: Built, seconds: float) -> z3.Solver:
    """A solver holding the obligation (and its lattice bounds), with a budget of ``seconds``."""
    solver = z3.Solver(ctx=built.ar.ctx)
    solver.set("rlimit", rlimit(seconds))
    solver.set("timeout", wall_ms(seconds))
    solver.add(*built.assertions, *built.bounds)
    return solver


def spent(solver: z3.Solver, built: Built) -> float:
    """The budget, in seconds of :data:`RLIMIT_PER_SECOND`, the context's checks used since the last
    call (z3's resource count is cumulative per context, over every solver in it)."""
    count = _rlimit_count(solver)
    used = (count - built.ar.rlimit_seen) / RLIMIT_PER_SECOND
    built.ar.rlimit_seen = count
    return used


def check(solver: z3.Solver, built: Built, seconds: float) -> Answer:
    """One ``check``; for sat, every named robot's centre as an exact fraction of a radius
    (algebraic values rounded to 40 digits and flagged: the replay decides whether they still work)."""
    t0 = time.perf_counter()
    res = solver.check()
    elapsed = time.perf_counter() - t0
    measured = spent(solver, built)
    used = seconds if res == z3.unknown else min(seconds, measured)  # unknown: the whole budget
    if res == z3.unsat:
        return Answer("unsat", elapsed, budget=used)
    if res == z3.unknown:
        return Answer("unknown", elapsed, unknown_reason(solver, seconds), budget=used)
    return decode(solver.model(), built, elapsed, used)


def decode(m: z3.ModelRef, built: Built, elapsed: float, used: float) -> Answer:
    """A ``sat`` answer from a model: every named robot's centre, exact (algebraic values rounded)."""
    positions: Positions = {}
    rounded = False
    for name, (x, y) in built.bodies.items():
        fx, rx = exact_value(m.eval(x, model_completion=True), built.ar.q)
        fy, ry = exact_value(m.eval(y, model_completion=True), built.ar.q)
        positions[name] = (fx, fy)
        rounded = rounded or rx or ry
    return Answer("sat", elapsed, positions=positions, rounded=rounded, budget=used)


def _nonlinear(e: z3.ExprRef, memo: dict[int, bool]) -> bool:
    """Whether ``e`` multiplies two terms that are not numerals (anywhere inside it)."""
    key = e.get_id()
    if key not in memo:
        product = z3.is_mul(e) and sum(not z3.is_arith(c) or not _numeral(c) for c in e.children()) > 1
        memo[key] = product or any(_nonlinear(c, memo) for c in e.children())
    return memo[key]


def _numeral(e: z3.ExprRef) -> bool:
    return z3.is_int_value(e) or z3.is_rational_value(e) or z3.is_algebraic_value(e)


def _connective(f: z3.ExprRef) -> bool:
    """A Boolean connective whose arguments are formulas (not an arithmetic comparison)."""
    if z3.is_and(f) or z3.is_or(f) or z3.is_not(f) or z3.is_implies(f):
        return True
    if z3.is_eq(f) or z3.is_app_of(f, z3.Z3_OP_ITE) or z3.is_app_of(f, z3.Z3_OP_XOR):
        return all(z3.is_bool(c) for c in f.children())
    return False


def relaxed_atoms(built: Built) -> tuple[list[z3.BoolRef], list[tuple[z3.BoolRef, z3.BoolRef]]]:
    """The obligation (its lattice bounds included) with every comparison that multiplies two
    non-constant terms replaced by a fresh Boolean (the same comparison by the same Boolean; one
    without unknowns by its value), and the pairs (comparison, Boolean)."""
    ctx = built.ar.ctx
    memo: dict[int, bool] = {}
    done: set[int] = set()  # terms walked (their count names each new Boolean)
    atoms: list[tuple[z3.BoolRef, z3.BoolRef]] = []
    pairs: list[tuple[z3.BoolRef, z3.BoolRef]] = []

    def walk(f: z3.BoolRef) -> None:
        key = f.get_id()
        if key in done:
            return
        if _connective(f):
            for c in f.children():
                walk(c)
        elif _nonlinear(f, memo):
            value = z3.simplify(f)
            if not (z3.is_true(value) or z3.is_false(value)):
                value = z3.Bool(f"relaxed!{len(done)}", ctx)
                atoms.append((f, value))
            pairs.append((f, value))
        done.add(key)

    formulas = [*built.assertions, *built.bounds]
    for f in formulas:
        walk(f)
    # z3 makes the replacements (in one call): rebuilding each connective through the Python API took a quarter
    # longer over the shipped models' 4,100 builds, for the same terms (an atom under a non-connective, which no
    # shipped obligation has, is replaced too: the same Boolean for the same atom, still a relaxation)
    if not pairs:
        return formulas, atoms
    if len(formulas) == 1:
        return [z3.substitute(formulas[0], *pairs)], atoms
    whole = z3.substitute(z3.And(*formulas), *pairs)  # one call: z3 keeps the conjunction's children apart
    return [whole.arg(i) for i in range(len(formulas))], atoms


def fixed(built: Built, positions: Positions) -> Built:
    """``built`` with every named robot fixed at ``positions`` (radii, relative to r): a solution of a
    restriction of the question (a lattice's) checked against the question itself."""
    at = [
        coordinate == built.ar.num(value)
        for name, (x, y) in built.bodies.items()
        for coordinate, value in zip((x, y), positions[name], strict=True)
    ]
    return replace(built, assertions=[*built.assertions, *at])


def among(built: Built, points: Sequence[tuple[Fraction, Fraction]]) -> Built:
    """``built`` with every named robot but r at one of ``points`` (radii, relative to r; several names may
    be one robot): the question asked of one known configuration."""
    num = built.ar.num
    at = [
        z3.Or(*[z3.And(x == num(px), y == num(py)) for px, py in points])
        for name, (x, y) in built.bodies.items()
        if name != "r"
    ]
    return replace(built, assertions=[*built.assertions, *at])


def relaxation(built: Built) -> Built:
    """The obligation's *linear relaxation* (:func:`relaxed_atoms`). Every solution of the
    obligation is one of its relaxation (give each Boolean its comparison's truth value), so an
    ``unsat`` relaxation means an ``unsat`` obligation; the relaxation is linear arithmetic with
    Booleans, which z3 decides completely and fast. A ``sat`` relaxation says nothing."""
    relaxed, _ = relaxed_atoms(built)
    return Built(built.ar, relaxed, built.bodies, built.focus, built.comment, [])


def block(solver: z3.Solver, built: Built, positions: Positions) -> None:
    """Exclude exactly this placement of the named robots (lattice searches go on past it)."""
    q = built.ar.q or 1
    terms = []
    for name, (x, y) in built.bodies.items():
        fx, fy = positions[name]
        terms += [x != int(fx * q), y != int(fy * q)]
    solver.add(z3.Or(*terms))


def smt2(built: Built) -> str:
    """The obligation as a plain SMT-LIB2 script (its argument as a comment header)."""
    solver = z3.Solver(ctx=built.ar.ctx)
    solver.add(*built.assertions, *built.bounds)
    header = "\n".join(f"; {line}" if line else ";" for line in built.comment.splitlines())
    logic = "QF_NIA" if built.ar.lattice else "QF_NRA"
    return f"{header}\n(set-logic {logic})\n{solver.sexpr()}(check-sat)\n"


def write(built: Built, path: Path) -> None:
    from ...outputs import write_text

    write_text(path, smt2(built))  # atomic, never through a link


def solver_version() -> str:
    return f"z3 {z3.get_version_string()}"


__all__ = ["Answer", "Positions", "block", "check", "relaxation", "smt2", "solver_for", "write"]
