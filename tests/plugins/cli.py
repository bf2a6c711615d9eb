"""What the plug-in tests share: where the installed packages are, and the CLI run in a fresh interpreter
with them on its path (or without them)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
SITE = HERE / "site"
"""Where the toy plug-in package is installed (its code and its ``.dist-info`` with the entry point)."""
USERS = HERE / "users"
"""The rule sets a new user might write, as another installed package."""
OPTIONED = HERE / "optioned"
"""A rule set with an option of its own (``turn-step``: its option ``turn``), as another installed package."""
MODEL = HERE / "toy-step.toml"
PAIRS = HERE / "pairs.toml"
"""The paper's rules under the toy scheduler: one or two robots a round."""
LEMMAS = ("connectivity", "no-collision", "progress", "rma-fixed", "approach", "termination")
TOY_DIST = {"distribution": "toy-fatline-plugin", "version": "0.1"}
"""What ``importlib.metadata`` says of the toy package (its ``.dist-info``)."""


def fatline(*argv: str, cwd: Path | None = None, sites: tuple[Path, ...] = (SITE,)) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter that has the plug-in packages ``sites`` installed (on its path)."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([*map(str, sites), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=cwd
    )


def without_plugin(*argv: str, cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh interpreter without the plug-in packages."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    return subprocess.run(
        [sys.executable, "-m", "fatline_verify.cli", *argv], capture_output=True, text=True, env=env, cwd=cwd
    )


Evidence = tuple[list[dict[str, Any]], dict[tuple[str, int], tuple[Any, ...]], dict[str, str]]
"""What a check shows: its searches (timings left out), its rows by (lemma, robots), its traces' text by name."""


def evidence_with_and_without(model: str, robots: str, tmp_path: Path) -> dict[str, Evidence]:
    """``fatline check MODEL --robots ROBOTS`` without and with the toy package installed (``"without"``,
    ``"with"``): what each shows (every run finds a violation: exit 1)."""
    runs = {}
    for name, site in (("without", None), ("with", SITE)):
        out, traces = tmp_path / f"{name}.json", tmp_path / name
        argv = ["check", model, "--robots", robots, "--json", str(out), "--traces", str(traces), "-q"]
        got = fatline(*argv, cwd=ROOT) if site is not None else without_plugin(*argv)
        assert got.returncode == 1, got.stderr
        data = json.loads(out.read_text())
        searches = [{k: v for k, v in s.items() if k not in ("seconds", "bytes")} for s in data["searches"]]
        rows = {(r["lemma"], r["robots"]): (r["verdict"], r["reason"], r["witness_rounds"]) for r in data["lemmas"]}
        runs[name] = (searches, rows, {p.name: p.read_text() for p in traces.glob("*.json")})
    return runs
