"""What the plug-in tests share: where the installed packages are, and the CLI run in a fresh interpreter
with them on its path (or without them)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
SITE = HERE / "site"
"""Where the toy plug-in package is installed (its code and its ``.dist-info`` with the entry point)."""
USERS = HERE / "users"
"""The rule sets a new user might write, as another installed package."""
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
