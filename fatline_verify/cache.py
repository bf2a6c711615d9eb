"""Fingerprints of results: what produced a cached result, so it is reused only while up to date."""

from __future__ import annotations

import hashlib
import json
from typing import Any

from . import __version__
from .config import Model, model_to_mapping


def fingerprint(model: Model, kind: str, **settings: Any) -> str:
    """A short hash of the model's readings, parameters and bounds, the tool version and the settings."""
    data = {
        "tool": __version__,
        "kind": kind,
        "model": model_to_mapping(model),
        "bounds": [list(model.bounds.robots), list(model.bounds.window), model.bounds.max_states],
        "settings": settings,
    }
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()[:16]
