"""ASYNC at scale: `fatline check paper-async` end to end, compiled engine next to the fast one.

For each robot count, one `fatline check` process per engine on `models/paper-async.toml` (K = 2 move
steps), initial configurations in the 9x9 window and explored within it, every lemma judged and every
witness replayed. Prints initial configurations, states, transitions, off-lattice successors (a robot
decided on a halfway view and its steps fall between lattice points: counted, not followed), seconds,
bytes a state (the search's arrays / states) and the process's peak memory; and checks that the two
engines' JSON is identical but for the engine's name and the seconds. The load average is printed
with each row: the machine may be shared.

    python bench/async.py                      # n = 4, 5, both engines
    python bench/async.py --robots 6 --engines compiled --max-memory 10G   # n = 6, compiled only
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from scale import run_measured

ROOT = Path(__file__).resolve().parent.parent


def _unnamed(data: object) -> object:
    """``data`` with every ``engine`` field blanked (a witness names the engine that found it)."""
    if isinstance(data, dict):
        return {k: "" if k == "engine" else _unnamed(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_unnamed(v) for v in data]
    return data


def fatline(n: int, engine: str, workdir: Path, max_memory: str, window: str) -> dict[str, object]:
    out = workdir / f"n{n}-{engine}.json"
    cmd = [sys.executable, "-m", "fatline_verify.cli", "check", str(ROOT / "models" / "paper-async.toml")]
    cmd += ["--robots", str(n)]
    cmd += ["--window", window, "--engine", engine, "--max-states", "400000000", "--max-memory", max_memory]
    cmd += ["--json", str(out), "--traces", str(workdir / f"traces-{engine}"), "--force", "-q"]
    wall, peak, _ = run_measured(cmd, workdir)
    data = json.loads(out.read_text())
    search = data["searches"][0]
    for s in data["searches"]:
        s["seconds"], s["engine"] = 0, ""
    for row in data["lemmas"]:  # the witness itself, not where this run wrote it
        if row.get("trace"):
            row["trace"] = _unnamed(json.loads(Path(row["trace"]).read_text()))
    return {
        "initial": search["initial"],
        "states": search["states"],
        "transitions": search["transitions"],
        "off_lattice": search["off_lattice"],
        "truncated": search.get("truncated", False),
        "seconds": wall,
        "peak_mb": peak,
        "bytes_per_state": search.get("bytes", 0) / max(1, search["states"]),
        "json": json.dumps(data, sort_keys=True),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robots", type=int, default=5, help="largest robot count (default 5; from 4)")
    parser.add_argument("--engines", default="compiled,fast", help="engines to run, first one's figures shown")
    parser.add_argument("--max-memory", default="10G", help="passed to fatline check (default 10G)")
    parser.add_argument("--window", default="9x9")
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    from fatline_verify.text import table

    engines = args.engines.split(",")
    heads = ["n", "initial", "states", "transitions", "off-lattice", *(f"{e} s" for e in engines)]
    heads += ["bytes/state", "peak MB", "load"]
    rows = []
    with tempfile.TemporaryDirectory(prefix="fatline-async-") as tmp:
        work = Path(tmp)
        for e in engines:
            fatline(3, e, work, args.max_memory, args.window)  # warm the compiled kernels' cache
        for n in range(4, args.robots + 1):
            runs = {e: fatline(n, e, work, args.max_memory, args.window) for e in engines}
            first = runs[engines[0]]
            for e, r in runs.items():
                assert r["json"] == first["json"], f"n={n}: engine {e} gives other results than {engines[0]}"
            row = [str(n), f"{first['initial']:,}", f"{first['states']:,}", f"{first['transitions']:,}"]
            row += [f"{first['off_lattice']:,}", *(f"{runs[e]['seconds']:.1f}" for e in engines)]
            row += [f"{first['bytes_per_state']:.0f}", f"{first['peak_mb']:.0f}"]
            row += [f"{os.getloadavg()[0]:.1f}" + (" (truncated)" if first["truncated"] else "")]
            rows.append(row)
            print(table(heads, rows)[-1], flush=True)
    print()
    print("\n".join(table(heads, rows)))


if __name__ == "__main__":
    main()
