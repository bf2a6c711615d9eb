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

- ``connectivity/answered`` (a family whose guards have a :func:`~fatline_verify.rules.family.lang.chain`),
  for every class of r and of o, o below r in the family's order (``MoveFamily.order``): r's test for o passed
  without a witness (o's own test not assumed), and r and o do not see each other after;
- ``connectivity/chain-first`` and ``chain-link`` (the same families), for every class of r and every class or
  rest of o (and of b): the chain's first link admits o (from r's end), or its link admits b to o, in r's view,
  and r and o (b and o) do not see each other after, and it is not an edge before the round with a mover above r
  in the order;
- ``connectivity/rules-out-rest.and.CLASS.by.ROLE`` (a role that rules out a class): a robot o moving by that
  class is the robot a witness b of the role speaks of, in the view of a robot r that sees both. Unsat: no
  robot moving by a class ever has a witness of a role ruling that class out, so every obligation may take that
  existential as false
  about such a robot (the bridged ones do, about o and about their witness b).

An existential is keyed by its role and the named robots its body speaks of (:func:`about`): the robot a
``forall`` binds (a bridge of the edge to o), or the witness an enclosing existential names (the class of that
witness a nested role rules out).

**Why unsat covers swarms of every size** (each obligation's header says so): every condition asserted is
one the real guards imply for the named robots, in any swarm. A collision in a round is between a mover
and another robot, at rest or moving: some ``leg`` obligation names the two (unseen robots included: a
condition on a robot applies only if the mover sees it, so the shapes alone must keep far robots apart).
An edge r-o before the round with a mover r at one end: if some mover's test for the other passed only
through a witness, name that mover r and the witness b: a ``bridged`` obligation covers it, and r-o is a
path of at most two edges after; otherwise each mover's test passed without a witness: the ``kept``
obligation covers it. So every edge before the round is a path of at most two edges after it, and a
connected swarm stays connected.

With chains (the closure over robots a rule set reaches another through, any number of links) the conclusion
is reached by induction. An edge's *level* is the greatest order of a mover at its ends (an edge with no mover
is kept); every edge of a level above ``L`` is connected after the round, and let r-o be of level ``L``, r a
mover of order ``L``, o at rest or a mover not above r. If r's test for o passed without a witness: o at rest is
``kept`` (with ``REST``); o a mover below r is ``answered`` (r's test alone); o a mover of the same order is
``kept`` (both tests), or else o's test passed through a witness and o is named r below. Through a bridge:
``bridged`` (a path of two edges after the round). Through a chain: each of its links is an edge after the round
or an edge before it with a mover above r (``chain-first``, ``chain-link``), so of a level above ``L`` and
connected after the round by the induction: the chain is a path after it. Levels are finitely many, so every
edge before the round is connected after it.
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
    Chain,
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
    chain_roles,
    edge_roles,
    free_names,
    roles,
    walk,
)
from ...rules.family.lang import Pt as LPt
from .cases import Arith, Pt, apart, d2, sees, view_reach
from .claims import Built, capsules_close, segment_close

LEG, KEPT, BRIDGED, RULES, ANSWERED = "leg", "kept", "bridged", "rules-out", "answered"
FIRST, LINK = "chain-first", "chain-link"
FORMS = {Lemma.NO_COLLISION: (LEG,), Lemma.CONNECTIVITY: (KEPT, ANSWERED, BRIDGED, FIRST, LINK, RULES)}
CLAIM = {
    (Lemma.CONNECTIVITY, ANSWERED): "r, above o in the family's order, and o, within view before the round, are within "
    "view after it (r's test for o passed without a witness; o's own test not assumed)",
    (Lemma.CONNECTIVITY, FIRST): "where r's chain starts at o, r sees o after the round, or o moves and is above r in "
    "the family's order",
    (Lemma.CONNECTIVITY, LINK): "where a link of r's chain joins b to o, b sees o after the round, or b-o is an edge "
    "before it with a mover above r in the family's order",
    (Lemma.CONNECTIVITY, RULES): "no robot o moving by the class the role rules out has a witness of the role (in the "
    "view of a robot r that sees both)",
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
    names: Mapping[str, str] | None = None,
) -> z3.BoolRef:
    """A z3 term for condition ``c`` of the robot ``mover`` (its ``me`` and ``end`` in ``env``) over the
    named robots of ``scene``: implied by ``c`` (``positive``) or implying it (under a negation); see the
    module docstring. ``bound``: the named robots the enclosing ``forall`` s are instantiated at.
    ``exact``: the named robots are every robot the mover sees (a ground view): each quantifier becomes the
    conjunction or disjunction of its instances, and the term is equivalent to ``c``, whatever the polarity
    (what the tests compare with the concrete interpreter). ``forced``: where a named witness is substituted,
    its term is also appended there (a bridged obligation asserts it: the test passed through that witness).
    ``names``: the named robot each variable of an enclosing quantifier is instantiated at; an existential is
    keyed in ``witnessed`` by its role and the robots its body speaks of (:func:`about`)."""
    ar, model = scene.ar, scene.model
    names = names or {}

    def rec(
        sub: Cond,
        pos: bool = positive,
        env2: dict[str, Pt] = env,
        b2: tuple[str, ...] = bound,
        n2: Mapping[str, str] = names,
    ) -> z3.BoolRef:
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
            names=n2,
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
                term = rec(body, True, inner, (*bound, u), {**names, v: u})
                if u in unkept:  # the test for u passed, but not without its witness
                    # every role of the body at u false: exactly "the test fails without its witnesses"
                    bare = {(role, u): None for role in roles(body)}
                    term = z3.And(
                        term,
                        z3.Not(
                            assumed(
                                body, scene, mover, inner, positive=False, witnessed=bare, bound=(*bound, u),
                                names={**names, v: u},
                            )
                        ),
                    )  # fmt: skip
                terms.append(z3.Implies(sees(ar, model, me, scene.at[u]), term))
            return ar.all(terms)
        case Exists(var=v, body=body, role=role):
            key = (role, "+".join(names.get(f, f) for f in about(c)))
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
                        z3.And(
                            sees(ar, model, me, scene.at[u]),
                            rec(body, positive, {**env, v: scene.at[u]}, bound, {**names, v: u}),
                        )
                        for u in at
                    ]
                )
                if forced is not None and positive:
                    forced.append(term)
                return term
            if not positive or exact:
                return ar.any(
                    [
                        z3.And(
                            sees(ar, model, me, scene.at[u]),
                            rec(body, False, {**env, v: scene.at[u]}, bound, {**names, v: u}),
                        )
                        for u in others
                    ]
                )
            return ar.true()
        case Chain(x=x, y=y, first=first, link=link, to=to, role=role):
            key = (role, "+".join(names.get(f, f) for f in about(c)))
            if witnessed is not None and witnessed.get(key, "") is None:
                return ar.false()
            if not exact:  # its links are proved apart (chain-first, chain-link): true, or false under a negation
                return ar.true() if positive else ar.false()
            # a ground view: the closure over the named robots, one more link per round
            seen_ = [u for u in others]
            step = {
                (w, u): rec(link, positive, {**env, x: scene.at[w], y: scene.at[u]})
                for w in seen_
                for u in seen_
                if w != u
            }
            reach = {u: rec(first, positive, {**env, y: scene.at[u]}) for u in seen_}
            for _ in seen_[1:]:
                reach = {u: z3.Or(reach[u], *(z3.And(reach[w], step[(w, u)]) for w in seen_ if w != u)) for u in seen_}
            target = _pt(to, env, ar)
            return ar.any(
                [
                    z3.And(
                        sees(ar, model, me, scene.at[u]),
                        target[0] == scene.at[u][0],
                        target[1] == scene.at[u][1],
                        reach[u],
                    )
                    for u in others
                ]
            )
    raise TypeError(f"{c!r}: not a condition of the guard language")


def about(c: Exists | Chain) -> tuple[str, ...]:
    """The variables an existential's body speaks of, bound outside it (not ``me``, ``end`` or its own witness):
    the robot a ``forall`` binds (``(c,)`` for a bridge of the edge to c), none for a leg's witness, the robot a
    named witness stands for in an existential nested in its body."""
    got = _ABOUT.get(id(c))
    if got is None or got[0] is not c:
        own = {c.var} if isinstance(c, Exists) else {c.x, c.y}
        got = _ABOUT[id(c)] = (c, tuple(n for n in free_names(c) if n not in own | {"me", "end"}))
    return got[1]


_ABOUT: dict[int, tuple[Exists | Chain, tuple[str, ...]]] = {}


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
        return bool(self.role) and self.form in (LEG, KEPT)

    @property
    def key(self) -> str:
        """``lemma/form-mine.and.other[.by.role-witness]``: how result rows and files name the obligation
        (``connectivity/rules-out-rest.and.CLASS.by.ROLE`` for a role's own)."""
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
            if form == RULES:
                used = {r for c in family.classes for r in roles(c.guard)}
                out += [
                    FamilySpec(lemma, RULES, REST, cls, role) for role, cls in family.rules_out.items() if role in used
                ]
                continue
            for i, mine in enumerate(names):
                chains = chain_roles(family.get(mine).guard)
                if form == ANSWERED:
                    out += [FamilySpec(lemma, form, mine, other) for other in names] if inducts(family) else []
                    continue
                if form == FIRST:
                    out += [FamilySpec(lemma, form, mine, other, role) for role in chains for other in (REST, *names)]
                    continue
                if form == LINK:
                    out += [
                        FamilySpec(lemma, form, mine, other, role, before)
                        for role in chains
                        for other in (REST, *names)
                        for before in (REST, *names)
                    ]
                    continue
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
    if spec.role and spec.form != FIRST:
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
    elif spec.form == ANSWERED:
        tests = {"r": {(role, "o"): None for role in _all_roles(family) if _split_on(family, role, spec.other)}}
    elif spec.form == KEPT:
        tests = {
            "r": {(role, "o"): None for role in _all_roles(family) if _split_on(family, role, spec.other)},
            "o": {(role, "r"): None for role in _all_roles(family) if _split_on(family, role, spec.mine)},
        }
    elif spec.form == BRIDGED:
        # the roles that rule out o's class, and b's, false about them (the rules-out obligations: a robot
        # moving by a class has no witness of a role ruling it out)
        tests = {"r": {(spec.role, "o"): "b", **_split(family, spec.other, "o"), **_split(family, classes["b"], "b")}}

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
    if spec.form in (KEPT, BRIDGED, RULES, ANSWERED, FIRST, LINK):
        asserts.append(sees(ar, model, at["r"], at["o"]))
    if spec.form in (RULES, LINK):
        asserts.append(sees(ar, model, at["r"], at["b"]))
    if inducts(family) and spec.form in (KEPT, ANSWERED) and spec.other != REST:
        # the induction's cases (module docstring): the edge's mover of the greatest order answers for it
        r_key, o_key = _key(ar, family, at["r"]), _key(ar, family, at["o"])
        asserts.append(r_key == o_key if spec.form == KEPT else o_key < r_key)
    if spec.form in (FIRST, LINK) and not immediate:
        asserts.append(_linked(scene, family, spec))
    if spec.form == RULES:
        asserts.append(sees(ar, model, at["r"], at["b"]))
        scene.ends["r"] = (ar.var("r.end.x"), ar.var("r.end.y"))  # what r's own end is: anything
    if closed is not None:
        asserts.append(connected(ar, model, list(at.values())))
    bodies = dict(at)
    bodies.update({f"{n}'": _after(scene, n) for n in names})
    if not vacuity:
        asserts.append(_violation(scene, spec, family))
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
    with the witness b (r sees b). Only existentials about o (:func:`about`: the ``forall``'s variable alone) are
    read, not those about a robot a chain or another witness binds; where another binds a variable their bodies
    use, nothing is asserted (the weaker case, still sound)."""
    ar = scene.ar
    r, o, b = scene.at["r"], scene.at["o"], scene.at["b"]
    cases: list[z3.BoolRef] = []
    for top in walk(guard):
        if not isinstance(top, Forall):
            continue
        for sub in walk(top.body):
            if isinstance(sub, Exists) and sub.role == role and about(sub) == (top.var,):
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


def inducts(family: MoveFamily) -> bool:
    """Whether the family's connectivity argument inducts over its order (its guards have chains)."""
    return any(chain_roles(c.guard) for c in family.classes)


def _chains(family: MoveFamily, cls: str, role: str) -> list[Chain]:
    """The chains of ``role`` in the guard of ``cls``; each speaks only of its own two robots, ``me`` and ``end``."""
    out = [sub for sub in walk(family.get(cls).guard) if isinstance(sub, Chain) and sub.role == role]
    for ch in out:
        stray = [n for n in free_names(ch.first) + free_names(ch.link) if n not in (ch.x, ch.y, "me", "end")]
        if stray:
            raise ValueError(
                f"move family {family.name!r}: the chain {role!r} of {cls} speaks of {sorted(set(stray))}; expected "
                "its links to speak of their two robots, me and end only"
            )
    return out


def _linked(scene: Scene, family: MoveFamily, spec: FamilySpec) -> z3.BoolRef:
    """r's chain of ``spec.role`` starts at o (``chain-first``) or links b to o (``chain-link``), in r's view; a
    role that rules out o's class or b's is false about it (the rules-out obligations)."""
    at = scene.at
    splits = {**_split(family, spec.other, "o"), **_split(family, spec.witness or REST, "b")}
    terms = []
    for ch in _chains(family, spec.mine, spec.role):
        env = {"me": at["r"], "end": scene.ends["r"], ch.y: at["o"]}
        names = {ch.y: "o"}
        body = ch.first
        if spec.form == LINK:
            env[ch.x], names[ch.x], body = at["b"], "b", ch.link
        terms.append(assumed(body, scene, "r", env, witnessed=splits, names=names))
    return scene.ar.any(terms)


def _key(ar: Arith, family: MoveFamily, p: Pt) -> z3.ArithRef:
    """A point's place in the family's order (``a x + b y``)."""
    a, b = family.order or (Fraction(0), Fraction(0))
    return _scalar(ar, Fraction(a)) * p[0] + _scalar(ar, Fraction(b)) * p[1]


def _occurrences(family: MoveFamily, role: str) -> list[Exists]:
    """Every existential of ``role`` in the family's guards, each speaking of one robot (:func:`about`)."""
    out: list[Exists] = []
    for cls in family.classes:
        for sub in walk(cls.guard):
            if isinstance(sub, Exists) and sub.role == role and all(sub is not e for e in out):
                if len(about(sub)) != 1:
                    raise ValueError(
                        f"move family {family.name!r}: role {role!r} rules out a class but its condition speaks of "
                        f"{list(about(sub)) or 'no robot'}; expected exactly one (the robot whose class it rules out)"
                    )
                out.append(sub)
    return out


def _ruling(scene: Scene, family: MoveFamily, role: str) -> z3.BoolRef:
    """Some existential of ``role`` holds in r's view about o (moving by the class it rules out), witness b."""
    at = scene.at
    terms = []
    for sub in _occurrences(family, role):
        (var,) = about(sub)
        env = {"me": at["r"], "end": scene.ends["r"], var: at["o"], sub.var: at["b"]}
        terms.append(assumed(sub.body, scene, "r", env, names={var: "o", sub.var: "b"}))
    return scene.ar.any(terms)


def _violation(scene: Scene, spec: FamilySpec, family: MoveFamily | None = None) -> z3.BoolRef:
    ar, model = scene.ar, scene.model
    if spec.form == LEG:
        return _movers_close(scene, "r", "o")
    if spec.form == RULES:
        assert family is not None
        return _ruling(scene, family, spec.role)
    if spec.form in (FIRST, LINK):
        assert family is not None
        r_key = _key(ar, family, scene.at["r"])
        a = "r" if spec.form == FIRST else "b"

        def above(name: str) -> z3.BoolRef:
            return _key(ar, family, scene.at[name]) > r_key if name in scene.ends and name != "r" else ar.false()

        inductive = z3.Or(above(a), above("o")) if a != "r" else above("o")
        if a != "r":
            inductive = z3.And(sees(ar, model, scene.at[a], scene.at["o"]), inductive)
        return z3.Not(z3.Or(sees(ar, model, _after(scene, a), _after(scene, "o")), inductive))
    r, o = _after(scene, "r"), _after(scene, "o")
    lost = z3.Not(sees(ar, model, r, o))
    if spec.form in (KEPT, ANSWERED):
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
            f"before the round is {_conclusion(family)} and the swarm stays connected.{split}{_why(spec)}",
            f"Rests on: {family.rests_on or 'nothing outside the family'}.",
            "Assumptions: exact real arithmetic; unit discs; one shared snapshot per round.",
        ]
    )


def _conclusion(family: MoveFamily) -> str:
    if not inducts(family):
        return "a path of at most two edges after it"
    a, b = family.order or (0, 0)
    return (
        f"connected after it, by induction over the order {a} x + {b} y of the edges' movers, from the greatest "
        "down (module docstring): the mover of the greatest order at an edge's ends answers for it (answered, "
        "kept), bridges it by a path of two edges after the round (bridged), or reaches the other end by a chain "
        "each of whose links is an edge after the round or one with a mover above it (chain-first, chain-link)"
    )


def _why(spec: FamilySpec) -> str:
    if spec.form == RULES:
        return (
            f" This obligation: a robot o moving by {spec.other} is never the robot a witness of {spec.role} speaks of "
            f"(in any robot's view); so every obligation may take {spec.role} as false about a robot moving by "
            f"{spec.other} (the bridged and chain ones do, about o and b)."
        )
    if spec.form == FIRST:
        return " This obligation: the first link of r's chain, from r's end to o."
    if spec.form == LINK:
        return " This obligation: a link of r's chain, from b to o (any robots r sees, anywhere in a chain)."
    if spec.form == ANSWERED:
        return " This obligation: o is below r in the order, so r's test alone answers for the edge."
    return ""


__all__ = [
    "ANSWERED",
    "BRIDGED",
    "FIRST",
    "FORMS",
    "KEPT",
    "LEG",
    "LINK",
    "RULES",
    "FamilySpec",
    "Scene",
    "about",
    "argument",
    "assumed",
    "build",
    "edge_roles",
    "leg_roles",
    "specs",
]
