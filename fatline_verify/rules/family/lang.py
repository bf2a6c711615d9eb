"""The guard language: conditions on what a robot sees, written once, read by two interpreters.

A condition is a value (a small tree), never a Python ``bool``: ``bool(condition)`` raises, so an
``if`` or ``and`` on one is caught where it is written. It speaks of points:

- :data:`me` — the deciding robot (the origin of its snapshot), :data:`end` — where its move ends;
- robots it sees, bound by :func:`forall` (every robot seen) or :func:`exists` (some robot seen, a
  *witness*, named by its ``role``);
- ``p.moved(dx, dy)``: a point offset by radii (``c.moved(1, 0)``: one radius right of ``c``).

and of numbers: ``p.x``, ``p.y``, constants in **radii** (``Fraction`` or ``int``), ``+``, ``-``, and
multiplication by a constant, compared with ``<``, ``<=``, ``==``, ``!=``, ``>=``, ``>``. The
predicates: :func:`sees` (within the model's visibility), :func:`clear` (a robot's disc clear of the
mover's swept disc, per the ``contact`` option), :func:`clear_of` (two swept discs clear of each
other), :func:`distinct`. Connectives: ``&``, ``|``, ``~``, :func:`implies`, :func:`all_of`,
:func:`any_of`.

The **concrete** interpreter (:func:`holds`) evaluates a condition on a snapshot in lattice units with
exact integers and ``Fraction`` s, as the engines run (each condition compiled once per model into closures,
its constants scaled to lattice units: integers on the lattice, no dispatch per evaluation); the **symbolic** one
(:mod:`fatline_verify.prove.smt.family`) turns it into z3 terms over the robots an obligation names.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from itertools import count
from typing import Any

from ...model.geometry import dist2, point_segment_dist2, segment_segment_dist2
from ...model.numbers import Number, Point

Radii = int | Fraction
"""A constant of the language, in radii."""


class _Value:
    """A term or condition of the language: never a truth value in Python."""

    __slots__ = ()

    def __bool__(self) -> bool:
        raise TypeError(
            "a guard condition is a value of the guard language, not a bool: combine conditions with &, |, ~, "
            "implies(), forall() and exists(), never with and/or/not/if"
        )


# --- numbers ----------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Num(_Value):
    """A linear number: ``const + sum(coef * coordinate)``, constants and coefficients in radii."""

    terms: tuple[tuple[str, int, Fraction], ...] = ()
    """``(point, axis, coefficient)``: ``axis`` 0 for x, 1 for y; a point is named (``"me"``, ``"end"``,
    a bound variable) with its offset folded into :attr:`const`."""
    const: Fraction = Fraction(0)

    def __add__(self, other: Num | Radii) -> Num:
        o = _num(other)
        return Num(self.terms + o.terms, self.const + o.const)

    __radd__ = __add__

    def __neg__(self) -> Num:
        return Num(tuple((p, a, -k) for p, a, k in self.terms), -self.const)

    def __sub__(self, other: Num | Radii) -> Num:
        return self + (-_num(other))

    def __rsub__(self, other: Num | Radii) -> Num:
        return _num(other) - self

    def __mul__(self, k: Radii) -> Num:
        if isinstance(k, _Value):
            raise TypeError("the guard language multiplies numbers by constants only (it stays linear)")
        f = Fraction(k)
        return Num(tuple((p, a, c * f) for p, a, c in self.terms), self.const * f)

    __rmul__ = __mul__

    def _cmp(self, op: str, other: Num | Radii) -> Cond:
        return Cmp(op, self - _num(other))

    def __lt__(self, other: Num | Radii) -> Cond:  # type: ignore[override]
        return self._cmp("<", other)

    def __le__(self, other: Num | Radii) -> Cond:  # type: ignore[override]
        return self._cmp("<=", other)

    def __gt__(self, other: Num | Radii) -> Cond:  # type: ignore[override]
        return self._cmp(">", other)

    def __ge__(self, other: Num | Radii) -> Cond:  # type: ignore[override]
        return self._cmp(">=", other)

    def __eq__(self, other: object) -> Cond:  # type: ignore[override]
        return self._cmp("==", other)  # type: ignore[arg-type]

    def __ne__(self, other: object) -> Cond:  # type: ignore[override]
        return self._cmp("!=", other)  # type: ignore[arg-type]

    __hash__ = None  # type: ignore[assignment]


def _num(v: Num | Radii) -> Num:
    if isinstance(v, Num):
        return v
    if isinstance(v, bool) or not isinstance(v, int | Fraction):
        raise TypeError(f"{v!r}: expected a number of the guard language or a constant in radii (int or Fraction)")
    return Num((), Fraction(v))


@dataclass(frozen=True, eq=False)
class Pt(_Value):
    """A point of the language: a named point (``me``, ``end``, a robot bound by a quantifier) and an
    offset in radii."""

    name: str
    offset: tuple[Fraction, Fraction] = (Fraction(0), Fraction(0))

    @property
    def x(self) -> Num:
        return Num(((self.name, 0, Fraction(1)),), self.offset[0])

    @property
    def y(self) -> Num:
        return Num(((self.name, 1, Fraction(1)),), self.offset[1])

    def moved(self, dx: Radii, dy: Radii) -> Pt:
        """This point offset by ``(dx, dy)`` radii (``c.moved(1, 0)``: one radius right of ``c``)."""
        return Pt(self.name, (self.offset[0] + Fraction(dx), self.offset[1] + Fraction(dy)))


@dataclass(frozen=True, eq=False)
class XY(Pt):
    """A point given by two numbers of the language (:func:`point`): ``point(c.x, me.y - 3)``."""

    cx: Num = field(default_factory=Num)
    cy: Num = field(default_factory=Num)

    @property
    def x(self) -> Num:
        return self.cx + self.offset[0]

    @property
    def y(self) -> Num:
        return self.cy + self.offset[1]

    def moved(self, dx: Radii, dy: Radii) -> Pt:
        return XY("", (self.offset[0] + Fraction(dx), self.offset[1] + Fraction(dy)), self.cx, self.cy)


def point(x: Num | Radii, y: Num | Radii) -> Pt:
    """The point ``(x, y)`` of two numbers of the language (its coordinates may come from different points)."""
    return XY("", (Fraction(0), Fraction(0)), _num(x), _num(y))


me = Pt("me")
"""The deciding robot, at the origin of its snapshot."""
end = Pt("end")
"""Where the deciding robot's move ends (relative to :data:`me`)."""

# --- conditions -------------------------------------------------------------------------------


class Cond(_Value):
    """A condition of the language."""

    __slots__ = ()

    def __and__(self, other: Cond) -> Cond:
        return And((self, _cond(other)))

    def __or__(self, other: Cond) -> Cond:
        return Or((self, _cond(other)))

    def __invert__(self) -> Cond:
        return Not(self)


def _cond(c: object) -> Cond:
    if not isinstance(c, Cond):
        raise TypeError(f"{c!r}: expected a condition of the guard language")
    return c


@dataclass(frozen=True, eq=False)
class Const(Cond):
    value: bool


TRUE = Const(True)
FALSE = Const(False)


@dataclass(frozen=True, eq=False)
class Cmp(Cond):
    """``expr op 0``."""

    op: str
    expr: Num


@dataclass(frozen=True, eq=False)
class Sees(Cond):
    """``a`` within the model's visibility of ``b`` (centres)."""

    a: Pt
    b: Pt


@dataclass(frozen=True, eq=False)
class Clear(Cond):
    """The disc swept along segment ``a0 -> a1`` clear of the disc swept along ``b0 -> b1`` (per ``contact``)."""

    a0: Pt
    a1: Pt
    b0: Pt
    b1: Pt


@dataclass(frozen=True, eq=False)
class Distinct(Cond):
    a: Pt
    b: Pt


@dataclass(frozen=True, eq=False)
class And(Cond):
    parts: tuple[Cond, ...]


@dataclass(frozen=True, eq=False)
class Or(Cond):
    parts: tuple[Cond, ...]


@dataclass(frozen=True, eq=False)
class Not(Cond):
    part: Cond


@dataclass(frozen=True, eq=False)
class Forall(Cond):
    """Every robot the deciding robot sees, bound to :attr:`var`, meets :attr:`body`."""

    var: str
    body: Cond


@dataclass(frozen=True, eq=False)
class Exists(Cond):
    """Some robot the deciding robot sees, bound to :attr:`var`, meets :attr:`body`; :attr:`role` names
    the witness (the prover names a robot for it)."""

    var: str
    body: Cond
    role: str


@dataclass(frozen=True, eq=False)
class Chain(Cond):
    """The point :attr:`to` (a robot seen) is reached from the deciding robot through robots it sees: a first one
    meeting :attr:`first` (bound to :attr:`y`), then each next one meeting :attr:`link` with the one before it
    (bound to :attr:`x` and :attr:`y`). :attr:`role` names it; the prover proves each link, not the chain."""

    x: str
    y: str
    first: Cond
    link: Cond
    to: Pt
    role: str


_fresh = count()


def _bind(fn: Callable[[Pt], Cond], stem: str) -> tuple[str, Cond]:
    var = f"{stem}{next(_fresh)}"
    return var, _cond(fn(Pt(var)))


def forall(fn: Callable[[Pt], Cond]) -> Cond:
    """``forall(lambda c: ...)``: every robot the deciding robot sees meets the condition."""
    return Forall(*_bind(fn, "c"))


def exists(fn: Callable[[Pt], Cond], *, role: str) -> Cond:
    """``exists(lambda b: ..., role="bridge")``: some robot the deciding robot sees, a witness named
    ``role``, meets the condition."""
    if not role or not role.isidentifier():
        raise ValueError(f"role={role!r}: expected a name (an identifier) for the witness")
    var, body = _bind(fn, role)
    return Exists(var, body, role)


def chain(first: Callable[[Pt], Cond], link: Callable[[Pt, Pt], Cond], *, to: Pt, role: str) -> Cond:
    """``chain(lambda y: ..., lambda x, y: ..., to=c, role="chain")``: ``c`` is reached through robots the deciding
    robot sees, the first meeting ``first(y)``, each next ``y`` meeting ``link(x, y)`` with the one ``x`` before
    it (the closure: any number of links). The prover proves that each link the conditions admit is an edge
    after the round, or one of a mover above the deciding robot in the family's order (``MoveFamily.order``),
    so the chain is a path after the round (``connectivity/chain-first``, ``chain-link``)."""
    if not role or not role.isidentifier():
        raise ValueError(f"role={role!r}: expected a name (an identifier) for the chain")
    n = next(_fresh)
    x, y = f"{role}_x{n}", f"{role}_y{n}"
    return Chain(x, y, _cond(first(Pt(y))), _cond(link(Pt(x), Pt(y))), to, role)


def sees(a: Pt, b: Pt) -> Cond:
    """``a`` and ``b`` within visibility of each other (the ``visibility`` option: ``<=`` or ``<`` rad_v)."""
    return Sees(a, b)


def clear(c: Pt, start: Pt = me, stop: Pt = end) -> Cond:
    """The disc of a robot at ``c`` clear of the disc swept along ``start -> stop`` (the mover's path by default)."""
    return Clear(start, stop, c, c)


def clear_of(a0: Pt, a1: Pt, b0: Pt, b1: Pt) -> Cond:
    """The disc swept along ``a0 -> a1`` clear of the disc swept along ``b0 -> b1``."""
    return Clear(a0, a1, b0, b1)


def distinct(a: Pt, b: Pt) -> Cond:
    """``a`` and ``b`` are different points (a witness other than the robot it vouches for)."""
    return Distinct(a, b)


def implies(a: Cond, b: Cond) -> Cond:
    return Or((Not(_cond(a)), _cond(b)))


def all_of(*parts: Cond) -> Cond:
    return And(tuple(_cond(p) for p in parts)) if parts else TRUE


def any_of(*parts: Cond) -> Cond:
    return Or(tuple(_cond(p) for p in parts)) if parts else FALSE


# --- the concrete interpreter -------------------------------------------------------------------


@dataclass(frozen=True)
class Ground:
    """What a condition is evaluated on: the model's lattice (``unit`` lattice units a radius), the
    robots seen (relative to the deciding robot, lattice units) and the named points."""

    model: Any
    seen: Sequence[Point]
    points: Mapping[str, Point] = field(default_factory=dict)

    def bind(self, var: str, p: Point) -> Ground:
        return Ground(self.model, self.seen, {**self.points, var: p})


def _exact(v: Number) -> Number:
    return int(v) if isinstance(v, Fraction) and v.denominator == 1 else v


_OPS: dict[str, Callable[[Any], bool]] = {
    "<": lambda v: v < 0,
    "<=": lambda v: v <= 0,
    ">": lambda v: v > 0,
    ">=": lambda v: v >= 0,
    "==": lambda v: v == 0,
    "!=": lambda v: v != 0,
}


def holds(c: Cond, g: Ground) -> bool:
    """Whether ``c`` holds on ``g``, exactly (integers and ``Fraction`` s; squared distances)."""
    env: dict[str, Any] = dict(g.points)
    env[_MEMO] = {}
    return _compiled(c, g.model)(g.seen, env)


_MEMO = " memo"
"""The key of an evaluation's memo in its points (no variable has a space in its name): each quantifier's and
swept-disc test's value by the values of the points it speaks of, computed once per evaluation (a guard asks
the same sub-condition of the same robot many times: a chain's links, each leg a robot might make)."""


Test = Callable[[Sequence[Point], dict[str, Point]], bool]
"""A condition compiled for one model: ``test(seen, points)``, ``points`` the named points (a quantifier binds
its variable there)."""

_COMPILED: dict[tuple[Any, ...], tuple[Cond, Test]] = {}
"""Each condition compiled once per geometry (by ``id``, the lattice, the view and the contact: all a test reads
of the model; the condition is kept beside the test, so its ``id`` is not reused while the entry lives)."""


def _compiled(c: Cond, model: Any) -> Test:
    key = (id(c), model.radius, model.view2, model.contact2, str(model.options.contact))
    got = _COMPILED.get(key)
    if got is None:
        if len(_COMPILED) > 2_000:
            _COMPILED.clear()
        got = _COMPILED[key] = (c, _compile(c, model))
    return got[1]


def _compile(c: Cond, model: Any) -> Test:
    """The concrete interpreter as closures built once: each node's constants scaled to lattice units (integers
    where they are integral, so a lattice evaluates in integers), no dispatch on the node per evaluation; a
    quantifier's or swept-disc test's value memoised per evaluation by the points it speaks of."""
    test = _compile_node(c, model)
    if not isinstance(c, Forall | Exists | Chain | Clear):
        return test
    free = tuple(free_names(c))
    slot = object()

    def memo(seen: Sequence[Point], env: dict[str, Any]) -> bool:
        key = (slot, *(env[v] for v in free))
        cache = env[_MEMO]
        got = cache.get(key)
        if got is None:
            got = cache[key] = test(seen, env)
        return got  # type: ignore[no-any-return]

    return memo


def free_names(c: Cond) -> list[str]:
    """The names of the points ``c`` speaks of that it does not bind (``me``, ``end``, enclosing variables)."""
    out: list[str] = []
    _free(c, frozenset(), out)
    return out


def _free(c: Cond, bound: frozenset[str], out: list[str]) -> None:
    def num(n: Num) -> None:
        out.extend(name for name, _, _ in n.terms if name not in bound and name not in out)

    def pt(p: Pt) -> None:
        if isinstance(p, XY):
            num(p.cx)
            num(p.cy)
        elif p.name and p.name not in bound and p.name not in out:
            out.append(p.name)

    match c:
        case Cmp(expr=e):
            num(e)
        case Sees(a=a, b=b) | Distinct(a=a, b=b):
            pt(a)
            pt(b)
        case Clear(a0=a0, a1=a1, b0=b0, b1=b1):
            for p in (a0, a1, b0, b1):
                pt(p)
        case And(parts=ps) | Or(parts=ps):
            for p in ps:
                _free(p, bound, out)
        case Not(part=p):
            _free(p, bound, out)
        case Forall(var=v, body=b) | Exists(var=v, body=b):
            _free(b, bound | {v}, out)
        case Chain(x=x, y=y, first=first, link=link, to=to):
            pt(to)
            _free(first, bound | {y}, out)
            _free(link, bound | {x, y}, out)


def _compile_node(c: Cond, model: Any) -> Test:
    match c:
        case Const(value=v):
            return lambda seen, env: v
        case Cmp(op=op, expr=e):
            value, test = _compile_num(e, model.radius), _OPS[op]
            return lambda seen, env: test(value(env))
        case Sees(a=a, b=b):
            pa, pb, sees_ = _compile_pt(a, model.radius), _compile_pt(b, model.radius), model.sees
            return lambda seen, env: bool(sees_(dist2(pa(env), pb(env))))
        case Clear(a0=a0, a1=a1, b0=b0, b1=b1):
            a0_, a1_, b0_, b1_ = (_compile_pt(p, model.radius) for p in (a0, a1, b0, b1))
            if b0 is b1:  # a disc at rest against a swept one
                return lambda seen, env: not touches(point_segment_dist2(b0_(env), a0_(env), a1_(env)), model)
            if a0 is a1:
                return lambda seen, env: not touches(point_segment_dist2(a0_(env), b0_(env), b1_(env)), model)
            return lambda seen, env: not touches(segment_segment_dist2(a0_(env), a1_(env), b0_(env), b1_(env)), model)
        case Distinct(a=a, b=b):
            pa, pb = _compile_pt(a, model.radius), _compile_pt(b, model.radius)
            return lambda seen, env: pa(env) != pb(env)
        case And(parts=ps):
            fs = tuple(_compile(p, model) for p in ps)
            return lambda seen, env: all(f(seen, env) for f in fs)
        case Or(parts=ps):
            fs = tuple(_compile(p, model) for p in ps)
            return lambda seen, env: any(f(seen, env) for f in fs)
        case Not(part=p):
            f = _compile(p, model)
            return lambda seen, env: not f(seen, env)
        case Chain(x=x, y=y, first=first, link=link, to=to):
            start, step, target = _compile(first, model), _compile(link, model), _compile_pt(to, model.radius)

            def chained(seen: Sequence[Point], env: dict[str, Point]) -> bool:
                goal = target(env)
                todo = []
                for s in seen:
                    env[y] = s
                    if start(seen, env):
                        todo.append(s)
                reached = set(todo)
                while todo and goal not in reached:
                    env[x] = todo.pop()
                    for s in seen:
                        if s not in reached:
                            env[y] = s
                            if step(seen, env):
                                reached.add(s)
                                todo.append(s)
                return goal in reached

            return chained
        case Forall(var=v, body=b) | Exists(var=v, body=b):
            f, every = _compile(b, model), isinstance(c, Forall)

            def quantified(seen: Sequence[Point], env: dict[str, Point]) -> bool:
                for s in seen:  # a variable's name is fresh (one binder each): setting it shadows nothing
                    env[v] = s
                    if f(seen, env) is not every:
                        return not every
                return every

            return quantified
    raise TypeError(f"{c!r}: not a condition of the guard language")


def _compile_num(n: Num, rho: int) -> Callable[[dict[str, Point]], Number]:
    const = _exact(n.const * rho)
    terms = tuple((name, axis, _exact(k)) for name, axis, k in n.terms)
    if len(terms) == 1 and terms[0][2] == 1:
        ((name, axis, _),) = terms
        return lambda env: env[name][axis] + const
    return lambda env: const + sum(k * env[name][axis] for name, axis, k in terms)


def _compile_pt(p: Pt, rho: int) -> Callable[[dict[str, Point]], Point]:
    if isinstance(p, XY):
        cx, cy = _compile_num(p.cx, rho), _compile_num(p.cy, rho)
        ox, oy = _exact(p.offset[0] * rho), _exact(p.offset[1] * rho)
        return lambda env: (cx(env) + ox, cy(env) + oy)
    name = p.name
    dx, dy = _exact(p.offset[0] * rho), _exact(p.offset[1] * rho)
    if not dx and not dy:
        return lambda env: env[name]
    return lambda env: (env[name][0] + dx, env[name][1] + dy)


def touches(d2: Number, model: Any) -> bool:
    """Whether two discs whose centres are ``d2`` apart (squared) meet, per the ``contact`` option (``strict``:
    touching is a collision too)."""
    limit = model.contact2
    return bool(d2 < limit or (model.options.contact == "strict" and d2 == limit))


def walk(c: Cond) -> Iterator[Cond]:
    """``c`` and every condition inside it."""
    yield c
    match c:
        case And(parts=ps) | Or(parts=ps):
            for p in ps:
                yield from walk(p)
        case Not(part=p):
            yield from walk(p)
        case Forall(body=b) | Exists(body=b):
            yield from walk(b)
        case Chain(first=first, link=link):
            yield from walk(first)
            yield from walk(link)


def roles(c: Cond) -> tuple[str, ...]:
    """The witness roles of ``c``'s existentials and chains, in order, each once."""
    out: list[str] = []
    for sub in walk(c):
        if isinstance(sub, Exists | Chain) and sub.role not in out:
            out.append(sub.role)
    return tuple(out)


def chain_roles(c: Cond) -> tuple[str, ...]:
    """The roles of ``c``'s chains."""
    return tuple(dict.fromkeys(sub.role for sub in walk(c) if isinstance(sub, Chain)))


def edge_roles(c: Cond) -> tuple[str, ...]:
    """The witness roles of ``c`` that vouch for the robot a ``forall`` binds (an edge's bridge): those whose
    ``exists`` lies inside a ``forall``. A role outside every ``forall`` is what the leg itself needs its mover
    to see (named by ``build(..., witnesses=True)``), never an edge's bridge."""
    out: list[str] = []
    chains = chain_roles(c)
    for sub in walk(c):
        if isinstance(sub, Forall):
            out += [r for r in roles(sub.body) if r not in out and r not in chains]
    return tuple(out)


__all__ = [
    "FALSE",
    "TRUE",
    "Cond",
    "Ground",
    "Num",
    "Pt",
    "all_of",
    "any_of",
    "chain",
    "chain_roles",
    "clear",
    "clear_of",
    "distinct",
    "edge_roles",
    "end",
    "exists",
    "forall",
    "holds",
    "implies",
    "me",
    "point",
    "roles",
    "sees",
    "touches",
    "walk",
]
