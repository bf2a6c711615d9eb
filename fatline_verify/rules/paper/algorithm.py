"""Look -> Compute: the paper's ``LineForm()`` as a pure function of one robot's snapshot.

``decide(snapshot, model)`` takes the robots ``r`` sees, as positions relative to ``r`` (``r`` at the
origin, lattice units: one radius is ``model.radius``), and returns a :class:`Decision`: how ``r``
classified each robot into the sets A ... I, which NoMovement bullet or Scenario fired, psi_right,
R_psi_right, every candidate point the vacancy search examined, the destination and the path.

It works on ``int`` and ``Fraction`` alike; nothing here rounds.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from enum import StrEnum

from ...model.config import Model
from ...model.geometry import Path, dist2, point_rect_dist2
from ...model.numbers import Number, Point
from ..decision import ORIGIN, Decision
from .options import (
    BandOverlap,
    Bands,
    PathShape,
    PsiRight,
    Quadrants,
    RPsi,
    Scenario4Drop,
    Scenario4FreePath,
    Scenario4Guard,
    SearchBound,
    SearchOrder,
    Uncovered,
    Vacant,
)


class Band(StrEnum):
    """The paper's eight sets (it names them A-I without H)."""

    A = "A"
    B = "B"
    C = "C"
    D = "D"
    E = "E"
    F = "F"
    G = "G"
    I = "I"  # noqa: E741 - the paper's name


class Rule(StrEnum):
    """What decided ``r``'s move. NoMovement bullets are numbered as in the paper."""

    ALONE = "nomovement-1-alone"
    """"If r does not find any other robot in its visibility circle"."""
    F_NONEMPTY = "nomovement-2-F"
    """"If F is not empty" (subsumed by bullet 3; reported first when it applies)."""
    EFG_NONEMPTY = "nomovement-3-EFG"
    """"If sets E u F u G are not empty"."""
    ONLY_AI = "nomovement-4-only-AI"
    """"If B u C u D u E u F u G is empty and A u I is not empty" (= getDestination's "B u C u D empty")."""
    SCENARIO_1 = "scenario-1"
    SCENARIO_2 = "scenario-2"
    SCENARIO_3 = "scenario-3"
    UNCOVERED_SEARCH = "uncovered-search"
    """``uncovered=search-both`` found a vacant point on psi_right."""
    UNCOVERED_STAY = "uncovered-stay"
    """``uncovered=stay``: a case Scenarios 1-3 leave out, and r stays."""
    SCENARIO_4_I_EMPTY = "scenario-4-I-empty"
    SCENARIO_4_I_NONEMPTY = "scenario-4-I-nonempty"
    SCENARIO_4_GUARD_FAILS = "scenario-4-guard-fails"
    """``scenario4_guard=all-three-full`` and the guard does not hold: no rule gives a move."""
    SCENARIO_4_PATH_BLOCKED = "scenario-4-path-blocked"
    """``scenario4_free_path=on`` and the path down is not free: "Otherwise it does not move"."""
    REPAIR_ALIGN = "repair-align"
    """Not the paper's: ``repair_stack=align``: r sees only A u I, some right of its vertical, and moves there."""
    REPAIR_CONTRACT = "repair-contract"
    """Not the paper's: ``repair_stack=align``: the top of a vertical moves down, or its bottom up, to contract it."""
    REPAIR_APPROACH = "repair-approach"
    """Not the paper's: ``repair_approach=on``: instead of Scenario 4's drop, r moves right to x_psi - 2."""
    REPAIR_LOCK = "repair-lock"
    """Not the paper's: ``repair_lock=left-first`` holds r, which sees a robot before it in (x, y)."""
    REPAIR_DETOUR = "repair-detour"
    """Not the paper's: ``repair_progress=detour`` (or ``corner``): every leg toward r's destination refused, r
    takes another (right; along its vertical toward a height from which right passes; up or down; with
    ``corner``, last, one radius right and one vertically at once)."""
    REPAIR_BLOCKED = "repair-blocked"
    """Not the paper's: ``repair_clear`` or ``repair_edges`` refuse every leg toward r's destination."""


class Case(StrEnum):
    """Which case of getDestination applied when its search found no vacant point."""

    SCENARIO_2 = "scenario-2"
    SCENARIO_3 = "scenario-3"
    UNCOVERED = "uncovered"
    """R_psi n C non-empty with R_psi n B, R_psi n D both empty or both non-empty."""


STAYING_RULES = frozenset(
    {
        Rule.ALONE,
        Rule.F_NONEMPTY,
        Rule.EFG_NONEMPTY,
        Rule.ONLY_AI,
        Rule.UNCOVERED_STAY,
        Rule.SCENARIO_4_GUARD_FAILS,
        Rule.SCENARIO_4_PATH_BLOCKED,
        Rule.REPAIR_LOCK,
        Rule.REPAIR_BLOCKED,
    }
)


@dataclass(frozen=True, slots=True)
class Candidate:
    """A point the vacancy search examined; ``blocker`` is a visible robot too close to it."""

    point: Point
    vacant: bool
    blocker: Point | None = None


# --- Look: classification into A ... I ----------------------------------------------------------


def _in_strip(offset: Number, model: Model, disc: bool) -> bool:
    """Whether a disc at ``offset`` from an axis is 'partially or fully present in the area of unit
    distance around' it: the disc meets the strip with positive area (``|offset| < 2``) or its centre
    lies in it (``|offset| <= 1``)."""
    rho = model.radius
    size = offset if offset >= 0 else -offset
    return size < 2 * rho if disc else size <= rho


def classify(c: Point, model: Model) -> frozenset[Band]:
    """The sets a visible robot at ``c`` (relative to ``r``) belongs to.

    "Set A consists of the robots partially or fully present in the area of unit distance around
    the positive Y axis ... Set B and D account for the robots that fall within the first and second
    quadrant ... (leaving the robots in A, C and I)."
    """
    opts = model.options
    x, y = c
    disc = opts.bands is Bands.DISC
    vertical = (Band.A if y > 0 else Band.I if y < 0 else None) if _in_strip(x, model, disc) else None
    horizontal = (Band.C if x > 0 else Band.F if x < 0 else None) if _in_strip(y, model, disc) else None
    if vertical and horizontal:
        if opts.band_overlap is BandOverlap.VERTICAL_FIRST:
            return frozenset({vertical})
        if opts.band_overlap is BandOverlap.HORIZONTAL_FIRST:
            return frozenset({horizontal})
        return frozenset({vertical, horizontal})
    if vertical or horizontal:
        return frozenset({vertical or horizontal})  # type: ignore[arg-type]
    if x == 0 or y == 0:  # only a robot at r's own centre: it overlaps r and is in no set
        return frozenset()
    if opts.quadrants is Quadrants.LOWER_RIGHT:
        band = (Band.B if y > 0 else Band.D) if x > 0 else (Band.E if y > 0 else Band.G)
    else:  # literal: B = Q1, D = Q2, E = Q3, G = Q4
        band = (Band.B if x > 0 else Band.D) if y > 0 else (Band.G if x > 0 else Band.E)
    return frozenset({band})


# --- Compute --------------------------------------------------------------------------------------


def _path(destination: Point, shape: PathShape) -> Path:
    """The rigid move from the origin to ``destination`` under the ``path`` option."""
    if destination == ORIGIN:
        return (ORIGIN,)
    dx, dy = destination
    corner = (dx, 0) if shape is PathShape.HORIZONTAL_THEN_VERTICAL else (0, dy)
    if shape is PathShape.STRAIGHT or corner in (ORIGIN, destination):
        return (ORIGIN, destination)
    return (ORIGIN, corner, destination)


def _stay(rule: Rule, classification: tuple[tuple[Point, frozenset[Band]], ...], **kw: object) -> Decision:
    return Decision(rule, ORIGIN, (ORIGIN,), classification, **kw)  # type: ignore[arg-type]


def vacancy_blocker(p: Point, snapshot: Iterable[Point], model: Model) -> Point | None:
    """A visible robot that makes ``p`` not vacant, or ``None`` when ``p`` is vacant.

    "A point is vacant if there exist no parts of another robot around a circular region of radius 1
    around this point": no visible robot's centre within 2 of ``p`` (at exactly 2 per ``vacant``).
    ``r`` itself is not "another robot" and is not in the snapshot.
    """
    limit = model.contact2
    strict = model.options.vacant is Vacant.STRICT
    for c in snapshot:
        d2 = dist2(c, p)
        if d2 < limit or (strict and d2 == limit):
            return c
    return None


def _search(
    psi: Number, direction: int, snapshot: Sequence[Point], model: Model, seen: list[Candidate]
) -> Point | None:
    """Scenario 2/3's search on psi_right: ``y_p = 0 -+ i Delta y``, ``i = 1, 2, ...`` with
    ``Delta y`` one radius, "till a vacant point is found" (bounded per ``search_bound``)."""
    rho = model.radius
    bounded = model.options.search_bound is SearchBound.WITHIN_VIEW
    limit = model.view * model.view
    i = 1
    while True:
        p = (psi, direction * i * rho)
        if bounded and p[0] * p[0] + p[1] * p[1] > limit:
            return None
        blocker = vacancy_blocker(p, snapshot, model)
        seen.append(Candidate(p, blocker is None, blocker))
        if blocker is None:
            return p
        i += 1


def _scenario_4(
    snapshot: Sequence[Point],
    classification: tuple[tuple[Point, frozenset[Band]], ...],
    model: Model,
    guard_holds: bool,
    **kw: object,
) -> Decision:
    """Scenario 4: r moves straight down.

    "If I is completely empty, then r moves towards either -Y axis such that x_p = 0,
    y_p = 0 - rad_v + 1. If I is not empty, then r moves along -Y axis such that x_p = 0,
    y_p = 0 - d + 1 where d = the vertical distance with r and the robot with maximum y value in I."
    """
    opts = model.options
    if opts.scenario4_guard is Scenario4Guard.ALL_THREE_FULL and not guard_holds:
        return _stay(Rule.SCENARIO_4_GUARD_FAILS, classification, **kw)
    rho = model.radius
    below = [c for c, m in classification if Band.I in m]
    drop = opts.scenario4_drop
    if not below:
        rule = Rule.SCENARIO_4_I_EMPTY
        y: Number = -model.view if drop is Scenario4Drop.PROOFS else -model.view + rho
    else:
        rule = Rule.SCENARIO_4_I_NONEMPTY
        d = -max(c[1] for c in below)
        y = {
            Scenario4Drop.LITERAL: -d + rho,
            Scenario4Drop.TOUCH: -d + 2 * rho,
            Scenario4Drop.GAP: -(d - 2 * rho) + rho,
            Scenario4Drop.PROOFS: -d + 2 * rho,
        }[drop]
    destination = (0, y)
    if opts.scenario4_free_path is Scenario4FreePath.ON and not free_path(destination, snapshot, model):
        return _stay(Rule.SCENARIO_4_PATH_BLOCKED, classification, **kw)
    return Decision(rule, destination, _path(destination, opts.path), classification, **kw)  # type: ignore[arg-type]


def free_path(destination: Point, snapshot: Iterable[Point], model: Model) -> bool:
    """ "A path ... is called free path, if from source to destination point the rectangular area
    having length as the source to destination distance and width as two units, is not contained
    any part of another robot." Only vertical and horizontal paths occur (Scenario 4 is vertical).

    A disc meets the rectangle iff its centre is closer than one radius to it (at exactly one
    radius, per the ``vacant`` option's boundary).
    """
    rho = model.radius
    (x0, y0), (x1, y1) = ORIGIN, destination
    lo: Point
    hi: Point
    if x0 == x1:
        lo, hi = (-rho, min(y0, y1)), (rho, max(y0, y1))
    elif y0 == y1:
        lo, hi = (min(x0, x1), -rho), (max(x0, x1), rho)
    else:
        raise ValueError(f"free_path: destination {destination} is not axis-parallel")
    strict = model.options.vacant is Vacant.STRICT
    limit = rho * rho
    for c in snapshot:
        d2 = point_rect_dist2(c, lo, hi)
        if d2 < limit or (strict and d2 == limit):
            return False
    return True


def decide(snapshot: Sequence[Point], model: Model) -> Decision:
    """``LineForm()`` for a robot at the origin that sees ``snapshot``: NoMovement, then getDestination,
    as the paper writes it under the model's readings (the paper's rule set; any model's own rules are
    :func:`fatline_verify.rules.registry.decide`)."""
    return paper_decide(snapshot, model)


def paper_decide(snapshot: Sequence[Point], model: Model) -> Decision:
    """``LineForm()`` as the paper writes it, under the model's readings."""
    opts = model.options
    classification = tuple((c, classify(c, model)) for c in snapshot)
    present = set().union(*(m for _, m in classification)) if classification else set()

    # NoMovement(r), bullets in the paper's order.
    if not snapshot:
        return _stay(Rule.ALONE, classification)
    if Band.F in present:
        return _stay(Rule.F_NONEMPTY, classification)
    if present & {Band.E, Band.G}:
        return _stay(Rule.EFG_NONEMPTY, classification)
    right = [c for c, m in classification if m & {Band.B, Band.C, Band.D}]
    if not right:
        return _stay(Rule.ONLY_AI, classification)

    # getDestination(r): "the nearest axis vertical to X axis that contains one or more robots
    # from B u C u D".
    rho = model.radius
    least_x = min(c[0] for c in right)
    psi = least_x if opts.psi_right is PsiRight.CENTRE_LINE else least_x - rho
    band_disc = opts.r_psi is RPsi.DISC or (opts.r_psi is RPsi.FOLLOWS_BANDS and opts.bands is Bands.DISC)
    r_psi = tuple((c, m) for c, m in classification if _in_strip(c[0] - psi, model, band_disc))
    rb = any(Band.B in m for _, m in r_psi)
    rc = any(Band.C in m for _, m in r_psi)
    rd = any(Band.D in m for _, m in r_psi)
    kw: dict[str, object] = {"psi": psi, "r_psi": tuple(c for c, _ in r_psi)}

    if not rc:  # Scenario 1: "If R_psi n C is empty ... x_p = 0 + Delta x, y_p = 0"
        destination = (psi, 0)
        return Decision(Rule.SCENARIO_1, destination, _path(destination, opts.path), classification, **kw)  # type: ignore[arg-type]

    seen: list[Candidate] = []
    if rb != rd:  # Scenario 2 (B, not D: search down) or Scenario 3 (D, not B: search up)
        case, found_rule = (Case.SCENARIO_2, Rule.SCENARIO_2) if rb else (Case.SCENARIO_3, Rule.SCENARIO_3)
        primary = -1 if rb else 1
        directions = [primary]
        if opts.search_order is SearchOrder.PRIMARY_THEN_OPPOSITE:
            directions.append(-primary)
    else:  # R_psi n C non-empty with R_psi n B, R_psi n D both empty or both non-empty
        case, found_rule = Case.UNCOVERED, Rule.UNCOVERED_SEARCH
        if opts.uncovered is Uncovered.STAY:
            return _stay(Rule.UNCOVERED_STAY, classification, case=case, **kw)
        directions = [-1, 1] if opts.uncovered is Uncovered.SEARCH_BOTH else []

    for direction in directions:
        found = _search(psi, direction, snapshot, model, seen)
        if found is not None:
            return Decision(found_rule, found, _path(found, opts.path), classification, candidates=tuple(seen), **kw)  # type: ignore[arg-type]
    return _scenario_4(snapshot, classification, model, rb and rc and rd, candidates=tuple(seen), case=case, **kw)
