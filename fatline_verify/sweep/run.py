"""``fatline sweep``: each lemma's verdict over a whole product of readings, covered by counterexamples.

Checking each of a million combinations is out of reach; most of them fall to the same few
counterexamples. So: check one open combination with the bounded checker; replay each witness it
finds under every combination still open for that lemma (:func:`fatline_verify.sweep.cover.cover`)
and close every one it refutes; a lemma that is not violated there gets that one combination's
verdict (HOLDS_WITHIN_BOUNDS or INCONCLUSIVE), and where it holds, so does every combination that
cannot tell its reason apart: a safety lemma's (or ``approach``'s) by graph equality
(:mod:`fatline_verify.sweep.equivalent`), ``progress``'s and ``termination``'s by an invariant over
the states the checks expanded (:mod:`fatline_verify.sweep.invariant`). Repeat until nothing is
open, or the check budget is spent. Each finished check is saved at once (``sweep.json`` +
``status.npz`` + the witnesses), and a rerun with the same settings resumes from there.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import time
import zipfile
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field, replace
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from ..cache import fingerprint
from ..errors import InvalidInput, OutputFailed
from ..integrity import bytes_digest, file_digest, matches, seal, sealed
from ..lemmas.properties import CHECKED, Lemma, LemmaResult, Verdict
from ..model.config import Model, model_to_mapping
from ..outputs import Kind, NotReadable, load_json, os_error_text, read_regular, write_bytes, write_json
from .cover import cover, refutes
from .equivalent import Equivalence, Explored, held_past_violations, same_exploration
from .invariant import SPREAD_SAFETY, TRAPPED, Trap, spread_termination, trapped, within_known
from .memo import Memo
from .space import Space, bearing

OPEN, REFUTED, HOLDS, INCONCLUSIVE = 0, 1, 2, 3
"""A combination's status for one lemma."""

STATUS = {REFUTED: Verdict.VIOLATED, HOLDS: Verdict.HOLDS_WITHIN_BOUNDS, INCONCLUSIVE: Verdict.INCONCLUSIVE}

GROW = 200_000
"""States a spread closure (``progress`` and the step lemmas) may take in beyond those the checks
expanded, per robot count: the open readings' searches run together (:func:`within_known`) until they
are done or this many new states were met."""

FORMAT = Kind.SWEEP.value
VERSION = 1
STATUS_FILE = "status.npz"


@dataclass(frozen=True, slots=True)
class SweepBounds:
    """The checker's bounds for every combination checked."""

    robots: tuple[int, int]
    window: tuple[int, int]
    engine: str | None = None
    max_states: int | None = None
    bound: tuple[int, int] | None = None
    """The exploration bound (``None``: the window)."""

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


def check_combo(model: Model, bounds: SweepBounds, combo: dict[str, int]) -> Found:
    """The bounded check of ``model`` (one combination's readings): worst verdict per lemma over the
    robot counts, the witness of the smallest violating count (replayed by the checker); then, if a
    lemma holds, what those counts expanded, and the same counts explored past violations
    (:mod:`fatline_verify.sweep.equivalent`)."""
    from ..check.checker import CheckPlan, explore_robots, lemma_verdicts

    t0 = time.perf_counter()
    plan = CheckPlan.of(
        model, bounds.robots, bounds.window, max_states=bounds.max_states, engine=bounds.engine, bound=bounds.bound
    )
    stops = [explore_robots(plan, n) for n in plan.counts]
    verdicts = _worst(lemma_verdicts(ex) for ex in stops)
    witnesses: dict[Lemma, dict[str, Any]] = {}
    explored: list[Explored] = []
    stopped: tuple[Explored, ...] = ()
    held: frozenset[Lemma] = frozenset()
    if any(v is Verdict.HOLDS_WITHIN_BOUNDS for v, _ in verdicts.values()):
        stopped = tuple(Explored.of(ex, stopped=True) for ex in stops)
        go_on = replace(plan, after_violation="continue")
        held = frozenset(CHECKED)
        for n in plan.counts:
            ex = explore_robots(go_on, n)
            explored.append(Explored.of(ex, stopped=False))
            held &= held_past_violations(ex)
    witnesses = {lemma: doc for lemma, (v, doc) in verdicts.items() if v is Verdict.VIOLATED and doc is not None}
    return Found(
        combo, {lemma: v for lemma, (v, _) in verdicts.items()}, witnesses, time.perf_counter() - t0,
        tuple(explored), held, stopped,
    )  # fmt: skip


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


def _check_job(args: tuple[Model, SweepBounds, dict[str, int]]) -> Found:
    return check_combo(*args)


@dataclass
class Sweep:
    """The sweep of ``space`` (every varied option) at ``bounds``; each lemma judged over the options
    that bear on it (:func:`fatline_verify.sweep.space.bearing`)."""

    space: Space
    bounds: SweepBounds
    out: Path
    lemmas: tuple[Lemma, ...] = CHECKED
    spaces: dict[Lemma, Space] = field(init=False)
    status: dict[Lemma, np.ndarray] = field(init=False)
    witnesses: list[dict[str, Any]] = field(default_factory=list)
    checks: list[dict[str, Any]] = field(default_factory=list)
    replays: int = 0
    _projections: dict[Lemma, np.ndarray] = field(default_factory=dict, init=False, repr=False)
    _memo: Memo = field(init=False, repr=False)
    _known: dict[tuple[int, tuple[int, int], tuple[int, int]], np.ndarray] = field(default_factory=dict, repr=False)
    """Per robot count and bounds, every state the checks of this run expanded (for :meth:`_within_known`)."""

    def __post_init__(self) -> None:
        self.spaces = {lemma: Space(self.space.base, bearing(lemma, self.space.names)) for lemma in self.lemmas}
        self.status = {lemma: np.zeros(s.size, dtype=np.uint8) for lemma, s in self.spaces.items()}
        self._memo = Memo(self.space)

    # --- files -----------------------------------------------------------------------------------
    @property
    def json_path(self) -> Path:
        return self.out / "sweep.json"

    @property
    def status_path(self) -> Path:
        return self.out / "status.npz"

    def trace_path(self, lemma: Lemma, k: int) -> Path:
        return self.out / "traces" / f"{lemma.value}-{k}.json"

    def fingerprint(self) -> str:
        return fingerprint(
            self.space.base,
            "sweep",
            vary=list(self.space.names),
            bounds=self.bounds.as_json(),
            lemmas=[lemma.value for lemma in self.lemmas],
            version=VERSION,
        )

    def resume(self) -> bool:
        """Load a saved sweep with the same settings; ``False`` if there is none. A saved sweep with
        other settings is refused (it is not this sweep's to overwrite), and so is one whose files do
        not match the digests ``sweep.json`` records (or, for a sweep saved before digests, whose
        ``status.npz`` does not match the counts ``sweep.json`` records): never a verdict nobody computed."""
        if not self.json_path.exists():
            return False
        where = f"out={str(self.out)!r}: sweep.json"
        data = load_json(self.json_path, what=where, expected="the sweep.json fatline sweep wrote (or a new --out)")
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise InvalidInput(f"out={str(self.out)!r}: sweep.json there is not a fatline sweep; expected a new --out")
        digests = data.get("files") if sealed(data, self.json_path) else None
        if data.get("fingerprint") != self.fingerprint():
            raise InvalidInput(
                f"out={str(self.out)!r}: holds a sweep with other settings (model, --vary, --lemma or bounds); "
                "expected another --out, or the same settings to resume it"
            )
        witnesses, checks, replays = data.get("witnesses"), data.get("checks"), data.get("replays", 0)
        if (
            not isinstance(witnesses, list)
            or not isinstance(checks, list)
            or not isinstance(replays, int)
            or not all(self._witness_ok(w) for w in witnesses)
            or (
                digests is not None
                and (
                    not isinstance(digests, dict)
                    or STATUS_FILE not in digests
                    or set(digests) != {STATUS_FILE, *(w["trace"] for w in witnesses)}
                )
            )
        ):
            raise InvalidInput(
                f"{where}: witnesses, checks, replays or files malformed; expected the file fatline sweep wrote"
            )
        if digests is not None:
            self._roll_forward(digests.get(STATUS_FILE))
            for name, digest in digests.items():
                if not matches(self.out / name, digest):
                    raise OutputFailed(
                        f"{(self.out / name).as_posix()}: its content does not match the digest sweep.json records "
                        "(changed since fatline sweep wrote it); expected the sweep as fatline left it, or a new --out"
                    )
        try:
            raw = read_regular(self.status_path)
            with np.load(io.BytesIO(raw), allow_pickle=False) as saved:
                loaded = {lemma: saved[lemma.value] for lemma in self.lemmas}
        except (NotReadable, KeyError, ValueError, OSError, EOFError, zipfile.BadZipFile) as exc:
            raise InvalidInput(
                f"out={str(self.out)!r}: status.npz cannot be read ({exc}); expected the sweep as fatline left it"
            ) from None
        for lemma, got in loaded.items():
            if got.shape != self.status[lemma].shape or got.dtype.kind not in "iu" or (len(got) and got.max() > 3):
                raise InvalidInput(f"out={str(self.out)!r}: status.npz does not match sweep.json")
            self.status[lemma] = got.astype(np.uint8)
        self.witnesses = list(witnesses)
        self.checks = list(checks)
        self.replays = replays
        if digests is None:  # saved before digests: its counts must be the ones sweep.json records
            self._agrees(data)
        return True

    def _witness_ok(self, w: object) -> bool:
        """A witness entry names a trace inside ``traces/`` of one of the sweep's lemmas."""
        if not isinstance(w, dict) or w.get("lemma") not in {lemma.value for lemma in CHECKED}:
            return False
        trace = w.get("trace")
        return isinstance(trace, str) and re.fullmatch(rf"traces/{re.escape(w['lemma'])}-\d+\.json", trace) is not None

    def _agrees(self, data: dict[str, Any]) -> None:
        """A sweep saved before digests: each lemma's counts (and first readings where it holds) in
        ``status.npz`` must be those ``sweep.json`` records beside them."""
        recorded = {s.get("lemma"): s for s in data.get("lemmas", []) if isinstance(s, dict)}
        for lemma in self.lemmas:
            mine, theirs = self.lemma_summary(lemma), recorded.get(lemma.value, {})
            keys = ("refuted", "holds", "inconclusive", "open", "holds_under")
            if any(mine[k] != theirs.get(k) for k in keys):
                raise OutputFailed(
                    f"{self.status_path.as_posix()}: does not match the counts sweep.json records for {lemma.value} "
                    "(changed since fatline sweep wrote it); expected the sweep as fatline left it, or a new --out"
                )

    def _pending(self, digest: str) -> Path:
        """Where a save puts the new status before ``sweep.json`` names it (named by its digest)."""
        return self.out / f".status-{digest.removeprefix('sha256:')[:16]}.npz"

    def _roll_forward(self, digest: object) -> None:
        """Finish a save killed between writing ``sweep.json`` and renaming the status it names."""
        if isinstance(digest, str) and not matches(self.status_path, digest) and matches(self._pending(digest), digest):
            os.replace(self._pending(digest), self.status_path)

    def save(self) -> None:
        """Save the status, the witnesses' digests and everything else: the status under a name of its own,
        then ``sweep.json`` (the manifest, last: the digests of the status and of every witness trace), then
        the status renamed into place. Killed anywhere, the next run finds the old sweep or the new one
        (:meth:`_roll_forward`), never a status without its counterexamples."""
        self.out.mkdir(parents=True, exist_ok=True)
        buffer = io.BytesIO()
        arrays: dict[str, Any] = {lemma.value: self.status[lemma] for lemma in self.lemmas}
        np.savez_compressed(buffer, **arrays)
        raw = buffer.getvalue()
        digest = bytes_digest(raw)
        write_bytes(self._pending(digest), raw)
        files = {STATUS_FILE: digest}
        for w in self.witnesses:
            files[w["trace"]] = file_digest(self.out / w["trace"])
        write_json(self.json_path, seal({**self.to_json(), "files": files}))
        try:
            os.replace(self._pending(digest), self.status_path)
        except OSError as exc:
            raise OutputFailed(os_error_text(self.status_path, exc)) from None
        for stale in self.out.glob(".status-*.npz"):  # the remains of saves killed before their manifest
            with contextlib.suppress(OSError):
                stale.unlink()

    # --- the loop --------------------------------------------------------------------------------
    def open_count(self) -> int:
        return sum(int((s == OPEN).sum()) for s in self.status.values())

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
        """Close what a check found: the combinations its witnesses refute (a lemma already refuted
        here keeps its earlier counterexamples), and, for each lemma it did not refute, every open
        combination that explores the same graph. Returns one line per change."""
        lines = []
        kept: dict[Lemma, int] = {}
        for lemma in self.lemmas:
            space, status = self.spaces[lemma], self.status[lemma]
            here = space.index(found.combo)
            if status[here] != OPEN:
                continue
            verdict = found.verdicts.get(lemma, Verdict.INCONCLUSIVE)
            doc = found.witnesses.get(lemma)
            if verdict is Verdict.VIOLATED and doc is not None:
                lines.append(self._cover(lemma, doc, found.combo))
            else:
                kept[lemma] = HOLDS if verdict is Verdict.HOLDS_WITHIN_BOUNDS else INCONCLUSIVE
        if kept:
            lines += self._equivalent(found, kept)
        self.checks.append(
            {
                "readings": self.space.text(found.combo),
                "verdicts": {lemma.value: str(v) for lemma, v in found.verdicts.items()},
                "seconds": round(found.seconds, 3),
            }
        )
        return lines

    def _cover(self, lemma: Lemma, doc: dict[str, Any], combo: dict[str, int]) -> str:
        """Replay a new counterexample under every open combination of ``lemma``; close those it refutes."""
        space, status = self.spaces[lemma], self.status[lemma]
        covered = cover(space, status == OPEN, partial(refutes, doc, lemma))
        self.replays += covered.replays
        if not covered.refuted[space.index(combo)]:
            raise AssertionError(f"{lemma.value}: the witness found under {space.text(combo)} does not refute it there")
        newly = int(covered.refuted.sum())
        status[covered.refuted] = REFUTED
        k = sum(1 for w in self.witnesses if w["lemma"] == lemma.value) + 1
        path = self.trace_path(lemma, k)
        write_json(path, doc)
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

    def _equivalent(self, found: Found, kept: dict[Lemma, int]) -> list[str]:
        """Close each lemma of ``kept`` at this combination with its verdict; a lemma that holds also
        at every open combination whose stopped graph it sees alike (a liveness lemma: that this
        combination's states trap, :mod:`fatline_verify.sweep.invariant`), and, if it holds even past
        violations, whose continued graph it sees alike (:mod:`fatline_verify.sweep.equivalent`)."""
        lines = []
        for lemma, code in kept.items():
            space, status = self.spaces[lemma], self.status[lemma]
            status[space.index(found.combo)] = code
            if code != HOLDS:
                continue
            # A spread of the open readings' searches covers every stopped graph equal to this one.
            stopped = self._within_known if lemma in TRAPPED + SPREAD_SAFETY else same_exploration
            closures = [(stopped, found.stopped)] + (
                [(same_exploration, found.explored)] if lemma in found.held else []
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
            lines.append(f"{lemma.value}: holds within bounds under {closed:,} readings (one graph)")
        return lines

    def _within_known(
        self, space: Space, among: np.ndarray, reference: Model, explored: list[Explored], lemma: Lemma
    ) -> Equivalence:
        """A spread closure: the combinations whose searches stay in the states every check so far
        expanded (this one's included) and those they meet, with no deadlock (:func:`within_known`), or
        for a step lemma no transition that violates it;
        for ``termination``, with nothing escaping and no transition on a cycle of any of their
        searches (:func:`spread_termination`), and also the combinations this one's states trap
        (:func:`trapped`: its own rank, where the shared one has no room)."""
        for ex in explored:
            where = (ex.n, ex.bound, ex.window)
            old = self._known.get(where)
            self._known[where] = np.union1d(ex.expanded if old is None else old, ex.expanded)
        known = [Trap(n, bound, window, keys) for (n, bound, window), keys in sorted(self._known.items())]
        if lemma is not Lemma.TERMINATION:
            return within_known(space, among, known, self._memo, grow=GROW, lemma=lemma)
        shared = spread_termination(space, among, known, self._memo, GROW)
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
    ) -> bool:
        """Check and cover until nothing is open (``True``) or ``max_checks`` more checks were made.
        Checks run ``workers`` at a time on a local Dask cluster, or on the Dask scheduler at
        ``cluster``; covering runs here, and every finished check is saved before the next."""
        for found in self._checks(max_checks, workers, cluster):
            for line in self.absorb(found):
                if progress:
                    progress(line)
            self.save()
            if progress:
                progress(f"{len(self.checks)} checks, {self.open_count():,} combinations open")
        return self.open_count() == 0

    def _checks(self, max_checks: int | None, workers: int, cluster: str | None) -> Iterator[Found]:
        from ..check.workers import Cluster

        left = max_checks
        with contextlib.ExitStack() as stack:
            dask = None
            if workers > 1 or cluster is not None:
                dask = stack.enter_context(Cluster(workers, cluster)).client
            while left is None or left > 0:
                combos = self.next_combos(max(workers, 1) if left is None else min(max(workers, 1), left))
                if not combos:
                    return
                jobs = [(self.space.model(c), self.bounds, c) for c in combos]
                if dask is None:
                    yield from map(_check_job, jobs)
                else:
                    yield from dask.gather(dask.map(_check_job, jobs, pure=False))  # type: ignore[no-untyped-call]
                if left is not None:
                    left -= len(combos)

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
        return {
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


def sweep_lines(sweep: Sweep) -> list[str]:
    """What ``fatline sweep`` prints: per lemma the headline, then the table and the witnesses."""
    b = sweep.bounds
    lo, hi = b.robots
    robots = str(lo) if lo == hi else f"{lo}..{hi}"
    lines = [
        f"sweep of {sweep.space.base.describe()}",
        f"varied: {', '.join(sweep.space.names)}; each combination checked at robots {robots}, "
        f"window {b.window[0]}x{b.window[1]}" + (f", bound {b.bound[0]}x{b.bound[1]}" if b.bound else ""),
        "",
    ]
    rows = [("lemma", "readings", "refuted", "holds", "inconclusive", "open", "counterexamples")]
    for lemma in sweep.lemmas:
        s = sweep.lemma_summary(lemma)
        rows.append((lemma.value, f"{s['combinations']:,}", f"{s['refuted']:,}", f"{s['holds']:,}",
                     f"{s['inconclusive']:,}", f"{s['open']:,}", str(s["counterexamples"])))  # fmt: skip
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
    for r in rows:
        lines.append(
            "  ".join(c.ljust(w) if k == 0 else c.rjust(w) for k, (c, w) in enumerate(zip(r, widths, strict=True)))
        )
    lines.append("")
    for lemma in sweep.lemmas:
        lines.append(headline(sweep, lemma))
    lines.append("")
    lines.append(f"{len(sweep.checks)} checks, {sweep.replays:,} replays; results in {sweep.json_path}")
    return lines


def headline(sweep: Sweep, lemma: Lemma) -> str:
    """One sentence: refuted under every reading by k counterexamples, or where it survives."""
    s = sweep.lemma_summary(lemma)
    n, k = s["combinations"], s["counterexamples"]
    by = f"by {k} counterexample{'s' if k != 1 else ''}"
    if s["refuted"] == n:
        return f"{lemma.value}: refuted under all {n:,} readings {by}"
    parts = []
    if s["holds"]:
        parts.append(f"holds within bounds under {s['holds']:,}")
    if s["inconclusive"]:
        parts.append(f"inconclusive under {s['inconclusive']:,}")
    if s["refuted"]:
        parts.append(f"refuted under {s['refuted']:,} {by}")
    if s["open"]:
        parts.append(f"{s['open']:,} not judged yet (rerun to go on)")
    return f"{lemma.value}: of {n:,} readings, " + "; ".join(parts)
