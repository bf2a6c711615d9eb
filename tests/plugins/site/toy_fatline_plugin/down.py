"""A step lemma of one's own that the paper's rules break: no robot ever moves down (its y never
decreases in a step). The paper's robots do step down (towards the lower-right quadrant), so every
shipped model of the paper has a witness of it: a plug-in lemma's trace, written, loaded and replayed.

Registered by the entry point ``no-down = toy_fatline_plugin.down`` of the group ``fatline.plugins``.
"""

import numpy as np

from fatline_verify.lemmas.registry import StepLemma, register


def violators(before, after, model):
    """The robots whose y decreased."""
    return [i for i, (b, a) in enumerate(zip(before, after, strict=True)) if a[1] < b[1]]


def batch(before, after, model):
    """Per step of ``(t, n, 2)`` arrays: some robot's y decreased."""
    return np.asarray((after[:, :, 1] < before[:, :, 1]).any(axis=1))


NO_DOWN = register(StepLemma("no-down", "A toy: no robot ever moves down.", violators, batch))
