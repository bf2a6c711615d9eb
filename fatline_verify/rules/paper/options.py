"""The paper's rule set's own options: one per open point of its rules' text (the bands, psi_right, the
vacancy search, Scenario 4, ...), every reading selectable, the default first.

The paper's rule set declares them (:mod:`.rule_set`), and so the catalogue
(:data:`fatline_verify.model.options.CATALOGUE`, ``docs/readings.md``, ``fatline explain``) lists them;
the options of the robots' model that every rule set takes (``visibility``, ``scheduler``, ``motion``,
``timing``, ``contact``, ``goal``) are the model layer's (:mod:`fatline_verify.model.options`). The
paper's rule set reads both kinds, in the order :data:`READINGS` lists them; the repaired rule set reads
them too (its rules are the paper's, repaired).
"""

from __future__ import annotations

from enum import StrEnum

from ...model.option_spec import OptionSpec
from ...model.option_spec import spec as _spec


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


READINGS: tuple[OptionSpec | str, ...] = (
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
    "visibility",  # the model layer's: which robots a robot sees
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
            "primary-then-opposite": "the scenario's own direction first (down in Scenario 2, up in 3), then the other",
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
    "scheduler",
    "motion",
    "timing",
    "contact",
    "goal",
)
"""What the paper's rule set reads, in the order the catalogue lists them: its own open points (declared
here) and, by name, the model layer's options, which every rule set takes (the paper's model: its
visibility circle, its scheduler and rigid moves, how movers are timed, when discs touch, what "a straight
line" means)."""

SPECS: tuple[OptionSpec, ...] = tuple(entry for entry in READINGS if isinstance(entry, OptionSpec))
"""The options the paper's rule set declares (its own)."""
