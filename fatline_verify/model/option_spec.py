"""One option, as the catalogue describes it (:mod:`fatline_verify.model.options`): an open point of a text, or
a change to an algorithm, with its readings. The model layer declares its own options with :func:`spec`, and
a rule set its own (``RuleSet(options=(spec(...), ...))``: the paper's readings,
:mod:`fatline_verify.rules.paper.options`; the repairs, :mod:`fatline_verify.rules.repaired.options`; a
plug-in's)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .options import Scheduler


@dataclass(frozen=True, slots=True)
class OptionSpec:
    """One option: its name (the key a model file's ``[options]`` table sets), the text it reads (quoted),
    what each reading means, and its default (the first reading)."""

    name: str
    enum: type[StrEnum]
    quote: str
    readings: dict[str, str]
    default: StrEnum
    note: str = ""
    only_under: Scheduler | None = None
    """The scheduler under which the option means something (``None``: every scheduler). Under the
    others it is left out of a model's data, so it changes no fingerprint and no trace."""
    repair: bool = False
    """A change to the algorithm, not a reading of its text (the repaired rule set's,
    :mod:`fatline_verify.rules.repaired.options`): left out of a model's data at its default (``off``), and
    not swept."""


def spec(
    name: str,
    enum: type[StrEnum],
    quote: str,
    readings: dict[str, str],
    note: str = "",
    only_under: Scheduler | None = None,
    *,
    repair: bool = False,
) -> OptionSpec:
    """Declare option ``name``: ``enum`` its readings (a :class:`~enum.StrEnum`, the first the default),
    ``quote`` the words it reads, ``readings`` what each reading means (one entry per member), ``note`` a
    remark shown under them; ``only_under`` the scheduler it means something under (``None``: every
    one); ``repair``: see :attr:`OptionSpec.repair`."""
    if not (isinstance(enum, type) and issubclass(enum, StrEnum)) or not list(enum):
        raise ValueError(f"option {name!r}: enum={enum!r}: expected a StrEnum of its readings")
    if not isinstance(readings, dict):
        raise ValueError(f"option {name!r}: readings={readings!r}: expected a dict of reading -> what it means")
    default = next(iter(enum))
    if set(readings) != {m.value for m in enum}:
        raise ValueError(
            f"option {name!r}: readings names {', '.join(sorted(readings))}; expected one entry per reading of "
            f"{enum.__name__}: {', '.join(m.value for m in enum)}"
        )
    return OptionSpec(name, enum, quote, readings, default, note, only_under, repair)
