"""The options of a model: one named option per open point of a text, every reading selectable, the default
first. Each option is declared once, by its owner:

- **the model layer** (here): the robots' model every rule set shares, ``visibility`` (which robots a
  robot sees), ``scheduler``, ``motion``, ``timing``, ``contact`` and ``goal``;
- **a rule set** (``RuleSet(options=...)``, :mod:`fatline_verify.rules.registry`): the readings of its own
  rules (the paper's, :mod:`fatline_verify.rules.paper.options`), its changes to them (the repairs,
  :mod:`fatline_verify.rules.repaired.options`), a plug-in's own.

A model file sets them in its ``[options]`` table (each its rule set's, or one of :data:`MODEL_OPTIONS`);
:data:`CATALOGUE` lists every declared one, ``python -m fatline_verify.docs`` publishes this package's as
``docs/readings.md`` (each spec quotes the words it reads), ``fatline explain`` prints them and ``fatline
sweep`` takes a model through their readings. :class:`Options` holds one reading per declared option.

This module imports no rule set: rule sets declare their options into it when they register
(:func:`declare`), and the rule-set registry asks to be loaded when the catalogue is read (:func:`add_completer`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import FrozenInstanceError
from enum import StrEnum
from typing import Any, NamedTuple

from ..errors import InvalidModel
from .option_spec import OptionSpec
from .option_spec import spec as _spec


class Visibility(StrEnum):
    """Which robots a robot sees."""

    CENTRE = "centre"
    ANY_PART = "any-part"
    WHOLE_DISC = "whole-disc"


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


MODEL_SPECS: tuple[OptionSpec, ...] = (
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
)
"""The model layer's options: the robots' model, whatever rule set moves them."""

MODEL_OPTIONS = frozenset({"scheduler", "motion", "timing", "contact", "goal"})
"""The model layer's options every rule set takes (the scheduler and the round's semantics, not a rule's
reading); ``visibility`` is taken by a rule set that names it (``RuleSet(options=("visibility", ...))``: the
paper's), so the data of every other model stays as it was."""

MODEL = ""
"""The owner of the model layer's options (a rule set's options are owned by its name)."""

OPTION_NAME = re.compile(r"[a-z][a-z0-9_]{0,39}")
"""An option's name: a bare TOML key of lower-case letters, digits and '_'."""


class Declared(NamedTuple):
    """One declared option and who declared it (:data:`MODEL`, or a rule set's name)."""

    spec: OptionSpec
    owner: str


_MODEL = {s.name: s for s in MODEL_SPECS}
_DECLARED: dict[str, Declared] = {}
"""The options rule sets declared, and the model layer's they named, in catalogue order."""
_pending: list[Callable[[], None]] = []
"""What loads the declarers not yet asked (:func:`add_completer`)."""


def add_completer(load: Callable[[], None]) -> None:
    """Have ``load`` (the rule-set registry's loading of this package's rule sets) run before the catalogue
    is first read, so that it lists their options; the model layer names no rule set."""
    _pending.append(load)


def _complete() -> None:
    while _pending:
        _pending.pop(0)()


def _names() -> list[str]:
    """Catalogue order: as rule sets declared or named their options, in the order they registered (the
    paper's first), then the model layer's options no rule set named."""
    _complete()
    return [*_DECLARED, *(name for name in _MODEL if name not in _DECLARED)]


class Catalogue(Mapping[str, OptionSpec]):
    """Every declared option by name, in catalogue order (:func:`_names`); reading it first loads this
    package's rule sets (:func:`add_completer`), so it lists their options."""

    def __getitem__(self, name: str) -> OptionSpec:
        _complete()
        found = _DECLARED.get(name)
        return found.spec if found is not None else _MODEL[name]

    def __contains__(self, name: object) -> bool:
        _complete()
        return name in _DECLARED or name in _MODEL

    def __iter__(self) -> Iterator[str]:
        return iter(_names())

    def __len__(self) -> int:
        return len(_names())


CATALOGUE: Mapping[str, OptionSpec] = Catalogue()
"""Every option: the paper's open points, the model layer's, then the repairs, then a plug-in's (each rule
set's in its declaration order)."""


def owner(name: str) -> str:
    """Who declared option ``name``: :data:`MODEL` (the model layer) or a rule set's name."""
    _complete()
    found = _DECLARED.get(name)
    return found.owner if found is not None else MODEL


def declare(entries: Iterable[OptionSpec | str], rule_set: str) -> tuple[str, ...]:
    """Add the options rule set ``rule_set`` declares (each :class:`OptionSpec` in ``entries``) to the
    catalogue, in order; a name in ``entries`` is an option it reads that the model layer or an earlier rule
    set declared (a model-layer option takes its place in the catalogue where a rule set first names it), and
    so is a declaration equal to the one already declared under its name (``options=PAPER.options``).
    Returns the names it reads; another declaration of a taken name, or a name nothing declares, is a
    one-line ``ValueError`` (raised when the plug-in registers), before anything is declared."""
    entries = sorted(entries, key=str) if isinstance(entries, set | frozenset) else list(entries)
    names: list[str] = []
    for entry in entries:
        if isinstance(entry, OptionSpec):
            if not isinstance(entry.name, str) or not OPTION_NAME.fullmatch(entry.name):
                raise ValueError(
                    f"rule set {rule_set!r}: option {entry.name!r}: expected a name of lower-case letters, digits "
                    "and '_', starting with a letter"
                )
            known = _MODEL.get(entry.name) or (_DECLARED[entry.name].spec if entry.name in _DECLARED else None)
            if known is not None and known != entry:  # the same declaration again reads it (a copy of options=)
                by = "the model layer" if entry.name in _MODEL else f"rule set {_DECLARED[entry.name].owner!r}"
                raise ValueError(
                    f"rule set {rule_set!r}: option {entry.name!r} is declared by {by} already; expected an option "
                    "name of its own (or the name alone, to read that option)"
                )
            names.append(entry.name)
        elif isinstance(entry, str):
            if not _known(entry):
                raise ValueError(
                    f"rule set {rule_set!r}: options names {entry!r}: no such option; expected one of "
                    f"{', '.join(CATALOGUE)}, or an OptionSpec declaring it (fatline_verify.model.option_spec.spec)"
                )
            names.append(entry)
        else:
            raise ValueError(
                f"rule set {rule_set!r}: options entry {entry!r}: expected an option's name or its declaration, an "
                "OptionSpec (fatline_verify.model.option_spec.spec)"
            )
    if len(set(names)) != len(names):
        twice = next(n for n in names if names.count(n) > 1)
        raise ValueError(f"rule set {rule_set!r}: options names {twice!r} twice; expected each option once")
    for name, entry in zip(names, entries, strict=True):
        if name in _MODEL:
            _DECLARED.setdefault(name, Declared(_MODEL[name], MODEL))
        elif isinstance(entry, OptionSpec):
            _DECLARED.setdefault(name, Declared(entry, rule_set))
    return tuple(names)


def _known(name: str) -> bool:
    """Whether option ``name`` is declared; the registered declarers are asked only when it is not yet (a
    rule set of this package imported on its own registers before the others are loaded)."""
    if name in _DECLARED or name in _MODEL:
        return True
    _complete()
    return name in _DECLARED


class Options:
    """One reading per declared option; an option the model does not set has its default (its first
    reading). Immutable and hashable; ``options.NAME`` is the reading of option ``NAME`` (a member of its
    spec's enum, which compares equal to the reading's text). :meth:`with_` makes a changed copy."""

    __slots__ = ("__dict__", "_key")

    def __init__(self, **readings: object) -> None:
        values: dict[str, Any] = {name: spec.default for name, spec in CATALOGUE.items()}
        for name, value in readings.items():
            values[name] = parse_reading(name, value)
        object.__setattr__(self, "__dict__", values)
        object.__setattr__(self, "_key", _key(values))

    def __getattr__(self, name: str) -> Any:
        """The default of an option declared after these options were made (a plug-in loaded since)."""
        if name.startswith("_") or name not in CATALOGUE:
            raise AttributeError(f"option {name!r}: not a declared option; expected one of {', '.join(CATALOGUE)}")
        default = CATALOGUE[name].default
        self.__dict__[name] = default
        return default

    def __setattr__(self, name: str, value: object) -> None:
        raise FrozenInstanceError(f"cannot assign to option {name!r}: Options are immutable; use with_()")

    def __delattr__(self, name: str) -> None:
        raise FrozenInstanceError(f"cannot delete option {name!r}: Options are immutable")

    def __eq__(self, other: object) -> bool:
        return self._key == other._key if isinstance(other, Options) else NotImplemented

    def __hash__(self) -> int:
        return hash(self._key)

    def __repr__(self) -> str:
        return f"Options({', '.join(f'{name}={str(value)!r}' for name, value in self._key)})"

    def __reduce__(self) -> tuple[Any, ...]:
        return (_restore, (self._key,))

    def given(self) -> dict[str, StrEnum | str]:
        """The readings that are not their option's default, by option name (sorted)."""
        return dict(self._key)

    @property
    def repaired(self) -> bool:
        """Whether any repair (:mod:`fatline_verify.rules.repaired.algorithm`) is on."""
        return is_repaired(self)

    def with_(self, **changes: object) -> Options:
        """A copy with some readings changed, by option name and reading text (or value); validated."""
        return Options(**{**dict(self._key), **changes})

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


def _key(values: dict[str, Any]) -> tuple[tuple[str, Any], ...]:
    """The readings of ``values`` that are not their option's default, sorted by name: what makes two
    :class:`Options` equal (whatever options were declared when each was made)."""
    return tuple(sorted((name, v) for name, v in values.items() if v is not CATALOGUE[name].default))


def _restore(key: tuple[tuple[str, Any], ...]) -> Options:
    """:class:`Options` from its readings that are not defaults (unpickling: no option is parsed again)."""
    options = Options.__new__(Options)
    values: dict[str, Any] = {name: spec.default for name, spec in CATALOGUE.items()}
    values.update(key)
    object.__setattr__(options, "__dict__", values)
    object.__setattr__(options, "_key", key)
    return options


def repairs() -> tuple[tuple[str, StrEnum], ...]:
    """The repair options (``OptionSpec.repair``) and their ``off`` readings."""
    return tuple((name, spec.default) for name, spec in CATALOGUE.items() if spec.repair)


def is_repaired(options: Any) -> bool:
    """Whether any repair is on, by reading the repair options one by one (so that the sweep's
    option recorder sees the repair options read, not every option)."""
    return any(getattr(options, name) is not off for name, off in repairs())


NAMED_BY: dict[str, Callable[[], Iterable[str]]] = {}
"""Per option whose reading may also be a registered object's name (``goal``: every registered goal, the
goal registry's :func:`~fatline_verify.goals.registry.names`, set when it is imported): what an error lists."""

SLUG_NAME = re.compile(r"[a-z][a-z0-9-]{0,39}")
"""A plug-in's name: lower-case letters, digits and '-'."""


def parse_reading(name: str, value: object) -> StrEnum | SchedulerName | GoalName:
    """The reading ``value`` of option ``name``, or a one-line :class:`InvalidModel`."""
    if name not in CATALOGUE:
        raise InvalidModel(f"option {name}={value!r}: unknown option; expected one of {', '.join(CATALOGUE)}")
    spec = CATALOGUE[name]
    try:
        if not isinstance(value, str):
            raise ValueError(value)
        if name == "scheduler" and value not in spec.readings and SLUG_NAME.fullmatch(value):
            return SchedulerName(value)  # a registered scheduler's, checked when the model is built
        if name == "goal" and value not in spec.readings and SLUG_NAME.fullmatch(value):
            return GoalName(value)  # a registered goal's, checked when the model is built
        return spec.enum(value)
    except ValueError:
        readings = list(spec.readings)
        if name in NAMED_BY:  # every registered goal, not only the paper's readings
            readings = list(NAMED_BY[name]())
        raise InvalidModel(f"option {name}={value!r}: unknown reading; expected one of {', '.join(readings)}") from None


def options_from_mapping(mapping: dict[str, object], *, where: str = "options") -> Options:
    """Build :class:`Options` from ``{name: reading}``; unset options keep their defaults."""
    if not isinstance(mapping, dict):
        raise InvalidModel(f"{where}={mapping!r}: expected a table of option = reading")
    return Options(**mapping)


_MOVED = {
    **dict.fromkeys(
        (
            "Quadrants", "Bands", "BandOverlap", "PsiRight", "RPsi", "Vacant", "PathShape", "SearchBound",
            "SearchOrder", "Uncovered", "Scenario4Guard", "Scenario4Drop", "Scenario4FreePath",
        ),
        "fatline_verify.rules.paper.options",
    ),
    **dict.fromkeys(
        (
            "RepairLock", "RepairStack", "RepairApproach", "RepairStep", "RepairClear", "RepairEdges",
            "RepairProgress", "REPAIR_SPECS",
        ),
        "fatline_verify.rules.repaired.options",
    ),
}  # fmt: skip
"""Names this module held before rule sets declared their own options, and where they are now."""


def __getattr__(name: str) -> Any:
    if name == "REPAIRS":  # a constant before plug-ins could declare options
        return repairs()
    if name in _MOVED:
        raise ImportError(
            f"fatline_verify.model.options.{name}: moved to {_MOVED[name]} (a rule set declares its own options); "
            f"expected: from {_MOVED[name]} import {name}"
        )
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
