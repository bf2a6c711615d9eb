"""The guard language's symbolic interpreter, and the safety obligations any move family gives.

A rule set that declares a :class:`~fatline_verify.rules.family.family.MoveFamily` is proved safe from
the family alone, whatever its policy (the checker holds every decision to the family:
:mod:`fatline_verify.rules.family.enforce`). An obligation names a few robots (r at the origin, moving
by one leg class; o, at rest or moving by a class; for a bridged edge, a witness b, at rest or moving),
asserts each mover's family conditions **for every named robot**, and asks for a violation.

**The symbolic interpreter** (:func:`assumed`) turns a condition about what a mover sees into a z3 term
that the condition *implies* for the named robots, in any swarm they are part of:

- ``forall c seen: P(c)`` becomes ``P(u)`` for each named robot ``u`` the mover sees (a universal fact
  holds for the named ones); under a negation (needing a term that *implies* the condition) it becomes
  false;
- ``exists b seen: P(b)`` becomes true (nothing is known of which robot it is), or, under a negation,
  ``P(u)`` for some named ``u`` — except where an obligation **names its witness**: inside the instance
  of r's guard for the robot ``o``, the existential of role ``R`` is either false (the *kept* form: r's
  test for o passed without it) or ``P(b)`` for the named robot b (the *bridged* form).

**The obligations** (:func:`specs`), for every class of r and every class (or rest) of the others:

- ``no-collision/leg``: r and o come within 2 during the round;
- ``connectivity/kept``: r sees o before, each mover's test for the other passed without a witness, and
  r and o do not see each other after;
- ``connectivity/bridged``: r sees o before, r's test for o passed through the witness b of role ``R``,
  and neither r-o nor both r-b and b-o are edges after.

**Why unsat covers swarms of every size** (each obligation's header says so): every condition asserted is
one the real guards imply for the named robots, in any swarm. A collision in a round is between a mover
and another robot, at rest or moving: some ``leg`` obligation names the two (unseen robots included: a
condition on a robot applies only if the mover sees it, so the shapes alone must keep far robots apart).
An edge r-o before the round with a mover r at one end: if some mover's test for the other passed only
through a witness, name that mover r and the witness b: a ``bridged`` obligation covers it, and r-o is a
path of at most two edges after; otherwise each mover's test passed without a witness: the ``kept``
obligation covers it. So every edge before the round is a path of at most two edges after it, and a
connected swarm stays connected.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction

import z3

from ...lemmas.properties import Lemma
from ...model.config import Model
from ...model.options import Timing
from ...rules.family.family import REST, MoveFamily
from ...rules.family.lang import (
    XY,
    And,
    Clear,
    Cmp,
    Cond,
    Const,
    Distinct,
    Exists,
    Forall,
    Not,
    Num,
    Or,
    Sees,
    edge_roles,
    roles,
    walk,
)
from ...rules.family.lang import Pt as LPt
from .cases import Arith, Pt, apart, d2, sees, view_reach
from .claims import Built, capsules_close, segment_close

LEG, KEPT, BRIDGED = "leg", "kept", "bridged"
FORMS = {Lemma.NO_COLLISION: (LEG,), Lemma.CONNECTIVITY: (KEPT, BRIDGED)}
CLAIM = {
    (Lemma.NO_COLLISION, LEG): "r and the other robot o never come within distance 2 during the round",
    (Lemma.CONNECTIVITY, KEPT): "r and o, within view before the round, are within view after it",
    (Lemma.CONNECTIVITY, BRIDGED): "r-o is an edge after the round, or r-b and b-o are",
}

Witnessed = Mapping[tuple[str, str], str | None]
"""For one mover: ``(role, o) -> b`` names the witness of role ``role`` inside its guard's instance for the
named robot ``o`` (``None``: the existential is false there)."""


# --- the symbolic interpreter -------------------------------------------------------------------


@dataclass
class Scene:
    """The named robots of an obligation and what the interpreter needs."""

    ar: Arith
    model: Model
    at: dict[str, Pt]
    """Each named robot's centre before the round."""
    ends: dict[str, Pt] = field(default_factory=dict)


def _pt(p: LPt, env: Mapping[str, Pt], ar: Arith) -> Pt:
    if isinstance(p, XY):
        return (_num(p.x, env, ar), _num(p.y, env, ar))
    x, y = env[p.name]
    if p.offset[0] or p.offset[1]:
        return (x + ar.num(p.offset[0]), y + ar.num(p.offset[1]))
    return (x, y)


def _scalar(ar: Arith, k: Fraction) -> z3.ArithRef:
    """A dimensionless coefficient (not a length): an integer on a lattice, a rational over the reals."""
    if ar.lattice:
        if k.denominator != 1:
            raise ValueError(f"coefficient {k} is not an integer: the lattice domain multiplies by integers only")
        return z3.IntVal(int(k), ar.ctx)
    return z3.RealVal(f"{k.numerator}/{k.denominator}", ar.ctx)


def _num(n: Num, env: Mapping[str, Pt], ar: Arith) -> z3.ArithRef:
    total = ar.num(n.const)
    for name, axis, k in n.terms:
        coord = env[name][axis]
        total = total + (coord if k == 1 else coord * _scalar(ar, k))
    return total


def _close(ar: Arith, model: Model, a0: Pt, a1: Pt, b0: Pt, b1: Pt, same_a: bool, same_b: bool) -> z3.BoolRef:
    if same_b:
        return segment_close(ar, model, b0, a0, a1)
    if same_a:
        return segment_close(ar, model, a0, b0, b1)
    return capsules_close(ar, model, (a0, a1), (b0, b1))


def assumed(
    c: Cond,
    scene: Scene,
    mover: str,
    env: dict[str, Pt],
    *,
    positive: bool = True,
    witnessed: Witnessed | None = None,
    bound: tuple[str, ...] = (),
    unkept: tuple[str, ...] = (),
    exact: bool = False,
    forced: list[z3.BoolRef] | None = None,
) -> z3.BoolRef:
    """A z3 term for condition ``c`` of the robot ``mover`` (its ``me`` and ``end`` in ``env``) over the
    named robots of ``scene``: implied by ``c`` (``positive``) or implying it (under a negation); see the
    module docstring. ``bound``: the named robots the enclosing ``forall`` s are instantiated at.
    ``exact``: the named robots are every robot the mover sees (a ground view): each quantifier becomes the
    conjunction or disjunction of its instances, and the term is equivalent to ``c``, whatever the polarity
    (what the tests compare with the concrete interpreter). ``forced``: where a named witness is substituted,
    its term is also appended there (a bridged obligation asserts it: the test passed through that witness)."""
    ar, model = scene.ar, scene.model

    def rec(sub: Cond, pos: bool = positive, env2: dict[str, Pt] = env, b2: tuple[str, ...] = bound) -> z3.BoolRef:
        return assumed(
            sub,
            scene,
            mover,
            env2,
            positive=pos,
            witnessed=witnessed,
            bound=b2,
            unkept=unkept if b2 == bound else (),
            exact=exact,
            forced=forced,
        )

    others = [u for u in scene.at if u != mover]
    me = env["me"]
    match c:
        case Const(value=v):
            return ar.true() if v else ar.false()
        case Cmp(op=op, expr=e):
            v = _num(e, env, ar)
            zero = ar.num(0)
            return {"<": v < zero, "<=": v <= zero, ">": v > zero, ">=": v >= zero, "==": v == zero, "!=": v != zero}[
                op
            ]
        case Sees(a=a, b=b):
            return sees(ar, model, _pt(a, env, ar), _pt(b, env, ar))
        case Clear(a0=a0, a1=a1, b0=b0, b1=b1):
            same_a = a0 is a1 or (a0.name == a1.name != "" and a0.offset == a1.offset)
            same_b = b0 is b1 or (b0.name == b1.name != "" and b0.offset == b1.offset)
            pts = [_pt(p, env, ar) for p in (a0, a1, b0, b1)]
            return z3.Not(_close(ar, model, *pts, same_a, same_b))
        case Distinct(a=a, b=b):
            pa, pb = _pt(a, env, ar), _pt(b, env, ar)
            return z3.Or(pa[0] != pb[0], pa[1] != pb[1])
        case And(parts=ps):
            return ar.all([rec(p) for p in ps])
        case Or(parts=ps):
            return ar.any([rec(p) for p in ps])
        case Not(part=p):
            return z3.Not(rec(p, not positive))
        case Forall(var=v, body=body):
            if not positive and not exact:
                return ar.false()
            terms = []
            for u in others:
                inner = {**env, v: scene.at[u]}
                term = rec(body, True, inner, (*bound, u))
                if u in unkept:  # the test for u passed, but not without its witness
                    # every role of the body at u false: exactly "the test fails without its witnesses"
                    bare = {(role, u): None for role in roles(body)}
                    term = z3.And(
                        term,
                        z3.Not(assumed(body, scene, mover, inner, positive=False, witnessed=bare, bound=(*bound, u))),
                    )
                terms.append(z3.Implies(sees(ar, model, me, scene.at[u]), term))
            return ar.all(terms)
        case Exists(var=v, body=body, role=role):
            key = (role, bound[-1]) if bound else (role, "")
            if witnessed is not None and key in witnessed:  # a substitution, whatever the polarity
                w = witnessed[key]
                if w is None:
                    return ar.false()
                # A leg's witness (outside every forall, named w.MOVER.ROLE) may be any robot the mover sees:
                # a named one (o, b, the other mover, another witness) or one more robot, w. So the role is
                # the disjunction over them; w, unbounded, can stand far from every robot when it is not needed.
                at = [w, *(u for u in others if u != w)] if key[1] == "" and w.startswith("w.") else [w]
                term = ar.any(
                    [
                        z3.And(sees(ar, model, me, scene.at[u]), rec(body, positive, {**env, v: scene.at[u]}, bound))
                        for u in at
                    ]
                )
                if forced is not None and positive:
                    forced.append(term)
                return term
            if not positive or exact:
                return ar.any(
                    [
                        z3.And(sees(ar, model, me, scene.at[u]), rec(body, False, {**env, v: scene.at[u]}, bound))
                        for u in others
                    ]
                )
            return ar.true()
    raise TypeError(f"{c!r}: not a condition of the guard language")


# --- the obligations --------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class FamilySpec:
    """One obligation of a move family: a lemma form, r's class, o's (or :data:`REST`), and for a
    bridged edge the witness role and the witness's class (or rest)."""

    lemma: Lemma
    form: str
    mine: str
    other: str
    role: str = ""
    witness: str = ""

    @property
    def name(self) -> str:
        return self.mine

    @property
    def other_name(self) -> str:
        if not self.role:
            return self.other
        return f"{self.other}.by.{self.role}" if not self.witness else f"{self.other}.by.{self.role}-{self.witness}"

    @property
    def ruled_out(self) -> bool:
        """A ``leg`` or ``kept`` obligation in the case where r's test for o passed only through a witness that
        rules out o's class (:attr:`~fatline_verify.rules.family.family.MoveFamily.rules_out`)."""
        return bool(self.role) and self.form != BRIDGED

    @property
    def key(self) -> str:
        """``lemma/form-mine.and.other[.by.role-witness]``: how result rows and files name the obligation."""
        return f"{self.lemma}/{self.form}-{self.mine}.and.{self.other_name}"

    @property
    def claim(self) -> str:
        return CLAIM[(self.lemma, self.form)]


def specs(family: MoveFamily, lemmas: tuple[Lemma, ...]) -> list[FamilySpec]:
    """Every obligation of ``family`` for ``lemmas``: unordered pairs where the two robots play the same
    part (``leg``, ``kept``); for ``bridged``, every class of r, every class or rest of o, every witness
    role of r's guard (but those that rule a class out) and every class or rest of the witness. A role that
    rules out a class (``rules_out``) adds, for every class of r whose guard names it, the ``leg`` and ``kept``
    obligations of o moving by that class with the witness named (``.by.ROLE``; the witness's own move is
    not assumed)."""
    names = [c.name for c in family.classes]
    out: list[FamilySpec] = []
    for lemma in lemmas:
        for form in FORMS.get(lemma, ()):
            for i, mine in enumerate(names):
                if form != BRIDGED:
                    out += [FamilySpec(lemma, form, mine, other) for other in (REST, *names[i:])]
                    out += [
                        FamilySpec(lemma, form, mine, family.rules_out[role], role)
                        for role in roles(family.get(mine).guard)
                        if role in family.rules_out
                    ]
                    continue
                for role in edge_roles(family.get(mine).guard):
                    if role in family.rules_out:
                        continue
                    out += [
                        FamilySpec(lemma, form, mine, other, role, witness)
                        for other in (REST, *names)
                        for witness in (REST, *names)
                    ]
    return out


def leg_roles(c: Cond) -> tuple[str, ...]:
    """The witness roles of ``c`` outside every ``forall``: robots the leg needs its mover to see."""

    def top(sub: Cond) -> list[str]:
        match sub:
            case Exists(role=role):
                return [role]
            case And(parts=ps) | Or(parts=ps):
                return [r for p in ps for r in top(p)]
            case Not(part=p):
                return top(p)
        return []

    return tuple(dict.fromkeys(top(c)))


def _move(
    scene: Scene,
    family: MoveFamily,
    name: str,
    cls: str,
    witnessed: Witnessed | None,
    unkept: tuple[str, ...] = (),
    *,
    exact: bool = False,
) -> list[z3.BoolRef]:
    """A mover's leg of class ``cls``: its end, the class's shape, not held, and its guard over the named robots
    (``exact``: the named robots are all it sees)."""
    ar = scene.ar
    at = scene.at[name]
    end = (ar.var(f"{name}.end.x"), ar.var(f"{name}.end.y"))
    scene.ends[name] = end
    leg = family.get(cls)
    env = {"me": at, "end": end}
    # A bridged edge (unkept) whose test has several witness roles: the test passed, not without a witness, so
    # through the witness of some role; this obligation is the case of the role it names, whose term is asserted
    # apart (inside the guard an unnamed role's existential is true and would leave the named one free).
    forced: list[z3.BoolRef] | None = [] if unkept and len(edge_roles(leg.guard)) > 1 else None
    guard = assumed(leg.guard, scene, name, env, witnessed=witnessed, unkept=unkept, exact=exact, forced=forced)
    return [
        assumed(leg.shape, scene, name, env),
        z3.Not(assumed(family.at_rest, scene, name, env, positive=False, exact=exact)),
        ar.all([guard, *(forced or [])]),
    ]


def connected(ar: Arith, model: Model, robots: list[Pt]) -> z3.BoolRef:
    """The visibility graph of ``robots`` (a handful) is connected: every cut has an edge across."""
    n = len(robots)
    cuts = []
    for mask in range(1, 2 ** (n - 1)):  # the last robot always on the other side: each cut once
        side = [bool(mask >> i & 1) for i in range(n - 1)] + [False]
        across = [
            sees(ar, model, robots[i], robots[j]) for i in range(n) for j in range(i + 1, n) if side[i] != side[j]
        ]
        cuts.append(ar.any(across))
    return ar.all(cuts)


def _after(scene: Scene, name: str) -> Pt:
    return scene.ends.get(name, scene.at[name])


def _movers_close(scene: Scene, a: str, b: str) -> z3.BoolRef:
    ar, model = scene.ar, scene.model
    a0, a1, b0, b1 = scene.at[a], _after(scene, a), scene.at[b], _after(scene, b)
    if b not in scene.ends:
        return segment_close(ar, model, b0, a0, a1)
    if model.options.timing is Timing.ANY_SPEED:
        return capsules_close(ar, model, (a0, a1), (b0, b1))
    d0 = (a0[0] - b0[0], a0[1] - b0[1])
    d1 = (a1[0] - b1[0], a1[1] - b1[1])
    return segment_close(ar, model, ar.origin(), d0, d1)


def build(
    ar: Arith,
    model: Model,
    family: MoveFamily,
    spec: FamilySpec,
    *,
    vacuity: bool = False,
    immediate: bool = False,
    initial: bool = False,
    witnesses: bool = False,
    closed: int | None = None,
) -> Built:
    """The obligation ``spec`` over ``ar``'s domain; ``vacuity`` keeps only "the legs occur together";
    ``immediate`` leaves out each mover's guard (its shape and at_rest stay): unsat means the claim follows
    from the classes' shapes alone. ``initial``: the named robots also form an initial configuration (at
    least delta apart, their visibility graph connected): where a counterexample is replayed from.
    ``witnesses``: each mover's leg witnesses (:func:`leg_roles`: a robot its leg needs it to see) are named
    robots too, ``w.MOVER.ROLE``, and each mover's guard is asserted for them (a stronger obligation, still
    implied: they are robots of the swarm). On a lattice every named robot but a leg witness lies within a box
    around r that excludes no violation (:func:`_box`; a leg witness is within view of its mover).
    ``closed``: the named robots and ``closed`` more at rest (``e1``, ...) are the whole swarm, connected, and
    each guard is read exactly on them (:func:`assumed`'s ``exact``): a stronger question whose answers are
    candidates for a counterexample, never a proof."""
    at = {"r": ar.origin(), "o": ar.point("o")}
    if spec.role:
        at["b"] = ar.point("b")
    classes = {"r": spec.mine, "o": spec.other, "b": spec.witness or REST}
    leg_witnesses: dict[str, dict[tuple[str, str], str]] = {}
    if witnesses:
        for name in list(at):
            cls = classes[name]
            if cls == REST:
                continue
            for role in leg_roles(family.get(cls).guard):
                w = f"w.{name}.{role}"
                at[w] = ar.point(w)
                leg_witnesses.setdefault(name, {})[(role, "")] = w
    for k in range(1, (closed or 0) + 1):
        at[f"e{k}"] = ar.point(f"e{k}")
    scene = Scene(ar, model, at)
    names = list(at)
    asserts: list[z3.BoolRef] = []
    for i, a in enumerate(names):
        asserts += [apart(ar, model, at[a], at[b]) for b in names[i + 1 :]]
    if initial:
        asserts += _initial(ar, model, [at[n] for n in names if not n.startswith("w.")])
    tests: dict[str, Witnessed] = {}
    if spec.ruled_out:  # r's test for o passed only through the witness b; o's test for r: unknown
        tests = {"r": {(spec.role, "o"): "b"}}
    elif spec.form == LEG and family.rules_out:
        tests = {"r": _split(family, spec.other, "o"), "o": _split(family, spec.mine, "r")}
    elif spec.form == KEPT:
        tests = {
            "r": {(role, "o"): None for role in _all_roles(family) if _split_on(family, role, spec.other)},
            "o": {(role, "r"): None for role in _all_roles(family) if _split_on(family, role, spec.mine)},
        }
    elif spec.form == BRIDGED:
        tests = {"r": {(spec.role, "o"): "b", **_split(family, spec.other, "o")}}
    for name, named in leg_witnesses.items():
        tests[name] = {**tests.get(name, {}), **named}
    for name in names:
        cls = classes.get(name, REST)
        if cls == REST:
            continue
        unkept = ("o",) if spec.form == BRIDGED and name == "r" else ()
        parts = _move(scene, family, name, cls, tests.get(name), unkept, exact=closed is not None)
        asserts += parts[:2] if immediate else parts
        if name == "r" and spec.ruled_out and not immediate:
            asserts.append(_witnessed(scene, family.get(cls).guard, spec.role))
    if spec.form in (KEPT, BRIDGED):
        asserts.append(sees(ar, model, at["r"], at["o"]))
    if closed is not None:
        asserts.append(connected(ar, model, list(at.values())))
    bodies = dict(at)
    bodies.update({f"{n}'": _after(scene, n) for n in names})
    if not vacuity:
        asserts.append(_violation(scene, spec))
    bounds = _box(ar, model, family, [at[n] for n in names if n in ("o", "b")]) if ar.lattice else []
    return Built(ar, asserts, bodies, "o", bounds=bounds)


def _box(ar: Arith, model: Model, family: MoveFamily, points: list[Pt]) -> list[z3.BoolRef]:
    """On a lattice: ``points`` within a box around r (at the origin) of half-side the larger of the view and
    ``2 + 2 max_step`` radii. o and b are seen by r (an edge, a bridge) or come within 2 of r's path while
    both move at most ``max_step`` (a collision), so the box excludes no violation; integers in a box keep the
    solver's nonlinear integer arithmetic finite."""
    half = max(view_reach(model), 2 + 2 * Fraction(family.max_step))
    box = ar.num(-(-half.numerator // half.denominator))
    return [z3.And(p[i] >= -box, p[i] <= box) for p in points for i in (0, 1)]


def _initial(ar: Arith, model: Model, points: list[Pt]) -> list[z3.BoolRef]:
    """The named robots at least delta apart, their visibility graph connected (two or three robots)."""
    delta = Fraction(model.parameters.delta)
    pairs = [(i, j) for i in range(len(points)) for j in range(i + 1, len(points))]
    out = [ar.cmp2(d2(points[i], points[j]), ">=", delta) for i, j in pairs]
    edges = [sees(ar, model, points[i], points[j]) for i, j in pairs]
    if len(points) == 2:
        return [*out, edges[0]]
    return [*out, z3.AtLeast(*edges, len(points) - 1)]


def _witnessed(scene: Scene, guard: Cond, role: str) -> z3.BoolRef:
    """The case of a ``.by.ROLE`` obligation: in r's guard, instantiated at o, some existential of ``role`` holds
    with the witness b (r sees b). Only existentials directly under the guard's ``forall`` over o are read;
    where another binds a variable their bodies use, nothing is asserted (the weaker case, still sound)."""
    ar = scene.ar
    r, o, b = scene.at["r"], scene.at["o"], scene.at["b"]
    cases: list[z3.BoolRef] = []
    for top in walk(guard):
        if not isinstance(top, Forall):
            continue
        for sub in walk(top.body):
            if isinstance(sub, Exists) and sub.role == role:
                env = {"me": r, "end": scene.ends["r"], top.var: o, sub.var: b}
                try:
                    body = assumed(sub.body, scene, "r", env)
                except KeyError:  # a variable bound elsewhere: no case to assert
                    return ar.true()
                cases.append(z3.And(sees(ar, scene.model, r, b), body))
    return ar.any(cases) if cases else ar.true()


def _split_on(family: MoveFamily, role: str, cls: str) -> bool:
    """Whether the existential of ``role`` about a robot moving by ``cls`` (or at rest) is split on: every
    bridge role, and a role that rules out exactly ``cls``; another that rules a class out is left unknown."""
    return role not in family.rules_out or family.rules_out[role] == cls


def _split(family: MoveFamily, cls: str, u: str) -> dict[tuple[str, str], str | None]:
    """The roles that rule out ``cls``, false in a test for the robot ``u`` (the case without their witness)."""
    return {(role, u): None for role, ruled in family.rules_out.items() if ruled == cls}


def _all_roles(family: MoveFamily) -> tuple[str, ...]:
    out: list[str] = []
    for c in family.classes:
        out += [r for r in roles(c.guard) if r not in out]
    return tuple(out)


def _violation(scene: Scene, spec: FamilySpec) -> z3.BoolRef:
    ar, model = scene.ar, scene.model
    if spec.form == LEG:
        return _movers_close(scene, "r", "o")
    r, o = _after(scene, "r"), _after(scene, "o")
    lost = z3.Not(sees(ar, model, r, o))
    if spec.form == KEPT:
        return lost
    b = _after(scene, "b")
    return z3.And(lost, z3.Not(z3.And(sees(ar, model, r, b), sees(ar, model, b, o))))


def argument(model: Model, family: MoveFamily, spec: FamilySpec, built: Built) -> str:
    """The obligation's header: the claim, the family, and why ``unsat`` covers every swarm size."""

    def robot(cls: str) -> str:
        return "at rest" if cls == REST else f"moving by a {cls} leg"

    named = ", ".join(n for n in built.bodies if not n.endswith("'"))
    witness = f"; the witness b of role {spec.role} {robot(spec.witness)}" if spec.role else ""
    if spec.ruled_out:
        witness = (
            f"; r's test for o passed only through the witness b of role {spec.role}, which rules out o's "
            f"{spec.other} leg (b's own move not assumed)"
        )
    split = (
        " A witness role that rules out a class of o (rules_out) is false in the plain obligation of a pair where o "
        "moves by that class and named in its .by.ROLE obligation (the two cases), and unknown elsewhere."
        if family.rules_out
        else ""
    )
    classes = "; ".join(f"{c.name}: {c.says or 'see the family'}" for c in family.classes)
    return "\n".join(
        [
            f"Obligation: {spec.lemma}, form {spec.form}, r's leg {spec.mine}, the other robot o {robot(spec.other)}"
            f"{witness}; model {model.name}, move family {family.name}, scheduler {model.options.scheduler}, "
            f"timing {model.options.timing}.",
            f"Claim: {spec.claim}.",
            f"Family: {family.says or family.name}. Classes: {classes}. Longest move {family.max_step} radii. "
            "Every decision of the rule set is held to the family as it runs (the step lemma in-family) and on "
            "every view of the lattice (the row in-family/views).",
            f"Named robots: {named} (r at the origin), pairwise disjoint discs; each mover's shape, not held "
            "(at_rest), and its guard for every named robot it sees (forall: each named robot; exists: true, "
            "or the named witness where the form names it).",
            "Why unsat covers swarms of every size: each asserted condition is implied by the family's guards for "
            "the named robots in any swarm; every collision, and every edge with a mover at one end, is an "
            "instance of one obligation (fatline_verify/prove/smt/family.py, the module docstring), so each edge "
            f"before the round is a path of at most two edges after it and the swarm stays connected.{split}",
            f"Rests on: {family.rests_on or 'nothing outside the family'}.",
            "Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.",
        ]
    )


__all__ = [
    "BRIDGED",
    "FORMS",
    "KEPT",
    "LEG",
    "FamilySpec",
    "Scene",
    "argument",
    "assumed",
    "build",
    "edge_roles",
    "leg_roles",
    "specs",
]
