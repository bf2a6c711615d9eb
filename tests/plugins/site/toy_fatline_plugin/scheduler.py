"""A scheduler of one's own, in one file: at most ``k`` robots act in a round (any set of one to ``k``
of the enabled robots; ``k`` = 2 unless the model's ``[scheduler]`` table sets it), each deciding on
the round's one snapshot.

Registered by the entry point ``pairs = toy_fatline_plugin.scheduler`` of the group ``fatline.plugins``.
"""

from typing import ClassVar

import numpy as np

from fatline_verify.model.options import SchedulerName
from fatline_verify.model.seams import Param
from fatline_verify.schedulers.activation import register

_WORDS = {1: "exactly one", 2: "one or two"}


class Pairs:
    """Activation sets of one to k enabled robots (k = 2: one or two)."""

    kind = SchedulerName("pairs")
    alone = True
    encoded = False
    parameters: ClassVar[dict[str, Param]] = {"k": Param(2, "at most k robots a round", minimum=1, maximum=64)}

    def __init__(self, k=2):
        self.k = k

    def configured(self, k):
        """This scheduler with the model's ``k``."""
        return self if k == self.k else Pairs(k)

    def masks(self, enabled, n):
        """Every set of one to k enabled robots, as bitmasks in increasing order."""
        return sorted(m for m in range(1, enabled + 1) if m & ~enabled == 0 and bin(m).count("1") <= self.k)

    def valid(self, masks, enabled):
        """Per state (its enabled mask) and offered mask: a set of one to k of its enabled robots."""
        count = np.array([bin(int(m)).count("1") for m in masks])
        return ((masks[None, :] & ~enabled[:, None]) == 0) & (count[None, :] <= self.k) & (masks[None, :] != 0)

    def forbids(self, active, n):
        """Why ``active`` is not a round of this scheduler, or None."""
        if 1 <= len(active) <= self.k:
            return None
        words = _WORDS.get(self.k, f"one to {self.k}")
        return f"activates {len(active)} robots; expected {words} under scheduler=pairs"

    def choose(self, rng, candidates, waiting, n):
        """A fair random pick: the longest-waiting candidate, and maybe up to k - 1 more."""
        first = max(candidates, key=lambda i: (waiting[i], -i))
        rest = [i for i in candidates if i != first]
        if self.k < 2 or not rest or rng.random() >= 0.5:
            return {first}
        if self.k == 2:
            return {first, rng.choice(rest)}
        return {first, *rng.sample(rest, rng.randint(1, min(len(rest), self.k - 1)))}


PAIRS = register(Pairs())
