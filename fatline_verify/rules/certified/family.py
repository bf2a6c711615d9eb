"""The certified rule set's move family: one leg class per lattice step it makes, and its safety argument
written as guards.

Classes (``q`` lattice units a radius; each class one exact step, so that a robot's class says where it ends):
``right`` (one radius right) and ``right-SofQ`` (``S`` of ``q`` lattice units right, shorter), ``up-right`` and
``down-right`` (one lattice unit along each axis), ``down``/``down-SofQ`` and ``up``/``up-SofQ`` along the
robot's vertical. Nothing holds a robot (no ``at_rest``): certified's locks are its policy's, not its safety's.

The guard of every class, for every robot ``c`` the mover r sees (what :func:`.algorithm.allowed` tests):

- **clear**: r's swept disc is clear of c at rest.
- **c's region** (:func:`.algorithm.region`): a leg ``W`` of c is *ruled out* when r can tell that c's own
  guard forbids it: c's path meets r or a robot ``d`` both see (c's guard has ``clear(d)`` for every ``d`` it
  sees), or ``W`` is up and c sees a robot off its vertical or one above it closer than ``UP_GAP`` radii to
  its end (c's ``up`` guard forbids both). ``d`` is a witness of role ``block_W``, declared as ruling out
  the class ``W`` of the robot it speaks of (:attr:`MoveFamily.rules_out`): where o moves by ``W``, the
  prover names the witness and o's own guard contradicts it. For c left of r, r's path is clear of, and r's
  end within view of, c's end by every leg not ruled out; for c on r's vertical, the same for every leg of
  higher rank than r's (:data:`.algorithm.RANK`: of two moves exactly one robot checks); a robot right of r
  checks r (r is left of it).
- **the edge**: r's end sees c (and every end just named), or a **hop** ``b`` (a witness both see, role
  ``hop``) carries it: r's end sees ``b`` wherever ``b`` may end (every class, none ruled out), and each of
  ``b``'s places sees each of c's places (c at rest and by every leg not ruled out).

The policy's own test is stronger in one way and weaker in three, and the family is what is proved:

- the region's last exclusion (a robot c that sees no robot r sees keeps its edge to r, so it never ends
  out of r's view) needs an argument about c's edges the guard language cannot name per obligation: the
  family does not rule those legs out, so r must clear them too;
- the closure over hops (r reaches c through chains of edges that hold whatever the robots concerned do,
  any length) is cut to one hop, with the hop's places taken as every leg it has (certified takes a robot
  right of r at rest, relying on its own guard: an induction over x the obligations' two-edge argument
  cannot state).

Where certified's decision passes its own test but not this guard, the step lemma ``in-family`` reports it
(a checker violation, replayed), and the row ``LEMMA/in-family-views-any`` finds it on views.
"""

from __future__ import annotations

from fractions import Fraction
from functools import cache
from typing import Any

from ..family.family import LegClass, MoveFamily
from ..family.held import held
from ..family.lang import (
    FALSE,
    Cond,
    Pt,
    all_of,
    any_of,
    chain,
    clear,
    clear_of,
    distinct,
    end,
    exists,
    forall,
    implies,
    me,
    sees,
)
from .algorithm import DN, DR, RANK, UP, UP_GAP, UR, R, propose

CHAIN = "chain"
"""The role of the chains of robots through which r's end reaches another."""


def _name(kind: str, s: int, q: int) -> str:
    return kind if s == q else f"{kind}-{s}of{q}"


def steps(q: int) -> tuple[tuple[str, str, Fraction, Fraction], ...]:
    """``(class, kind, dx, dy)`` in radii: every step certified makes on the lattice ``q``."""
    out: list[tuple[str, str, Fraction, Fraction]] = []
    out += [(_name(R, s, q), R, Fraction(s, q), Fraction(0)) for s in range(q, 0, -1)]
    out += [(UR, UR, Fraction(1, q), Fraction(1, q)), (DR, DR, Fraction(1, q), Fraction(-1, q))]
    out += [(_name(DN, s, q), DN, Fraction(0), Fraction(-s, q)) for s in range(q, 0, -1)]
    out += [(_name(UP, s, q), UP, Fraction(0), Fraction(s, q)) for s in range(q, 0, -1)]
    return tuple(out)


def _block(cls: str) -> str:
    return "block_" + cls.replace("-", "_")


def ruled_out(c: Pt, step: tuple[str, str, Fraction, Fraction]) -> Cond:
    """c's leg ``step`` is one its own guard forbids, as r can tell from itself and the robots both see."""
    cls, kind, dx, dy = step
    to = c.moved(dx, dy)

    def reason(d: Pt) -> Cond:
        parts = [~clear(d, c, to)]
        if kind == UP:
            parts += [d.x != c.x, (d.y > c.y) & (to.y > d.y - UP_GAP)]
        return any_of(*parts)

    witness = exists(lambda d: distinct(d, c) & sees(c, d) & reason(d), role=_block(cls))
    return reason(me) | witness


def _higher(kind: str, c: Pt, theirs: str) -> Cond:
    """c, on r's vertical, makes a leg of kind ``theirs`` that outranks r's of kind ``kind``."""
    above = RANK[("upper", theirs)] > RANK[("lower", kind)]
    below = RANK[("lower", theirs)] > RANK[("upper", kind)]
    return any_of(*([c.y > me.y] if above else []), *([c.y < me.y] if below else []))


def _checked(kind: str, c: Pt, theirs: str) -> Cond:
    """r answers for c's legs of kind ``theirs``: c is left of r, or on r's vertical with the higher rank."""
    return (c.x < me.x) | ((c.x == me.x) & _higher(kind, c, theirs))


def _places(c: Pt, q: int) -> list[tuple[Pt, Cond]]:
    """Where c may be after the round as r's chains count it, each with the condition under which it is left out:
    at rest (never), and the end of each of its legs, left out when r can tell c's own guard forbids that leg or
    c is right of r (it is then taken at rest: where it moves, its edges have a mover right of r, which the
    induction over x answers for)."""
    return [(c, FALSE)] + [(c.moved(s[2], s[3]), ruled_out(c, s) | (c.x > me.x)) for s in steps(q)]


def _sure(p: Pt, b: Pt, q: int) -> Cond:
    """``p`` sees every place of ``b``."""
    return all_of(*(no | sees(p, place) for place, no in _places(b, q)))


def _chain(c: Pt, q: int) -> Cond:
    """c reached from r's end through robots r sees, each link every place of one seeing every place of the next
    (certified's closure, :func:`.algorithm.allowed`)."""

    def link(a: Pt, b: Pt) -> Cond:
        return distinct(a, b) & all_of(*(no | _sure(place, b, q) for place, no in _places(a, q)))

    return chain(lambda b: _sure(end, b, q), link, to=c, role=CHAIN)


def _guard(q: int, kind: str) -> Cond:
    def each(c: Pt) -> Cond:
        parts: list[Cond] = [clear(c)]
        kept: list[Cond] = [sees(end, c)]
        for s in steps(q):
            to = c.moved(s[2], s[3])
            ok = ruled_out(c, s) | (clear_of(me, end, c, to) & sees(end, to))
            parts.append(implies(_checked(kind, c, s[1]), ruled_out(c, s) | clear_of(me, end, c, to)))
            kept.append(implies(_checked(kind, c, s[1]), ok))
        return all_of(*parts, all_of(*kept) | _chain(c, q))

    return forall(each)


@cache
def family_for_q(q: int) -> MoveFamily:
    """The certified family on the lattice ``q``."""
    classes = []
    for cls, kind, dx, dy in steps(q):
        shape = (end.x == me.x + dx) & (end.y == me.y + dy)
        guard = _guard(q, kind)
        if kind == UP:
            guard = guard & forall(lambda c: (c.x == me.x) & implies(c.y > me.y, end.y <= c.y - UP_GAP))
        classes.append(LegClass(cls, shape, guard, f"({dx}, {dy}) radii ({kind})"))
    longest = Fraction(3, 2) if q == 1 else Fraction(1)
    return MoveFamily(
        f"certified-q{q}",
        tuple(classes),
        max_step=longest,
        says="certified's steps: right, one lattice unit diagonally right, along the vertical; each clear of every "
        "robot seen and of every leg r answers for, r's edges kept or carried by one hop",
        rules_out={_block(s[0]): s[0] for s in steps(q)},
        order=(Fraction(1), Fraction(0)),
        lattice=True,
        witnesses={
            CHAIN: "the robots through which r's end reaches the robot whose edge it carries",
            **{_block(s[0]): f"a robot both see that the other's {s[0]} leg would violate" for s in steps(q)},
        },
    )


def family(model: Any) -> MoveFamily:
    """The family of ``model``'s lattice."""
    return family_for_q(model.parameters.q)


decide = held(propose, family)
"""The certified rules held to the family (:class:`~fatline_verify.rules.family.held.Held`): the first move the
rules allow that the family admits. The rules' closure over hops reaches a little further than the family's
chains (a robot that sees no robot r sees keeps its edge to r, so it never ends out of r's view: the region's
last exclusion, which the guard language does not state), and those moves are not made."""


__all__ = ["CHAIN", "decide", "family", "family_for_q", "ruled_out", "steps"]
