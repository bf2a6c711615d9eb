"""What the hostile-state tests share (``test_hostile_state.py``, ``test_hostile_runs.py``): the
artefacts they tamper with, a snapshot of a directory, and the one-line refusal they expect."""

from __future__ import annotations

import json
import os
import shutil
import sys
from pathlib import Path

from fatline_verify.cli import main
from fatline_verify.integrity import seal
from fatline_verify.outputs import write_json

ROOT = Path(__file__).resolve().parent.parent
PRECIOUS = b"precious: not an output of fatline\n"
FATLINE = [sys.executable, "-m", "fatline_verify.cli"]

SWEEP_ARGS = ["--vary", "quadrants,path", "--lemma", "connectivity,no-collision", "--robots", "2", "--window", "5x5"]
CHECK_CKPT = ["check", "--robots", "2", "--checkpoint", "ck", "--traces", "t2", "-q"]
SWEEP_AGAIN = ["sweep", *SWEEP_ARGS, "--out", "sw", "--max-checks", "0", "-q"]
REPORT = ["report", "paper", "--out", "reports", "--proofs", "proofs", "-q"]
PROVE = ["prove", "paper", "--lemma", "no-collision", "--redo-inconclusive", "--out", "proofs", "-q"]
RESULTS = "proofs/paper/results.json"


def snapshot(root: Path) -> dict[str, bytes | str | None]:
    """Every path below ``root``: a file's bytes, a link's target, None for a directory."""
    out: dict[str, bytes | str | None] = {}
    for path in sorted(root.rglob("*")):
        key = str(path.relative_to(root))
        if path.is_symlink():
            out[key] = f"-> {os.readlink(path)}"
        elif path.is_file():
            out[key] = path.read_bytes()
        elif path.is_dir():
            out[key] = None
        else:
            out[key] = "special"
    return out


def refused(capsys, argv: list[str], fragment: str) -> str:
    """Run ``argv``: exit 2, one line naming ``fragment``, nothing on stdout; the line."""
    code = main(argv)
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out, err)
    assert len(lines) == 1, err
    assert lines[0].startswith("fatline: error: "), lines[0]
    assert "internal error" not in err and "Traceback" not in err
    assert fragment.lower() in lines[0].lower(), lines[0]
    assert len(lines[0]) < 1100, lines[0][:300]
    for verdict in ("VIOLATED", "HOLDS_WITHIN_BOUNDS", "PROVED"):
        assert verdict not in out, out  # never a verdict from a file that lies
    return lines[0]


def make_artefacts(root: Path) -> Path:
    """In ``root``: a checkpoint (``ck``) and a sweep (``sw``) made by the tool itself, and copies of the
    committed prover results and report cache, as written before digests (``legacy``) and as the tool
    writes them now, with their digest (``sealed``)."""
    old = Path.cwd()
    os.chdir(root)
    try:
        assert main(CHECK_CKPT) == 1  # two robots: the default readings break connectivity
        assert main(["sweep", *SWEEP_ARGS, "--out", "sw", "-q"]) == 1
    finally:
        os.chdir(old)
    # the committed prover results and report cache, as written before digests (legacy) ...
    shutil.copytree(ROOT / "proofs" / "paper", root / "legacy" / "proofs" / "paper")
    (root / "legacy" / "reports" / "paper").mkdir(parents=True)
    shutil.copyfile(ROOT / "reports" / "paper" / "check.json", root / "legacy" / "reports" / "paper" / "check.json")
    for path in (  # the committed files may carry a digest since a later save: legacy ones have none
        root / "legacy" / "proofs" / "paper" / "results.json",
        root / "legacy" / "reports" / "paper" / "check.json",
    ):
        write_json(path, {k: v for k, v in json.loads(path.read_text()).items() if k != "digest"})
    (root / "legacy" / "reports" / "traces").mkdir()
    for trace in (ROOT / "reports" / "traces").glob("paper-*.json"):
        if trace.name.startswith(("paper-check-", "paper-prove-")):
            shutil.copyfile(trace, root / "legacy" / "reports" / "traces" / trace.name)
    # ... and as the tool writes them now, with their digest
    shutil.copytree(root / "legacy", root / "sealed")
    for path in (
        root / "sealed" / "proofs" / "paper" / "results.json",
        root / "sealed" / "reports" / "paper" / "check.json",
    ):
        write_json(path, seal(json.loads(path.read_text())))
    return root
