"""A scheduler of one's own, in one file: at most two robots act in a round (any set of one or two
of the enabled robots), each deciding on the round's one snapshot.

Registered by the entry point ``pairs = toy_fatline_plugin.scheduler`` of the group ``fatline.plugins``.
"""

import numpy as np

from fatline_verify.model.options import SchedulerName
from fatline_verify.schedulers.activation import register


class Pairs:
    """Activation sets of one or two enabled robots."""

    kind = SchedulerName("pairs")
    alone = True
    encoded = False

    def masks(self, enabled, n):
        """Every set of one or two enabled robots, as bitmasks in increasing order."""
        return sorted(m for m in range(1, enabled + 1) if m & ~enabled == 0 and bin(m).count("1") <= 2)

    def valid(self, masks, enabled):
        """Per state (its enabled mask) and offered mask: a set of one or two of its enabled robots."""
        count = np.array([bin(int(m)).count("1") for m in masks])
        return ((masks[None, :] & ~enabled[:, None]) == 0) & (count[None, :] <= 2) & (masks[None, :] != 0)

    def forbids(self, active, n):
        """Why ``active`` is not a round of this scheduler, or None."""
        if 1 <= len(active) <= 2:
            return None
        return f"activates {len(active)} robots; expected one or two under scheduler=pairs"

    def choose(self, rng, candidates, waiting, n):
        """A fair random pick: the longest-waiting candidate, and maybe one more."""
        first = max(candidates, key=lambda i: (waiting[i], -i))
        rest = [i for i in candidates if i != first]
        return {first, rng.choice(rest)} if rest and rng.random() < 0.5 else {first}


PAIRS = register(Pairs())
