"""One open point of the paper, or one repair, as the catalogue describes it (:mod:`fatline_verify.model.options`,
:mod:`fatline_verify.rules.repaired.options`)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .options import Scheduler


@dataclass(frozen=True, slots=True)
class OptionSpec:
    """One open point of the paper: its id, the quoted text, and what each reading means."""

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
    """A change to the algorithm, not a reading of the paper (the repaired rule set's,
    :mod:`fatline_verify.rules.repaired.options`): left out of a model's data at ``off``, and not swept."""


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
    default = next(iter(enum))
    if set(readings) != {m.value for m in enum}:
        raise AssertionError(f"catalogue for {name} does not describe every reading")
    return OptionSpec(name, enum, quote, readings, default, note, only_under, repair)
