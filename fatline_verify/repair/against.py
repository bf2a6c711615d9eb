"""The regression corpus under another rule set: is each counterexample gone?

For each counterexample trace of the corpus (``reports/traces/``) from another model, the checker
explores ``model`` from the trace's initial configuration, under the trace's own scheduler, over
*every* activation (not only the trace's): the trace's lemma then holds within the bounds from that
configuration, or is violated with a replayed witness, or the search is inconclusive (with why).
``fatline report`` shows the result beside each counterexample on a repaired model's page.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from fractions import Fraction
from math import lcm
from pathlib import Path
from typing import Any

import numpy as np

from ..check.search import explore
from ..check.verdicts import lemma_verdicts
from ..errors import FatlineError
from ..lemmas.properties import Lemma, Verdict
from ..model.config import Model, model_from_mapping
from ..model.numbers import Point
from ..outputs import Kind as OutputKind
from ..outputs import is_output, read_json
from ..rules import registry
from ..schedulers.round import play_round
from ..schedulers.systems import system_for
from ..trace.simulate import Outcome, Run, outcome_after
from ..trace.traces import initial_positions, initial_radii, replayed_document

MARGIN = 6
"""Lattice points (of the model's own lattice) added on each axis to a configuration's bounding box
for the exploration bound (at least the model's own window): room for the moves the rules make."""

MAX_STATES = 200_000
"""A cap on the states explored from one configuration (the result says so if it is reached)."""


@dataclass(frozen=True)
class Against:
    """One corpus counterexample and what ``model`` does from its initial configuration."""

    trace: str
    """The trace's file name in the corpus."""
    source: str
    """The model the counterexample breaks."""
    lemma: str
    robots: int
    scheduler: str
    rounds: int
    """The counterexample's length (rounds or events)."""
    verdict: str
    """``model``'s verdict on the lemma from that configuration, or ``NOT CHECKED``."""
    reason: str
    states: int = 0
    witness: dict[str, Any] | None = None


NOT_CHECKED = "NOT CHECKED"
GONE_ON_ITS_ROUNDS = "GONE ON ITS ROUNDS"
"""Not explored (no lattice holds the configuration, or its bound does not fit the state keys): the
trace's own activations replayed under the model with exact rationals, and the lemma not violated."""
STILL_ON_ITS_ROUNDS = "VIOLATED ON ITS ROUNDS"


def _under_scheduler(model: Model, source: Model) -> Model:
    """``model`` under ``source``'s scheduler (and ASYNC step count): the counterexample's own."""
    steps = source.parameters.async_steps
    if source.options.scheduler is model.options.scheduler and steps == model.parameters.async_steps:
        return model
    options = model.options.with_(scheduler=str(source.options.scheduler))
    return replace(model, options=options, parameters=replace(model.parameters, async_steps=steps))


FINEST = 20
"""The finest lattice (points per radius) a configuration is explored on."""


def _on_lattice(doc: dict[str, Any], model: Model) -> tuple[Model, list[Point]] | None:
    """``model`` on the coarsest lattice (a multiple of its own ``q``, at most :data:`FINEST`) that holds
    the trace's initial configuration, and the configuration in its units; ``None`` if none does."""
    radii = initial_radii(doc)
    q = model.radius * lcm(*((Fraction(v) * model.radius).denominator for p in radii for v in p))
    if q > FINEST:
        return None
    if q != model.radius:
        w, h = model.bounds.window
        scale = q // model.radius
        bounds = replace(model.bounds, window=((w - 1) * scale + 1, (h - 1) * scale + 1))
        model = replace(model, parameters=replace(model.parameters, q=q), bounds=bounds)
    return model, [model.to_lattice(p) for p in radii]


def against(model: Model, path: Path) -> Against | None:
    """What ``model`` does from the initial configuration of the counterexample at ``path`` (``None``
    for a trace of ``model`` itself, or a file that is not a trace)."""
    doc = read_json(path)
    if not doc or not is_output(path, OutputKind.TRACE):
        return None
    source = model_from_mapping(doc["model"], default_name="trace")
    if source.name == model.name:
        return None
    if registry.of(source).robots != registry.of(model).robots:
        return None  # a configuration of point robots is none of disc robots (they may overlap), or the reverse
    origin = doc.get("origin") or {}
    lemma = str(origin.get("lemma") or (doc.get("violation") or {}).get("property", ""))
    target = _under_scheduler(model, source)

    def row(verdict: str, reason: str, states: int = 0, witness: dict[str, Any] | None = None) -> Against:
        return Against(
            path.name, source.name, lemma, len(doc["initial"]), str(target.options.scheduler),
            len(doc.get("rounds") or []), verdict, reason, states, witness,
        )  # fmt: skip

    fitted = _on_lattice(doc, target)
    if fitted is None:
        return _its_rounds(doc, target, row, f"its initial configuration is on no lattice up to q={FINEST}")
    target, points = fitted
    wanted = next((known for known in Lemma if known.value == lemma), None)
    arr = np.array([points], dtype=np.int64)
    arr -= arr.min(axis=1, keepdims=True)
    width, height = (int(arr[0, :, k].max()) + 1 for k in (0, 1))
    window = target.bounds.window
    margin = MARGIN * target.radius // model.radius
    bound = (max(window[0], width + margin), max(window[1], height + margin))
    system = system_for(target)
    canon, _ = system.canonical(system.initial(arr))
    try:
        ex = explore(system, canon, bound, system.default_engine, max_states=MAX_STATES)
    except (FatlineError, ValueError) as exc:  # ValueError: the bound does not pack into the state keys
        return _its_rounds(doc, model, row, f"q={target.radius}, bound {bound[0]}x{bound[1]}: {exc}")
    result = next((r for r in lemma_verdicts(ex) if r.lemma is wanted), None)
    if result is None:
        return row(NOT_CHECKED, f"lemma {lemma!r} is not one the checker judges")
    reason = result.reason
    if result.verdict is Verdict.HOLDS_WITHIN_BOUNDS:
        reason = f"every activation from this configuration: {reason}"
    return row(result.verdict.value, reason, ex.n_states, result.witness)


def its_rounds(doc: dict[str, Any], model: Model) -> Run | None:
    """The trace's own rounds (each round's active robots) played by ``model`` from the trace's initial
    configuration, in exact rationals, up to the first round that breaks a lemma; ``None``
    for a trace whose steps are not rounds (ASYNC events)."""
    rounds = doc.get("rounds") or []
    if any("active" not in r or "event" in r for r in rounds):
        return None
    state = initial_positions(doc, model)
    initial, played = state, []
    for r in rounds:
        result = play_round(state, r["active"], model)
        played.append(result)
        if result.violations:
            return Run(model, initial, tuple(played), Outcome.VIOLATION)
        state = result.after
    end = outcome_after(state, played[-1] if played else None, model) or Outcome.ROUND_LIMIT
    return Run(model, initial, tuple(played), end)


def _its_rounds(doc: dict[str, Any], model: Model, row: Callable[..., Against], why: str) -> Against:
    """The fallback of a configuration the checker cannot explore: :func:`its_rounds`, the lemma
    judged on each round."""
    run = its_rounds(doc, model)
    lemma = row(NOT_CHECKED, "").lemma
    if run is None:
        return row(NOT_CHECKED, f"{why}; its steps are not rounds")
    if run.outcome is Outcome.VIOLATION and any(v.lemma.value == lemma for v in run.rounds[-1].violations):
        witness = replayed_document(run, {"tool": "fatline report", "lemma": lemma}, lemma)
        k = len(run.rounds)
        return row(STILL_ON_ITS_ROUNDS, f"{why}; its rounds replayed: {lemma} violated in round {k}", 0, witness)
    return row(GONE_ON_ITS_ROUNDS, f"{why}; its {len(run.rounds)} round(s) replayed exactly: {lemma} not violated")


def corpus_against(model: Model, corpus: Path) -> list[Against]:
    """Every counterexample of ``corpus`` of another model, in file-name order, under ``model``."""
    rows = [against(model, path) for path in sorted(corpus.glob("*.json"))]
    return [row for row in rows if row is not None]


__all__ = [
    "GONE_ON_ITS_ROUNDS",
    "NOT_CHECKED",
    "STILL_ON_ITS_ROUNDS",
    "Against",
    "against",
    "corpus_against",
    "its_rounds",
]
