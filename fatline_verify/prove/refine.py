"""Do a rule set's declared liveness cases cover its decision function? (issue 37, holes 3 and 6)

The liveness obligations (:mod:`fatline_verify.prove.smt.liveness`) prove, case by case, that a robot
of the left-most vertical does not stay and that every move makes the measure fall. Their any-size
argument rests on every decision ``decide`` makes being in one of the declared
:class:`~fatline_verify.prove.smt.live_rules.LiveCase` s *with the case's destination*: a decision no
case describes is never looked at by any obligation (a plug-in that leaves a case out gets progress
PROVED for a rule set that deadlocks). This module checks that refinement on **views**.

A *view* is what a robot at the origin sees: a set of lattice points ``p != 0`` of the model's own
lattice that it sees (``model.sees``), whose discs are pairwise disjoint and disjoint from its own
(:func:`fatline_verify.schedulers.round.collides` per ``contact``). ``decide`` reads nothing else, so
the views are every input ``decide`` can get on that lattice; :func:`all_views` enumerates them (at
q = 1, rad_v = 4: 40 candidate points and 1,624,375 views, the empty one included).

For each view, ``decide`` gives a decision; a case *holds* on the view when some assignment of its
roles to robots of the view or to the decider itself (names may denote one robot, as in the
obligations) satisfies its constraints, the universe being the robots of the view; it *matches* when
it holds with its destination equal to the decision's. A view no case matches is **uncovered** (a
counterexample to the refinement: it names the view, decide's rule and destination); a view two or
more cases hold on is **overlapping** (the declaration's "exactly one" fails; the obligations, which
consider every case's behaviour, stay sound, so an overlap is reported, not a violation).

The z3 constraints are not solved per view: per universe size, every case's constraints over
symbolic universe and role points are compiled once into Python (:func:`_compile`): the constraints
split into clauses, every clause free of roles computed once per view, the roles searched over the
view by backtracking with each clause checked at the first role that completes it. Integers only.
"""

from __future__ import annotations

import itertools
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import z3

from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model
from ..model.numbers import show_point
from ..rules import registry
from .smt.cases import Arith, Pt
from .smt.live_rules import LiveCase, live_cases
from .tasks import ProofResult, row_key
from .views import View, all_views, largest_view, random_views

FORM = "coverage"
CASE = "cases"
KEY = f"{Lemma.PROGRESS}/{FORM}-{CASE}"
"""The prover row of the refinement check (``progress/coverage-cases``)."""

SHOWN = 5
"""Uncovered and overlapping views kept in a result (the first ones, in enumeration order)."""


# --- the cases compiled to Python ---------------------------------------------------------------


class NotCompilable(ValueError):
    """A case's constraints use a term the evaluator does not know (named, never guessed)."""


@dataclass(frozen=True, slots=True, eq=False)
class Node:
    """A z3 term read once through z3's C API (the Python API's per-call checks cost more than the
    checking itself): its operator kind, its variable name or numeral, its arguments."""

    key: int
    kind: int
    text: str
    args: tuple[Node, ...]
    roles: frozenset[int]
    """The roles (indices into the case's roles) the term mentions."""


class _Reader:
    """z3 terms of one context as :class:`Node` s, each distinct term once (by its id, the terms kept
    alive so that z3 does not give a freed term's id to another)."""

    def __init__(self, ctx: z3.Context) -> None:
        self.ref = ctx.ref()
        self.roles: dict[str, int] = {}
        """A role coordinate's variable name -> the role's index (set per case before reading it)."""
        self._nodes: dict[int, Node] = {}
        self._keep: list[z3.ExprRef] = []

    def read(self, e: z3.ExprRef) -> Node:
        self._keep.append(e)
        return self._node(e.as_ast())

    def _node(self, a: Any) -> Node:
        c = self.ref
        key = z3.Z3_get_ast_id(c, a)
        got = self._nodes.get(key)
        if got is not None:
            return got
        if z3.Z3_get_ast_kind(c, a) == z3.Z3_NUMERAL_AST:
            node = Node(key, z3.Z3_OP_ANUM, z3.Z3_get_numeral_string(c, a), (), frozenset())
        else:
            d = z3.Z3_get_app_decl(c, a)
            kind = z3.Z3_get_decl_kind(c, d)
            args = tuple(self._node(z3.Z3_get_app_arg(c, a, i)) for i in range(z3.Z3_get_app_num_args(c, a)))
            text = z3.Z3_get_symbol_string(c, z3.Z3_get_decl_name(c, d)) if kind == z3.Z3_OP_UNINTERPRETED else ""
            roles = frozenset({self.roles[text]}) if text in self.roles else frozenset().union(*(x.roles for x in args))
            node = Node(key, kind, text, args, roles)
        self._nodes[key] = node
        return node


Literal = tuple[Node, bool]
Clause = tuple[Literal, ...]
MAX_PRODUCT = 64
"""A disjunction of conjunctions is distributed into clauses up to this many; beyond, it stays one literal."""


def _clauses(e: Node, positive: bool = True) -> list[Clause]:
    """``e`` (or its negation) as a conjunction of clauses (disjunctions of literals), distributing
    as far as :data:`MAX_PRODUCT` allows: a clause free of roles is then decided once per view, and a
    clause of few roles as soon as they are chosen."""
    kind = e.kind
    if kind == z3.Z3_OP_NOT:
        return _clauses(e.args[0], not positive)
    if kind == (z3.Z3_OP_AND if positive else z3.Z3_OP_OR):
        return [c for child in e.args for c in _clauses(child, positive)]
    if kind == z3.Z3_OP_IMPLIES:
        a, b = e.args
        if positive:  # not a, or b
            return _product([_clauses(a, False), _clauses(b, True)], e, positive)
        return _clauses(a, True) + _clauses(b, False)
    if kind == (z3.Z3_OP_OR if positive else z3.Z3_OP_AND):
        return _product([_clauses(child, positive) for child in e.args], e, positive)
    return [((e, positive),)]


def _product(parts: list[list[Clause]], whole: Node, positive: bool) -> list[Clause]:
    """The disjunction of the conjunctions ``parts`` as clauses (``whole`` one literal if too many)."""
    size = 1
    for part in parts:
        size *= len(part)
    if size > MAX_PRODUCT or size == 0:
        return [((whole, positive),)]
    return [tuple(lit for clause in combo for lit in clause) for combo in itertools.product(*parts)]


_NARY = {
    z3.Z3_OP_ADD: " + ",
    z3.Z3_OP_SUB: " - ",
    z3.Z3_OP_MUL: " * ",
    z3.Z3_OP_AND: " and ",
    z3.Z3_OP_OR: " or ",
}
_BINARY = {
    z3.Z3_OP_LE: " <= ",
    z3.Z3_OP_LT: " < ",
    z3.Z3_OP_GE: " >= ",
    z3.Z3_OP_GT: " > ",
    z3.Z3_OP_EQ: " == ",
}


@dataclass
class _Scope:
    """A search level's block: its statements so far and the terms with roles it has computed."""

    lines: list[str]
    names: dict[int, str]
    counter: list[int]
    """Shared by a block's pieces: its temporaries are numbered once."""


class _Code:
    """Python source for terms over named variables. A compound term free of roles is a temporary
    computed once per view (:attr:`prelude`), shared by every case; one that mentions roles, a
    temporary of the search block that needs it (:class:`_Scope`), computed per choice of roles."""

    def __init__(self, names: dict[str, str]) -> None:
        self.names = names
        """z3 variable name -> Python name."""
        self.prelude: list[str] = []
        self._code: dict[int, str] = {}

    def expr(self, e: Node, scope: _Scope | None = None) -> str:
        """Python for ``e``: a literal, a variable or a temporary's name."""
        if not e.roles:
            got = self._code.get(e.key)
            if got is None:
                text, compound = self._build(e, None)
                if compound:
                    got = f"t{len(self.prelude)}"
                    self.prelude.append(f"{got} = {text}")
                else:
                    got = text
                self._code[e.key] = got
            return got
        assert scope is not None, "a term with roles outside a search block"
        got = scope.names.get(e.key)
        if got is None:
            text, compound = self._build(e, scope)
            if compound:
                got = f"v{scope.counter[0]}"
                scope.counter[0] += 1
                scope.lines.append(f"{got} = {text}")
            else:
                got = text
            scope.names[e.key] = got
        return got

    def _build(self, e: Node, scope: _Scope | None) -> tuple[str, bool]:
        kind = e.kind
        if kind == z3.Z3_OP_TRUE:
            return "True", False
        if kind == z3.Z3_OP_FALSE:
            return "False", False
        if kind == z3.Z3_OP_ANUM:
            value = Fraction(e.text)
            return (
                str(value) if value.denominator == 1 else f"Fraction({value.numerator}, {value.denominator})"
            ), False
        if kind == z3.Z3_OP_UNINTERPRETED and not e.args:
            if e.text not in self.names:
                raise NotCompilable(f"variable {e.text!r} is neither a robot of the view nor a role")
            return self.names[e.text], False
        args = [self.expr(c, scope) for c in e.args]
        return _operator(e, args), True

    def test(self, clause: Clause, scope: _Scope) -> tuple[list[str], str]:
        """The statements computing the temporaries ``clause`` needs that the block has not computed
        yet, and its test, its role-free literals (temporaries of the prelude) first."""
        block = _Scope([], scope.names, scope.counter)
        lits = sorted(clause, key=lambda lit: bool(lit[0].roles))
        test = " or ".join(self._lit(t, pos, block) for t, pos in lits) or "False"  # no literal: false
        return block.lines, test

    def clause(self, clause: Clause, scope: _Scope) -> list[str]:
        """Statements that ``continue`` unless ``clause`` holds (clauses are checked in order, so a
        failed one spares the later ones their temporaries)."""
        lines, test = self.test(clause, scope)
        return [*lines, f"if not ({test}): continue"]

    def _lit(self, t: Node, positive: bool, scope: _Scope | None) -> str:
        text = self.expr(t, scope)
        return text if positive else f"(not {text})"


def _operator(e: Node, args: list[str]) -> str:
    """Python for ``e``'s operator applied to its operands' Python ``args``."""
    kind = e.kind
    if kind in _NARY:
        return "(" + _NARY[kind].join(args) + ")"
    if kind in _BINARY and len(args) == 2:
        return f"({args[0]}{_BINARY[kind]}{args[1]})"
    if kind == z3.Z3_OP_NOT:
        return f"(not {args[0]})"
    if kind == z3.Z3_OP_IMPLIES:
        return f"((not {args[0]}) or {args[1]})"
    if kind == z3.Z3_OP_UMINUS:
        return f"(-{args[0]})"
    if kind == z3.Z3_OP_ITE:
        return f"({args[1]} if {args[0]} else {args[2]})"
    if kind == z3.Z3_OP_DISTINCT:
        return "(" + " and ".join(f"{a} != {b}" for a, b in itertools.combinations(args, 2)) + ")"
    if kind == z3.Z3_OP_TO_REAL:
        return args[0]
    raise NotCompilable(f"operator kind {kind} ({e.text or 'built-in'}) is not evaluated")


Checker = Callable[[View, tuple[Any, Any]], tuple[tuple[int, ...], tuple[int, ...]]]
"""``check(view, destination) -> (cases holding, cases matching)``, case indices."""


def _compile(model: Model, cases: Sequence[LiveCase], k: int) -> Checker:
    """Every case's constraints over a universe of ``k`` robots, as one Python function of a view of
    ``k`` robots and a destination: which cases hold on it, and which hold with that destination."""
    ar = Arith(model.parameters.q)
    me = ar.origin()
    universe: list[Pt] = [ar.point(f"u{i}") for i in range(k)]
    names = {f"u{i}.{a}": f"U{i}{a}" for i in range(k) for a in "xy"}
    names.update({"D.x": "Dx", "D.y": "Dy"})
    want = (ar.var("D.x"), ar.var("D.y"))
    lines = [
        "def check(view, dest):",
        *([f"    ({', '.join(f'(U{i}x, U{i}y)' for i in range(k))},) = view"] if k else []),
        "    Dx, Dy = dest",
        "    dom = ((0, 0),) + view",
        f"    held = [False] * {len(cases)}",
    ]
    body: list[str] = []
    calls: list[str] = []
    code = _Code(names)  # one for every case: a role-free term is one z3 term, computed once per view
    reader = _Reader(ar.ctx)
    for n, case in enumerate(cases):
        roles = {name: ar.point(f"r{n}.{name}") for name in case.roles}
        reader.roles = {f"r{n}.{name}.{a}": j for j, name in enumerate(case.roles) for a in "xy"}
        code.names.update({v: f"R{j}{v[-1]}" for v, j in reader.roles.items()})  # case n's roles, its own
        cs, dest = case.encode(ar, model, me, roles, universe)
        clauses = [c for e in cs for c in _clauses(reader.read(_as_z3(ar, e)))]
        at: list[Clause] = [((reader.read(_as_z3(ar, dest[i]) == want[i]), True),) for i in (0, 1)]
        body += _search(code, n, clauses, at)
        calls += [f"    if C{n}():", f"        match.append({n})", f"    if held[{n}]:", f"        hold.append({n})"]
    lines += [f"    {line}" for line in code.prelude]
    lines += [f"    {line}" for line in body]
    lines += ["    hold = []", "    match = []", *calls, "    return tuple(hold), tuple(match)"]
    namespace: dict[str, Any] = {"Fraction": Fraction}
    exec(compile("\n".join(lines), f"<coverage k={k}>", "exec"), namespace)
    return namespace["check"]  # type: ignore[no-any-return]


def _as_z3(ar: Arith, v: Any) -> z3.ExprRef:
    """A case's term, or a plain number it returned, as a z3 term of ``ar``'s context."""
    if isinstance(v, z3.ExprRef):
        return v
    if isinstance(v, bool):
        return z3.BoolVal(v, ar.ctx)
    return z3.IntVal(int(v), ar.ctx) if Fraction(v).denominator == 1 else z3.RealVal(str(Fraction(v)), ar.ctx)


def _search(code: _Code, n: int, clauses: list[Clause], at: list[Clause]) -> list[str]:
    """Python for ``C{n}()``: whether some assignment of the roles to ``dom`` satisfies ``clauses`` and
    ``at`` (the destination's clauses), setting ``held[n]`` when one satisfies ``clauses``. The roles
    are tried in order, each clause checked as soon as its last role is assigned (clauses of no role
    at once, on the prelude's temporaries), ``at`` once all are. Roles no clause mentions are not
    searched."""
    used = sorted(frozenset().union(*(t.roles for c in [*clauses, *at] for t, _ in c)))
    level: dict[int, list[Clause]] = {}
    for clause in clauses:
        rs = frozenset().union(*(t.roles for t, _ in clause))
        level.setdefault(max((used.index(r) for r in rs), default=-1), []).append(clause)
    name = f"C{n}"

    def leaf(scope: _Scope, indent: str) -> list[str]:
        tests = [code.test(clause, scope) for clause in at]
        lines = [line for got, _ in tests for line in got]
        both = " and ".join(f"({test})" for _, test in tests)
        return [f"{indent}held[{n}] = True", *(f"{indent}{line}" for line in lines), f"{indent}if {both}: return True"]

    out = [f"def {name}():"]
    first = [code.test(c, _Scope([], {}, [0]))[1] for c in level.get(-1, [])]
    if first:  # role-free clauses: temporaries of the prelude only
        out.append(f"    if not ({' and '.join(f'({c})' for c in first)}): return False")
    if used:
        out.append(f"    return {name}_0()")
    else:
        out += leaf(_Scope([], {}, [0]), "    ")
        out.append("    return False")
    for depth, role in enumerate(used):
        args = ", ".join(f"R{r}x, R{r}y" for r in used[:depth])
        out.append(f"def {name}_{depth}({args}):")
        out.append(f"    for R{role}x, R{role}y in dom:")
        scope = _Scope([], {}, [0])
        for clause in level.get(depth, []):
            out += [f"        {line}" for line in code.clause(clause, scope)]
        if depth + 1 < len(used):
            deeper = ", ".join(f"R{r}x, R{r}y" for r in used[: depth + 1])
            out.append(f"        if {name}_{depth + 1}({deeper}): return True")
        else:
            out += leaf(scope, "        ")
        out.append("    return False")
    return out


# --- the check ------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Seen:
    """One view and what the rule set and its cases make of it."""

    view: View
    rule: str
    """decide's rule on the view."""
    destination: tuple[Any, Any]
    """decide's destination (relative, lattice units)."""
    holding: tuple[str, ...]
    """The cases that hold on the view (with any destination)."""
    matching: tuple[str, ...]
    """The cases that hold with decide's destination."""

    def describe(self, model: Model) -> str:
        """One line: the view in radii, decide's rule and destination, the cases."""
        robots = ", ".join(show_point(model.from_lattice(p)) for p in self.view) or "no robot"
        dest = show_point(model.from_lattice(self.destination))
        cases = f"cases holding: {', '.join(self.holding)}" if self.holding else "no case holds"
        return f"view {{{robots}}}: decide says {self.rule} to {dest}; {cases}"


@dataclass(frozen=True)
class Coverage:
    """The refinement check's outcome over some views of one model."""

    model: str
    rule_set: str
    views: int
    covered: int
    overlapping: int
    seconds: float
    """Wall seconds deciding and checking the views."""
    compiling: float
    """Wall seconds compiling the cases (once per process, model and rule set; see :func:`checkers`)."""
    exhaustive: bool
    """Whether the views were every view (:func:`all_views`)."""
    per_case: dict[str, int] = field(default_factory=dict)
    """Views matched by each case (a view in two cases counts in both)."""
    uncovered_views: tuple[Seen, ...] = ()
    """The first :data:`SHOWN` uncovered views."""
    overlapping_views: tuple[Seen, ...] = ()
    """The first :data:`SHOWN` overlapping views."""

    @property
    def uncovered(self) -> int:
        return self.views - self.covered

    @property
    def rate(self) -> float:
        """Views per second."""
        return self.views / self.seconds if self.seconds else float("inf")


_MADE: dict[tuple[Model, int], tuple[registry.RuleSet, list[LiveCase], dict[int, Checker]]] = {}
"""Compiled checkers by model and rule set (the rule set kept, so that its id is not reused)."""


def checkers(model: Model) -> tuple[list[LiveCase], Callable[[int], Checker]]:
    """``model``'s declared cases and, per universe size, their compiled checker (each made once per
    process, model and rule set: compiling the paper's 29 cases takes about a second per size)."""
    rule_set = registry.of(model)
    key = (model, id(rule_set))
    if key not in _MADE:
        cases = live_cases(model)
        if not cases:
            raise ValueError(f"rules={model.rules!r}: the rule set declares no liveness cases")
        _MADE[key] = (rule_set, cases, {})
    _, cases, made = _MADE[key]

    def get(k: int) -> Checker:
        if k not in made:
            made[k] = _compile(model, cases, k)
        return made[k]

    return cases, get


def _scan(model: Model, views: Iterable[View], shard: int = 0, shards: int = 1) -> tuple[Any, ...]:
    """Check ``views`` (every ``shards``-th from ``shard``): counts, per-case counts and first views
    found, with their positions in ``views`` (to merge shards in order)."""
    cases, get = checkers(model)
    decide = registry.decider(model)
    n = covered = overlapping = 0
    per_case = [0] * len(cases)
    uncovered_seen: list[tuple[int, Seen]] = []
    overlap_seen: list[tuple[int, Seen]] = []
    for index, given in enumerate(views):
        if index % shards != shard:
            continue
        view = tuple(given)
        n += 1
        decision = decide(view, model)
        dest = decision.destination
        hold, match = get(len(view))(view, dest)
        for c in match:
            per_case[c] += 1
        if match:
            covered += 1
        if len(hold) > 1:
            overlapping += 1
        if (not match and len(uncovered_seen) < SHOWN) or (len(hold) > 1 and len(overlap_seen) < SHOWN):
            seen = Seen(
                view, str(decision.rule), (dest[0], dest[1]),
                tuple(cases[c].name for c in hold), tuple(cases[c].name for c in match),
            )  # fmt: skip
            if not match and len(uncovered_seen) < SHOWN:
                uncovered_seen.append((index, seen))
            if len(hold) > 1 and len(overlap_seen) < SHOWN:
                overlap_seen.append((index, seen))
    names = {c.name: per_case[i] for i, c in enumerate(cases)}
    return n, covered, overlapping, names, uncovered_seen, overlap_seen


_JOB: tuple[Model, bool, list[View] | None, int] | None = None
"""The job a forked worker reads (the model need not pickle: a plug-in's rule set lives in the registry)."""


def _worker(shard: int) -> tuple[Any, ...]:
    assert _JOB is not None
    model, exhaustive, views, shards = _JOB
    return _scan(model, all_views(model) if exhaustive else views or [], shard, shards)


def coverage(model: Model, views: Iterable[View] | None = None, *, processes: int = 1) -> Coverage:
    """Check that every view's decision is in a declared case with the decision's destination.

    ``views``: the views to check (each a tuple of lattice points); ``None``: every view of the
    model's lattice (:func:`all_views`: exhaustive). ``processes > 1`` shares the views among forked
    processes, each taking every ``processes``-th view."""
    global _JOB
    made = time.perf_counter()
    exhaustive = views is None
    listed = None if exhaustive else [tuple(v) for v in views]  # type: ignore[union-attr]
    _, get = checkers(model)  # every size compiled first (and before a fork: every process has them)
    for k in range(1 + largest_view(model)) if listed is None else sorted({len(v) for v in listed}):
        get(k)
    start = time.perf_counter()
    if processes > 1:
        import multiprocessing

        _JOB = (model, exhaustive, listed, processes)
        try:
            with multiprocessing.get_context("fork").Pool(processes) as pool:
                parts = pool.map(_worker, range(processes))
        finally:
            _JOB = None
    else:
        parts = [_scan(model, all_views(model) if exhaustive else listed or [])]
    per_case: dict[str, int] = {}
    for part in parts:
        for name, c in part[3].items():
            per_case[name] = per_case.get(name, 0) + c
    uncovered = sorted((s for part in parts for s in part[4]), key=lambda s: s[0])[:SHOWN]
    overlaps = sorted((s for part in parts for s in part[5]), key=lambda s: s[0])[:SHOWN]
    return Coverage(
        model.name, model.rules,
        sum(p[0] for p in parts), sum(p[1] for p in parts), sum(p[2] for p in parts),
        time.perf_counter() - start, start - made, exhaustive, per_case,
        tuple(s for _, s in uncovered), tuple(s for _, s in overlaps),
    )  # fmt: skip


def sampled(model: Model, n: int = 2000, seed: int = 0) -> Coverage:
    """:func:`coverage` on ``n`` random views (:func:`random_views`)."""
    return coverage(model, random_views(model, n, seed))


# --- the prover's row and the lemma-level hook ---------------------------------------------------


def prove_coverage(model: Model, *, exhaustive: bool = False, sample: int = 2000, processes: int = 1) -> ProofResult:
    """The row ``progress/coverage-cases``: VIOLATED with the first uncovered view (its robots, the
    decider first at ``0,0``, as the row's configuration, in radii); PROVED when every view of the
    model's lattice was checked and each is covered; INCONCLUSIVE when a random sample of ``sample``
    views is covered (not every view was looked at). Overlapping views are named in the reason: the
    obligations consider every case's behaviour, so an overlap leaves them sound."""
    got = coverage(model, None, processes=processes) if exhaustive else sampled(model, sample)
    q = model.parameters.q
    where = f"views of the lattice q={q}, rad_v={model.parameters.rad_v}"
    overlap = ""
    if got.overlapping:
        overlap = f"; {got.overlapping} view(s) in two or more cases, first: {got.overlapping_views[0].describe(model)}"
    config: tuple[str, ...] = ()
    if got.uncovered:
        first = got.uncovered_views[0]
        config = tuple(f"{x},{y}" for x, y in (model.from_lattice(p) for p in ((0, 0), *first.view)))
        verdict = Verdict.VIOLATED
        reason = (
            f"{got.uncovered} of {got.views} {where} are in no declared case with decide's destination "
            f"(the liveness obligations never look at such a decision); first: {first.describe(model)}{overlap}"
        )
    elif got.exhaustive:
        verdict = Verdict.PROVED
        reason = f"every one of the {got.views} {where} is in a declared case with decide's destination{overlap}"
    else:
        verdict = Verdict.INCONCLUSIVE
        reason = (
            f"{got.views} random {where} each in a declared case with decide's destination; not every view was "
            f"checked (fatline prove --coverage all, or fatline cover --all, checks every one){overlap}"
        )
    reason += f" ({got.seconds:.1f} s, {got.rate:.0f} views/s; the cases compiled in {got.compiling:.1f} s)"
    return ProofResult(
        Lemma.PROGRESS, FORM, "any", verdict, 0, got.exhaustive, got.seconds, reason, "",
        case=CASE, configuration=config,
    )  # fmt: skip


def refinement_gap(rows: Sequence[dict[str, Any]]) -> str | None:
    """For the lemma-level judgement of progress and termination: ``None`` when the row
    :data:`KEY` is PROVED (every decision is in a declared case, so the enabledness and measure rows
    speak of every decision); otherwise why not (the row missing, INCONCLUSIVE, or VIOLATED with its
    view). An uncovered view is a hole in the argument, not a stuck configuration: it makes the
    lemmas NOT PROVED, never VIOLATED (a deadlock is refuted by a replayed stuck configuration only)."""
    row = next((r for r in rows if row_key(r) == KEY), None)
    if row is None:
        return f"the declared cases are not checked against the rule set's decide ({KEY} not run)"
    if row.get("verdict") == "PROVED":
        return None
    return f"{KEY} {row.get('verdict')}: {row.get('reason', '')}".rstrip(": ")


__all__ = [
    "CASE",
    "FORM",
    "KEY",
    "Coverage",
    "NotCompilable",
    "Seen",
    "coverage",
    "prove_coverage",
    "refinement_gap",
    "sampled",
]
