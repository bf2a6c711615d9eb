"""The interpretation catalogue: one named option per open point of the paper.

The paper is informal; each place where its text admits several precise readings is an option
here, every reading selectable, the default marked. ``python -m fatline_verify.docs`` publishes it as
``docs/readings.md``; each option's spec quotes the paper's words it reads. ``fatline explain`` prints
this catalogue. The repairs, changes to the algorithm rather than readings of it, are options too; their enums and
entries live in :mod:`fatline_verify.rules.repaired.options`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, fields, replace
from enum import StrEnum
from typing import Any

from ..errors import InvalidModel
from ..rules.repaired.options import (
    REPAIR_SPECS,
    RepairApproach,
    RepairClear,
    RepairEdges,
    RepairLock,
    RepairProgress,
    RepairStack,
    RepairStep,
)
from .option_spec import OptionSpec
from .option_spec import spec as _spec


class Quadrants(StrEnum):
    """Which quadrant each of B, D, E, G is."""

    LOWER_RIGHT = "lower-right"
    LITERAL = "literal"


class Bands(StrEnum):
    """When a robot belongs to the bands A, C, F, I around the axes."""

    DISC = "disc"
    CENTRE = "centre"


class BandOverlap(StrEnum):
    """Where a robot that meets a vertical and a horizontal band goes."""

    BOTH = "both"
    VERTICAL_FIRST = "vertical-first"
    HORIZONTAL_FIRST = "horizontal-first"


class Visibility(StrEnum):
    """Which robots a robot sees."""

    CENTRE = "centre"
    ANY_PART = "any-part"
    WHOLE_DISC = "whole-disc"


class PsiRight(StrEnum):
    """Where the axis psi_right lies."""

    CENTRE_LINE = "centre-line"
    TOUCH_LINE = "touch-line"


class RPsi(StrEnum):
    """Which robots form R_psi_right, the band around psi_right."""

    FOLLOWS_BANDS = "follows-bands"
    DISC = "disc"
    CENTRE = "centre"


class Vacant(StrEnum):
    """When a point is vacant."""

    TOUCHING_ALLOWED = "touching-allowed"
    STRICT = "strict"


class PathShape(StrEnum):
    """The shape of a rigid move."""

    STRAIGHT = "straight"
    HORIZONTAL_THEN_VERTICAL = "horizontal-then-vertical"
    VERTICAL_THEN_HORIZONTAL = "vertical-then-horizontal"


class SearchBound(StrEnum):
    """How far the vacancy search of Scenarios 2 and 3 goes."""

    WITHIN_VIEW = "within-view"
    UNBOUNDED = "unbounded"


class SearchOrder(StrEnum):
    """Which directions the vacancy search tries."""

    PRIMARY_THEN_OPPOSITE = "primary-then-opposite"
    PRIMARY_ONLY = "primary-only"


class Uncovered(StrEnum):
    """What happens in the cases Scenarios 1-3 leave out."""

    SCENARIO_4 = "scenario-4"
    SEARCH_BOTH = "search-both"
    STAY = "stay"


class Scenario4Guard(StrEnum):
    """When Scenario 4 applies."""

    OTHERWISE = "otherwise"
    ALL_THREE_FULL = "all-three-full"


class Scenario4Drop(StrEnum):
    """How far Scenario 4 moves down."""

    LITERAL = "literal"
    TOUCH = "touch"
    GAP = "gap"
    PROOFS = "proofs"


class Scenario4FreePath(StrEnum):
    """Whether Scenario 4 checks a free path first."""

    OFF = "off"
    ON = "on"


class Scheduler(StrEnum):
    """Which robots are activated in a round."""

    SSYNC = "ssync"
    FSYNC = "fsync"
    CENTRALIZED = "centralized"
    ASYNC = "async"


class SchedulerName(str):
    """The ``scheduler`` of a model that names a registered round scheduler of its own (a plug-in:
    :mod:`fatline_verify.schedulers.activation`), not one of :class:`Scheduler`."""

    __slots__ = ()

    @property
    def value(self) -> str:
        return str(self)


class Motion(StrEnum):
    """Whether the asynchronous scheduler may end a move before its destination."""

    RIGID = "rigid"
    NON_RIGID = "non-rigid"


class Timing(StrEnum):
    """How two robots moving in the same round are timed."""

    ANY_SPEED = "any-speed"
    LOCKSTEP = "lockstep"


class Contact(StrEnum):
    """Whether discs at distance exactly 2 collide."""

    TOUCH_ALLOWED = "touch-allowed"
    STRICT = "strict"


class Goal(StrEnum):
    """What "form a straight line" means: the paper's three readings. Other registered goals
    (:mod:`fatline_verify.goals`) are named by a :class:`GoalName`."""

    VERTICAL_LINE = "vertical-line"
    ANY_LINE = "any-line"
    LINE_MEETS_DISCS = "line-meets-discs"


class GoalName(str):
    """The ``goal`` of a model that names a registered goal other than the paper's three readings
    (``point``, ``circle``, a plug-in's: :mod:`fatline_verify.goals.registry`), checked when the model is built."""

    __slots__ = ()

    @property
    def value(self) -> str:
        return str(self)


CATALOGUE: dict[str, OptionSpec] = {
    s.name: s
    for s in [
        _spec(
            "quadrants",
            Quadrants,
            "Set B and D account for the robots that fall within the first and second quadrant ... "
            "The robots which are in third and fourth quadrant ... make the sets E and G",
            {
                "lower-right": "B = upper right, D = lower right, E = upper left, G = lower left: "
                "getDestination calls B, C, D the robots to the RIGHT and Scenario 2 moves down because D is empty",
                "literal": "B = first quadrant (upper right), D = second (upper left), E = third (lower left), "
                "G = fourth (lower right)",
            },
        ),
        _spec(
            "bands",
            Bands,
            "Set A consists of the robots partially or fully present in the area of unit distance around "
            "the positive Y axis",
            {
                "disc": "the disc meets the strip of half-width 1 with positive area: A = {|x| < 2, y > 0}, "
                "I = {|x| < 2, y < 0}, C = {|y| < 2, x > 0}, F = {|y| < 2, x < 0}",
                "centre": "the centre lies in the strip: A = {|x| <= 1, y > 0}, and likewise I, C, F",
            },
        ),
        _spec(
            "band_overlap",
            BandOverlap,
            "the set of robots visible to r can be divided into eight distinct and non-overlapping sets",
            {
                "both": "a robot meeting a vertical and a horizontal band (e.g. at (3/2, 3/2) under bands=disc) "
                "belongs to both",
                "vertical-first": "it belongs to A or I only",
                "horizontal-first": "it belongs to C or F only",
            },
        ),
        _spec(
            "visibility",
            Visibility,
            "a circular area centered at the center of the robot having radius rad_v",
            {
                "centre": "r sees c iff |c| <= rad_v",
                "any-part": "r sees c iff some part of c's disc is in view: |c| <= rad_v + 1",
                "whole-disc": "r sees c iff all of c's disc is in view: |c| <= rad_v - 1",
            },
        ),
        _spec(
            "psi_right",
            PsiRight,
            "the nearest axis vertical to X axis that contains one or more robots from B u C u D",
            {
                "centre-line": "x_psi = the least x of a centre in B u C u D",
                "touch-line": "x_psi = (least x of a centre in B u C u D) - 1: the first vertical line touching a disc",
            },
        ),
        _spec(
            "r_psi",
            RPsi,
            "the robots partially or fully present in the area of unit distance around the axis psi_right",
            {
                "follows-bands": "as the bands option reads 'partially or fully present': |x - x_psi| < 2 "
                "under bands=disc, <= 1 under bands=centre",
                "disc": "|x - x_psi| < 2 whatever the bands option",
                "centre": "|x - x_psi| <= 1 whatever the bands option",
            },
            note="membership in B, C, D is as classified by r",
        ),
        _spec(
            "vacant",
            Vacant,
            "A point is vacant if there exist no parts of another robot around a circular region of radius 1 "
            "around this point",
            {
                "touching-allowed": "p is vacant iff |c - p| >= 2 for every robot c that r sees (r excluded)",
                "strict": "p is vacant iff |c - p| > 2 for every robot c that r sees",
            },
            note="the free-path test of scenario4_free_path uses the same boundary",
        ),
        _spec(
            "path",
            PathShape,
            "its horizontal movement must be followed by a vertical movement",
            {
                "straight": "the segment from source to destination",
                "horizontal-then-vertical": "horizontally to the destination's x, then vertically",
                "vertical-then-horizontal": "vertically to the destination's y, then horizontally",
            },
        ),
        _spec(
            "search_bound",
            SearchBound,
            "y_p = 0 - i Delta y, i = 2, 3 ... This process continues till a vacant point is found",
            {
                "within-view": "only candidates p with |p| <= rad_v are tried",
                "unbounded": "candidates go on until one is vacant (only visible robots can block)",
            },
        ),
        _spec(
            "search_order",
            SearchOrder,
            "If no vacant point is found in R_psi n B using this procedure, then the vacant point can be "
            "found in the same manner in R_psi n D",
            {
                "primary-then-opposite": "the scenario's own direction first (down in Scenario 2, up in 3), "
                "then the other",
                "primary-only": "the scenario's own direction only",
            },
        ),
        _spec(
            "uncovered",
            Uncovered,
            "Scenarios 1-3 leave out R_psi n C non-empty with R_psi n B, R_psi n D both empty or both non-empty",
            {
                "scenario-4": "those cases go to Scenario 4",
                "search-both": "search down, then up, then Scenario 4",
                "stay": "r does not move",
            },
        ),
        _spec(
            "scenario4_guard",
            Scenario4Guard,
            "If there is no vacant point in R_psi n B and R_psi n C and R_psi n B",
            {
                "otherwise": "Scenario 4 applies whenever Scenarios 1-3 give no destination",
                "all-three-full": "Scenario 4 applies only when R_psi n B, R_psi n C, R_psi n D are all non-empty; "
                "otherwise r stays",
            },
        ),
        _spec(
            "scenario4_drop",
            Scenario4Drop,
            "y_p = 0 - rad_v + 1 (I empty); y_p = 0 - d + 1 where d = the vertical distance with r and the "
            "robot with maximum y value in I",
            {
                "literal": "I empty: y_p = -rad_v + 1; else y_p = -d + 1 with d the vertical centre distance",
                "touch": "I empty: y_p = -rad_v + 1; else y_p = -d + 2 (r ends touching a robot straight below)",
                "gap": "I empty: y_p = -rad_v + 1; else y_p = -d + 1 with d = vertical centre distance - 2",
                "proofs": "as Lemma 1's proof: I empty: y_p = -rad_v ('moves along -Y, rad_v distance'); "
                "else y_p = -d + 2 ('till it touches the robots in I')",
            },
        ),
        _spec(
            "scenario4_free_path",
            Scenario4FreePath,
            "r moves down along -Y axis if it has free path. Otherwise it does not move (proof of Lemma 4)",
            {
                "off": "the algorithm as written: no free-path test",
                "on": "r stays unless the width-2 rectangle from source to destination meets no visible robot",
            },
        ),
        _spec(
            "scheduler",
            Scheduler,
            "semi-synchronous scheduling where an arbitrary set of robots look, compute and move "
            "simultaneously (model); 'asynchronous' (theorem)",
            {
                "ssync": "every non-empty set of robots, one shared snapshot",
                "fsync": "every robot, every round",
                "centralized": "one robot a round",
                "async": "one event at a time: an idle robot looks and computes on the current positions (a "
                "moving robot is seen where it is), a moving robot takes one of async_steps move steps; "
                "snapshots may be stale",
            },
            note="async in full: events L<i> (robot i looks and computes; if it would move it starts moving), "
            "M<i> (one move step: 1/K of its path at constant speed, an L-shaped path by arc length) and, under "
            "motion=non-rigid, S<i> (the move ends here, after at least one step); K = the model parameter "
            "async_steps (default 2; 1 = atomic moves but stale looks, 2 = robots can be seen halfway), "
            "positions exact on a K-times finer lattice; collision is judged per move step, the swept part "
            "of the path against every other robot where it is now; connectivity and the RMA on every "
            "state; fairness: in a fair cycle every robot that is moving, or idle and would move, takes an "
            "event (or is disabled somewhere on the cycle)",
        ),
        _spec(
            "motion",
            Motion,
            "The robots do not stop before reaching its destination",
            {
                "rigid": "every move goes to its destination (in async_steps steps)",
                "non-rigid": "the scheduler may end a move after any of its steps, at least one",
            },
            note="asynchronous scheduler only: a round's move is always rigid",
            only_under=Scheduler.ASYNC,
        ),
        _spec(
            "timing",
            Timing,
            "The robots do not stop before reaching its destination (rigid motion); speeds are not given",
            {
                "any-speed": "two movers collide iff their swept capsules come within 2: some pair of points of "
                "their paths is closer than 2",
                "lockstep": "equal start, constant speed, equal arrival: the centres' closest approach over the "
                "common move is below 2",
            },
        ),
        _spec(
            "contact",
            Contact,
            "the mutual distance between two robots is at least delta > 2; Scenario 4 'till it touches'",
            {
                "touch-allowed": "centres at distance exactly 2 touch; that is not a collision",
                "strict": "centres at distance exactly 2 collide",
            },
        ),
        _spec(
            "goal",
            Goal,
            "after a finite number of execution cycles, the robots in R will form a straight line",
            {
                "vertical-line": "all centres share one x (the proof puts every robot on the RMA)",
                "any-line": "all centres are collinear",
                "line-meets-discs": "some straight line meets every disc",
            },
        ),
        *REPAIR_SPECS,
    ]
}
"""Every option: the paper's open points, then the repairs (:mod:`fatline_verify.rules.repaired.options`)."""


@dataclass(frozen=True, slots=True)
class Options:
    """One reading per open point; the defaults are the readings marked (default) in docs/readings.md."""

    quadrants: Quadrants = Quadrants.LOWER_RIGHT
    bands: Bands = Bands.DISC
    band_overlap: BandOverlap = BandOverlap.BOTH
    visibility: Visibility = Visibility.CENTRE
    psi_right: PsiRight = PsiRight.CENTRE_LINE
    r_psi: RPsi = RPsi.FOLLOWS_BANDS
    vacant: Vacant = Vacant.TOUCHING_ALLOWED
    path: PathShape = PathShape.STRAIGHT
    search_bound: SearchBound = SearchBound.WITHIN_VIEW
    search_order: SearchOrder = SearchOrder.PRIMARY_THEN_OPPOSITE
    uncovered: Uncovered = Uncovered.SCENARIO_4
    scenario4_guard: Scenario4Guard = Scenario4Guard.OTHERWISE
    scenario4_drop: Scenario4Drop = Scenario4Drop.LITERAL
    scenario4_free_path: Scenario4FreePath = Scenario4FreePath.OFF
    scheduler: Scheduler = Scheduler.SSYNC
    motion: Motion = Motion.RIGID
    timing: Timing = Timing.ANY_SPEED
    contact: Contact = Contact.TOUCH_ALLOWED
    goal: Goal | GoalName = Goal.VERTICAL_LINE
    repair_lock: RepairLock = RepairLock.OFF
    repair_stack: RepairStack = RepairStack.OFF
    repair_approach: RepairApproach = RepairApproach.OFF
    repair_step: RepairStep = RepairStep.OFF
    repair_clear: RepairClear = RepairClear.OFF
    repair_edges: RepairEdges = RepairEdges.OFF
    repair_progress: RepairProgress = RepairProgress.OFF

    @property
    def repaired(self) -> bool:
        """Whether any repair (:mod:`fatline_verify.rules.repaired.algorithm`) is on."""
        return is_repaired(self)

    def with_(self, **changes: str) -> Options:
        """A copy with some readings changed, by option name and reading text; validated."""
        parsed: dict[str, Any] = {k: parse_reading(k, v) for k, v in changes.items()}
        return replace(self, **parsed)

    def as_dict(self) -> dict[str, str]:
        """Every option that means something under this scheduler and its reading, as text, in catalogue
        order; a repair only when it is on (the paper's models keep their data)."""
        return {
            name: str(getattr(self, name))
            for name, spec in CATALOGUE.items()
            if (spec.only_under is None or spec.only_under is self.scheduler)
            and not (spec.repair and getattr(self, name) is spec.default)
        }

    def differences(self, other: Options | None = None) -> dict[str, str]:
        """The options whose reading differs from ``other`` (default: from the defaults)."""
        base = {name: str(getattr(other or Options(), name)) for name in CATALOGUE}
        return {k: v for k, v in self.as_dict().items() if base[k] != v}


REPAIRS = tuple((name, spec.default) for name, spec in CATALOGUE.items() if spec.repair)
"""The repair options and their ``off`` readings."""


def is_repaired(options: Any) -> bool:
    """Whether any repair is on, by reading the repair options one by one (so that the sweep's
    option recorder sees the repair options read, not every option)."""
    return any(getattr(options, name) is not off for name, off in REPAIRS)


SLUG_NAME = re.compile(r"[a-z][a-z0-9-]{0,39}")
"""A plug-in's name: lower-case letters, digits and '-'."""


def parse_reading(name: str, value: object) -> StrEnum | SchedulerName | GoalName:
    """The reading ``value`` of option ``name``, or a one-line :class:`InvalidModel`."""
    spec = CATALOGUE.get(name)
    if spec is None:
        raise InvalidModel(f"option {name}={value!r}: unknown option; expected one of {', '.join(CATALOGUE)}")
    try:
        if not isinstance(value, str):
            raise ValueError(value)
        if name == "scheduler" and value not in spec.readings and SLUG_NAME.fullmatch(value):
            return SchedulerName(value)  # a registered scheduler's, checked when the model is built
        if name == "goal" and value not in spec.readings and SLUG_NAME.fullmatch(value):
            return GoalName(value)  # a registered goal's, checked when the model is built
        return spec.enum(value)
    except ValueError:
        readings = spec.readings
        if name == "goal":  # every registered goal, not only the paper's readings
            from ..goals import registry

            readings = registry.names()
        raise InvalidModel(f"option {name}={value!r}: unknown reading; expected one of {', '.join(readings)}") from None


def options_from_mapping(mapping: dict[str, object], *, where: str = "options") -> Options:
    """Build :class:`Options` from ``{name: reading}``; unset options keep their defaults."""
    if not isinstance(mapping, dict):
        raise InvalidModel(f"{where}={mapping!r}: expected a table of option = reading")
    parsed: dict[str, Any] = {name: parse_reading(name, value) for name, value in mapping.items()}
    return Options(**parsed)


assert [f.name for f in fields(Options)] == list(CATALOGUE)
