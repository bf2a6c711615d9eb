"""What-if leg obligations: the left and corner legs of ``fatline reach --with`` (not the shipped rules).

``fatline reach --with left,corner`` (:mod:`fatline_verify.repair.reach`) adds to the repaired family
two kinds of leg that no shipped obligation covers (:data:`fatline_verify.repair.reach.WHAT_IF`):

- ``left``: ``(-k, 0)``, ``1 <= k <= q`` lattice units (one radius or less), by a robot that sees no
  robot strictly left of it (the lock) and one right of it;
- ``left-alone``: ``left`` guarded: the mover sees no other robot on its own vertical (visibility is
  symmetric, so no robot that sees it on its vertical moves with it when one of them steps left:
  every pair of movers that see each other, and every bridge, with a ``left-alone`` leg never occurs),
  and the leg is at most ``spec.reach`` units (:func:`fatline_verify.repair.reach.left_alone_reach`: no
  robot the mover does not see reaches its path by a leg of the family);
- ``top-corner`` / ``bottom-corner`` (``corner``): ``(k, -j)`` by a robot seeing robots below it on its
  vertical and none above, ``(k, j)`` by one seeing robots above and none below, ending at least 3
  radii below each; ``1 <= k, j <= q`` (up to sqrt(2) radii long). ``repairs.allowed`` then also
  keeps the path clear of each robot on the mover's vertical moving one radius right, and its edge
  tests run with ``repair_progress = corner``.

Each mover's leg passed ``repairs.allowed`` for every robot it sees: not strictly left of it, clear of
its swept disc, its class's condition on its vertical, and the edge kept or bridged (the same tests as
:mod:`fatline_verify.prove.smt.family`). These obligations are those of :mod:`~fatline_verify.prove.smt.family`
(``no-collision/leg``, ``connectivity/kept``, ``connectivity/bridged``) over the extended set of
classes, every pair in which at least one robot is on a what-if class or, with ``corner`` (whose
edge tests differ), every pair. Two differences from the shipped forms, both still covering every
edge: ``bridged`` is asked only when r's edge test failed *kept* (``repairs._edge_kept`` tries it
first; otherwise each mover kept the edge: the ``kept`` form), and claims that r-o is an edge after
the round or r-b and b-o are (a path of at most two edges either way).

They are decided **on the lattice** of the model (``x = X / q``, integers, exact), where the family
of ``reach`` lives: a corner leg is sqrt(2) radii long, which the reals' nonlinear arithmetic does
not decide in time, while on the lattice every quantity is an integer. ``unsat`` covers every swarm
size on that lattice by the argument of :mod:`fatline_verify.prove.smt.family` (the conditions are
universal over the robots a mover sees; every collision and every edge with a mover at one end is
an instance of one obligation). ``repairs._edge_kept`` passes an edge it does not keep through a
robot right of the mover (at rest: the lock holds it), or, under ``corner``, through a robot on the
mover's own vertical, which may move (``bridged-vertical``, one obligation per leg of that robot).
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...model.options import Timing
from .cases import Arith, Pt, apart, sees, view_reach
from .claims import Built, capsules_close, segment_close

LEFT = "left"
LEFT_ALONE = "left-alone"
CORNER = "corner"
KINDS = (LEFT, LEFT_ALONE, CORNER)
"""The what-if kinds, as ``fatline reach --with`` names them."""

HORIZONTAL, TOP, BOTTOM = "horizontal", "top", "bottom"
LEFTWARD, TOP_CORNER, BOTTOM_CORNER = "left", "top-corner", "bottom-corner"
ALONE = "left-alone"
"""The guarded left leg's class (same name as its kind)."""
LEFTS = (LEFTWARD, ALONE)
VERTICAL_PART = (TOP, BOTTOM, TOP_CORNER, BOTTOM_CORNER)
CORNERS = (TOP_CORNER, BOTTOM_CORNER)
REST = "rest"
LEG, KEPT, BRIDGED, VERTICAL_BRIDGE = "leg", "kept", "bridged", "bridged-vertical"
FORMS = {Lemma.NO_COLLISION: (LEG,), Lemma.CONNECTIVITY: (KEPT, BRIDGED, VERTICAL_BRIDGE)}
BRIDGES = (BRIDGED, VERTICAL_BRIDGE)
CLAIM = {
    (Lemma.NO_COLLISION, LEG): "r and the other robot o never come within distance 2 during the round",
    (Lemma.CONNECTIVITY, KEPT): "r and o, within view before the round, are within view after it",
    (Lemma.CONNECTIVITY, BRIDGED): "r-o is an edge after the round, or r-b and b-o are (b at rest)",
    (Lemma.CONNECTIVITY, VERTICAL_BRIDGE): "r-o is an edge after the round, or r-b and b-o are (b on r's vertical, "
    "at rest or moving)",
}


def classes(kinds: frozenset[str]) -> tuple[str, ...]:
    """The leg classes of the family with the what-if ``kinds``."""
    out = [HORIZONTAL, TOP, BOTTOM]
    if LEFT in kinds:
        out.append(LEFTWARD)
    if LEFT_ALONE in kinds:
        out.append(ALONE)
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
    via: str = REST
    """``bridged-vertical``: the bridge b's leg (or :data:`REST`)."""
    reach: int | None = None
    """The longest ``left-alone`` leg in lattice units (:func:`fatline_verify.repair.reach.left_alone_reach`);
    ``None``: one radius (``q``)."""

    @property
    def left_units(self) -> int:
        """The longest ``left-alone`` leg, lattice units."""
        return self.q if self.reach is None else self.reach

    @property
    def key(self) -> str:
        """``lemma/form-leg.and.other[.via.leg]@q``: how rows and files name the obligation."""
        via = f".via.{self.via}" if self.form == VERTICAL_BRIDGE else ""
        return f"{self.lemma}/{self.form}-{self.mine}.and.{self.other}{via}@q{self.q}"

    @property
    def claim(self) -> str:
        return CLAIM[(self.lemma, self.form)]

    @property
    def corner_mode(self) -> bool:
        return CORNER in self.kinds


def whatif_specs(
    kinds: frozenset[str], q: int, lemmas: tuple[Lemma, ...], reach: int | None = None
) -> list[WhatIfSpec]:
    """Every obligation of the family with ``kinds``: as :func:`fatline_verify.prove.smt.family.specs`
    over :func:`classes`, keeping only pairs with a what-if class unless ``corner`` (whose edge tests
    differ from the shipped ones) is among the kinds. ``reach``: the longest ``left-alone`` leg
    (lattice units; ``None``: one radius)."""
    legs = classes(kinds)
    shipped = {HORIZONTAL, TOP, BOTTOM}
    specs: list[WhatIfSpec] = []
    for lemma in lemmas:
        for form in FORMS.get(lemma, ()):
            if form == VERTICAL_BRIDGE and CORNER not in kinds:
                continue  # repairs._edge_kept bridges through a robot on r's vertical only under corner
            for i, mine in enumerate(legs):
                others = [REST, *(legs if form in BRIDGES else legs[i:])]
                for other in others:
                    if form == VERTICAL_BRIDGE:
                        specs += [
                            WhatIfSpec(lemma, form, mine, other, frozenset(kinds), q, via, reach)
                            for via in (REST, *legs)
                        ]
                        continue
                    if CORNER not in kinds and mine in shipped and other in (shipped | {REST}):
                        continue  # a shipped obligation, unchanged (fatline prove repaired)
                    specs.append(WhatIfSpec(lemma, form, mine, other, frozenset(kinds), q, REST, reach))
    return specs


@dataclass(frozen=True)
class Mover:
    """A robot and its leg: start, end, class."""

    at: Pt
    end: Pt
    leg: str


def mover(ar: Arith, name: str, leg: str, at: Pt, left: Fraction = Fraction(1)) -> tuple[Mover, list[z3.BoolRef]]:
    """A leg of class ``leg`` from ``at``: whole lattice units, at most one radius along each axis it uses
    (a ``left-alone`` leg at most ``left`` radii)."""
    k = ar.var(f"{name}.k")
    zero, one = ar.num(0), ar.num(1)
    shape = [k > zero, k <= one]
    if leg == HORIZONTAL:
        end = (at[0] + k, at[1])
    elif leg in LEFTS:
        end = (at[0] - k, at[1])
        if leg == ALONE:
            shape = [k > zero, k <= ar.num(left)]
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
    # the lock: not strictly left of m; the left-alone guard: not on m's vertical either
    facts = [c[0] > m.at[0] if m.leg == ALONE else c[0] >= m.at[0], z3.Not(segment_close(ar, model, c, m.at, m.end))]
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


def places(
    ar: Arith, model: Model, m: Mover, c: Pt, corner_mode: bool, swarm: list[Pt] | None = None, c_leg: str = REST
) -> list[tuple[z3.BoolRef, Pt]]:
    """Where ``repairs._anywhere`` says a robot ``c`` that m sees may be after the round, each place with
    the condition under which it is listed. Under ``corner`` the top's and bottom's places depend on
    what else m sees on its vertical: with ``swarm`` (the named robots are all there are:
    :func:`closed_swarm`) exactly; without, only what c's own leg ``c_leg`` says: if c on m's vertical
    makes a top or top-corner leg, m sees no robot above c there (one above c that m sees is nearer to
    c than to m, so c would see it and not be the top), so the top's places are listed; likewise the
    bottom's for a bottom or bottom-corner leg. Leaving a place out weakens the test: still implied."""
    one, true = ar.num(1), ar.true()
    on = c[0] == m.at[0]
    out: list[tuple[z3.BoolRef, Pt]] = [(true, c), (on, _right(ar, c))]
    if not corner_mode:
        above_m = z3.And(on, c[1] > m.at[1])
        return [*out, (above_m, (c[0], c[1] + one)), (above_m, (c[0], c[1] - one))]

    def none_seen(beyond: z3.BoolRef, p: Pt) -> z3.BoolRef:
        return z3.Not(z3.And(sees(ar, model, m.at, p), p[0] == m.at[0], beyond))

    others = [p for p in swarm or [] if p is not c and p is not m.at]
    above = [none_seen(p[1] > c[1], p) for p in others]
    below = [none_seen(p[1] < c[1], p) for p in others]
    if swarm is None:
        above = [] if c_leg in (TOP, TOP_CORNER) else [ar.false()]
        below = [] if c_leg in (BOTTOM, BOTTOM_CORNER) else [ar.false()]
    top = z3.And(on, c[1] > m.at[1], *above)
    out += [(top, (c[0], c[1] + one)), (top, (c[0], c[1] - one)), (top, (c[0] + one, c[1] - one))]
    rise = z3.If(c[1] + one <= m.at[1] - ar.num(3), c[1] + one, m.at[1] - ar.num(3))
    bottom = z3.And(on, c[1] < m.at[1] - ar.num(3), *below)
    return [*out, (bottom, (c[0], rise)), (bottom, (c[0] + one, rise))]


def bridged(
    ar: Arith,
    model: Model,
    m: Mover,
    c: Pt,
    b: Pt,
    corner_mode: bool,
    swarm: list[Pt] | None = None,
    c_leg: str = REST,
) -> z3.BoolRef:
    """``repairs._edge_kept``'s second test: ``b`` right of m, seen by m, sees m's end and every place
    :func:`places` lists for ``c``."""
    where = places(ar, model, m, c, corner_mode, swarm, c_leg)
    anywhere = [z3.Implies(cond, sees(ar, model, b, p)) for cond, p in where]
    return z3.And(b[0] > m.at[0], sees(ar, model, m.at, b), sees(ar, model, m.end, b), *anywhere)


def vertical_bridged(
    ar: Arith,
    model: Model,
    m: Mover,
    c: Pt,
    b: Pt,
    swarm: list[Pt] | None = None,
    c_leg: str = REST,
    b_leg: str = REST,
) -> z3.BoolRef:
    """``repairs._edge_kept``'s third test (``repair_progress = corner``): ``b`` on m's vertical, seen by
    m; every place :func:`places` lists for b sees m's end and every place it lists for c."""
    bs = places(ar, model, m, b, True, swarm, b_leg)
    cs = places(ar, model, m, c, True, swarm, c_leg)
    facts = [z3.Implies(cb, sees(ar, model, pb, m.end)) for cb, pb in bs]
    facts += [z3.Implies(z3.And(cb, cc), sees(ar, model, pb, pc)) for cb, pb in bs for cc, pc in cs]
    return z3.And(b[0] == m.at[0], sees(ar, model, m.at, b), *facts)


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
    ar: Arith,
    model: Model,
    spec: WhatIfSpec,
    *,
    vacuity: bool = False,
    closed: bool = False,
    extra: int = 0,
    witnesses: bool = False,
) -> Built:
    """The obligation ``spec`` on ``ar``'s lattice; ``vacuity`` keeps only "the legs occur together".
    ``closed``: the named robots are the whole swarm (:func:`closed_swarm`), a stronger question whose
    answers are candidates for a counterexample, never a proof; ``extra`` more robots at rest ``e1``, ...
    join them there (a test of a mover may pass through one). ``witnesses``: each mover's leg needs a
    robot it sees (:func:`witness`); name one per mover, a stronger obligation, still implied.
    Every named robot lies within a box of the larger of the view and 5 radii around r: a violation
    needs the robots within view (an edge) or within 2 + 2 sqrt(2) < 5 (a collision), so the box
    excludes none."""
    left = Fraction(spec.left_units, spec.q)
    r, asserts = mover(ar, "r", spec.mine, ar.origin(), left)
    o_at = ar.point("o")
    bodies: dict[str, Pt] = {"r": r.at, "o": o_at}
    movers = {"r": r}
    if spec.other != REST:
        o, more = mover(ar, "o", spec.other, o_at, left)
        asserts += more
        movers["o"] = o
    if spec.form in BRIDGES:
        bodies["b"] = ar.point("b")
        if spec.form == VERTICAL_BRIDGE and spec.via != REST:
            b, more = mover(ar, "b", spec.via, bodies["b"], left)
            asserts += more
            movers["b"] = b
    for k in range(1, extra + 1 if closed else 1):
        bodies[f"e{k}"] = ar.point(f"e{k}")
    if witnesses:
        for n, m in list(movers.items()):
            bodies[f"w{n}"] = ar.point(f"w{n}")
            asserts.append(witness(ar, model, m, bodies[f"w{n}"]))
    box = ar.num(max(5, int(view_reach(model)) + 1))
    bounds = [z3.And(p[i] >= -box, p[i] <= box) for n, p in bodies.items() if n != "r" for i in (0, 1)]
    names = list(bodies)
    for i, a in enumerate(names):
        asserts += [apart(ar, model, bodies[a], bodies[b]) for b in names[i + 1 :]]
    for m in movers.values():
        asserts += [conditions(ar, model, m, p) for p in bodies.values() if p is not m.at]
    swarm = list(bodies.values()) if closed else None
    if spec.form == KEPT:
        asserts += [sees(ar, model, r.at, o_at), kept(ar, model, r, o_at)]
        asserts += [kept(ar, model, m, r.at) for n, m in movers.items() if n != "r"]
    if spec.form in BRIDGES:
        asserts += [sees(ar, model, r.at, o_at), z3.Not(kept(ar, model, r, o_at))]  # r's test did not keep it
    if spec.form == BRIDGED:
        asserts.append(bridged(ar, model, r, o_at, bodies["b"], spec.corner_mode, swarm, c_leg=spec.other))
    if spec.form == VERTICAL_BRIDGE:
        asserts.append(vertical_bridged(ar, model, r, o_at, bodies["b"], swarm, spec.other, spec.via))
    if closed:
        asserts += closed_swarm(ar, model, spec, list(movers.values()), list(bodies.values()))
        asserts.append(connected(ar, model, list(bodies.values())))
    ends = {n: (movers[n].end if n in movers else p) for n, p in bodies.items()}
    for n in movers:
        bodies[f"{n}'"] = ends[n]
    if not vacuity:
        asserts.append(_violation(ar, model, spec, movers, ends))
    return Built(ar, asserts + bounds, bodies, "o")


def witness(ar: Arith, model: Model, m: Mover, w: Pt) -> z3.BoolRef:
    """The robot ``reach.family_legs`` needs ``m`` to see for its leg: one below it on its vertical for a
    top-corner, above for a bottom or bottom-corner, right of it for a left leg, at least as far right
    as the leg goes for a horizontal one (a top needs none: ``w`` is then any robot it sees)."""
    seen = sees(ar, model, m.at, w)
    on = w[0] == m.at[0]
    if m.leg == TOP_CORNER:
        return z3.And(seen, on, w[1] < m.at[1])
    if m.leg in (BOTTOM, BOTTOM_CORNER):
        return z3.And(seen, on, w[1] > m.at[1])
    if m.leg in LEFTS:
        return z3.And(seen, w[0] > m.at[0])
    if m.leg == HORIZONTAL:
        return z3.And(seen, w[0] - m.at[0] >= m.end[0] - m.at[0])
    return seen


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
            bridges = [bridged(ar, model, m, p, b, spec.corner_mode, robots) for b in seen if b is not p]
            if spec.corner_mode:
                bridges += [vertical_bridged(ar, model, m, p, b, robots) for b in seen if b is not p]
            out.append(z3.Implies(sees(ar, model, m.at, p), z3.Or(kept(ar, model, m, p), *bridges)))
        dx = m.end[0] - m.at[0]
        if m.leg in (HORIZONTAL, *CORNERS):
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] - m.at[0] >= dx) for p in seen]))
        if m.leg in LEFTS:
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] > m.at[0]) for p in seen]))
        if m.leg == TOP_CORNER:
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] == m.at[0], p[1] < m.at[1]) for p in seen]))
        if m.leg in (BOTTOM, BOTTOM_CORNER):
            out.append(z3.Or(*[z3.And(sees(ar, model, m.at, p), p[0] == m.at[0], p[1] > m.at[1]) for p in seen]))
    return out


def _violation(ar: Arith, model: Model, spec: WhatIfSpec, movers: dict[str, Mover], ends: dict[str, Pt]) -> z3.BoolRef:
    r, o_end = movers["r"], ends["o"]
    if spec.form == LEG:
        if "o" not in movers:
            return segment_close(ar, model, o_end, r.at, r.end)
        return _movers_close(ar, model, r, movers["o"])
    if spec.form == KEPT:
        return z3.Not(sees(ar, model, r.end, o_end))
    b = ends["b"]
    path = z3.And(sees(ar, model, r.end, b), sees(ar, model, b, o_end))
    return z3.Not(z3.Or(sees(ar, model, r.end, o_end), path))


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
        "ending >= 3 radii below each above; left (-k, 0); left-alone (-k, 0), k <= "
        f"{spec.left_units} units, seeing no other robot on its own vertical; top-corner (k, -j) seeing none "
        "above; bottom-corner (k, j) seeing none below, ending >= 3 radii below each above.",
        "Each mover's conditions for every named robot it sees (repairs.allowed): not strictly left of it (the "
        "lock; for a left-alone leg not on its vertical either: the guard), clear of its swept disc (and of the "
        "robot's move right if on its vertical, for a corner leg), its class's condition on its vertical; kept: "
        "its end sees the robot (and it one radius right if the mover's leg is vertical in part and the robot on "
        "its vertical); bridged: b right of r, seen by r, sees r's end and o wherever repairs._anywhere puts it"
        + (" (under corner: at rest and one radius right)" if spec.corner_mode else "")
        + "; b sees r strictly left of it, so the lock holds it at rest.",
        f"Named robots: {', '.join(n for n in built.bodies if not n.endswith(chr(39)))} (r at the origin), "
        "pairwise disjoint discs, within a box that excludes no violation.",
        "Why unsat covers swarms of every size on this lattice: the conditions asserted are universal over the "
        "robots a mover sees, and every collision, and every edge with a mover at one end, is an instance of one "
        "obligation (fatline_verify/prove/smt/family.py): bridged when some mover's test for the other failed kept "
        "(that mover is r), through a robot right of it (bridged) or, under corner, on its vertical "
        "(bridged-vertical, that robot's leg named), kept otherwise; each edge before the round is then a path of "
        "at most two edges after.",
    ]
    return "\n".join(lines)


__all__ = ["KINDS", "WhatIfSpec", "argument", "arith", "build", "classes", "whatif_specs"]
