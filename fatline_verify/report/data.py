"""What the report knows of one model: the data every page is rendered from."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..model.config import Model
from .places import Places


@dataclass(frozen=True)
class ModelReport:
    """One model's results, as cached or freshly computed."""

    model: Model
    check: dict[str, Any]
    prove: dict[str, Any]
    traces: list[dict[str, Any]]
    """Per trace: name, path (relative to the report root), source, lemma, summary, frame files, the document."""
    against: list[dict[str, Any]] = field(default_factory=list)
    """A repaired model: the corpus of the other models under it (:mod:`fatline_verify.report.against_pages`)."""
    places: Places = field(default_factory=Places)
    """Where the report was written: what its pages' commands and links name (:mod:`.places`)."""
