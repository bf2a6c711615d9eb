"""One check of a sweep: the bounded checker at one combination of readings, and what the sweep keeps
of it (:class:`Found`). The checks are the sweep's only calls into the checker; what they find is
closed over the other combinations by :mod:`fatline_verify.sweep.run`."""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from typing import Any

from ..lemmas.properties import CHECKED, Lemma, LemmaResult, Verdict
from ..model.config import Model
from ..progress import estimate, rate_text
from .equivalent import Explored, held_past_violations

Activity = Callable[[str], None]
"""What the sweep is doing now, as one short text (the progress layer shows it; the engine never prints)."""


@dataclass
class Doing:
    """What the sweep is doing now (the progress layer reads it; the engine never prints)."""

    what: str = "starting"
    count: int = 0
    unit: str = ""
    replays: Callable[[], int] | None = None
    """The replays made so far, where they are not the unit counted (a spread's remembered answers)."""
    since: float = field(default_factory=time.monotonic)
    """When this step began: its count's rate is shown, since the judgements move only between steps."""

    def set(self, what: str, unit: str = "", replays: Callable[[], int] | None = None) -> None:
        self.what, self.count, self.unit, self.replays = what, 0, unit, replays
        self.since = time.monotonic()

    def tick(self, count: int) -> None:
        self.count = count

    def __str__(self) -> str:
        rate, _ = estimate(self.count, None, self.since, self.since, time.monotonic())
        pace = f" ({rate_text(rate)})" if rate is not None else ""
        text = self.what + (f", {self.count:,} {self.unit}{pace}" if self.unit else "")
        return text + (f", {self.replays():,} replays" if self.replays is not None else "")


@dataclass(frozen=True, slots=True)
class SweepBounds:
    """The checker's bounds for every combination checked."""

    robots: tuple[int, int]
    window: tuple[int, int]
    engine: str | None = None
    max_states: int | None = None
    bound: tuple[int, int] | None = None
    """The exploration bound (``None``: the window)."""
    max_memory: int | None = None
    """Bytes a check's search may hold (``None``: the checker's default share of the machine). A resource,
    not a setting of the sweep: not saved, not fingerprinted."""

    def as_json(self) -> dict[str, Any]:
        """The bounds as saved (and fingerprinted: a sweep without ``bound`` keeps the fingerprint it had
        before the option existed, so it still resumes)."""
        out: dict[str, Any] = {"robots": list(self.robots), "window": list(self.window), "max_states": self.max_states}
        if self.bound is not None and self.bound != self.window:
            out["bound"] = list(self.bound)
        return out


@dataclass(frozen=True, slots=True)
class Found:
    """What one check found at one combination: per lemma the verdict and, if violated, the witness;
    and what it explored (for :func:`fatline_verify.sweep.equivalent.same_exploration`)."""

    combo: dict[str, int]
    verdicts: dict[Lemma, Verdict]
    witnesses: dict[Lemma, dict[str, Any]]
    seconds: float
    explored: tuple[Explored, ...] = ()
    """The robot counts explored past violations (only when some lemma holds)."""
    held: frozenset[Lemma] = frozenset()
    """The lemmas that hold there too."""
    stopped: tuple[Explored, ...] = ()
    """The robot counts as the check explored them, stopping at violations (only when some lemma holds)."""


def check_combo(model: Model, bounds: SweepBounds, combo: dict[str, int], activity: Activity | None = None) -> Found:
    """The bounded check of ``model`` (one combination's readings): worst verdict per lemma over the
    robot counts, the witness of the smallest violating count (replayed by the checker); then, if a
    lemma holds, what those counts expanded, and the same counts explored past violations
    (:mod:`fatline_verify.sweep.equivalent`). ``activity`` hears of each search level."""
    from ..check.checker import CheckPlan, explore_robots
    from ..check.verdicts import lemma_verdicts

    t0 = time.perf_counter()
    plan = CheckPlan.of(
        model,
        bounds.robots,
        bounds.window,
        max_states=bounds.max_states,
        engine=bounds.engine,
        bound=bounds.bound,
        max_memory=bounds.max_memory,
    )
    tick = None
    if activity is not None:
        say = activity

        def tick(label: str, done: int, total: int, note: str) -> None:
            say(f"{label}" + (f", {note}" if note else ""))

    stops = [explore_robots(plan, n, progress=tick) for n in plan.counts]
    verdicts = _worst(lemma_verdicts(ex) for ex in stops)
    explored: list[Explored] = []
    stopped: tuple[Explored, ...] = ()
    held: frozenset[Lemma] = frozenset()
    if any(v is Verdict.HOLDS_WITHIN_BOUNDS for v, _ in verdicts.values()):
        stopped = tuple(Explored.of(ex, stopped=True) for ex in stops)
        go_on = replace(plan, after_violation="continue")
        held = frozenset(CHECKED)
        for n in plan.counts:
            ex = explore_robots(go_on, n, progress=None if tick is None else _past(tick))
            explored.append(Explored.of(ex, stopped=False))
            held &= held_past_violations(ex)
    witnesses = {lemma: doc for lemma, (v, doc) in verdicts.items() if v is Verdict.VIOLATED and doc is not None}
    return Found(
        combo, {lemma: v for lemma, (v, _) in verdicts.items()}, witnesses, time.perf_counter() - t0,
        tuple(explored), held, stopped,
    )  # fmt: skip


def _past(tick: Callable[[str, int, int, str], None]) -> Callable[[str, int, int, str], None]:
    def relabel(label: str, done: int, total: int, note: str) -> None:
        tick(f"{label} (past violations)", done, total, note)

    return relabel


def _worst(runs: Iterable[list[LemmaResult]]) -> dict[Lemma, tuple[Verdict, dict[str, Any] | None]]:
    """Per checked lemma, the worst verdict over the robot counts (smallest first) and the witness of
    the first violating count."""
    order = [Verdict.VIOLATED, Verdict.INCONCLUSIVE, Verdict.HOLDS_WITHIN_BOUNDS]
    out: dict[Lemma, tuple[Verdict, dict[str, Any] | None]] = {}
    for results in runs:
        for r in results:
            if r.lemma not in CHECKED:
                continue
            now, doc = out.get(r.lemma, (Verdict.HOLDS_WITHIN_BOUNDS, None))
            if order.index(r.verdict) < order.index(now):
                now, doc = r.verdict, r.witness
            out[r.lemma] = (now, doc)
    return out


def check_job(args: tuple[Model, SweepBounds, dict[str, int]]) -> Found:
    """One check on a Dask worker (no activity: a worker's progress is not this process's)."""
    return check_combo(*args)
