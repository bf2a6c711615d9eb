"""The parameters a registered scheduler or rule set declares of its own ("at most ``k`` robots a
round"), set in a model file in a table named after its seam, validated, and carried in the model's
data (so into its fingerprint and its traces).

A registered round scheduler declares them as ``parameters: dict[str, Param]`` and provides
``configured(**values)``, the scheduler with those values (its methods take no model); a rule set
declares them as ``RuleSet(..., parameters={...})`` and its decision function reads
``model.setting("rules")``. One without ``parameters`` takes none, as before. In a model file::

    [options]
    scheduler = "pairs"

    [scheduler]     # the scheduler's own parameters
    k = 3

    [rules]         # the rule set's: its name, then its own parameters
    name = "toy-step"
    reach = 4

(``rules = "toy-step"``, a string, names a rule set with its defaults, as before: TOML has no key
that is both a string and a table.) An unknown key or a value of the wrong type is one line, before
any work. ``fatline explain`` lists them (``fatline explain scheduler.k``), ``fatline sweep --vary
scheduler.k`` takes a model through the values they declare (:meth:`Param.swept`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from ..errors import InvalidModel

Value = int | bool | str
"""What a parameter holds: its default's type."""

SEAMS = ("scheduler", "rules", "goal")
"""The seams whose registered objects may declare parameters, by their table's name."""

MAX_SWEPT = 16
"""The widest range of whole numbers a sweep takes a parameter through without declared values."""

Settings = tuple[tuple[str, tuple[tuple[str, Value], ...]], ...]
"""A model's values, per seam, every declared parameter (defaults filled), in declaration order."""


@dataclass(frozen=True, slots=True)
class Param:
    """One declared parameter: its default (whose type, ``int``, ``bool`` or ``str``, is the
    parameter's), what it means, and for an integer its least and greatest value."""

    default: Value
    doc: str
    minimum: int | None = None
    maximum: int | None = None
    values: tuple[Value, ...] = ()
    """The values ``fatline sweep`` takes it through (each a valid value; a model file may set any valid
    one). Left empty: ``False`` and ``True`` for a flag, every whole number of a range of at most
    :data:`MAX_SWEPT`, else the parameter is not swept unless it declares them."""
    choices: tuple[str, ...] = ()
    """For a string parameter: the values it may take (a reading's names); empty: any string."""

    def __post_init__(self) -> None:
        if not isinstance(self.default, int | str):  # bool is an int
            raise ValueError(f"Param default={self.default!r}: expected an int, a bool or a str")
        if not isinstance(self.values, tuple) or len(set(self.values)) != len(self.values):
            raise ValueError(f"Param values={self.values!r}: expected a tuple of distinct values")
        try:  # a declaration's mistake is the plug-in's (ValueError when it registers), not a model's
            if not isinstance(self.default, bool) and isinstance(self.default, int | str):
                self.parse("default", self.default)
            for value in self.values:
                self.parse("values", value)
        except InvalidModel as exc:
            raise ValueError(f"Param {exc}") from None

    def swept(self) -> tuple[Value, ...]:
        """The values a sweep takes this parameter through (:attr:`values`, or what its type and range
        allow); ``()`` when it declares none and its range is open or wider than :data:`MAX_SWEPT`."""
        if self.values:
            return self.values
        if self.choices:
            return self.choices
        if isinstance(self.default, bool):
            return (False, True)
        lo, hi = self.minimum, self.maximum
        if isinstance(self.default, int) and lo is not None and hi is not None and hi - lo < MAX_SWEPT:
            return tuple(range(lo, hi + 1))
        return ()

    def expected(self) -> str:
        """What a value must be, in words."""
        if isinstance(self.default, bool):
            return "true or false"
        if isinstance(self.default, str):
            return f"one of {', '.join(self.choices)}" if self.choices else "a string"
        lo, hi = self.minimum, self.maximum
        if lo is not None and hi is not None:
            return f"a whole number {lo}..{hi}"
        if lo is not None:
            return f"a whole number >= {lo}"
        return f"a whole number <= {hi}" if hi is not None else "a whole number"

    def parse(self, where: str, value: object) -> Value:
        """``value`` checked against this parameter, or a one-line :class:`InvalidModel` naming ``where``."""
        kind = bool if isinstance(self.default, bool) else type(self.default)
        ok = type(value) is kind
        if ok and kind is int:
            assert isinstance(value, int)
            ok = (self.minimum is None or value >= self.minimum) and (self.maximum is None or value <= self.maximum)
        if ok and kind is str and self.choices:
            ok = value in self.choices
        if not ok:
            raise InvalidModel(f"{where}={value!r}: expected {self.expected()} ({self.doc})")
        return value  # type: ignore[return-value]


KEY = re.compile(r"^[A-Za-z_][A-Za-z0-9_-]*$")
"""A parameter's name: a bare TOML key without a dot (``SEAM.NAME`` names it on the command line)."""


def declared(owner: Any) -> dict[str, Param]:
    """The parameters ``owner`` (a registered scheduler or rule set) declares; none when it has no
    ``parameters`` (a plug-in written before parameters existed). A declaration that is not a dict of
    names to :class:`Param` is a one-line ``ValueError`` (raised when the plug-in registers)."""
    found = getattr(owner, "parameters", None) or {}
    name = getattr(owner, "name", None) or getattr(owner, "kind", None) or type(owner).__name__
    if not isinstance(found, dict):
        raise ValueError(f"{name}: parameters={found!r}: expected a dict of name -> Param (fatline_verify.model.seams)")
    for key, param in found.items():
        if not isinstance(key, str) or not KEY.match(key):
            raise ValueError(f"{name}: parameters key {key!r}: expected a name of letters, digits, '_' and '-'")
        if not isinstance(param, Param):
            raise ValueError(f"{name}: parameters[{key!r}]={param!r}: expected a Param (fatline_verify.model.seams)")
    return found


def parse_table(seam: str, what: str, params: dict[str, Param], raw: object) -> tuple[tuple[str, Value], ...]:
    """The ``[seam]`` table of a model file (``raw``, ``None`` when absent) for ``what`` (``"scheduler
    'pairs'"``), which declares ``params``: every declared parameter with its value or its default."""
    if raw is None:
        raw = {}
    if not isinstance(raw, dict):
        where = " (the scheduler itself is [options] scheduler)" if seam == "scheduler" else ""
        raise InvalidModel(f"{seam}={raw!r}: expected a [{seam}] table of the parameters of the {what}{where}")
    for key, value in raw.items():
        if key not in params:
            known = f"expected one of {', '.join(params)}" if params else f"the {what} takes no parameters"
            raise InvalidModel(f"{seam}.{key}={value!r}: unknown key; {known}")
    return tuple((key, p.parse(f"{seam}.{key}", raw[key]) if key in raw else p.default) for key, p in params.items())


def filled(params: dict[str, Param], given: dict[str, Value]) -> dict[str, Value]:
    """Every declared parameter's value: ``given``'s, else its default."""
    return {key: given.get(key, p.default) for key, p in params.items()}


def with_values(settings: Settings, owners: dict[str, dict[str, Param]], values: dict[str, Value]) -> Settings:
    """``settings`` with the values ``{"scheduler.k": 3}`` set (each checked), every declared parameter
    of the seams ``owners`` names (seam -> its owner's parameters) filled."""
    given = {seam: dict(pairs) for seam, pairs in settings}
    for name, value in values.items():
        seam, key = name.split(".", 1)
        given.setdefault(seam, {})[key] = owners[seam][key].parse(name, value)
    out = []
    for seam in SEAMS:
        params = owners.get(seam, {})
        if params:
            out.append((seam, tuple(filled(params, given.get(seam, {})).items())))
    return tuple(out)


__all__ = [
    "MAX_SWEPT",
    "SEAMS",
    "Param",
    "Settings",
    "Value",
    "declared",
    "filled",
    "parse_table",
    "with_values",
]
