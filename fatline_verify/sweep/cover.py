"""Which readings a counterexample refutes: one replay per class of readings it cannot tell apart.

A trace is replayed by the executable model under a combination of readings through
:class:`Recorder`, which notes every varied option the replay reads. The replay is a deterministic
function of what it reads, so every combination that agrees on those readings replays identically:
the *leaf* cube. The rest of the cube is split on the first read option that differs and searched
the same way, so one witness is judged under a whole product of readings in as many replays as its
decision tree has leaves (:func:`cover`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..errors import InvalidInput, InvalidTrace
from ..lemmas.properties import SAFETY, Lemma
from ..model.config import Model
from ..model.options import CATALOGUE, Options
from ..model.swarm import initial_problems
from ..schedulers.systems import system_for
from ..trace.traces import derive_violation, initial_positions, replay
from .space import Space


class Recorder:
    """:class:`Options` that note which of the ``watched`` options were read, in order.

    Reading a method (``as_dict``, ``with_``, ...) counts as reading every watched option: the
    recorder never under-reports what a computation depended on."""

    __slots__ = ("_options", "_watched", "reads")

    def __init__(self, options: Options, watched: tuple[str, ...]) -> None:
        self._options = options
        self._watched = watched
        self.reads: dict[str, str] = {}

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._options, name)
        if name in self._watched:
            self.reads.setdefault(name, str(value))
        elif name not in CATALOGUE:
            for watched in self._watched:
                self.reads.setdefault(watched, str(getattr(self._options, watched)))
        return value


Judge = Callable[[Model], bool]
"""Whether a witness refutes the lemma under a model (the model's options may be a :class:`Recorder`)."""


def refutes(doc: dict[str, Any], lemma: Lemma, model: Model) -> bool:
    """Whether trace ``doc``, replayed under ``model``, is a counterexample to ``lemma``.

    Its initial positions must meet the initial condition under ``model``. A step lemma is refuted
    by the first step that violates anything, if it violates ``lemma`` (a swarm that collided or
    split has left the model, as in the checker). The other lemmas are judged on the whole replay as
    :func:`fatline_verify.trace.traces.derive_violation` judges a trace: a deadlock, or a lasso that closes
    fairly without a violation."""
    system = system_for(model)
    try:
        initial = initial_positions(doc, model)
        if initial_problems(initial, model):
            return False
        if lemma not in SAFETY:
            run = replay(doc, model)
            return derive_violation(run, [{}] * len(run.rounds), lemma) is not None
        state = system.start(initial)
        n = len(initial)
        for k, record in enumerate(doc["rounds"], start=1):
            action = system.action_from_json(record, n, f"rounds/{k - 1}")
            system.check_action(state, action, k)
            step = system.play(state, action)
            if step.violations:
                return any(v.lemma is lemma for v in step.violations)
            state = step.target
    except (InvalidTrace, InvalidInput):
        return False  # the recorded actions do not apply under these readings
    return False


@dataclass(frozen=True, slots=True)
class Covered:
    """What one witness refutes among the combinations it was replayed under."""

    refuted: np.ndarray
    """Boolean mask over the space."""
    replays: int


def cover(space: Space, among: np.ndarray, judge: Judge, tick: Callable[[int], None] | None = None) -> Covered:
    """Judge every combination of ``among`` (a mask over ``space``) with as few replays as the
    decision tree of ``judge`` over the varied options has leaves; ``tick`` hears the replays so far."""
    refuted = np.zeros(space.size, dtype=bool)
    digits = space.digits
    stack = [np.flatnonzero(among)]
    replays = 0
    while stack:
        inside = stack.pop()
        if not len(inside):
            continue
        combo = space.combo(int(inside[0]))
        recorder = Recorder(space.options(combo), space.names)
        got = judge(replace(space.base, options=recorder))  # type: ignore[arg-type]
        replays += 1
        if tick is not None:
            tick(replays)
        for k, name in enumerate(space.names):
            if name in recorder.reads:
                same = digits[inside, k] == combo[name]
                stack.append(inside[~same])
                inside = inside[same]
        if got:
            refuted[inside] = True
    return Covered(refuted, replays)
