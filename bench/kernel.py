"""Benchmark one search step: the fast engine (decode + expand + canonical + encode) against the
compiled engine's ``expand_keys``, on the same frontier keys.

For n = 4, 5, 6 robots (every initial configuration in a 9x9 window, the SPIN anchor's reading, keys in
a 20x20 bound) it walks the state space level by level (after_violation = stop, as the search does)
and times both engines on every level's frontier twice: first with the caches as the level finds them
(new snapshots and pair keys go through the executable model, in both engines), then again with warm
caches (pure engine throughput). Both engines' results are checked equal on every level. Then it
times numba's compilation in fresh interpreters: cold (the compiled engine's on-disk cache deleted)
and warm (the cache present).

    python bench/kernel.py                    # n = 4, 5, 6, the whole state space
    python bench/kernel.py --robots 4 5       # fewer robot counts
    python bench/kernel.py --initial-only     # only the initial frontier of each n
    python bench/kernel.py --no-compile-time  # skip the cold/warm compile measurement
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from fatline_verify.check import compiled  # noqa: E402
from fatline_verify.check.compiled import CompiledEngine, KeyExpansion, distinct  # noqa: E402
from fatline_verify.check.fast import FastEngine  # noqa: E402
from fatline_verify.check.initial import initial_array  # noqa: E402
from fatline_verify.model.config import load_model  # noqa: E402
from fatline_verify.model.lattice import KeyCodec, canonical  # noqa: E402
from fatline_verify.schedulers.systems import system_for  # noqa: E402
from fatline_verify.text import table  # noqa: E402

MODEL = ROOT.parent / "shared" / "anchors" / "spin" / "spin-reading.toml"
BOUND = (20, 20)
WINDOW = (9, 9)
BATCH = 50_000


def fast_step(engine: FastEngine, codec: KeyCodec, keys: np.ndarray) -> KeyExpansion:
    """What the search does per batch with the fast engine, as a :class:`KeyExpansion`."""
    ex = engine.expand(codec.decode(keys))
    canon, _ = canonical(ex.after)
    fits = codec.fits(canon)
    key = np.zeros(len(canon), dtype=np.int64)
    if fits.any():
        key[fits] = codec.encode(canon[fits])
    return KeyExpansion(ex.enabled, ex.goal, ex.src, ex.action, key, ex.flags, fits, ex.exact)


def timed(step: Callable[[np.ndarray], KeyExpansion], keys: np.ndarray) -> tuple[list[KeyExpansion], float]:
    t0 = time.perf_counter()
    out = [step(keys[i : i + BATCH]) for i in range(0, len(keys), BATCH)]
    return out, time.perf_counter() - t0


def joined(parts: list[KeyExpansion], name: str) -> np.ndarray:
    return np.concatenate([getattr(p, name) for p in parts])


def run(n: int, initial_only: bool) -> list[list[str]]:
    model = load_model(MODEL)
    system = system_for(model)
    codec = KeyCodec(n, BOUND)
    fast, comp = FastEngine(system), CompiledEngine(system)
    frontier = distinct(codec.encode(initial_array(n, WINDOW, model)))
    visited = frontier.copy()
    states = transitions = 0
    cold = {"fast": 0.0, "compiled": 0.0}
    warm = {"fast": 0.0, "compiled": 0.0}
    while len(frontier):
        a, cold_fast = timed(lambda k: fast_step(fast, codec, k), frontier)
        b, cold_comp = timed(lambda k: comp.expand_keys(k, codec), frontier)
        _, warm_fast = timed(lambda k: fast_step(fast, codec, k), frontier)
        _, warm_comp = timed(lambda k: comp.expand_keys(k, codec), frontier)
        for name in ("enabled", "goal", "src", "action", "key", "flags", "fits", "exact"):
            assert np.array_equal(joined(a, name), joined(b, name)), f"engines disagree on {name}"
        states += len(frontier)
        transitions += sum(len(p.src) for p in b)
        cold["fast"] += cold_fast
        cold["compiled"] += cold_comp
        warm["fast"] += warm_fast
        warm["compiled"] += warm_comp
        if initial_only:
            break
        key, fits, flags = joined(b, "key"), joined(b, "fits"), joined(b, "flags")
        nxt = distinct(key[fits & (flags == 0)])
        pos = np.minimum(np.searchsorted(visited, nxt), len(visited) - 1)
        nxt = nxt[visited[pos] != nxt]
        visited = np.sort(np.concatenate([visited, nxt]))
        frontier = nxt
    rows = []
    for label, t in (("first pass", cold), ("warm caches", warm)):
        f, c = t["fast"], t["compiled"]
        rows.append(
            [
                f"n={n}",
                label,
                f"{states:,}",
                f"{transitions:,}",
                f"{f:.2f}",
                f"{c:.2f}",
                f"{states / f:,.0f}",
                f"{states / c:,.0f}",
                f"{transitions / f:,.0f}",
                f"{transitions / c:,.0f}",
                f"{f / c:.1f}x",
            ]
        )
    return rows


HEADERS = [
    "robots",
    "caches",
    "states",
    "transitions",
    "fast s",
    "compiled s",
    "fast states/s",
    "compiled states/s",
    "fast trans/s",
    "compiled trans/s",
    "speed-up",
]

PROBE = """
import time
t0 = time.perf_counter()
import numpy as np
from fatline_verify.model.config import load_model
from fatline_verify.check.compiled import CompiledEngine
from fatline_verify.model.lattice import KeyCodec
from fatline_verify.schedulers.systems import system_for
t1 = time.perf_counter()
model = load_model({model!r})
codec = KeyCodec(3, (20, 20))
keys = codec.encode(np.array([[[0, 0], [0, 3], [3, 0]]]))
engine = CompiledEngine(system_for(model))
engine.expand_keys(keys, codec)
engine.expand(codec.decode(keys))
print(t1 - t0, time.perf_counter() - t1)
"""


def compile_times() -> tuple[tuple[float, float], tuple[float, float]]:
    """(import s, first call s) in a fresh interpreter with the on-disk cache deleted, then present."""
    cache = Path(compiled.__file__).parent / "__pycache__"

    def probe() -> tuple[float, float]:
        out = subprocess.run(
            [sys.executable, "-c", PROBE.format(model=str(MODEL))], cwd=ROOT, capture_output=True, text=True, check=True
        )
        a, b = out.stdout.split()
        return float(a), float(b)

    for f in [f for stem in ("compiled", "compiled_common") for f in cache.glob(f"{stem}.*.nb[ic]")]:
        f.unlink()
    cold = probe()
    warm = probe()
    return cold, warm


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robots", type=int, nargs="+", default=[4, 5, 6])
    parser.add_argument("--initial-only", action="store_true")
    parser.add_argument("--no-compile-time", action="store_true")
    args = parser.parse_args()
    if not args.no_compile_time:
        (ci, cc), (wi, wc) = compile_times()
        print(f"numba compile, cold cache: import {ci:.2f} s, first call {cc:.2f} s")
        print(f"numba compile, warm cache: import {wi:.2f} s, first call {wc:.2f} s", flush=True)
    rows: list[list[str]] = []
    CompiledEngine(system_for(load_model(MODEL))).expand_keys(np.zeros(0, dtype=np.int64), KeyCodec(2, BOUND))
    for n in args.robots:
        rows += run(n, args.initial_only)
        print("\n".join(table(HEADERS, rows)[-2:]), flush=True)
    print()
    print("\n".join(table(HEADERS, rows)))


if __name__ == "__main__":
    main()
