"""A sweep over the parameters a scheduler or rule set declares of its own (``--vary scheduler.k``).

The readings of the paper's options are one product, closed by counterexamples and shared graphs
(:mod:`.space`); a parameter is read through ``model.setting(...)``, which the option recorder does not
see, so no closure may carry a verdict from one of its values to another. Each combination of the
parameters' values (:meth:`~fatline_verify.model.seams.Param.swept`: the values each declares) is a
sweep of its own, of the model with those values, in a directory of its own under the model's
(``OUT/MODEL/scheduler.k-3``), with its own fingerprint (the values are in the model's data).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

from ..errors import InvalidInput
from ..model.config import Model, own_parameters, with_parameters
from ..model.seams import MAX_SWEPT, Value
from ..outputs import SLUG


@dataclass(frozen=True, slots=True)
class Swept:
    """One parameter a sweep takes through its values."""

    name: str
    """Its model-file name, ``SEAM.KEY``."""
    values: tuple[Value, ...]


def default_parameters(model: Model) -> tuple[Swept, ...]:
    """The parameters swept unless ``--vary`` names others: those that declare their values."""
    return tuple(Swept(name, p.values) for name, (_, p) in own_parameters(model).items() if p.values)


def split_vary(text: str | None, model: Model) -> tuple[str | None, tuple[Swept, ...]]:
    """``--vary`` split into the options (as text for :func:`~.space.parse_vary`, ``None``: its default)
    and the parameters (``SEAM.KEY``), each checked: one of the model's, with values to sweep."""
    if text is None:
        return None, default_parameters(model)
    names = [t.strip() for t in text.split(",") if t.strip()]
    params = [n for n in names if "." in n]
    options = ",".join(n for n in names if "." not in n)
    own = own_parameters(model)
    swept = []
    for name in params:
        if name not in own:
            known = ", ".join(own) or "none"
            raise InvalidInput(
                f"vary={name!r}: not a parameter of model {model.name}'s scheduler or rule set; expected one of {known}"
            )
        what, param = own[name]
        values = param.swept()
        if not values:
            raise InvalidInput(
                f"vary={name!r}: {what} declares no values to sweep it through (its range is open or wider than "
                f"{MAX_SWEPT}); expected a parameter with values (Param(..., values=(...)))"
            )
        swept.append(Swept(name, values))
    if len(set(params)) != len(params):
        raise InvalidInput(f"vary={text!r}: a parameter is named twice; expected each once")
    if not options:  # the parameters alone: no option varied (nothing named at all: parse_vary says so)
        return ("" if params else text), tuple(swept)
    return options, tuple(swept)


def combinations(swept: tuple[Swept, ...]) -> list[dict[str, Value]]:
    """Every combination of the swept parameters' values, the first parameter's slowest (one empty
    combination when none is swept)."""
    names = [s.name for s in swept]
    return [dict(zip(names, values, strict=True)) for values in itertools.product(*(s.values for s in swept))]


def label(combo: dict[str, Value]) -> str:
    """A combination as a directory name: ``scheduler.k-3`` (``_`` between parameters); a value that
    is not a file-name word by its index among the declared ones."""
    parts = []
    for name, value in combo.items():
        word = str(value).lower() if isinstance(value, bool) else str(value)
        parts.append(f"{name}-{word}")
    text = "_".join(parts)
    if not SLUG.match(text):
        raise InvalidInput(f"vary: {text!r} cannot name a directory; expected parameter values of letters and digits")
    return text


def model_at(model: Model, combo: dict[str, Value]) -> Model:
    """The model with the combination's values."""
    return with_parameters(model, combo) if combo else model


__all__ = ["Swept", "combinations", "default_parameters", "label", "model_at", "split_vary"]
