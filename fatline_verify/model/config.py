"""A Model: the algorithm's readings, its parameters, and the checker's bounds; TOML in, validated.

Units. The paper's unit is the robot radius. The engine works on a lattice of ``q`` points per
radius, so a radius is ``q`` lattice units, visibility is ``rad_v * q`` (which must be an integer)
and two discs touch at ``2 q``. Positions at the boundary (CLI, traces) are in radius units;
:meth:`Model.to_lattice` and :meth:`Model.from_lattice` convert, exactly.
"""

from __future__ import annotations

import functools
import math
import tomllib
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..errors import InvalidModel
from ..goals import registry as goals
from ..lemmas.properties import CHECKED
from ..outputs import SLUG, NotReadable, read_regular
from ..rules import registry
from .numbers import MAX_DIGITS, Number, Point, format_number, normalize, parse_number
from .options import Options, Scheduler, Visibility, is_repaired, options_from_mapping
from .seams import SEAMS, Param, Settings, Value, declared, filled, parse_table, with_values

MODELS_DIR = Path(__file__).parent.parent / "models"
"""Where the shipped model files live (``models/`` at the top of the repository links here)."""


@dataclass(frozen=True, slots=True)
class Parameters:
    """The paper's free parameters. It fixes none of them; the shipped models pick small values.

    ``rad_v``: visibility radius in radii. ``q``: lattice points per radius. ``delta``: the initial
    condition "the mutual distance between two robots is at least delta > 2": distance >= delta, and delta > 2.
    """

    rad_v: Number = 4
    q: int = 1
    delta: Number = Fraction(21, 10)
    async_steps: int = 2
    """ASYNC only: the move steps a move takes (positions exact on a lattice this many times finer).
    1: moves are atomic but snapshots may be stale; 2: a robot may also be seen halfway; ..."""

    def __post_init__(self) -> None:
        if not isinstance(self.q, int) or isinstance(self.q, bool) or self.q < 1:
            raise InvalidModel(f"q={self.q!r}: expected a whole number of lattice points per radius, at least 1")
        if self.rad_v <= 2:
            raise InvalidModel(
                f"rad_v={format_number(self.rad_v)}: expected a visibility radius above 2 "
                "(a robot must be able to see a neighbour it does not touch)"
            )
        if (Fraction(self.rad_v) * self.q).denominator != 1:
            raise InvalidModel(
                f"rad_v={format_number(self.rad_v)} with q={self.q}: expected rad_v * q to be an integer"
            )
        if (
            not isinstance(self.async_steps, int)
            or isinstance(self.async_steps, bool)
            or not 1 <= self.async_steps <= 16
        ):
            raise InvalidModel(f"async_steps={self.async_steps!r}: expected a whole number of move steps, 1..16")
        if self.delta <= 2:
            raise InvalidModel(f"delta={format_number(self.delta)}: expected delta > 2 (the paper: 'delta > 2 units')")


@dataclass(frozen=True, slots=True)
class Bounds:
    """The checker's default bounds for this model (command-line flags override them)."""

    robots: tuple[int, int] = (3, 3)
    window: tuple[int, int] = (7, 7)
    max_states: int | None = None
    """A cap on states per search; ``None``: what ``--max-memory`` affords."""


def _robots(rules: str) -> str:
    """The robots of the rule set called ``rules`` (``"discs"`` or ``"points"``); the paper's discs for a name
    no rule set has (a model being built is checked elsewhere)."""
    try:
        return registry.get(rules or "paper").robots
    except InvalidModel:
        return "discs"


@functools.cache
def _view(rad_v: Number, q: int) -> int:
    """:attr:`Model.view`, computed once per parameters (it is asked for on every pair of every round)."""
    return int(Fraction(rad_v) * q)


@functools.cache
def _view2(rad_v: Number, q: int, visibility: Visibility) -> int:
    """:attr:`Model.view2`, computed once per parameters and reading."""
    extra = {Visibility.CENTRE: 0, Visibility.ANY_PART: 1, Visibility.WHOLE_DISC: -1}[visibility]
    reach = _view(rad_v, q) + extra * q
    return reach * reach


@dataclass(frozen=True, slots=True)
class Model:
    """Algorithm readings + parameters + bounds. Passed explicitly everywhere; there is no global model."""

    name: str = "paper"
    options: Options = field(default_factory=Options)
    parameters: Parameters = field(default_factory=Parameters)
    bounds: Bounds = field(default_factory=Bounds)
    description: str = ""
    source: str = ""
    expected: dict[str, str] = field(default_factory=dict, compare=False)
    """Golden verdicts at the model's own bounds, lemma -> verdict (worst over robot counts)."""
    algorithm: Callable[..., Any] | None = field(default=None, repr=False, compare=False)
    """A replacement for the rule set's decision function (seeded-bug tests); ``None``: the rule set's."""
    rules: str = ""
    """The rule set (:mod:`fatline_verify.rules.registry`). Left empty, or one of the paper's two, it is
    :func:`implied_rules`: ``repaired`` where a repair option is on, else ``paper`` (the repaired rules
    with every repair off decide as the paper's)."""
    settings: Settings = ()
    """The values of the parameters its scheduler and its rule set declare (:mod:`.seams`), per seam,
    as the model file set them (defaults filled); read them with :meth:`setting`."""

    def __post_init__(self) -> None:
        if self.rules in IMPLIED:
            object.__setattr__(self, "rules", implied_rules(self.options))

    @property
    def ref(self) -> str:
        """How a command names this model: its shipped name, or the file it was read from (advice in an
        error, ``fatline check REF``, must work for a model file too)."""
        if not self.source:
            return self.name
        path = Path(self.source)
        if path.resolve() == (MODELS_DIR / f"{self.name}.toml").resolve():
            return self.name
        return self.source

    def setting(self, seam: str) -> dict[str, Value]:
        """The parameters of this model's scheduler (``seam="scheduler"``) or rule set (``"rules"``):
        every one its registered object declares, with the model's value or else the default; empty
        for one that declares none (the paper's)."""
        given = dict(next((values for name, values in self.settings if name == seam), ()))
        return filled(declared(seam_owner(self, seam)), given)

    def with_q(self, q: int) -> Model:
        """The same model on a lattice of ``q`` points per radius (every other parameter kept)."""
        return replace(self, parameters=replace(self.parameters, q=q))

    # --- lattice quantities, all in lattice units (radius = q) -------------------------------
    @property
    def radius(self) -> int:
        """One robot radius in lattice units."""
        return self.parameters.q

    @property
    def view(self) -> int:
        """The visibility radius in lattice units."""
        return _view(self.parameters.rad_v, self.parameters.q)

    @property
    def view2(self) -> int:
        """Squared distance up to which a robot sees another's centre, per ``visibility``."""
        return _view2(self.parameters.rad_v, self.parameters.q, self.options.visibility)

    @property
    def contact2(self) -> int:
        """Squared centre distance at which two discs touch: ``(2q)^2``."""
        return 4 * self.radius * self.radius

    @property
    def points(self) -> bool:
        """Whether its rule set's robots are points (``RuleSet(robots="points")``), not the paper's discs."""
        return _robots(self.rules) == "points"

    @property
    def apart2(self) -> int:
        """The least integer squared lattice distance that meets the initial condition (>= delta; 1 for
        point robots, whose condition is distinct positions)."""
        if self.points:
            return 1
        bound = (Fraction(self.parameters.delta) * self.parameters.q) ** 2
        return math.ceil(bound)

    def sees(self, d2: Number) -> bool:
        """Whether a robot at squared distance ``d2`` is visible (the boundary is included)."""
        return d2 <= self.view2

    def initially_apart(self, d2: Number) -> bool:
        """The initial condition on one pair: "the mutual distance between two robots is at least
        delta > 2", i.e. ``d2 >= (delta q)^2`` (distance exactly delta meets it); for point robots,
        distinct positions (``d2 > 0``): delta speaks of discs."""
        if self.points:
            return d2 > 0
        return d2 >= (Fraction(self.parameters.delta) * self.parameters.q) ** 2

    def to_lattice(self, point: Point) -> Point:
        """Radius units to lattice units."""
        return (normalize(Fraction(point[0]) * self.radius), normalize(Fraction(point[1]) * self.radius))

    def from_lattice(self, point: Point) -> Point:
        """Lattice units to radius units."""
        return (normalize(Fraction(point[0], self.radius)), normalize(Fraction(point[1], self.radius)))

    def describe(self) -> str:
        """One line: name, parameters and the readings that differ from the defaults."""
        p = self.parameters
        diff = self.options.differences()
        readings = ", ".join(f"{k}={v}" for k, v in diff.items()) or (
            "every default reading" if self.rules in IMPLIED else "the scheduler's defaults"
        )
        steps = f", async_steps={p.async_steps}" if self.options.scheduler is Scheduler.ASYNC else ""
        rules = "" if self.rules in IMPLIED else f"rules={self.rules}, "
        own = "".join(
            f"; {seam} " + ", ".join(f"{k}={v}" for k, v in values)
            for seam, values in ((seam, self.setting(seam).items()) for seam in ("rules", "scheduler", "goal"))
            if values
        )
        return (
            f"{self.name}: {rules}rad_v={format_number(p.rad_v)}, q={p.q}, delta={format_number(p.delta)}{steps}; "
            f"{readings}{own}"
        )


def seam_owner(model: Model, seam: str, scheduler: str | None = None) -> Any:
    """The registered object whose parameters the ``seam`` table sets: the model's round scheduler
    (``scheduler``: another one's name) or its rule set; ``None`` for ASYNC, which declares none."""
    if seam == "rules":
        return registry.of(model)
    if seam == "goal":
        return goals.of(model)
    name = str(scheduler or model.options.scheduler)
    if name == Scheduler.ASYNC.value:
        return None
    from ..schedulers.activation import round_scheduler

    return round_scheduler(name)


def own_parameters(model: Model) -> dict[str, tuple[str, Param]]:
    """The parameters of ``model``'s scheduler and rule set, by their model-file name (``scheduler.k``):
    per name, what declares it (``"scheduler 'pairs'"``) and its :class:`~.seams.Param`."""
    found: dict[str, tuple[str, Param]] = {}
    for seam in SEAMS:
        name = str(model.options.scheduler) if seam == "scheduler" else model.rules
        what = f"scheduler {name!r}" if seam == "scheduler" else f"rule set {name!r}"
        for key, param in declared(seam_owner(model, seam)).items():
            found[f"{seam}.{key}"] = (what, param)
    return found


def with_parameters(model: Model, values: dict[str, Value]) -> Model:
    """``model`` with some of its own parameters set (``{"rules.reach": 4}``, each checked against its
    declaration: a one-line :class:`InvalidModel` otherwise)."""
    owners = {seam: declared(seam_owner(model, seam)) for seam in SEAMS}
    for name in values:
        seam, _, key = name.partition(".")
        if key not in owners.get(seam, {}):
            known = ", ".join(own_parameters(model)) or "none"
            raise InvalidModel(f"{name}={values[name]!r}: not a parameter of this model; expected one of {known}")
    return replace(model, settings=with_values(model.settings, owners, values))


IMPLIED = ("", "paper", "repaired")
"""Rule sets a model's options imply: the paper's, and the paper's with repairs."""


def implied_rules(options: Options) -> str:
    """The rule set of a model that names none: ``repaired`` where a repair option is on (model files
    and traces written before rule sets were named), else ``paper``. The repair options are read one
    by one (the sweep's option recorder sees just those read)."""
    return "repaired" if is_repaired(options) else "paper"


_TOP_KEYS = {"name", "description", "rules", "parameters", "options", "bounds", "expected", "scheduler", "goal"}
_LEMMAS = tuple(lemma.value for lemma in CHECKED)
_VERDICTS = ("VIOLATED", "HOLDS_WITHIN_BOUNDS", "PROVED", "INCONCLUSIVE")
_PARAM_KEYS = {"rad_v", "q", "delta", "async_steps"}
_BOUND_KEYS = {"robots", "window", "max_states"}


def _unknown(table: dict[str, object], allowed: set[str], where: str) -> None:
    for key in table:
        if key not in allowed:
            raise InvalidModel(
                f"{where}{key}={table[key]!r}: unknown key; expected one of {', '.join(sorted(allowed))}"
            )


def parse_robots(text: object, *, error: type[Exception] = InvalidModel) -> tuple[int, int]:
    """``3`` or ``"2..5"`` to an inclusive range of robot counts."""
    raw = str(text).strip()
    parts = raw.split("..")
    try:
        lo, hi = (int(parts[0]), int(parts[-1])) if len(parts) in (1, 2) else (0, -1)
    except ValueError:
        lo, hi = 0, -1
    if not (1 <= lo <= hi):
        raise error(f"robots={raw!r}: expected a count like 3 or a range like 2..5 with 1 <= low <= high")
    return lo, hi


def parse_window(text: object, *, error: type[Exception] = InvalidModel, name: str = "window") -> tuple[int, int]:
    """``"9x9"`` to (width, height) in lattice points (``name``: the flag, for the error)."""
    raw = str(text).strip().lower()
    parts = raw.split("x")
    try:
        w, h = (int(parts[0]), int(parts[1])) if len(parts) == 2 else (0, 0)
    except ValueError:
        w, h = 0, 0
    if w < 1 or h < 1:
        raise error(f"{name}={raw!r}: expected WIDTHxHEIGHT in lattice points, like 9x9")
    return w, h


def model_from_mapping(data: dict[str, object], *, source: str = "", default_name: str = "model") -> Model:
    """Build and validate a Model from a parsed TOML/JSON mapping."""
    _unknown(data, _TOP_KEYS, "")
    params_raw = data.get("parameters", {})
    if not isinstance(params_raw, dict):
        raise InvalidModel(f"parameters={params_raw!r}: expected a table")
    _unknown(params_raw, _PARAM_KEYS, "parameters.")
    params: dict[str, object] = {}
    for key in ("rad_v", "delta"):
        if key in params_raw:
            try:
                params[key] = parse_number(params_raw[key], name=key, allow_decimal=True)
            except ValueError as exc:
                raise InvalidModel(str(exc)) from None
    for key in ("q", "async_steps"):
        if key in params_raw:
            params[key] = params_raw[key]
    parameters = Parameters(**params)  # type: ignore[arg-type]
    options_raw = data.get("options", {})
    rules_raw, rules_table = data.get("rules"), None
    if isinstance(rules_raw, dict):  # [rules]: the rule set's name, then its own parameters
        rules_table = {k: v for k, v in rules_raw.items() if k != "name"}
        rules_raw = rules_raw.get("name")
        if not isinstance(rules_raw, str):
            raise InvalidModel(f"rules.name={rules_raw!r}: expected the name of a rule set in the [rules] table")
    if rules_raw is not None and isinstance(options_raw, dict):  # a named rule set: its options, before any reading
        _accepted(_rule_set(rules_raw), options_raw)
    options = options_from_mapping(options_raw)  # type: ignore[arg-type]
    rules = _rules(rules_raw, options, options_raw)  # type: ignore[arg-type]
    options = _goal(rules, options, data.get("options", {}))  # type: ignore[arg-type]
    if not isinstance(options.scheduler, Scheduler):
        from ..schedulers.activation import scheduler_named

        scheduler_named(str(options.scheduler))  # a registered one, or one line naming every scheduler
    settings = _settings(rules, options, data.get("scheduler"), rules_table, data.get("goal"))
    bounds_raw = data.get("bounds", {})
    if not isinstance(bounds_raw, dict):
        raise InvalidModel(f"bounds={bounds_raw!r}: expected a table")
    _unknown(bounds_raw, _BOUND_KEYS, "bounds.")
    bounds = Bounds()
    if "robots" in bounds_raw:
        bounds = Bounds(parse_robots(bounds_raw["robots"]), bounds.window, bounds.max_states)
    if "window" in bounds_raw:
        bounds = Bounds(bounds.robots, parse_window(bounds_raw["window"]), bounds.max_states)
    if "max_states" in bounds_raw:
        ms = bounds_raw["max_states"]
        if not isinstance(ms, int) or isinstance(ms, bool) or ms < 1:
            raise InvalidModel(f"bounds.max_states={ms!r}: expected a positive integer")
        bounds = Bounds(bounds.robots, bounds.window, ms)
    expected_raw = data.get("expected", {})
    if not isinstance(expected_raw, dict):
        raise InvalidModel(f"expected={expected_raw!r}: expected a table of lemma = verdict")
    _unknown(expected_raw, set(_LEMMAS), "expected.")
    for lemma, verdict in expected_raw.items():
        if verdict not in _VERDICTS:
            raise InvalidModel(f"expected.{lemma}={verdict!r}: unknown verdict; expected one of {', '.join(_VERDICTS)}")
    name = data.get("name", default_name)
    if not isinstance(name, str) or not SLUG.match(name) or name in (".", ".."):
        raise InvalidModel(
            f"name={name!r}: expected a slug of lower-case letters, digits, '.', '_' and '-' (it names output files)"
        )
    description = data.get("description", "")
    if not isinstance(description, str):
        raise InvalidModel(f"description={description!r}: expected a string")
    return Model(
        name, options, parameters, bounds, description, source, dict(expected_raw), rules=rules, settings=settings
    )


def _settings(
    rules: str, options: Options, scheduler_table: object, rules_table: object, goal_table: object = None
) -> Settings:
    """The ``[scheduler]``, ``[rules]`` and ``[goal]`` tables, checked against what the model's scheduler,
    rule set and goal declare (:mod:`.seams`): every declared parameter's value, defaults filled."""
    probe = Model(options=options, rules=rules)
    out = []
    names = {"scheduler": f"scheduler {str(options.scheduler)!r}", "rules": f"rule set {rules!r}"}
    names["goal"] = f"goal {str(options.goal)!r}"
    for seam, table in (("scheduler", scheduler_table), ("rules", rules_table), ("goal", goal_table)):
        owner = seam_owner(probe, seam)
        what = names[seam]
        values = parse_table(seam, what, declared(owner), table)
        if values:
            out.append((seam, values))
    return tuple(out)


def _goal(rules: str, options: Options, given: dict[str, object]) -> Options:
    """``options`` with the goal the model means: the one its file sets, else the one its rule set declares
    (``RuleSet(goal=...)``), else the paper's default; a registered goal (one line naming every goal
    otherwise) that means something for the rule set's robots (:func:`~fatline_verify.goals.registry.require_for`)."""
    rule_set = registry.get(rules)
    if "goal" not in (given if isinstance(given, dict) else {}) and rule_set.goal is not None:
        options = options.with_(goal=rule_set.goal)
        goals.get(str(options.goal), where=f"rule set {rules!r}: goal")
    goals.require_for(Model(options=options, rules=rules), rule_set.robots, rules)
    return options


def _rule_set(raw: object) -> Any:
    """The registered rule set a model file names (``rules``), or a one-line :class:`InvalidModel`."""
    if not isinstance(raw, str):
        raise InvalidModel(f"rules={raw!r}: expected the name of a rule set ({', '.join(registry.names())})")
    return registry.get(raw)


def _accepted(rule_set: Any, given: dict[str, object]) -> None:
    """Refuse, in one line naming it and the rule set, an option ``given`` sets that ``rule_set`` neither
    declares nor reads (:meth:`~fatline_verify.rules.registry.RuleSet.accepts`)."""
    from .options import MODEL_OPTIONS

    for key in given:
        if not rule_set.accepts(key):
            raise InvalidModel(
                f"options.{key}={given[key]!r}: not an option of rule set {rule_set.name!r}; "
                f"expected one of {', '.join(sorted({*rule_set.reads(), *MODEL_OPTIONS}))}"
            )


def _rules(raw: object, options: Options, given: dict[str, object]) -> str:
    """The rule set a model names (or implies), checked against the registry; every option the file
    sets must be one the rule set reads."""
    rule_set = _rule_set(raw) if raw is not None else registry.get(implied_rules(options))
    _accepted(rule_set, given)
    return rule_set.name


def resolve_model_path(spec: str | Path) -> Path:
    """A model argument: a path to a TOML file, or the name of a shipped model (``paper``)."""
    path = Path(spec)
    if path.is_file():
        return path
    if path.exists() and not path.is_dir():  # a FIFO or a device: never read (it would block or never end)
        raise InvalidModel(f"model={str(spec)!r}: not a regular file; expected a model file or a shipped model name")
    shipped = MODELS_DIR / f"{spec}.toml"
    if not path.suffix and shipped.is_file():
        return shipped
    known = ", ".join(p.stem for p in shipped_models())
    raise InvalidModel(f"model={str(spec)!r}: no such file; expected a model file or a shipped model name ({known})")


MAX_MODEL_BYTES = 2**20
"""The largest model file read (the shipped ones are under 2 KB)."""


def _long_number(path: Path, text: str) -> str:
    """The error for a number too long to read: the key it is the value of, and its length."""
    import re

    m = re.search(r"(?m)^\s*([A-Za-z0-9_.\"'-]+)\s*=\s*[+-]?([0-9_]{1000,})", text)
    if m is None:
        return f"model={str(path)!r}: holds a number too long to read; expected numbers of at most {MAX_DIGITS} digits"
    key, digits = m.group(1).strip("\"'"), m.group(2).replace("_", "")
    where = path.as_posix()
    return f"{key}={digits[:20]}...: a number of {len(digits):,} digits; expected at most {MAX_DIGITS} digits ({where})"


def load_model(spec: str | Path = "paper") -> Model:
    """Read, parse and validate a model file. Every problem is one :class:`InvalidModel` line."""
    path = resolve_model_path(spec)
    try:
        text = read_regular(path, limit=MAX_MODEL_BYTES).decode("utf-8")
    except NotReadable as exc:
        raise InvalidModel(f"model={str(path)!r}: {exc}; expected a TOML model file") from None
    except UnicodeDecodeError:
        raise InvalidModel(f"model={str(path)!r}: not UTF-8 text; expected a TOML model file") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InvalidModel(f"model={str(path)!r}: not valid TOML ({exc})") from None
    except RecursionError:
        raise InvalidModel(
            f"model={str(path)!r}: arrays or tables nested too deep; expected a TOML model (name, parameters, "
            "options, bounds)"
        ) from None
    except ValueError:  # Python's limit on converting long digit strings: name the key that holds one
        raise InvalidModel(_long_number(path, text)) from None
    if not data:
        raise InvalidModel(
            f"model={str(path)!r}: the file is empty; expected a TOML model (name, parameters, options, bounds)"
        )
    return model_from_mapping(data, source=str(path), default_name=path.stem)


def model_to_mapping(model: Model) -> dict[str, object]:
    """The model as plain data (for traces and JSON results): name, every option, every parameter."""
    p = model.parameters
    parameters: dict[str, object] = {"rad_v": format_number(p.rad_v), "q": p.q, "delta": format_number(p.delta)}
    if model.options.scheduler is Scheduler.ASYNC:  # means nothing under a round scheduler
        parameters["async_steps"] = p.async_steps
    out: dict[str, object] = {"name": model.name}
    own = model.setting("rules")
    if own:  # the [rules] table: the name, then the rule set's own parameters
        out["rules"] = {"name": model.rules, **own}
    elif model.rules != implied_rules(model.options):
        out["rules"] = model.rules
    out |= {"parameters": parameters, "options": declared_options(model)}
    for seam in ("scheduler", "goal"):
        values = model.setting(seam)
        if values:
            out[seam] = values
    return out


def declared_options(model: Model) -> dict[str, str]:
    """The options that mean something for ``model``: under its scheduler, and read by its rule set."""
    rule_set = registry.of(model)
    return {k: v for k, v in model.options.as_dict().items() if rule_set.accepts(k)}


def shipped_models() -> list[Path]:
    """The shipped model files, sorted by name."""
    return sorted(MODELS_DIR.glob("*.toml"), key=lambda p: p.stem)
