"""Decision cases: the partition of ``LineForm()``'s outcomes that the prover's obligations enumerate.

A :class:`Case` fixes everything that makes a robot's destination a known term: the rule, the branch
of getDestination (which of R_psi n B, R_psi n C, R_psi n D are non-empty), the directions whose
vacancy search found nothing, the candidate where a search stopped, and whether I is empty. For
every snapshot, :func:`case_of` names the one case its decision falls in, and :func:`witnesses`
names the few robots that make the decision what it is:

- the psi_right robot (a least-x robot of B u C u D), one robot each for the non-empty sets among
  R_psi n B, R_psi n C, R_psi n D, one blocker per blocked search candidate, the highest robot of I,
  a robot on a blocked Scenario-4 path; for NoMovement, one robot of F, of E u G or of A u I.

Every other condition of a case is *universal* over the robots the decider sees ("no robot in E u F u
G", "every B u C u D robot has x >= x_psi", "no robot in R_psi n D", "candidate p is vacant", "no I
robot above the top one"), so it holds in every sub-swarm. Hence the **witness argument** the prover
rests on: the decider, its witnesses and any other robots, taken out of a swarm of any size, make
the same decision (tests/test_cases.py checks it on random and crowded swarms).

This module is pure Python (no z3): :mod:`fatline_verify.prove.smt.cases` encodes the same cases.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum
from fractions import Fraction
from math import floor

from ...model.config import Model
from ...model.numbers import Point
from .algorithm import Band, Decision, Rule, _scenario_4, free_path
from .options import Scenario4FreePath, Scenario4Guard, SearchBound, SearchOrder, Uncovered


class Branch(StrEnum):
    """getDestination's branch: which of R_psi n B, R_psi n C, R_psi n D are non-empty."""

    S1 = "scenario-1"
    """R_psi n C empty."""
    S2 = "scenario-2"
    """R_psi n C, R_psi n B non-empty, R_psi n D empty: search down first."""
    S3 = "scenario-3"
    """R_psi n C, R_psi n D non-empty, R_psi n B empty: search up first."""
    NEITHER = "uncovered-neither"
    """R_psi n C non-empty, R_psi n B and R_psi n D both empty."""
    BOTH = "uncovered-both"
    """R_psi n B, R_psi n C, R_psi n D all non-empty."""


NO_MOVEMENT = (Rule.ALONE, Rule.F_NONEMPTY, Rule.EFG_NONEMPTY, Rule.ONLY_AI)
"""The NoMovement bullets: cases with no branch."""


@dataclass(frozen=True, slots=True)
class Case:
    """One decision case (see the module docstring)."""

    rule: Rule
    branch: Branch | None = None
    failed: tuple[int, ...] = ()
    """Directions (-1 down, +1 up) searched to the end with no vacant candidate, in search order."""
    found: tuple[int, int] | None = None
    """``(direction, i)``: candidates 1 .. i-1 of that direction are blocked and candidate i is vacant."""
    i_empty: bool | None = None
    """For Scenario 4 (and its blocked path): whether I is empty."""

    @property
    def name(self) -> str:
        """A stable, file-name-safe name: ``scenario-2.down-2``, ``scenario-3.down-1-after-up``,
        ``scenario-4-I-empty.from-uncovered-neither``, ``scenario-4-path-blocked.from-scenario-2.I-empty``."""
        parts = [self.rule.value]
        if self.found is not None:
            direction, i = self.found
            after = "".join(f"-after-{'down' if d < 0 else 'up'}" for d in self.failed)
            parts.append(f"{'down' if direction < 0 else 'up'}-{i}{after}")
        if self.branch is not None and self.branch.value != self.rule.value:
            parts.append(f"from-{self.branch.value}")
        if self.rule is Rule.SCENARIO_4_PATH_BLOCKED:
            parts.append("I-empty" if self.i_empty else "I-nonempty")
        return ".".join(parts)

    @property
    def moves(self) -> bool:
        """Whether the decider moves in this case."""
        return self.rule in MOVING_RULES


MOVING_RULES = frozenset(
    {
        Rule.SCENARIO_1,
        Rule.SCENARIO_2,
        Rule.SCENARIO_3,
        Rule.UNCOVERED_SEARCH,
        Rule.SCENARIO_4_I_EMPTY,
        Rule.SCENARIO_4_I_NONEMPTY,
    }
)


def candidates(model: Model) -> int:
    """How many candidates one search direction can examine (radii): within view, ``i <= rad_v``;
    unbounded, up to the first one more than 2 beyond every visible robot (which is always vacant)."""
    rad_v = Fraction(model.parameters.rad_v)
    if model.options.search_bound is SearchBound.WITHIN_VIEW:
        return floor(rad_v)
    return floor(rad_v) + 4


def directions(branch: Branch, model: Model) -> tuple[int, ...]:
    """The search directions of a branch, in order ("Scenario 2 ... y_p = 0 - i Delta y";
    Scenario 3 upwards; the opposite direction next under ``search_order=primary-then-opposite``)."""
    opts = model.options
    if branch is Branch.S1:
        return ()
    if branch in (Branch.S2, Branch.S3):
        primary = -1 if branch is Branch.S2 else 1
        both = opts.search_order is SearchOrder.PRIMARY_THEN_OPPOSITE
        return (primary, -primary) if both else (primary,)
    return (-1, 1) if opts.uncovered is Uncovered.SEARCH_BOTH else ()


def _found_rule(branch: Branch) -> Rule:
    return {Branch.S2: Rule.SCENARIO_2, Branch.S3: Rule.SCENARIO_3}.get(branch, Rule.UNCOVERED_SEARCH)


def cases_for(model: Model) -> list[Case]:
    """Every case of ``model``'s readings, NoMovement bullets first, then the moving and staying
    outcomes of each branch in the paper's order."""
    opts = model.options
    out = [Case(rule) for rule in NO_MOVEMENT]
    out.append(Case(Rule.SCENARIO_1, Branch.S1))
    n = candidates(model)
    bounded = opts.search_bound is SearchBound.WITHIN_VIEW
    for branch in (Branch.S2, Branch.S3, Branch.NEITHER, Branch.BOTH):
        if branch in (Branch.NEITHER, Branch.BOTH) and opts.uncovered is Uncovered.STAY:
            out.append(Case(Rule.UNCOVERED_STAY, branch))
            continue
        dirs = directions(branch, model)
        for j, direction in enumerate(dirs):
            out += [Case(_found_rule(branch), branch, dirs[:j], (direction, i)) for i in range(1, n + 1)]
            if not bounded:  # an unbounded search always finds a vacant point in its first direction
                break
        if dirs and not bounded:
            continue
        if opts.scenario4_guard is Scenario4Guard.ALL_THREE_FULL and branch is not Branch.BOTH:
            out.append(Case(Rule.SCENARIO_4_GUARD_FAILS, branch, dirs))
            continue
        for empty in (True, False):
            rule = Rule.SCENARIO_4_I_EMPTY if empty else Rule.SCENARIO_4_I_NONEMPTY
            out.append(Case(rule, branch, dirs, None, empty))
            if opts.scenario4_free_path is Scenario4FreePath.ON:
                out.append(Case(Rule.SCENARIO_4_PATH_BLOCKED, branch, dirs, None, empty))
    return out


def moving_cases(model: Model) -> list[Case]:
    """The cases in which the decider moves."""
    return [c for c in cases_for(model) if c.moves]


def staying_cases(model: Model) -> list[Case]:
    """The cases in which the decider stays (NoMovement and every rule that gives no move)."""
    return [c for c in cases_for(model) if not c.moves]


# --- concrete side: which case a decision falls in, and its witnesses ---------------------------


def _branch(decision: Decision) -> Branch | None:
    if decision.psi is None:
        return None
    bands = dict(decision.classification)
    rb = any(Band.B in bands[c] for c in decision.r_psi)
    rc = any(Band.C in bands[c] for c in decision.r_psi)
    rd = any(Band.D in bands[c] for c in decision.r_psi)
    if not rc:
        return Branch.S1
    if rb and not rd:
        return Branch.S2
    if rd and not rb:
        return Branch.S3
    return Branch.BOTH if rb else Branch.NEITHER


def case_of(decision: Decision, model: Model) -> Case:
    """The case ``decision`` (made by :func:`fatline_verify.rules.paper.algorithm.decide`) falls in."""
    rule = decision.rule
    branch = _branch(decision)
    if branch is None:
        return Case(rule)
    if branch is Branch.S1:
        return Case(rule, branch)
    if rule is Rule.UNCOVERED_STAY:
        return Case(rule, branch)
    dirs = directions(branch, model)
    if rule in (Rule.SCENARIO_2, Rule.SCENARIO_3, Rule.UNCOVERED_SEARCH):
        last = decision.candidates[-1]
        direction = 1 if last.point[1] > 0 else -1
        i = int((direction * last.point[1]) // model.radius)
        return Case(rule, branch, dirs[: dirs.index(direction)], (direction, i))
    bands = dict(decision.classification)
    empty = not any(Band.I in m for m in bands.values())
    if rule is Rule.SCENARIO_4_GUARD_FAILS:
        return Case(rule, branch, dirs)
    return Case(rule, branch, dirs, None, empty)


def witnesses(decision: Decision, snapshot: Sequence[Point], model: Model) -> list[Point]:
    """The robots (relative to the decider) that make ``decision`` what it is; see the module docstring.

    Any sub-swarm of the decider's swarm that contains these robots gives the same decision."""
    bands = list(decision.classification)
    out: list[Point] = []

    def first(pred: object) -> None:
        for c, m in bands:
            if pred(c, m):  # type: ignore[operator]
                out.append(c)
                return

    rule = decision.rule
    if rule is Rule.ALONE:
        return out
    if rule is Rule.F_NONEMPTY:
        first(lambda c, m: Band.F in m)
        return out
    if rule is Rule.EFG_NONEMPTY:
        first(lambda c, m: m & {Band.E, Band.G})
        return out
    if rule is Rule.ONLY_AI:
        first(lambda c, m: m & {Band.A, Band.I})
        return out
    right = [c for c, m in bands if m & {Band.B, Band.C, Band.D}]
    out.append(min(right, key=lambda c: c[0]))
    in_r = set(decision.r_psi)
    for band in (Band.B, Band.C, Band.D):
        first(lambda c, m, band=band: c in in_r and band in m)
    out += [cand.blocker for cand in decision.candidates if cand.blocker is not None]
    below = [c for c, m in bands if Band.I in m]
    if below and rule in (Rule.SCENARIO_4_I_NONEMPTY, Rule.SCENARIO_4_PATH_BLOCKED):
        out.append(max(below, key=lambda c: c[1]))
    if rule is Rule.SCENARIO_4_PATH_BLOCKED:
        out.append(_path_blocker(decision, snapshot, model))
    return list(dict.fromkeys(out))


def _path_blocker(decision: Decision, snapshot: Sequence[Point], model: Model) -> Point:
    """A visible robot on the blocked Scenario-4 path (the first one, in snapshot order)."""
    from dataclasses import replace

    free = replace(model, options=model.options.with_(scenario4_free_path="off"))
    dest = _scenario_4(list(snapshot), decision.classification, free, True).destination
    for c in snapshot:
        if not free_path(dest, [c], model):
            return c
    raise AssertionError("a blocked path with no robot on it")


def sub_swarm(
    state: Sequence[Point],
    deciders: Sequence[int],
    decisions: Sequence[Decision],
    model: Model,
    keep: Sequence[int] = (),
) -> list[int]:
    """The indices of ``state`` the witness argument keeps: each decider, its witnesses, and ``keep``."""
    chosen = dict.fromkeys([*deciders, *keep])
    index = {p: k for k, p in enumerate(state)}
    for i, dec in zip(deciders, decisions, strict=True):
        me = state[i]
        snapshot = [(c[0] - me[0], c[1] - me[1]) for c in state if c != me]
        for w in witnesses(dec, snapshot, model):
            chosen[index[(w[0] + me[0], w[1] + me[1])]] = None
    return list(chosen)


__all__ = [
    "Branch",
    "Case",
    "case_of",
    "cases_for",
    "moving_cases",
    "staying_cases",
    "sub_swarm",
    "witnesses",
]


def describe(case: Case, model: Model) -> list[str]:
    """The case in words: its witnesses (existential) and its universal conditions."""
    rule = case.rule
    if case.branch is None:
        return {
            Rule.ALONE: ["no witness; universal: the decider sees no robot"],
            Rule.F_NONEMPTY: ["witness f: a visible robot in F"],
            Rule.EFG_NONEMPTY: ["witness e: a visible robot in E u G; universal: no visible robot in F"],
            Rule.ONLY_AI: ["witness a: a visible robot in A u I; universal: no visible robot in B u C u D u E u F u G"],
        }[rule]
    lines = [
        "witness w: a visible robot of B u C u D; x_psi from its x (psi_right); universal: no visible robot "
        "in E u F u G, every visible B u C u D robot has x >= x_w"
    ]
    sets = {
        Branch.S1: ("", "R_psi n C"),
        Branch.S2: ("b in R_psi n B, c in R_psi n C", "R_psi n D"),
        Branch.S3: ("c in R_psi n C, d in R_psi n D", "R_psi n B"),
        Branch.NEITHER: ("c in R_psi n C", "R_psi n B and R_psi n D"),
        Branch.BOTH: ("b, c, d in R_psi n B, C, D", ""),
    }[case.branch]
    if sets[0]:
        lines.append(f"witnesses {sets[0]}")
    if sets[1]:
        lines.append(f"universal: no visible robot in {sets[1]}")
    n = candidates(model)
    for d in case.failed:
        lines.append(
            f"search {'down' if d < 0 else 'up'} fails: each of its candidates 1..{n} within view has a "
            "visible blocker (witnesses k)"
        )
    if case.found is not None:
        d, i = case.found
        way = "down" if d < 0 else "up"
        if i > 1:
            lines.append(f"candidates 1..{i - 1} {way} are blocked (witnesses k)")
        lines.append(f"candidate {i} {way} is within the search bound; universal: it is vacant")
    if case.i_empty is True:
        lines.append("universal: no visible robot in I")
    elif case.i_empty is False:
        lines.append("witness t: the highest visible robot of I; universal: no visible I robot above it")
    if rule is Rule.SCENARIO_4_PATH_BLOCKED:
        lines.append("witness p: a visible robot on the path down")
    elif rule in (Rule.SCENARIO_4_I_EMPTY, Rule.SCENARIO_4_I_NONEMPTY) and (
        model.options.scenario4_free_path is Scenario4FreePath.ON
    ):
        lines.append("universal: no visible robot on the path down")
    return lines
