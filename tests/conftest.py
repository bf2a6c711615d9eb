"""Shared helpers: models with some readings changed, the committed reports, the artefacts the hostile-state
tests tamper with."""

from __future__ import annotations

import os
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest

from fatline_verify.model.config import Model, Parameters
from fatline_verify.model.options import Options

os.environ["FATLINE_ANSWERS"] = "off"  # no test reads or writes answers kept by other runs (tests/test_store.py: on)


def make_model(rad_v: int | Fraction = 4, q: int = 1, **readings: str) -> Model:
    """The default model with ``rad_v``/``q`` and some readings changed."""
    return Model(name="test", options=Options().with_(**readings), parameters=Parameters(rad_v=rad_v, q=q))


def task_named(model: Model, key: str) -> Any:
    """The prover's obligation of ``model`` named ``key`` (``lemma/form-case[.and.other]``)."""
    from fatline_verify.prove.prover import tasks_for

    return next(t for t in tasks_for(model) if t.key == key)


@pytest.fixture
def model() -> Model:
    return make_model()


@pytest.fixture(scope="session")
def committed_reports() -> list[Any]:
    """Every model's report as committed (``reports/``, ``proofs/``), by model name: read once a
    session, since reading it schema-checks every corpus trace (seconds). Tests only read it."""
    from fatline_verify.report.build import _earlier

    root = Path(__file__).resolve().parent.parent
    return sorted(_earlier([], root / "reports", root / "proofs"), key=lambda r: r.model.name)


@pytest.fixture(scope="session")
def made(tmp_path_factory) -> Path:
    """The artefacts the hostile-state tests tamper with, made once (:func:`tests.hostile.make_artefacts`)."""
    from tests.hostile import make_artefacts

    return make_artefacts(tmp_path_factory.mktemp("made"))
