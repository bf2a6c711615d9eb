"""Step lemmas of one's own, registered: a claim about every step of the transition system, with a
scalar check (the executable model's, used by replay and the scalar engine's witnesses) and a
vectorised one (every engine's successors, in one numpy pass).

The paper's lemmas are :class:`~fatline_verify.lemmas.properties.Lemma`; a registered lemma sits
beside them and is judged on the same explored graph. It never prunes the exploration: the search
stops only at a step that breaks the model's own safety (a swarm that collided, split or crossed its
right-most axis has left the model), so registering a lemma leaves every other lemma's states,
transitions, verdicts and traces as they were. A trace names the lemma it witnesses, and replay
re-judges that one by its scalar check.

Each registered lemma gets the next bit of a transition's violation flags after the paper's; the
flags are one byte (:data:`FLAG_BITS`), and a lemma that would not fit is refused when it registers,
never truncated.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from .properties import FLAG, Judged

FLAG_BITS = 8
"""The width of a transition's violation flags in the search's records (``uint8``)."""

CORE_FLAGS = 0
for _bit in FLAG.values():
    CORE_FLAGS |= _bit
"""The paper's step lemmas' bits: the steps the search does not follow."""

Points = Sequence[tuple[Any, Any]]


@dataclass(frozen=True, slots=True)
class StepLemma:
    """A registered step lemma. ``violators(before, after, model)``: the robots a step from positions
    ``before`` to ``after`` (robot ``i`` is ``before[i]`` and ``after[i]``, lattice units) breaks the
    lemma for, empty if it holds; ``batch(before, after, model)``: the same for ``(t, n, 2)`` integer
    arrays, one bool per step."""

    name: str
    paper: str
    violators: Callable[[Points, Points, Any], list[int]] = field(repr=False, compare=False)
    batch: Callable[[np.ndarray, np.ndarray, Any], np.ndarray] = field(repr=False, compare=False)
    version: int = 1
    """Part of the check fingerprint: a changed lemma invalidates the results that judged it."""
    flag: int = 0
    """Its bit in a transition's violation flags (given by :func:`register`)."""
    applies: Callable[[Any], bool] | None = field(default=None, repr=False, compare=False)
    """Whether it is judged for a model (``None``: for every model): the lemma ``in-family`` only for a rule
    set that declares a move family."""

    @property
    def value(self) -> str:
        return self.name

    @property
    def judged(self) -> Judged:
        return Judged.STEP

    def __str__(self) -> str:
        return self.name


_REGISTRY: dict[str, StepLemma] = {}


def register(lemma: StepLemma) -> StepLemma:
    """Add ``lemma`` with the next free flag bit; its name must be new (the paper's lemmas' too)."""
    from .properties import Lemma

    if lemma.name in {m.value for m in Lemma}:
        raise ValueError(f"lemma {lemma.name!r}: a lemma of the paper has that name")
    known = _REGISTRY.get(lemma.name)
    if known is not None:
        return known
    bit = (CORE_FLAGS.bit_length()) + len(_REGISTRY)
    if bit >= FLAG_BITS:
        raise ValueError(
            f"lemma {lemma.name!r}: the violation flags hold {FLAG_BITS} step lemmas; "
            f"expected at most {FLAG_BITS - CORE_FLAGS.bit_length()} registered ones"
        )
    placed = StepLemma(lemma.name, lemma.paper, lemma.violators, lemma.batch, lemma.version, 1 << bit, lemma.applies)
    _REGISTRY[lemma.name] = placed
    from ..rules import registry as rules

    if not str(getattr(lemma.violators, "__module__", "")).startswith("fatline_verify."):
        rules.claim("lemma", lemma.name)  # the plug-in package registering it, if any (not this package's own,
        # registered while a plug-in's import first loads the built-ins)
    return placed


def registered() -> tuple[StepLemma, ...]:
    """The registered step lemmas (plug-ins loaded), in registration order."""
    from ..rules import registry as rules

    rules.names()  # loads the plug-ins, whose modules may register lemmas too
    return tuple(_REGISTRY.values())


def judged(model: Any) -> tuple[StepLemma, ...]:
    """The registered step lemmas judged for ``model`` (each whose :attr:`StepLemma.applies` says so)."""
    return tuple(lemma for lemma in registered() if lemma.applies is None or lemma.applies(model))


def checked() -> tuple[Any, ...]:
    """Every lemma ``fatline check`` gives a verdict: the paper's (:data:`~.properties.CHECKED`, in
    report order), then the registered step lemmas (plug-ins loaded)."""
    from .properties import CHECKED

    return (*CHECKED, *registered())


def find(name: str) -> StepLemma | None:
    """The registered lemma called ``name``, if any."""
    return next((lemma for lemma in registered() if lemma.name == name), None)


def extra_flags(
    before: np.ndarray, after: np.ndarray, model: Any, lemmas: Sequence[StepLemma], unit: int = 1
) -> np.ndarray:
    """The registered lemmas' bits for steps ``before[k] -> after[k]`` (``(t, n, 2)`` integer arrays in
    units of ``1/unit`` lattice unit: :meth:`~fatline_verify.schedulers.base.TransitionSystem.step_positions`).

    A step whose positions all lie on the lattice is judged by the lemma's vectorised check, in lattice
    units, as it always was; one with a robot between lattice points (an asynchronous robot halfway
    through its move) by its scalar check on the exact positions, which is what replay judges. So
    every engine judges the same steps the executable model plays, under every scheduler."""
    bits = np.zeros(len(before), dtype=np.int64)
    if not lemmas or not len(before):
        return bits
    whole = ((before % unit == 0) & (after % unit == 0)).all(axis=(1, 2)) if unit != 1 else np.ones(len(before), bool)
    on = np.flatnonzero(whole)
    off = np.flatnonzero(~whole)
    b_on, a_on = before[on] // unit, after[on] // unit
    exact = _exact_steps(before[off], after[off], unit)
    for lemma in lemmas:
        hit = np.zeros(len(before), dtype=bool)
        if len(on):
            got = np.asarray(lemma.batch(b_on, a_on, model), dtype=bool)
            if got.shape != (len(on),):
                raise ValueError(f"lemma {lemma.name!r}: batch check gave shape {got.shape}; expected ({len(on)},)")
            hit[on] = got
        for k, (b, a) in zip(off, exact, strict=True):
            hit[k] = bool(lemma.violators(b, a, model))
        bits |= np.where(hit, lemma.flag, 0)
    return bits


def _exact_steps(before: np.ndarray, after: np.ndarray, unit: int) -> list[tuple[Points, Points]]:
    """Steps as exact positions in lattice units (a whole number as an ``int``, a fraction as a
    :class:`~fractions.Fraction`, as the executable model keeps them); each distinct value converted once."""
    from ..model.numbers import normalize

    if not len(before):
        return []
    exact = {int(v): normalize(Fraction(int(v), unit)) for v in np.unique(np.concatenate([before, after]))}
    rows = zip(before.tolist(), after.tolist(), strict=True)
    return [([(exact[x], exact[y]) for x, y in b], [(exact[x], exact[y]) for x, y in a]) for b, a in rows]


__all__ = [
    "CORE_FLAGS",
    "FLAG_BITS",
    "StepLemma",
    "checked",
    "extra_flags",
    "find",
    "judged",
    "register",
    "registered",
]
