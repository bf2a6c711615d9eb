"""The reading space: the product of the readings of some options, the others fixed by a model.

A combination is a point of the product, numbered in mixed radix (the first varied option is the
most significant digit; each option's readings in catalogue order, so combination 0 is every
varied option at its first reading). A *cube* fixes some options to sets of readings and leaves
the others free; :meth:`Space.mask` turns a cube into a boolean mask over every combination.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from ..errors import InvalidInput
from ..lemmas.properties import SAFETY, Lemma
from ..model.config import Model, declared_options
from ..model.options import CATALOGUE, Options

Cube = Mapping[str, frozenset[int]]
"""Option name -> the reading indices allowed; an option not named is free."""

NOT_SWEPT = ("scheduler",)
"""Options the sweep never varies: the scheduler is the model's (the lemmas are stated for one)."""


def default_vary(model: Model) -> tuple[str, ...]:
    """Every option that means something under the model's scheduler, but the scheduler."""
    return tuple(name for name in declared_options(model) if name not in NOT_SWEPT)


def parse_vary(text: str | None, model: Model) -> tuple[str, ...]:
    """``--vary a,b,c`` as option names in catalogue order (default: :func:`default_vary`)."""
    if text is None:
        return default_vary(model)
    names = [t.strip() for t in text.split(",") if t.strip()]
    if not names:
        raise InvalidInput(f"vary={text!r}: expected a comma-separated list of option names")
    meaningful = declared_options(model)
    for name in names:
        if name not in CATALOGUE:
            raise InvalidInput(f"vary={name!r}: unknown option; expected one of {', '.join(default_vary(model))}")
        if name in NOT_SWEPT:
            raise InvalidInput(f"vary={name!r}: the scheduler is fixed by the model; expected one of the other options")
        if name not in meaningful:
            raise InvalidInput(
                f"vary={name!r}: means nothing under scheduler={model.options.scheduler} and rules={model.rules}; "
                f"expected one of {', '.join(default_vary(model))}"
            )
    if len(set(names)) != len(names):
        raise InvalidInput(f"vary={text!r}: an option is named twice; expected each option once")
    return tuple(name for name in CATALOGUE if name in names)


def bearing(lemma: Lemma, vary: Iterable[str]) -> tuple[str, ...]:
    """The varied options that can change ``lemma``'s verdict. The goal option bears only on the lemmas
    about where the swarm ends (a step lemma is judged on one step, and the search explores past goal
    states: the robots do not know they form a line)."""
    return tuple(name for name in vary if not (name == "goal" and lemma in SAFETY))


@dataclass(frozen=True)
class Space:
    """The product of the readings of ``names``, the other options as in ``base``."""

    base: Model
    names: tuple[str, ...]
    sizes: tuple[int, ...] = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "sizes", tuple(len(CATALOGUE[n].readings) for n in self.names))

    @property
    def size(self) -> int:
        return int(np.prod(self.sizes, dtype=np.int64)) if self.names else 1

    def readings(self, name: str) -> list[str]:
        return list(CATALOGUE[name].readings)

    @cached_property
    def digits(self) -> np.ndarray:
        """``(size, len(names))`` int8: every combination's reading index per option."""
        if not self.names:
            return np.zeros((1, 0), dtype=np.int8)
        out = np.empty((self.size, len(self.names)), dtype=np.int8)
        for k, size in enumerate(self.sizes):  # mixed radix, built in int8 (no wide temporaries)
            above, below = (
                int(np.prod(self.sizes[:k], dtype=np.int64)),
                int(np.prod(self.sizes[k + 1 :], dtype=np.int64)),
            )
            out[:, k] = np.tile(np.repeat(np.arange(size, dtype=np.int8), below), above)
        return out

    def combo(self, index: int) -> dict[str, int]:
        """Reading index per varied option of combination ``index``."""
        return dict(zip(self.names, (int(d) for d in np.unravel_index(index, self.sizes)), strict=True))

    def index(self, combo: Mapping[str, int]) -> int:
        """The number of a combination (options outside this space are ignored)."""
        if not self.names:
            return 0
        return int(np.ravel_multi_index(tuple(combo[n] for n in self.names), self.sizes))

    def reading_indices(self, options: Options) -> dict[str, int]:
        """Reading index per varied option of ``options``."""
        return {n: self.readings(n).index(str(getattr(options, n))) for n in self.names}

    def options(self, combo: Mapping[str, int]) -> Options:
        """The base model's options with the combination's readings."""
        return self.base.options.with_(**{n: self.readings(n)[combo[n]] for n in self.names if n in combo})

    def model(self, combo: Mapping[str, int]) -> Model:
        return replace(self.base, options=self.options(combo))

    def text(self, combo: Mapping[str, int]) -> dict[str, str]:
        """A combination as option -> reading text."""
        return {n: self.readings(n)[combo[n]] for n in self.names if n in combo}

    def mask(self, cube: Cube) -> np.ndarray:
        """The combinations inside ``cube``."""
        out = np.ones(self.size, dtype=bool)
        for k, name in enumerate(self.names):
            allowed = cube.get(name)
            if allowed is None or len(allowed) == self.sizes[k]:
                continue
            out &= np.isin(self.digits[:, k], np.fromiter(allowed, dtype=np.int8))
        return out

    def project(self, combo: Mapping[str, int], onto: Space) -> int:
        """The number in ``onto`` (a sub-space) of this space's combination ``combo``."""
        return onto.index(combo)
