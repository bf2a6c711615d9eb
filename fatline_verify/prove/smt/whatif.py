"""What-if leg obligations: the left and corner legs of ``fatline reach --with`` (not the shipped rules).

``fatline reach --with left,corner`` (:mod:`fatline_verify.repair.reach`) adds to the repaired family
two kinds of leg that no shipped obligation covers (:data:`fatline_verify.repair.reach.WHAT_IF`):

- ``left``: ``(-k, 0)``, ``1 <= k <= q`` lattice units (one radius or less), by a robot that sees no
  robot strictly left of it (the lock) and one right of it;
- ``top-corner`` / ``bottom-corner`` (``corner``): ``(k, -j)`` by a robot seeing robots below it on its
  vertical and none above, ``(k, j)`` by one seeing robots above and none below, ending at least 3
  radii below each; ``1 <= k, j <= q`` (up to sqrt(2) radii long). ``repairs.allowed`` then also
  keeps the path clear of each robot on the mover's vertical moving one radius right, and its edge
  tests run with ``repair_progress = corner``.

Each mover's leg passed ``repairs.allowed`` for every robot it sees: not strictly left of it, clear of
its swept disc, its class's condition on its vertical, and the edge kept or bridged (the same tests as
:mod:`fatline_verify.prove.smt.legs`). These obligations are those of :mod:`~fatline_verify.prove.smt.legs`
(``no-collision/leg``, ``connectivity/kept``, ``connectivity/bridged``) over the extended set of
classes, every pair in which at least one robot is on a what-if class or, with ``corner`` (whose
edge tests differ), every pair.

They are decided **on the lattice** of the model (``x = X / q``, integers, exact), where the family
of ``reach`` lives: a corner leg is sqrt(2) radii long, which the reals' nonlinear arithmetic does
not decide in time, while on the lattice every quantity is an integer. ``unsat`` covers every swarm
size on that lattice by the argument of :mod:`fatline_verify.prove.smt.legs` (the conditions are
universal over the robots a mover sees; every collision and every edge with a mover at one end is
an instance of one obligation), with one exception said in each header: under ``corner`` an edge may
also pass a test bridged through a robot on the mover's own vertical, which may move, and no
obligation here covers that form, so the corner's connectivity is not proved as a whole.
"""

from __future__ import annotations

from dataclasses import dataclass

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...model.options import Timing
from .cases import Arith, Pt, apart, sees, view_reach
from .claims import Built, capsules_close, segment_close

LEFT = "left"
CORNER = "corner"
KINDS = (LEFT, CORNER)
"""The what-if kinds, as ``fatline reach --with`` names them."""

HORIZONTAL, TOP, BOTTOM = "horizontal", "top", "bottom"
LEFTWARD, TOP_CORNER, BOTTOM_CORNER = "left", "top-corner", "bottom-corner"
VERTICAL_PART = (TOP, BOTTOM, TOP_CORNER, BOTTOM_CORNER)
CORNERS = (TOP_CORNER, BOTTOM_CORNER)
REST = "rest"
LEG, KEPT, BRIDGED = "leg", "kept", "bridged"
FORMS = {Lemma.NO_COLLISION: (LEG,), Lemma.CONNECTIVITY: (KEPT, BRIDGED)}
CLAIM = {
    (Lemma.NO_COLLISION, LEG): "r and the other robot o never come within distance 2 during the round",
    (Lemma.CONNECTIVITY, KEPT): "r and o, within view before the round, are within view after it",
    (Lemma.CONNECTIVITY, BRIDGED): "r-b and b-o are edges after the round, b at rest",
}


def classes(kinds: frozenset[str]) -> tuple[str, ...]:
    """The leg classes of the family with the what-if ``kinds``."""
    out = [HORIZONTAL, TOP, BOTTOM]
    if LEFT in kinds:
        out.append(LEFTWARD)
    if CORNER in kinds:
        out += list(CORNERS)
    return tuple(out)


@dataclass(frozen=True, slots=True)
class WhatIfSpec:
    """One what-if obligation: a lemma form, r's leg class, the other robot's (or :data:`REST`), the
    kinds of the family (they decide the edge tests), and the lattice ``q``."""

    lemma: Lemma
    form: str
    mine: str
    other: str
    kinds: frozenset[str]
    q: int

    @property
    def key(self) -> str:
        """``lemma/form-leg.and.other@q``: how rows and files name the obligation."""
        return f"{self.lemma}/{self.form}-{self.mine}.and.{self.other}@q{self.q}"

    @property
    def claim(self) -> str:
        return CLAIM[(self.lemma, self.form)]

    @property
    def corner_mode(self) -> bool:
        return CORNER in self.kinds


def whatif_specs(kinds: frozenset[str], q: int, lemmas: tuple[Lemma, ...]) -> list[WhatIfSpec]:
    """Every obligation of the family with ``kinds``: as :func:`fatline_verify.prove.smt.legs.leg_specs`
    over :func:`classes`, keeping only pairs with a what-if class unless ``corner`` (whose edge tests
    differ from the shipped ones) is among the kinds."""
    legs = classes(kinds)
    shipped = {HORIZONTAL, TOP, BOTTOM}
    specs: list[WhatIfSpec] = []
    for lemma in lemmas:
        for form in FORMS.get(lemma, ()):
            for i, mine in enumerate(legs):
                others = [REST, *(legs if form == BRIDGED else legs[i:])]
                for other in others:
                    if CORNER not in kinds and mine in shipped and other in (shipped | {REST}):
                        continue  # a shipped obligation, unchanged (fatline prove repaired)
                    specs.append(WhatIfSpec(lemma, form, mine, other, frozenset(kinds), q))
    return specs


@dataclass(frozen=True)
class Mover:
    """A robot and its leg: start, end, class."""

    at: Pt
    end: Pt
    leg: str


def mover(ar: Arith, name: str, leg: str, at: Pt) -> tuple[Mover, list[z3.BoolRef]]:
    """A leg of class ``leg`` from ``at``: whole lattice units, at most one radius along each axis it uses."""
    k = ar.var(f"{name}.k")
    zero, one = ar.num(0), ar.num(1)
    shape = [k > zero, k <= one]
    if leg == HORIZONTAL:
        end = (at[0] + k, at[1])
    elif leg == LEFTWARD:
        end = (at[0] - k, at[1])
    elif leg == TOP:
        end = (at[0], at[1] + k)
        shape = [k != zero, k >= -one, k <= one]
    elif leg == BOTTOM:
        end = (at[0], at[1] + k)
    else:
        j = ar.var(f"{name}.j")
        shape += [j > zero, j <= one]
        end = (at[0] + k, at[1] - j) if leg == TOP_CORNER else (at[0] + k, at[1] + j)
    return Mover(at, end, leg), shape


def _right(ar: Arith, c: Pt) -> Pt:
    return (c[0] + ar.num(1), c[1])


def conditions(ar: Arith, model: Model, m: Mover, c: Pt) -> z3.BoolRef:
    """What ``repairs.allowed`` and ``reach.family_legs`` say of a robot ``c`` that ``m`` sees: not
    strictly left of m (the lock), clear of m's swept disc (and, for a corner leg, of c's move right
    when c is on m's vertical), and the class's condition on m's vertical."""
    on_vertical = c[0] == m.at[0]
    facts = [c[0] >= m.at[0], z3.Not(segment_close(ar, model, c, m.at, m.end))]
    if m.leg in CORNERS:
        facts.append(z3.Implies(on_vertical, z3.Not(capsules_close(ar, model, (m.at, m.end), (c, _right(ar, c))))))
    if m.leg in (TOP, TOP_CORNER):
        facts.append(z3.Not(z3.And(on_vertical, c[1] > m.at[1])))
    elif m.leg in (BOTTOM, BOTTOM_CORNER):
        facts.append(z3.Implies(on_vertical, z3.And(c[1] > m.at[1], m.end[1] <= c[1] - ar.num(3))))
    return z3.Implies(sees(ar, model, m.at, c), z3.And(*facts))


def kept(ar: Arith, model: Model, m: Mover, c: Pt) -> z3.BoolRef:
    """``repairs._edge_kept``'s first test (``_wherever``): m's end sees ``c``, and ``c`` one radius right
    when m's leg has a vertical part and c is on m's vertical."""
    at_rest = sees(ar, model, m.end, c)
    if m.leg not in VERTICAL_PART:
        return at_rest
    return z3.And(at_rest, z3.Implies(c[0] == m.at[0], sees(ar, model, m.end, _right(ar, c))))


def bridged(ar: Arith, model: Model, m: Mover, c: Pt, b: Pt, corner_mode: bool) -> z3.BoolRef:
    """``repairs._edge_kept``'s second test: ``b`` right of m, seen by m, sees m's end and every place
    ``repairs._anywhere`` lists for ``c``. Under ``corner`` only the places it lists whatever else m
    sees (c, and c one radius right if on m's vertical): fewer places, a weaker, still implied, test."""
    anywhere = [sees(ar, model, b, c), z3.Implies(c[0] == m.at[0], sees(ar, model, b, _right(ar, c)))]
    if not corner_mode:
        up, down = (c[0], c[1] + ar.num(1)), (c[0], c[1] - ar.num(1))
        vertical = z3.And(sees(ar, model, b, up), sees(ar, model, b, down))
        anywhere.append(z3.Implies(z3.And(c[0] == m.at[0], c[1] > m.at[1]), vertical))
    return z3.And(b[0] > m.at[0], sees(ar, model, m.at, b), sees(ar, model, m.end, b), *anywhere)


def _movers_close(ar: Arith, model: Model, r: Mover, o: Mover) -> z3.BoolRef:
    if model.options.timing is Timing.ANY_SPEED:
        return capsules_close(ar, model, (r.at, r.end), (o.at, o.end))
    d0 = (r.at[0] - o.at[0], r.at[1] - o.at[1])
    d1 = (r.end[0] - o.end[0], r.end[1] - o.end[1])
    return segment_close(ar, model, ar.origin(), d0, d1)


def arith(spec: WhatIfSpec) -> Arith:
    """The obligation's domain: the lattice ``x = X / q``."""
    return Arith(spec.q)


def build(
    ar: Arith, model: Model, spec: WhatIfSpec, *, vacuity: bool = False, closed: bool = False, extra: int = 0
) -> Built:
    """The obligation ``spec`` on ``ar``'s lattice; ``vacuity`` keeps only "the legs occur together".
    ``closed``: the named robots are the whole swarm (:func:`closed_swarm`), a stronger question whose
    answers are candidates for a counterexample, never a proof; ``extra`` more robots at rest ``e1``, ...
    join them there (a test of a mover may pass through one).
    Every named robot lies within a box of the larger of the view and 5 radii around r: a violation
    needs the robots within view (an edge) or within 2 + 2 sqrt(2) < 5 (a collision), so the box
    excludes none."""
    r, asserts = mover(ar, "r", spec.mine, ar.origin())
    o_at = ar.point("o")
    bodies: dict[str, Pt] = {"r": r.at, "o": o_at}
    movers = [r]
    o_end = o_at
    if spec.other != REST:
        o, more = mover(ar, "o", spec.other, o_at)
        asserts += more
        movers.append(o)
        o_end = o.end
    if spec.form == BRIDGED:
        bodies["b"] = ar.point("b")
    for k in range(1, extra + 1 if closed else 1):
        bodies[f"e{k}"] = ar.point(f"e{k}")
    box = ar.num(max(5, int(view_reach(model)) + 1))
    bounds = [z3.And(p[i] >= -box, p[i] <= box) for n, p in bodies.items() if n != "r" for i in (0, 1)]
    names = list(bodies)
    for i, a in enumerate(names):
        asserts += [apart(ar, model, bodies[a], bodies[b]) for b in names[i + 1 :]]
    for m in movers:
        asserts += [conditions(ar, model, m, p) for p in bodies.values() if p is not m.at]
    if spec.form == KEPT:
        asserts += [sees(ar, model, r.at, o_at), kept(ar, model, r, o_at)]
        asserts += [kept(ar, model, m, r.at) for m in movers[1:]]
    if spec.form == BRIDGED:
        asserts += [sees(ar, model, r.at, o_at), bridged(ar, model, r, o_at, bodies["b"], spec.corner_mode)]
    if closed:
        asserts += closed_swarm(ar, model, spec, movers, [p for n, p in bodies.items()])
    before = list(bodies.values())
    for m in movers:
        bodies[f"{'r' if m is r else 'o'}'"] = m.end
    if closed:
        asserts.append(connected(ar, model, before))
    if not vacuity:
        asserts.append(_violation(ar, model, spec, movers, o_end, bodies.get("b")))
    return Built(ar, asserts + bounds, bodies, "o")


def connected(ar: Arith, model: Model, robots: list[Pt]) -> z3.BoolRef:
    """The visibility graph of ``robots`` (a handful) is connected: every cut has an edge across."""
    n = len(robots)
    cuts = []
    for mask in range(1, 2 ** (n - 1)):  # robot n-1 always on the other side: each cut once
        side = [bool(mask >> i & 1) for i in range(n - 1)] + [False]
        pairs = [(i, j) for i in range(n) for j in range(i + 1, n) if side[i] != side[j]]
        across = [sees(ar, model, robots[i], robots[j]) for i, j in pairs]
        cuts.append(z3.Or(*across))
    return z3.And(*cuts) if cuts else ar.true()


def closed_swarm(ar: Arith, model: Model, spec: WhatIfSpec, movers: list[Mover], robots: list[Pt]) -> list[z3.BoolRef]:
    """What the family's tests ask when the named robots are all a mover sees: each edge kept or bridged
    through a named robot, and the legs' own existential conditions (``reach.family_legs``): a robot
    to its right at least as far as a right or corner leg goes, a seen robot right of a left mover,
    one below a top-corner, one above a bottom or bottom-corner leg. Used only to look for a
    counterexample the replay accepts (:func:`fatline_verify.prove.whatif.prove_whatif`)."""
    out: list[z3.BoolRef] = []
    for m in movers:
        seen = [p for p in robots if p is not m.at]
        for p in seen:
            bridges = [bridged(ar, model, m, p, b, spec.corner_mode) for b in seen if b is not p]
            out.append(z3.Implies(sees(ar, model, m.at, p), z3.Or(kept(ar, model, m, p), *bridges)))
        dx = m.end[0] - m.at[0]
        if m.leg in (HORIZONTAL, *CORNERS):
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] - m.at[0] >= dx) for p in seen]))
        if m.leg == LEFTWARD:
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] > m.at[0]) for p in seen]))
        if m.leg == TOP_CORNER:
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] == m.at[0], p[1] < m.at[1]) for p in seen]))
        if m.leg in (BOTTOM, BOTTOM_CORNER):
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] == m.at[0], p[1] > m.at[1]) for p in seen]))
    return out


def _violation(ar: Arith, model: Model, spec: WhatIfSpec, movers: list[Mover], o_end: Pt, b: Pt | None) -> z3.BoolRef:
    r = movers[0]
    if spec.form == LEG:
        if len(movers) == 1:
            return segment_close(ar, model, o_end, r.at, r.end)
        return _movers_close(ar, model, r, movers[1])
    if spec.form == KEPT:
        return z3.Not(sees(ar, model, r.end, o_end))
    assert b is not None
    return z3.Not(z3.And(sees(ar, model, r.end, b), sees(ar, model, b, o_end)))


GAP = (
    "Under corner, repairs._edge_kept also passes an edge bridged through a robot on the mover's own vertical "
    "(which may move); no obligation here covers that form, so the corner's connectivity obligations, even all "
    "unsat, do not prove connectivity as a whole."
)


def argument(model: Model, spec: WhatIfSpec, built: Built) -> str:
    """The obligation's header: the claim, the legs, and what ``unsat`` covers."""
    other = "at rest" if spec.other == REST else f"moving by a {spec.other} leg"
    kinds = ",".join(sorted(spec.kinds))
    lines = [
        f"What-if obligation (fatline reach --with {kinds}; not the shipped rules): {spec.lemma}, form {spec.form}, "
        f"r's leg {spec.mine}, the other robot o {other}; model {model.name}, scheduler {model.options.scheduler}, "
        f"timing {model.options.timing}; on the lattice q = {spec.q} (integers, exact).",
        f"Claim: {spec.claim}.",
        "Legs (fatline_verify/repair/reach.py, family_legs), whole lattice units, at most one radius per axis: "
        "horizontal (k, 0); top (0, +-k) seeing no robot above on its vertical; bottom (0, k) seeing none below, "
        "ending >= 3 radii below each above; left (-k, 0); top-corner (k, -j) seeing none above; bottom-corner "
        "(k, j) seeing none below, ending >= 3 radii below each above.",
        "Each mover's conditions for every named robot it sees (repairs.allowed): not strictly left of it (the "
        "lock), clear of its swept disc (and of the robot's move right if on its vertical, for a corner leg), its "
        "class's condition on its vertical; kept: its end sees the robot (and it one radius right if the mover's "
        "leg is vertical in part and the robot on its vertical); bridged: b right of r, seen by r, sees r's end and "
        "o wherever repairs._anywhere puts it"
        + (" (under corner: at rest and one radius right)" if spec.corner_mode else "")
        + "; b sees r strictly left of it, so the lock holds it at rest.",
        f"Named robots: {', '.join(n for n in built.bodies if not n.endswith(chr(39)))} (r at the origin), "
        "pairwise disjoint discs, within a box that excludes no violation.",
        "Why unsat covers swarms of every size on this lattice: the conditions asserted are universal over the "
        "robots a mover sees, and every collision, and every edge with a mover at one end, is an instance of one "
        "obligation (fatline_verify/prove/smt/legs.py).",
    ]
    if spec.corner_mode and spec.lemma is Lemma.CONNECTIVITY:
        lines.append(GAP)
    return "\n".join(lines)


__all__ = ["KINDS", "WhatIfSpec", "argument", "arith", "build", "classes", "whatif_specs"]
