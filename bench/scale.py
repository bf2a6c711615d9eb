"""Scale benchmark: `fatline check` end to end next to SPIN on the same state space.

For each robot count, one `fatline check` process on the SPIN anchor's reading
(`../shared/anchors/spin/spin-reading.toml`), initial configurations in the 9x9 window, explored within
a bound nothing escapes from (20x20, checked: escaped = 0), every lemma judged and every witness
replayed. Prints initial configurations, states, transitions, seconds, states/s, bytes a state (what
the search keeps / states: the compact store's key, parent, action, enabled, goal) and the process's
peak memory; and, when `spin` and `gcc` are on the PATH, SPIN's whole pipeline (generate, spin -a,
gcc, pan) on the same state space, measured in the same run (up to `--spin-robots`, default 7: SPIN
at n = 8 needs an estimated 17 GB). Every fatline run starts with no answers kept (a fresh
`FATLINE_ANSWERS` directory: as a first run); `warm s` is a second run of the same n with the answers
the first one kept (fatline_verify/check/answers.py), for n up to `--warm-robots` (default 6).
`--workers 2` adds a column with the search shared by two Dask workers and the speed-up.

    python bench/scale.py                  # n = 4, 5, 6
    python bench/scale.py --robots 7       # n = 4..7 (n = 7 takes minutes)
    python bench/scale.py --workers 2      # also with two worker processes
    python bench/scale.py --robots 8 --max-memory 15G   # n = 8: 72-bit states, ranked keys
    python bench/scale.py --robots 8 --max-memory 15G --keep runs/   # and keep each check's JSON
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ANCHOR = ROOT.parent / "shared" / "anchors" / "spin"
BOUND = "20x20"


def run_measured(
    cmd: list[str], cwd: Path, env: dict[str, str] | None = None, ok: tuple[int, ...] = (0, 1, 3)
) -> tuple[float, float, str]:
    """Wall seconds, peak RSS in MB (of the process tree, via /usr/bin/time when present) and stdout."""
    timer = shutil.which("time") or ("/usr/bin/time" if Path("/usr/bin/time").exists() else None)
    stats = cwd / "time.out"
    full = [timer, "-f", "%e %M", "-o", str(stats), *cmd] if timer else cmd
    t0 = time.perf_counter()
    out = subprocess.run(full, cwd=cwd, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    peak = float(stats.read_text().split()[-1]) / 1024 if timer and stats.exists() else float("nan")
    if out.returncode not in ok:
        sys.exit(f"{cmd[0]} failed ({out.returncode}): {out.stderr.strip()[-400:]}")
    return wall, peak, out.stdout


def fatline(
    n: int, workdir: Path, workers: int, answers: Path, max_memory: str | None = None, keep: Path | None = None
) -> dict[str, float]:
    out = workdir / f"n{n}-w{workers}.json"
    cmd = [sys.executable, "-m", "fatline_verify.cli", "check", str(ANCHOR / "spin-reading.toml"), "--robots", str(n)]
    cmd += ["--window", "9x9", "--bound", BOUND, "--max-states", "400000000", "--workers", str(workers)]
    cmd += ["--json", str(out), "--traces", str(workdir / "traces"), "--force", "-q"]
    cmd += ["--max-memory", max_memory] if max_memory else []
    env = dict(os.environ, FATLINE_ANSWERS=str(answers))
    wall, peak, _ = run_measured(cmd, workdir, env)
    if keep is not None:  # the check's JSON, for comparing runs (--workers, a resumed run) field by field
        shutil.copyfile(out, keep / out.name)
    search = json.loads(out.read_text())["searches"][0]
    assert search["escaped"] == 0, f"n={n}: {search['escaped']} successors escape {BOUND}; raise BOUND"
    return {
        "initial": search["initial"],
        "states": search["states"],
        "transitions": search["transitions"],
        "seconds": wall,
        "peak_mb": peak,
        "bytes_per_state": search.get("bytes", 0) / max(1, search["states"]),
        "verdicts": {row["lemma"]: row["verdict"] for row in json.loads(out.read_text())["lemmas"]},
    }


def spin(n: int, workdir: Path) -> dict[str, float] | None:
    """SPIN's whole pipeline for n robots (None when spin or gcc is missing)."""
    if not (shutil.which("spin") and shutil.which("gcc")) or not ANCHOR.exists():
        return None
    env = dict(os.environ, W="9", REPS="1", WORK=str(workdir / "spin"))
    if n >= 7:  # the configuration index needs wider digits to fit a Promela int
        env["B"] = "64"
    if n >= 6:  # a hash table large enough for the state count (the anchor's README)
        env["PANFLAGS"] = "-c0 -m10000 -w24" if n == 6 else "-c0 -m10000 -w27"
    wall, _, out = run_measured(["bash", str(ANCHOR / "run_spin.sh"), str(n)], workdir, env)
    row = next(line.split() for line in out.splitlines() if re.match(r"^dfs\s+\d", line))
    if not row[3].isdigit():
        print(f"n={n}: the SPIN pipeline failed ({' '.join(row[3:])})", file=sys.stderr)
        return None
    states = int(row[3]) - 1  # SPIN's "states stored" counts its start state
    return {"states": states, "seconds": wall, "pan_seconds": float(row[10]), "peak_mb": float(row[12])}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robots", type=int, default=6, help="largest robot count (default 6)")
    parser.add_argument("--workers", type=int, default=1, help="also measure with this many Dask workers")
    parser.add_argument("--spin-robots", type=int, default=7, help="run SPIN up to this robot count (default 7)")
    parser.add_argument("--warm-robots", type=int, default=6, help="a second run with kept answers up to this n")
    parser.add_argument("--max-memory", default=None, help="fatline's --max-memory (default: its own)")
    parser.add_argument("--keep", type=Path, default=None, help="copy each first run's JSON (nN-wW.json) here")
    args = parser.parse_args()
    if args.keep is not None:
        args.keep.mkdir(parents=True, exist_ok=True)
    sys.path.insert(0, str(ROOT))
    from fatline_verify.text import table

    heads = ["n", "initial", "states", "transitions", "fatline s", "warm s", "states/s", "bytes/state", "peak MB"]
    heads += ["SPIN s (pan s)", "SPIN peak MB", "SPIN / fatline"]
    if args.workers > 1:
        heads += [f"{args.workers} workers s", "speed-up"]
    rows = []
    with tempfile.TemporaryDirectory(prefix="fatline-bench-") as tmp:
        work = Path(tmp)
        fatline(3, work, 1, work / "answers-3")  # warm the compiled kernels' cache (numba's, not the answers)
        for n in range(4, args.robots + 1):
            ours = fatline(n, work, 1, work / f"answers-{n}", args.max_memory, args.keep)
            warm = fatline(n, work, 1, work / f"answers-{n}", args.max_memory) if n <= args.warm_robots else None
            if warm is not None:
                assert (warm["states"], warm["verdicts"]) == (ours["states"], ours["verdicts"])
            theirs = spin(n, work) if n <= args.spin_robots else None
            row = [str(n), f"{ours['initial']:,}", f"{ours['states']:,}", f"{ours['transitions']:,}"]
            row += [f"{ours['seconds']:.2f}", f"{warm['seconds']:.2f}" if warm else "-"]
            row += [f"{ours['states'] / ours['seconds']:,.0f}"]
            row += [f"{ours['bytes_per_state']:.0f}", f"{ours['peak_mb']:.0f}"]
            if theirs:
                same = "" if theirs["states"] == ours["states"] else f" (SPIN: {theirs['states']:,} states!)"
                row += [f"{theirs['seconds']:.2f} ({theirs['pan_seconds']:.2f}){same}", f"{theirs['peak_mb']:.0f}"]
                row += [f"{theirs['seconds'] / ours['seconds']:.2f}x"]
            else:
                row += ["(not run)" if n > args.spin_robots else "(spin not installed)", "-", "-"]
            if args.workers > 1:
                par = fatline(n, work, args.workers, work / f"answers-{n}-w", args.max_memory, args.keep)
                assert (par["states"], par["verdicts"]) == (ours["states"], ours["verdicts"])
                row += [f"{par['seconds']:.2f}", f"{ours['seconds'] / par['seconds']:.2f}x"]
            rows.append(row)
            print(table(heads, rows)[-1], " ".join(f"{k}={v}" for k, v in ours["verdicts"].items()), flush=True)
    print()
    print("\n".join(table(heads, rows)))


if __name__ == "__main__":
    main()
