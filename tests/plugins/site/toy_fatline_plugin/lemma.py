"""A step lemma of one's own, in one file: no robot ever moves left (its x never decreases in a step).

Registered by the entry point ``no-left = toy_fatline_plugin.lemma`` of the group ``fatline.plugins``.
"""

import numpy as np

from fatline_verify.lemmas.registry import StepLemma, register


def violators(before, after, model):
    """The robots whose x decreased."""
    return [i for i, (b, a) in enumerate(zip(before, after, strict=True)) if a[0] < b[0]]


def batch(before, after, model):
    """Per step of ``(t, n, 2)`` arrays: some robot's x decreased."""
    return np.asarray((after[:, :, 0] < before[:, :, 0]).any(axis=1))


NO_LEFT = register(StepLemma("no-left", "A toy: no robot ever moves left.", violators, batch))
