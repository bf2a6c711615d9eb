"""``fatline check``: every lemma, every small swarm, every activation set, within stated bounds.

For each robot count the checker enumerates the initial configurations, explores every reachable
canonical state breadth-first, and gives each lemma a verdict: VIOLATED with a shortest witness
that has been replayed by the executable model, HOLDS_WITHIN_BOUNDS with the bounds and counts, or
INCONCLUSIVE with the reason. The engine never prints; progress goes through a callback.
"""

from __future__ import annotations

import re
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from fractions import Fraction
from math import isqrt
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InvalidInput
from ..lemmas.properties import Lemma, LemmaResult, Verdict
from ..lemmas.registry import StepLemma, judged
from ..model.config import Model
from ..model.lattice import KeyCodec, RankedCodec
from ..model.numbers import format_number
from ..outputs import Kind, child
from ..resources import default_max_memory, format_size
from ..rules.registry import applies as rule_lemmas
from ..schedulers.base import ENGINES, unknown_engine
from ..schedulers.systems import system_for
from . import keys as keyset
from .checkpoint import claim_checkpoint
from .engines import engine_for
from .exploration import Exploration
from .initial import initial_array, initial_keys
from .offlattice import OffLattice
from .search import explore_keys
from .verdicts import lemma_verdicts
from .workers import Cluster, require_dask

ProgressFn = Callable[[str, int, int, str], None]
"""``progress(stage, done, total, note)``: the stage (robot count and BFS level), states of the level's
frontier expanded so far, the frontier's size, and a note (states found so far)."""

CHECKER_VERSION = 2
"""Bumped whenever the checker's semantics change (part of the report cache's fingerprint)."""


@dataclass(frozen=True, slots=True)
class SearchStats:
    """The size of one robot count's search."""

    robots: int
    window: tuple[int, int]
    engine: str
    initial: int
    states: int
    transitions: int
    escaped: int
    violating_only: int
    off_lattice: int
    truncated: bool
    seconds: float
    bound: tuple[int, int] | None = None
    """The exploration bound (``None``: the window)."""
    nbytes: int = 0
    """Bytes held by the search's arrays at the end."""
    asked: str = ""
    """The engine asked for, when another made the search (a decision off the lattice: ``scalar``)."""


@dataclass(frozen=True, slots=True)
class CheckResult:
    """Every lemma's verdict for every robot count, with the search sizes."""

    model: Model = field(repr=False)
    window: tuple[int, int]
    max_states: int | None
    """``None``: the memory budget was the only limit."""
    after_violation: str
    stats: tuple[SearchStats, ...]
    results: tuple[LemmaResult, ...]
    complete: bool = True
    """False when the run was interrupted: only the robot counts in ``stats`` were searched."""
    bound: tuple[int, int] | None = None
    max_memory: int = 0

    @property
    def any_violated(self) -> bool:
        return any(r.verdict is Verdict.VIOLATED for r in self.results)

    @property
    def any_inconclusive(self) -> bool:
        return any(r.verdict is Verdict.INCONCLUSIVE for r in self.results)


def validate_bounds(
    model: Model,
    robots: tuple[int, int],
    window: tuple[int, int],
    max_states: int | None,
    engine: str = "fast",
    bound: tuple[int, int] | None = None,
) -> None:
    """Reject bounds no search can meet, naming the value."""
    bound = window if bound is None else bound
    if engine in ("fast", "compiled") and max(bound) > 128:
        raise InvalidInput(
            f"bound={bound[0]}x{bound[1]}: the fast engine packs offsets in 8 bits; expected at most 128x128 "
            "or --engine scalar"
        )
    if max_states is not None and max_states < 1:
        raise InvalidInput(f"max-states={max_states}: expected a positive number of states")
    w, h = window
    if w < 1 or h < 1:
        raise InvalidInput(f"window={w}x{h}: expected a positive width and height")
    if bound[0] < w or bound[1] < h:
        raise InvalidInput(
            f"bound={bound[0]}x{bound[1]}: expected at least the window {w}x{h} (the bound limits exploration, "
            "the window the initial configurations)"
        )
    system = system_for(model)
    for n in range(robots[0], robots[1] + 1):
        try:
            if isinstance(system.codec(n, bound), RankedCodec):
                try:
                    KeyCodec(n, window)  # the initial configurations are enumerated packed, then ranked
                except ValueError:
                    raise InvalidInput(
                        f"window={w}x{h} with robots={n}: the initial configurations do not pack into 63 bits; "
                        "expected a smaller window or fewer robots"
                    ) from None
        except ValueError:
            what = "window" if bound == window else "bound"
            bw, bh = bound
            raise InvalidInput(
                f"{what}={bw}x{bh} with robots={n}: a state does not pack or rank into 63 bits; "
                f"expected a smaller {what} "
                "or fewer robots"
            ) from None


MAX_VIEW_OFFSETS = 1_000_000
"""The initial enumeration keeps one entry per lattice offset a robot sees; past this many, refuse."""


def validate_resources(model: Model, robots: tuple[int, int], window: tuple[int, int]) -> None:
    """Refuse, before any work, a search whose lattice cannot fit in memory or that has nothing to search."""
    reach = isqrt(model.view2)
    offsets = (2 * reach + 1) ** 2
    if offsets > MAX_VIEW_OFFSETS:
        p = model.parameters
        q0 = Fraction(p.rad_v).denominator  # the coarsest lattice rad_v is whole on
        coarse = isqrt(model.with_q(q0).view2) if p.q > q0 else reach
        if p.q > q0 and (2 * coarse + 1) ** 2 <= MAX_VIEW_OFFSETS:  # the lattice is too fine: q is the knob
            raise InvalidInput(
                f"q={p.q}: a robot sees {offsets:,} lattice offsets (rad_v={format_number(p.rad_v)}, q={p.q}), more "
                f"than {MAX_VIEW_OFFSETS:,} fit in memory; expected a smaller --q"
            )
        raise InvalidInput(  # even one lattice point per radius is too fine: the visibility radius is the knob
            f"rad_v={format_number(p.rad_v)}: a robot sees {offsets:,} lattice offsets (q={p.q}), more than "
            f"{MAX_VIEW_OFFSETS:,} fit in memory; expected a smaller rad_v in the model"
        )
    w, h = window
    if robots[1] >= 2 and (w - 1) ** 2 + (h - 1) ** 2 < model.apart2:
        raise InvalidInput(
            f"window={w}x{h}: no two robots fit at distance >= delta={format_number(model.parameters.delta)} "
            f"({model.parameters.q} lattice points per radius); expected a larger --window"
        )


def guard_starts(
    model: Model, robots: tuple[int, int], window: tuple[int, int], budget: int, per_start: int, budget_name: str
) -> None:
    """Refuse, before any work, robot counts whose initial configurations alone would need more than
    ``budget`` bytes at ``per_start`` bytes each (counted, not enumerated, and only up to the budget)."""
    from .initial import count_initial

    cap = max(1, budget // per_start)
    for n in range(robots[0], robots[1] + 1):
        found = count_initial(n, window, model, cap)
        if found > cap:
            raise InvalidInput(
                f"robots={n} window={window[0]}x{window[1]}: more than {found:,} initial configurations, at least "
                f"{format_size(found * per_start)} of memory, beyond {format_size(budget)} ({budget_name}); expected "
                "fewer robots or a smaller --window"
            )


def check(
    model: Model,
    robots: tuple[int, int] | None = None,
    window: tuple[int, int] | None = None,
    *,
    progress: ProgressFn | None = None,
    **settings: Any,
) -> CheckResult:
    """Check every lemma for every robot count in ``robots`` (bounds default to the model's; ``settings``
    as :meth:`CheckPlan.of`)."""
    plan = CheckPlan.of(model, robots, window, **settings)
    return plan.result(list(plan.searches(progress)))


@dataclass(frozen=True, slots=True)
class CheckPlan:
    """A validated check: the model and its bounds, run one robot count at a time (so an interrupted
    run keeps the counts it finished)."""

    model: Model
    robots: tuple[int, int]
    window: tuple[int, int]
    max_states: int | None
    """``None``: the memory budget is the only limit."""
    engine: str
    after_violation: str
    bound: tuple[int, int] | None = None
    """The exploration bound; ``None``: the window."""
    max_memory: int = 0
    """Bytes the search's arrays may hold (0: no limit)."""
    workers: int = 1
    cluster: str | None = None
    checkpoint: Path | None = None

    @classmethod
    def of(
        cls,
        model: Model,
        robots: tuple[int, int] | None = None,
        window: tuple[int, int] | None = None,
        max_states: int | None = None,
        engine: str | None = None,
        after_violation: str = "stop",
        *,
        bound: tuple[int, int] | None = None,
        max_memory: int | None = None,
        workers: int = 1,
        cluster: str | None = None,
        checkpoint: Path | None = None,
    ) -> CheckPlan:
        """Fill the model's default bounds and reject what no search can meet, before any work.
        ``max_memory`` defaults to a share of the machine, ``max_states`` to the model's or else to what
        ``max_memory`` affords, ``engine`` to the system's fastest."""
        robots = model.bounds.robots if robots is None else robots
        window = model.bounds.window if window is None else window
        if bound == window:
            bound = None
        max_memory = default_max_memory() if max_memory is None else max_memory
        if max_states is None:
            max_states = model.bounds.max_states
        engine = system_for(model).default_engine if engine is None else engine
        if engine not in ENGINES:
            raise unknown_engine(engine)
        if workers < 1:
            raise InvalidInput(f"workers={workers}: expected a positive number of worker processes")
        if cluster is not None and not re.fullmatch(r"(tcp|tls|ucx)://[A-Za-z0-9_.\-\[\]:]+:\d+", cluster):
            raise InvalidInput(f"cluster={cluster!r}: expected a Dask scheduler address like tcp://HOST:PORT")
        if workers > 1 or cluster is not None:
            require_dask(f"workers={workers}" if cluster is None else f"cluster={cluster!r}")
        engine_for(system_for(model), engine)  # a system without this engine refuses it here, before any work
        validate_bounds(model, robots, window, max_states, engine, bound)
        validate_resources(model, robots, window)
        if max_memory:  # the initial keys, 8 bytes each, are held before the memory guard of the search
            guard_starts(model, robots, window, max_memory, 8, "--max-memory")
        if checkpoint is not None:
            claim_checkpoint(checkpoint, range(robots[0], robots[1] + 1))
        return cls(
            model, robots, window, max_states, engine, after_violation, bound, max_memory, workers, cluster,
            checkpoint,
        )  # fmt: skip

    @property
    def counts(self) -> range:
        return range(self.robots[0], self.robots[1] + 1)

    def searches(self, progress: ProgressFn | None = None) -> Iterator[tuple[SearchStats, list[LemmaResult]]]:
        """One finished search per robot count, smallest first (on one Dask cluster for all of them)."""
        if self.workers == 1 and self.cluster is None:
            for n in self.counts:
                yield check_robots(self, n, None, progress)
            return
        with Cluster(self.workers, self.cluster) as cluster:
            for n in self.counts:
                yield check_robots(self, n, cluster, progress)

    def result(self, done: list[tuple[SearchStats, list[LemmaResult]]]) -> CheckResult:
        """The result of the searches in ``done`` (all of them, or those finished before an interrupt)."""
        stats = tuple(s for s, _ in done)
        results = tuple(r for _, rs in done for r in rs)
        complete = len(done) == len(self.counts)
        return CheckResult(
            self.model,
            self.window,
            self.max_states,
            self.after_violation,
            stats,
            results,
            complete,
            self.bound,
            self.max_memory,
        )


def initial_keys_for(system: Any, n: int, window: tuple[int, int], codec: Any) -> np.ndarray:
    """The sorted keys (in ``codec``) of every initial configuration of ``n`` robots in ``window``."""
    model = system.model
    if system.fields == 2 and isinstance(codec, RankedCodec):
        return _ranked_initial_keys(n, window, model, codec)
    if system.fields == 2 and isinstance(codec, KeyCodec):
        return initial_keys(n, window, model, codec)
    states = initial_array(n, window, model)
    return keyset.sort(codec.encode(system.initial(states))) if len(states) else np.zeros(0, dtype=codec.dtype)


def _ranked_initial_keys(n: int, window: tuple[int, int], model: Model, codec: RankedCodec) -> np.ndarray:
    """The initial keys in a ranked codec: enumerated packed in the window's own codec (which must pack),
    then ranked a million at a time, and sorted."""
    small = KeyCodec(n, window)
    keys = initial_keys(n, window, model, small)
    for start in range(0, len(keys), 1 << 20):
        part = keys[start : start + (1 << 20)]
        keys[start : start + len(part)] = codec.encode(small.decode(part))
    keys.sort()
    return keys


def check_robots(
    plan: CheckPlan, n: int, cluster: Cluster | None = None, progress: ProgressFn | None = None
) -> tuple[SearchStats, list[LemmaResult]]:
    """Explore every execution of ``n`` robots under ``plan`` and give every lemma its verdict."""
    t0 = time.perf_counter()
    ex = explore_robots(plan, n, cluster, progress)
    results = lemma_verdicts(ex)
    stats = SearchStats(
        n,
        plan.window,
        ex.engine,
        ex.n_initial,
        ex.n_states,
        ex.n_transitions,
        ex.escaped,
        ex.violating_only,
        ex.off_lattice,
        ex.truncated,
        time.perf_counter() - t0,
        plan.bound,
        ex.nbytes,
        "" if ex.engine == plan.engine else plan.engine,
    )
    return stats, results


def kernels_cached(engine: str, family: str = "rounds") -> bool:
    """Whether the numba kernels a search with ``engine`` over a system of ``family`` runs are compiled
    in this process or cached on disk for this source (so no compile comes first); ``True`` where
    numba cannot tell."""
    from . import compiled, compiled_async, cycles, hashtable, initial, keys

    def own(module: Any) -> list[Any]:
        """The module's own kernels (one imported from another is compiled into its callers there)."""
        return [
            v
            for v in vars(module).values()
            if getattr(getattr(v, "py_func", None), "__module__", None) == module.__name__
        ]

    kernels = own(initial) + own(cycles)  # cycles: the fair-cycle search, after the exploration
    if engine == "compiled":
        kernels += own(hashtable) + own(compiled) + (own(compiled_async) if family == "async" else [])
    if family == "async":  # keys past 63 bits (n >= 4 in 9x9), whatever the engine
        kernels += [keys._argsort, keys._bisect, keys._walk, keys._ascending]
    try:
        for value in kernels:
            cache = getattr(value, "_cache", None)
            if not hasattr(value, "signatures") or cache is None or value.signatures:
                continue
            if getattr(value, "targetoptions", {}).get("inline") == "always":
                continue  # compiled into its callers only
            if not cache._cache_file._load_index():
                return False
    except Exception:  # numba's cache layout is not an API: no message rather than a wrong one
        return True
    return True


def explore_robots(
    plan: CheckPlan, n: int, cluster: Cluster | None = None, progress: ProgressFn | None = None
) -> Exploration:
    """Every execution of ``n`` robots under ``plan``: the explored transition system."""
    model, window = plan.model, plan.window
    bound = plan.bound or window
    system = system_for(model)
    codec = system.codec(n, bound)
    compiling = progress is not None and not kernels_cached(plan.engine, system.family)
    if progress:
        # A first run compiles the numba kernels (seconds to a minute, once: they are cached); a stage
        # that says so stands until the first level's first batch, which the compile precedes.
        what = "compiling kernels, first run only" if compiling else "enumerating initial configurations in"
        progress(f"n={n}: {what} {window[0]}x{window[1]}" if not compiling else f"n={n}: {what}", 0, 0, "")
    initial = initial_keys_for(system, n, window, codec)
    if progress and not compiling:
        progress(f"n={n}: {len(initial):,} initial configurations", len(initial), len(initial), "")
    if not len(initial):
        raise InvalidInput(
            f"robots={n} window={window[0]}x{window[1]}: no initial configuration fits (pairwise distance >= delta "
            "and connected); expected a larger window"
        )
    tick = None
    if progress is not None:
        report = progress
        started = time.perf_counter()

        def tick(level: int, done: int, frontier: int, states: int) -> None:
            rate = states / max(time.perf_counter() - started, 1e-9)
            report(f"n={n}: level {level}", done, frontier, f"{states:,} states, {rate:,.0f} states/s")

    def search(engine: str) -> Exploration:
        pool = None if cluster is None else cluster.shards(system, n, bound, engine, plan.after_violation)
        try:
            return explore_keys(
                system,
                n,
                initial,
                bound,
                engine,
                max_states=plan.max_states,  # None: the memory budget is the only limit
                max_bytes=plan.max_memory or None,
                after_violation=plan.after_violation,
                progress=tick,
                pool=pool,
                checkpoint=None if plan.checkpoint is None else plan.checkpoint / f"n{n}",
                initial_window=window,
            )
        finally:
            if pool is not None:
                pool.close()

    try:
        return search(plan.engine)
    except OffLattice as off:
        if plan.engine == "scalar":  # pragma: no cover - the scalar engine never packs moves
            raise
        if progress is not None:
            progress(f"n={n}: {off}; continuing on the scalar engine", 0, 0, "")
        return search("scalar")  # the exploration's engine says which engine made it


def witness_path(directory: Path, prefix: str, lemma: Lemma | StepLemma, robots: int) -> Path:
    """Where :func:`write_witnesses` puts the witness of ``lemma`` for ``robots`` robots."""
    return child(directory, f"{prefix}{lemma.value}-n{robots}", ".json")


def witness_paths(plan: CheckPlan, directory: Path, prefix: str) -> list[Path]:
    """Every file a check of ``plan`` may write into ``directory`` (checked before the run)."""
    lemmas: tuple[Lemma | StepLemma, ...] = (*rule_lemmas(plan.model), *judged(plan.model))
    return [witness_path(directory, prefix, lemma, n) for n in plan.counts for lemma in lemmas]


def write_witnesses(result: CheckResult, directory: Path, prefix: str) -> dict[tuple[str, int], str]:
    """Write every witness as ``DIRECTORY/PREFIX<lemma>-n<robots>.json``; the paths by (lemma, robots)."""
    from ..trace.traces import write_trace

    paths = {}
    for r in result.results:
        if r.witness is not None:
            path = witness_path(directory, prefix, r.lemma, r.robots)
            write_trace(r.witness, path)
            paths[(r.lemma.value, r.robots)] = path.as_posix()
    return paths


def check_fingerprint(model: Model) -> str:
    """What a check result at the model's own bounds depends on: the model, the checker's version,
    the registered lemmas' versions and the sources of the plug-ins that decide for the model
    (:func:`fatline_verify.provenance.plugin_settings`). This package's own sources are not in it (a
    change of the checker's results bumps ``CHECKER_VERSION``), so a built-in model's fingerprint,
    and the committed ``reports/*/check.json``, stay as they were while no plug-in is installed."""
    from ..cache import fingerprint
    from ..provenance import plugin_settings

    extras = {lemma.name: lemma.version for lemma in judged(model)}
    return fingerprint(
        model, "check", engine=CHECKER_VERSION, **({"lemmas": extras} if extras else {}), **plugin_settings(model)
    )


def check_to_json(result: CheckResult, paths: dict[tuple[str, int], str]) -> dict[str, Any]:
    """The check result as plain data (``--json``, the report's cache)."""
    from ..model.config import model_to_mapping

    return {
        "format": Kind.CHECK.value,
        "complete": result.complete,
        "model": model_to_mapping(result.model),
        "window": list(result.window),
        **({"bound": list(result.bound)} if result.bound is not None else {}),
        "max_states": result.max_states,
        "after_violation": result.after_violation,
        "searches": [
            {
                "robots": s.robots,
                "initial": s.initial,
                "states": s.states,
                "transitions": s.transitions,
                "escaped": s.escaped,
                "violating_only": s.violating_only,
                "off_lattice": s.off_lattice,
                "truncated": s.truncated,
                "seconds": round(s.seconds, 3),
                "bytes": s.nbytes,
                "engine": s.engine,
            }
            for s in result.stats
        ],
        "lemmas": [
            {
                "lemma": r.lemma.value,
                "robots": r.robots,
                "verdict": r.verdict.value,
                "reason": r.reason,
                "witness_rounds": r.witness_rounds,
                "trace": paths.get((r.lemma.value, r.robots)),
            }
            for r in result.results
        ],
    }


__all__ = ["CheckResult", "SearchStats", "check", "check_robots", "lemma_verdicts"]
