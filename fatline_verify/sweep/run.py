"""``fatline sweep``: each lemma's verdict over a whole product of readings, covered by counterexamples.

Checking each of a million combinations is out of reach; most of them fall to the same few
counterexamples. So: check one open combination with the bounded checker
(:func:`fatline_verify.sweep.check.check_combo`); replay each witness it finds under every
combination still open for that lemma (:func:`fatline_verify.sweep.cover.cover`) and close every one
it refutes; a lemma that is not violated there gets that one combination's verdict
(HOLDS_WITHIN_BOUNDS or INCONCLUSIVE), and where it holds, so does every combination that cannot tell
its reason apart: a safety lemma's (or ``approach``'s) by graph equality
(:mod:`fatline_verify.sweep.equivalent`), ``progress``'s and ``termination``'s by an invariant over
the states the checks expanded (:mod:`fatline_verify.sweep.invariant`). Repeat until nothing is
open, the check budget is spent, or the time is up.

Each *step* (one lemma closed from one check) is saved at once (:mod:`fatline_verify.sweep.state`),
and a rerun with the same settings resumes from there, closing what a fresh run would. Memory is
bounded by ``max_memory``: the checks' searches, the remembered answers (:class:`Memo`) and the spread
closures each get a share of it (a spread that would pass its share leaves the combinations it cannot
follow open: fewer closed, none closed wrongly).
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from ..cache import fingerprint
from ..lemmas.properties import CHECKED, Lemma, Verdict
from ..model.config import model_to_mapping
from ..outputs import write_json
from . import state
from .check import Doing, Found, SweepBounds, check_combo, check_job
from .cover import cover, refutes
from .equivalent import Equivalence, Explored, same_exploration
from .invariant import SPREAD_SAFETY, TRAPPED, Trap, spread_termination, trapped, within_known
from .memo import Memo
from .space import Space, bearing
from .state import FORMAT, HOLDS, INCONCLUSIVE, OPEN, REFUTED, VERSION, Where
from .text import headline, sweep_lines

__all__ = [
    "HOLDS", "INCONCLUSIVE", "OPEN", "REFUTED", "Doing", "Found", "Sweep", "SweepBounds", "check_combo", "headline",
    "sweep_lines",
]  # fmt: skip

STATUS = {REFUTED: Verdict.VIOLATED, HOLDS: Verdict.HOLDS_WITHIN_BOUNDS, INCONCLUSIVE: Verdict.INCONCLUSIVE}

GROW = 200_000
"""States a spread closure (``progress`` and the step lemmas) may take in beyond those the checks
expanded, per robot count: the open readings' searches run together (:func:`within_known`) until they
are done or this many new states were met."""

WORK = 20_000
"""Answers a spread closure may use per robot count (a state's expansion under one class of readings;
about one replay each when nothing is remembered), and replays a graph-equality closure may make:
past them the readings not yet shown alike stay open for a later check, and a step ends in minutes,
not hours. ``fatline sweep`` bounds closures so when it has a time limit (``--max-time``); without one
they run to the end, which closes far more per check (the shipped rma-fixed sweep closed 497,664
readings by graph equality in 3.3 million replays)."""

MEMO_SHARE = 4
"""The remembered answers may hold ``max_memory / MEMO_SHARE`` (then they are forgotten and replayed
again as asked: the same answers, more replays)."""
SPREAD_SHARE = 4
"""A spread closure may hold ``max_memory / SPREAD_SHARE`` in its per-state sets of combinations."""
CHECK_SHARE = 2
"""A check's search may hold ``max_memory / CHECK_SHARE`` (the checker's own guard)."""


@dataclass
class Sweep:
    """The sweep of ``space`` (every varied option) at ``bounds``; each lemma judged over the options
    that bear on it (:func:`fatline_verify.sweep.space.bearing`). ``max_memory``: bytes the run may hold
    (0: no bound)."""

    space: Space
    bounds: SweepBounds
    out: Path
    lemmas: tuple[Lemma, ...] = CHECKED
    max_memory: int = 0
    work: int = 0
    """Answers or replays a closure may use (:data:`WORK`; 0: no bound, as for the shipped sweeps)."""
    spaces: dict[Lemma, Space] = field(init=False)
    status: dict[Lemma, np.ndarray] = field(init=False)
    witnesses: list[dict[str, Any]] = field(default_factory=list)
    checks: list[dict[str, Any]] = field(default_factory=list)
    replays: int = 0
    known: dict[Where, np.ndarray] = field(default_factory=dict, repr=False)
    """Per robot count and bounds, every state the checks so far expanded (for :meth:`_within_known`; saved)."""
    pending: list[dict[str, int]] = field(default_factory=list)
    """The check under way: the combinations picked and not yet closed from (saved)."""
    absorbed: list[Lemma] = field(default_factory=list)
    """The lemmas already closed from the first of ``pending`` (saved)."""
    doing: Doing = field(default_factory=Doing, repr=False)
    _projections: dict[Lemma, np.ndarray] = field(default_factory=dict, init=False, repr=False)
    _memo: Memo = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.spaces = {lemma: Space(self.space.base, bearing(lemma, self.space.names)) for lemma in self.lemmas}
        self.status = {lemma: np.zeros(s.size, dtype=np.uint8) for lemma, s in self.spaces.items()}
        self._memo = Memo(self.space, limit=self.max_memory // MEMO_SHARE)

    # --- files -----------------------------------------------------------------------------------
    @property
    def json_path(self) -> Path:
        return self.out / "sweep.json"

    @property
    def status_path(self) -> Path:
        return self.out / state.STATUS_FILE

    def trace_path(self, lemma: Lemma, k: int) -> Path:
        return self.out / "traces" / f"{lemma.value}-{k}.json"

    def fingerprint(self) -> str:
        """What the saved sweep was computed from: the base model (its own parameters' values included),
        the settings, and the sources of every plug-in that decides for it (as ``check`` and ``prove``
        fingerprint theirs: a built-in model's is as it was)."""
        from ..provenance import plugin_settings

        return fingerprint(
            self.space.base,
            "sweep",
            vary=list(self.space.names),
            bounds=self.bounds.as_json(),
            lemmas=[lemma.value for lemma in self.lemmas],
            version=VERSION,
            **plugin_settings(self.space.base),
        )

    def resume(self) -> bool:
        """Load a saved sweep with the same settings (:func:`fatline_verify.sweep.state.resume`)."""
        return state.resume(self)

    def save(self) -> None:
        """Save everything, the manifest last (:func:`fatline_verify.sweep.state.save`)."""
        self.doing.set("saving")
        state.save(self)

    # --- the loop --------------------------------------------------------------------------------
    def open_count(self) -> int:
        return sum(int((s == OPEN).sum()) for s in self.status.values())

    def judgements(self) -> int:
        """Combinations times lemmas: what the sweep judges in all."""
        return sum(s.size for s in self.spaces.values())

    def next_combos(self, k: int) -> list[dict[str, int]]:
        """Up to ``k`` distinct combinations open for some lemma: the first open ones of the first lemma
        with any (the options that do not bear on it as in the base model), then the next lemma's."""
        picked: list[dict[str, int]] = []
        for lemma in self.lemmas:
            space = self.spaces[lemma]
            for index in np.flatnonzero(self.status[lemma] == OPEN)[:k]:
                combo = {**self._base_combo(), **space.combo(int(index))}
                if combo not in picked:
                    picked.append(combo)
                if len(picked) == k:
                    return picked
        return picked

    def _base_combo(self) -> dict[str, int]:
        return self.space.reading_indices(self.space.base.options)

    def absorb(self, found: Found) -> list[str]:
        """Close everything a check found (every lemma's step, then its record). Returns one line per change."""
        lines = []
        for lemma in self.lemmas:
            lines += self.absorb_lemma(found, lemma)
        self._record(found)
        return lines

    def absorb_lemma(self, found: Found, lemma: Lemma) -> list[str]:
        """One step: close what a check found for ``lemma``: the combinations its witness refutes (a
        lemma already judged here keeps its earlier verdict), or, if it was not refuted, this one with
        its verdict and, where it holds, every open combination that cannot tell its reason apart."""
        space, status = self.spaces[lemma], self.status[lemma]
        if status[space.index(found.combo)] != OPEN:
            return []
        self.doing.set(f"check {len(self.checks) + 1}: closing {lemma.value}")
        verdict = found.verdicts.get(lemma, Verdict.INCONCLUSIVE)
        doc = found.witnesses.get(lemma)
        if verdict is Verdict.VIOLATED and doc is not None:
            return [self._cover(lemma, doc, found.combo)]
        return self._equivalent(found, lemma, HOLDS if verdict is Verdict.HOLDS_WITHIN_BOUNDS else INCONCLUSIVE)

    def _record(self, found: Found) -> None:
        self.checks.append(
            {
                "readings": self.space.text(found.combo),
                "verdicts": {lemma.value: str(v) for lemma, v in found.verdicts.items()},
                "seconds": round(found.seconds, 3),
            }
        )

    def _cover(self, lemma: Lemma, doc: dict[str, Any], combo: dict[str, int]) -> str:
        """Replay a new counterexample under every open combination of ``lemma``; close those it refutes."""
        space, status = self.spaces[lemma], self.status[lemma]
        self.doing.set(f"check {len(self.checks) + 1}: replaying the {lemma.value} counterexample", "replays")
        covered = cover(space, status == OPEN, partial(refutes, doc, lemma), tick=self.doing.tick)
        self.replays += covered.replays
        if not covered.refuted[space.index(combo)]:
            raise AssertionError(f"{lemma.value}: the witness found under {space.text(combo)} does not refute it there")
        newly = int(covered.refuted.sum())
        k = sum(1 for w in self.witnesses if w["lemma"] == lemma.value) + 1
        path = self.trace_path(lemma, k)
        write_json(path, doc)
        status[covered.refuted] = REFUTED
        self.witnesses.append(
            {
                "lemma": lemma.value,
                "trace": path.relative_to(self.out).as_posix(),
                "found_under": space.text(combo),
                "robots": len(doc["initial"]),
                "refutes": newly,
                "replays": covered.replays,
            }
        )
        return f"{lemma.value}: a counterexample of {len(doc['initial'])} robots refutes {newly:,}"

    def _equivalent(self, found: Found, lemma: Lemma, code: int) -> list[str]:
        """Close ``lemma`` at this combination with its verdict; if it holds, also at every open
        combination whose stopped graph it sees alike (a liveness lemma: that this combination's states
        trap, :mod:`fatline_verify.sweep.invariant`), and, if it holds even past violations, whose
        continued graph it sees alike (:mod:`fatline_verify.sweep.equivalent`)."""
        space, status = self.spaces[lemma], self.status[lemma]
        status[space.index(found.combo)] = code
        if code != HOLDS:
            return []
        # A spread of the open readings' searches covers every stopped graph equal to this one.
        stopped = self._within_known if lemma in TRAPPED + SPREAD_SAFETY else self._same_exploration
        closures = [(stopped, found.stopped)] + (
            [(self._same_exploration, found.explored)] if lemma in found.held else []
        )
        closed = 1
        for closure, explored in closures:
            if not explored:
                continue
            among = (status == OPEN)[self._projection(lemma)]
            eq = closure(self.space, among, self.space.model(found.combo), list(explored), lemma)
            self.replays += eq.replays
            targets = np.unique(self._projection(lemma)[eq.same])
            status[targets] = HOLDS
            closed += len(targets)
        return [f"{lemma.value}: holds within bounds under {closed:,} readings (one graph)"]

    def _same_exploration(
        self, space: Space, among: np.ndarray, reference: Any, explored: list[Explored], lemma: Lemma
    ) -> Equivalence:
        self.doing.set(f"check {len(self.checks) + 1}: closing {lemma.value} (same graph)", "replays")
        return same_exploration(space, among, reference, explored, lemma, tick=self.doing.tick, work=self.work)

    def _within_known(
        self, space: Space, among: np.ndarray, reference: Any, explored: list[Explored], lemma: Lemma
    ) -> Equivalence:
        """A spread closure: the combinations whose searches stay in the states every check so far
        expanded (this one's included) and those they meet, with no deadlock (:func:`within_known`), or
        for a step lemma no transition that violates it;
        for ``termination``, with nothing escaping and no transition on a cycle of any of their
        searches (:func:`spread_termination`), and also the combinations this one's states trap
        (:func:`trapped`: its own rank, where the shared one has no room)."""
        for ex in explored:
            where = (ex.n, ex.bound, ex.window)
            old = self.known.get(where)
            self.known[where] = np.union1d(ex.expanded if old is None else old, ex.expanded)
        known = [Trap(n, bound, window, keys) for (n, bound, window), keys in sorted(self.known.items())]
        budget = self.max_memory // SPREAD_SHARE
        start = self._memo.replays
        self.doing.set(
            f"check {len(self.checks) + 1}: closing {lemma.value} (spread)",
            "states spread",
            lambda: self._memo.replays - start,
        )
        tick = self.doing.tick
        if lemma is not Lemma.TERMINATION:
            return within_known(
                space, among, known, self._memo, grow=GROW, lemma=lemma, budget=budget, tick=tick, work=self.work
            )
        shared = spread_termination(space, among, known, self._memo, GROW, budget=budget, tick=tick, work=self.work)
        own = trapped(space, among & ~shared.same, reference, explored, lemma, self._memo)
        return Equivalence(shared.same | own.same, shared.replays + own.replays)

    def _projection(self, lemma: Lemma) -> np.ndarray:
        """Each combination of the whole space as a combination of ``lemma``'s space."""
        if lemma not in self._projections:
            space = self.spaces[lemma]
            columns = [self.space.names.index(name) for name in space.names]
            digits = self.space.digits[:, columns].astype(np.int64)
            self._projections[lemma] = np.ravel_multi_index(tuple(digits.T), space.sizes).astype(np.int64)
        return self._projections[lemma]

    def run(
        self,
        max_checks: int | None = None,
        workers: int = 1,
        cluster: str | None = None,
        progress: Callable[[str], None] | None = None,
        deadline: float | None = None,
    ) -> bool:
        """Check and close, step by step, until nothing is open (``True``), ``max_checks`` more checks
        were picked, or the clock (``time.monotonic()``) passed ``deadline`` between two steps (a run
        makes one step at least, and each check closes one step at least: every run gets on). Checks
        run ``workers`` at a time on a local Dask cluster, or on the Dask scheduler at ``cluster``;
        closing runs here, and every step is saved before the next. ``progress`` hears one line per
        change."""
        left = max_checks
        steps = 0

        def late() -> bool:  # never before the first step: every run gets on
            return steps > 0 and deadline is not None and time.monotonic() >= deadline

        with contextlib.ExitStack() as stack:
            dask: Any = None
            while True:
                if not self.pending:
                    if (left is not None and left <= 0) or late():
                        break
                    combos = self.next_combos(max(workers, 1) if left is None else min(max(workers, 1), left))
                    if not combos:
                        break
                    self.pending, self.absorbed = combos, []
                    if left is not None:
                        left -= len(combos)
                elif late():
                    break
                if dask is None and (workers > 1 or cluster is not None) and len(self.pending) > 1:
                    from ..check.workers import Cluster

                    dask = stack.enter_context(Cluster(workers, cluster)).client
                first = True
                for found in self._checks(list(self.pending), dask):
                    for lemma in self.lemmas:
                        if lemma in self.absorbed:
                            continue
                        if late() and not first:
                            return self.open_count() == 0
                        first = False
                        lines = self.absorb_lemma(found, lemma)
                        self.absorbed.append(lemma)
                        self.save()
                        steps += 1
                        for line in lines if progress else ():
                            progress(line)  # type: ignore[misc]
                    self._record(found)
                    self.pending, self.absorbed = self.pending[1:], []
                    self.save()
                    if progress:
                        progress(f"{len(self.checks)} checks, {self.open_count():,} combinations open")
        return self.open_count() == 0

    def _checks(self, combos: list[dict[str, int]], dask: Any) -> Iterator[Found]:
        """The checks of ``combos``, in order: here one by one, or all at once on ``dask``."""
        if dask is None or len(combos) == 1:
            for combo in combos:
                self.doing.set(f"check {len(self.checks) + 1}: {self._short(combo)}")
                yield check_combo(self.space.model(combo), self._check_bounds(), combo, self._say)
            return
        self.doing.set(f"checks {len(self.checks) + 1}..{len(self.checks) + len(combos)} on the workers")
        jobs = [(self.space.model(c), self._check_bounds(), c) for c in combos]
        yield from dask.gather(dask.map(check_job, jobs, pure=False))

    def _check_bounds(self) -> SweepBounds:
        if not self.max_memory:
            return self.bounds
        return SweepBounds(
            self.bounds.robots, self.bounds.window, self.bounds.engine, self.bounds.max_states, self.bounds.bound,
            self.max_memory // CHECK_SHARE,
        )  # fmt: skip

    def _say(self, text: str) -> None:
        self.doing.what = f"check {len(self.checks) + 1}: {text}"

    def _short(self, combo: dict[str, int]) -> str:
        """The readings of ``combo`` that differ from the model's (or "the model's readings")."""
        base = self._base_combo()
        differ = {name: text for name, text in self.space.text(combo).items() if combo[name] != base[name]}
        return ", ".join(f"{k}={v}" for k, v in differ.items()) or "the model's readings"

    # --- results ---------------------------------------------------------------------------------
    def lemma_summary(self, lemma: Lemma) -> dict[str, Any]:
        status = self.status[lemma]
        names = {REFUTED: "refuted", HOLDS: "holds", INCONCLUSIVE: "inconclusive", OPEN: "open"}
        counts = {name: int((status == code).sum()) for code, name in names.items()}
        space = self.spaces[lemma]
        holds = [space.text(space.combo(int(i))) for i in np.flatnonzero(status == HOLDS)[:50]]
        return {
            "lemma": lemma.value,
            "options": list(space.names),
            "combinations": space.size,
            **counts,
            "counterexamples": sum(1 for w in self.witnesses if w["lemma"] == lemma.value),
            "holds_under": holds,
        }

    def to_json(self) -> dict[str, Any]:
        out = {
            "format": FORMAT,
            "version": VERSION,
            "fingerprint": self.fingerprint(),
            "model": model_to_mapping(self.space.base),
            "vary": list(self.space.names),
            "bounds": self.bounds.as_json(),
            "lemmas": [self.lemma_summary(lemma) for lemma in self.lemmas],
            "witnesses": self.witnesses,
            "checks": self.checks,
            "replays": self.replays,
        }
        if self.pending:
            out["pending"] = {"combos": self.pending, "absorbed": [lemma.value for lemma in self.absorbed]}
        return out
