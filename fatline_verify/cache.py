"""Fingerprints of results: what produced a cached result, so it is reused only while up to date."""

from __future__ import annotations

import hashlib
import json
from typing import Any

from . import __version__
from .model.config import Model, model_to_mapping

LEGACY_MAX_STATES = 1_000_000
"""The cap every shipped model once set. A model without a cap fingerprints as if it had this one: no
search at a shipped model's own bounds comes near it (the largest, paper-async at 4 robots, has 69,515
states), so its results are the same either way and the cached ones stay valid."""


def _max_states(model: Model) -> int:
    return LEGACY_MAX_STATES if model.bounds.max_states is None else model.bounds.max_states


def fingerprint(model: Model, kind: str, **settings: Any) -> str:
    """A short hash of the model's readings, parameters and bounds, the tool version and the settings."""
    data = {
        "tool": __version__,
        "kind": kind,
        "model": model_to_mapping(model),
        "bounds": [list(model.bounds.robots), list(model.bounds.window), _max_states(model)],
        "settings": settings,
    }
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()[:16]
