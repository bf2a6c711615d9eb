"""Hostile state: saved files that cannot lie, concurrent runs that lose nothing, no hang and no internal
error on hostile input (issue 29).

Every refusal is one line ``fatline: error: ...`` on stderr, exit 2, no verdict on stdout, and every
file that existed before the command is byte-identical after it. The artefacts tampered with are made
once per module (a checkpoint and a sweep by the tool itself; copies of the committed prover results
and report cache, as written before digests and as the tool writes them now, with their digest).
"""

from __future__ import annotations

import errno
import io
import json
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.cli import main
from fatline_verify.integrity import bytes_digest, seal
from fatline_verify.locks import holding
from fatline_verify.outputs import write_json

ROOT = Path(__file__).resolve().parent.parent
PRECIOUS = b"precious: not an output of fatline\n"
FATLINE = [sys.executable, "-m", "fatline_verify.cli"]

SWEEP_ARGS = ["--vary", "quadrants,path", "--lemma", "connectivity,no-collision", "--robots", "2", "--window", "5x5"]
CHECK_CKPT = ["check", "--robots", "2", "--checkpoint", "ck", "--traces", "t2", "-q"]
SWEEP_AGAIN = ["sweep", *SWEEP_ARGS, "--out", "sw", "--max-checks", "0", "-q"]
REPORT = ["report", "paper", "--out", "reports", "--proofs", "proofs", "-q"]
PROVE = ["prove", "paper", "--lemma", "no-collision", "--redo-inconclusive", "--out", "proofs", "-q"]


def _snapshot(root: Path) -> dict[str, bytes | str | None]:
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


def _refused(capsys, argv: list[str], fragment: str) -> str:
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


# --- the artefacts, made once ---------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def made(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("made")
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


def _json_edit(path: Path, change: Callable[[dict], None], *, reseal: bool) -> None:
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(seal(data) if reseal else data, indent=1) + "\n")


def _npz_edit(path: Path, change: Callable[[dict[str, np.ndarray]], None]) -> None:
    with np.load(path) as saved:
        arrays = {k: saved[k].copy() for k in saved.files}
    change(arrays)
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)
    path.write_bytes(buffer.getvalue())


def _new_npz(**arrays: np.ndarray) -> bytes:
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)
    return buffer.getvalue()


def _reseal_sweep_file(out: Path, name: str, data: bytes) -> None:
    """Replace a file of a sweep and make sweep.json agree (what only a forger would do)."""
    (out / name).write_bytes(data)
    _json_edit(out / "sweep.json", lambda d: d["files"].__setitem__(name, bytes_digest(data)), reseal=True)


def _truncate(path: Path) -> None:
    path.write_bytes(path.read_bytes()[: len(path.read_bytes()) // 2])


def _move_flags(arrays: dict[str, np.ndarray]) -> None:
    """The level's least connectivity-violating transition moved to an unused flag bit in its summary:
    still a violating transition (so the files stay consistent with each other), but of no lemma the
    checker reads."""
    summary = arrays["summary"]
    connectivity, unused = 4 + 2 * 1, 4 + 2 * 7  # Lemma.CONNECTIVITY.flag = 2 (bit 1); bit 7 is free
    assert summary[connectivity] >= 0
    summary[unused : unused + 2] = summary[connectivity : connectivity + 2]
    summary[connectivity : connectivity + 2] = -1


def _move_all_flags(ck: Path) -> None:
    for level in sorted((ck / "n2").glob("level-*.npz"))[1:]:
        _npz_edit(level, _move_flags) if np.load(level)["summary"][6] >= 0 else None


def _reseal_level(ck: Path, level: str, data: bytes) -> None:
    """Replace a level file and make the manifest agree (what only a forger would do)."""
    (ck / "n2" / level).write_bytes(data)
    _json_edit(ck / "n2" / "manifest.json", lambda m: m["files"].__setitem__(level, bytes_digest(data)), reseal=True)


def _first_row(rows: list[dict], **match: object) -> dict:
    return next(r for r in rows if all(r.get(k) == v for k, v in match.items()))


def _violated_to_proved(data: dict, *, clear_trace: bool) -> None:
    row = _first_row(data["obligations"], verdict="VIOLATED", lemma="no-collision")
    row["verdict"] = "PROVED"
    if clear_trace:
        row["trace"] = None


def _violated_to_holds(data: dict, *, clear_trace: bool = True) -> None:
    row = _first_row(data["lemmas"], verdict="VIOLATED", lemma="connectivity", robots=2)
    row["verdict"] = "HOLDS_WITHIN_BOUNDS"
    if clear_trace:
        row["trace"] = None


CK = "ck/n2"
SW = "sw/paper"
RESULTS = "proofs/paper/results.json"
CACHE = "reports/paper/check.json"

# (id, what to copy from ``made`` into the working directory, tamper(cwd), argv, fragment of the error line)
TAMPERED: list[tuple[str, dict[str, str], Callable[[Path], None], list[str], str]] = [
    # a checkpoint: level files and manifest
    (
        "ckpt-level-flag-moved",
        {"ck": "ck"},
        lambda w: _move_all_flags(w / "ck"),
        CHECK_CKPT,
        "level-00001.npz: its content does not match the digest",
    ),
    (
        "ckpt-level-truncated",
        {"ck": "ck"},
        lambda w: _truncate(w / CK / "level-00002.npz"),
        CHECK_CKPT,
        "level-00002.npz: its content does not match",
    ),
    (
        "ckpt-level-garbage-resealed",
        {"ck": "ck"},
        lambda w: _reseal_level(w / "ck", "level-00001.npz", b"PK\x03\x04junk"),
        CHECK_CKPT,
        "level-00001.npz': not a level file",
    ),
    (
        "ckpt-level-columns-resealed",
        {"ck": "ck"},
        lambda w: _reseal_level(
            w / "ck",
            "level-00001.npz",
            _npz_bytes(w / CK / "level-00001.npz", lambda a: a.__setitem__("parent", a["parent"][:-1])),
        ),
        CHECK_CKPT,
        "columns do not fit together",
    ),
    (
        "ckpt-manifest-truncated",
        {"ck": "ck"},
        lambda w: _truncate(w / CK / "manifest.json"),
        CHECK_CKPT,
        "manifest.json': not JSON",
    ),
    (
        "ckpt-manifest-edited",
        {"ck": "ck"},
        lambda w: _json_edit(w / CK / "manifest.json", lambda m: m.__setitem__("levels", 1), reseal=False),
        CHECK_CKPT,
        "manifest.json: its content does not match its digest",
    ),
    (
        "ckpt-manifest-levels-mistyped",
        {"ck": "ck"},
        lambda w: _json_edit(w / CK / "manifest.json", lambda m: m.__setitem__("levels", "2"), reseal=True),
        CHECK_CKPT,
        "levels='2'",
    ),
    (
        "ckpt-manifest-no-digests",
        {"ck": "ck"},
        lambda w: _json_edit(w / CK / "manifest.json", lambda m: m.pop("files"), reseal=True),
        CHECK_CKPT,
        "without a digest of each level file",
    ),
    (
        "ckpt-manifest-unsealed",
        {"ck": "ck"},
        lambda w: _json_edit(w / CK / "manifest.json", lambda m: m.pop("digest"), reseal=False),
        CHECK_CKPT,
        "manifest.json: no digest",
    ),
    (
        "ckpt-manifest-old-version",
        {"ck": "ck"},
        lambda w: _json_edit(w / CK / "manifest.json", lambda m: m.__setitem__("version", 2), reseal=True),
        CHECK_CKPT,
        "version='2'",
    ),
    # a sweep: status, sweep.json (the manifest) and the witnesses it names
    (
        "sweep-status-flipped",
        {"sw": "sw"},
        lambda w: _npz_edit(w / SW / "status.npz", lambda a: a["no-collision"].__setitem__(0, 1)),
        SWEEP_AGAIN,
        "status.npz: its content does not match the digest sweep.json records",
    ),
    (
        "sweep-status-garbage",
        {"sw": "sw"},
        lambda w: (w / SW / "status.npz").write_bytes(b"junk"),
        SWEEP_AGAIN,
        "status.npz: its content does not match",
    ),
    (
        "sweep-json-edited",
        {"sw": "sw"},
        lambda w: _json_edit(w / SW / "sweep.json", lambda d: d.__setitem__("replays", d["replays"] + 1), reseal=False),
        SWEEP_AGAIN,
        "sweep.json: its content does not match its digest",
    ),
    (
        "sweep-json-truncated",
        {"sw": "sw"},
        lambda w: _truncate(w / SW / "sweep.json"),
        SWEEP_AGAIN,
        "sweep.json: not JSON",
    ),
    (
        "sweep-json-mistyped-resealed",
        {"sw": "sw"},
        lambda w: _json_edit(w / SW / "sweep.json", lambda d: d.__setitem__("witnesses", "x"), reseal=True),
        SWEEP_AGAIN,
        "malformed",
    ),
    (
        "sweep-witness-outside-resealed",
        {"sw": "sw"},
        lambda w: _json_edit(
            w / SW / "sweep.json", lambda d: d["witnesses"][0].__setitem__("trace", "../../precious.txt"), reseal=True
        ),
        SWEEP_AGAIN,
        "malformed",
    ),
    (
        "sweep-witness-edited",
        {"sw": "sw"},
        lambda w: (w / SW / "traces" / "connectivity-1.json").write_text("{}"),
        SWEEP_AGAIN,
        "connectivity-1.json: its content does not match",
    ),
    (
        "sweep-known-flipped",
        {"sw": "sw"},
        lambda w: _npz_edit(w / SW / "known.npz", lambda a: a.__setitem__("where", a["where"].astype(np.int32))),
        SWEEP_AGAIN,
        "known.npz: its content does not match the digest sweep.json records",
    ),
    (
        "sweep-known-garbage-resealed",
        {"sw": "sw"},
        lambda w: _reseal_sweep_file(w / SW, "known.npz", b"junk"),
        SWEEP_AGAIN,
        "known.npz: not the known states fatline sweep saved",
    ),
    (
        "sweep-known-mistyped-resealed",
        {"sw": "sw"},
        lambda w: _reseal_sweep_file(w / SW, "known.npz", _new_npz(where=np.zeros((1, 5), dtype=np.int64))),
        SWEEP_AGAIN,
        "known.npz: not the known states fatline sweep saved",
    ),
    (
        "sweep-known-left-out-of-the-manifest-resealed",
        {"sw": "sw"},
        lambda w: _json_edit(
            w / SW / "sweep.json",
            lambda d: d["files"].pop("known.npz") and d["files"].__setitem__("other.npz", d["files"]["status.npz"]),
            reseal=True,
        ),
        SWEEP_AGAIN,
        "malformed",
    ),
    (
        "sweep-pending-malformed-resealed",
        {"sw": "sw"},
        lambda w: _json_edit(
            w / SW / "sweep.json",
            lambda d: d.__setitem__("pending", {"combos": [{"quadrants": 9, "path": 0}], "absorbed": []}),
            reseal=True,
        ),
        SWEEP_AGAIN,
        "malformed",
    ),
    (
        "sweep-pending-lemma-twice-resealed",
        {"sw": "sw"},
        lambda w: _json_edit(
            w / SW / "sweep.json",
            lambda d: d.__setitem__(
                "pending", {"combos": [{"quadrants": 0, "path": 0}], "absorbed": ["connectivity", "connectivity"]}
            ),
            reseal=True,
        ),
        SWEEP_AGAIN,
        "malformed",
    ),
    # the prover's results.json, written before digests: rows against their evidence
    (
        "results-legacy-violated-set-proved",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _json_edit(w / RESULTS, lambda d: _violated_to_proved(d, clear_trace=False), reseal=False),
        REPORT,
        "is PROVED, but",
    ),
    (
        "results-legacy-proved-trace-cleared",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _json_edit(w / RESULTS, lambda d: _violated_to_proved(d, clear_trace=True), reseal=False),
        REPORT,
        "replays a counterexample of it",
    ),
    (
        "results-legacy-proved-prove",
        {"legacy/proofs": "proofs"},
        lambda w: _json_edit(w / RESULTS, lambda d: _violated_to_proved(d, clear_trace=True), reseal=False),
        PROVE,
        "is PROVED, but",
    ),
    (
        "results-legacy-trace-names-a-file-outside",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _json_edit(
            w / RESULTS,
            lambda d: _first_row(d["obligations"], verdict="VIOLATED").__setitem__("trace", str(w / "precious.txt")),
            reseal=False,
        ),
        REPORT,
        "precious.txt': not JSON",
    ),
    (
        "results-truncated",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _truncate(w / RESULTS),
        REPORT,
        "is not a fatline prove result",
    ),
    # ... and as written now: a digest
    (
        "results-sealed-row-edited",
        {"sealed/proofs": "proofs", "sealed/reports": "reports"},
        lambda w: _json_edit(
            w / RESULTS,
            lambda d: _first_row(d["obligations"], verdict="PROVED").__setitem__("verdict", "VIOLATED"),
            reseal=False,
        ),
        REPORT,
        "results.json: its content does not match its digest",
    ),
    (
        "results-sealed-prove",
        {"sealed/proofs": "proofs"},
        lambda w: _json_edit(w / RESULTS, lambda d: _violated_to_proved(d, clear_trace=True), reseal=False),
        PROVE,
        "results.json: its content does not match its digest",
    ),
    (
        "results-row-mistyped-resealed",
        {"sealed/proofs": "proofs", "sealed/reports": "reports"},
        lambda w: _json_edit(w / RESULTS, lambda d: d["obligations"][0].__setitem__("slots", "x"), reseal=True),
        REPORT,
        "obligations[0].slots='x'",
    ),
    (
        "results-obligations-mistyped-resealed",
        {"sealed/proofs": "proofs"},
        lambda w: _json_edit(w / RESULTS, lambda d: d.__setitem__("obligations", {"a": 1}), reseal=True),
        PROVE,
        "obligations=",
    ),
    # the report's check cache
    (
        "cache-legacy-violated-set-holds",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _json_edit(w / CACHE, _violated_to_holds, reseal=False),
        REPORT,
        "is HOLDS_WITHIN_BOUNDS, but",
    ),
    (
        "cache-legacy-violated-without-trace",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _json_edit(
            w / CACHE, lambda d: _first_row(d["lemmas"], verdict="VIOLATED").__setitem__("trace", None), reseal=False
        ),
        REPORT,
        "VIOLATED without a trace",
    ),
    (
        "cache-legacy-trace-names-a-file-outside",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _json_edit(
            w / CACHE,
            lambda d: _first_row(d["lemmas"], verdict="VIOLATED").__setitem__("trace", "../precious.txt"),
            reseal=False,
        ),
        REPORT,
        "trace='../precious.txt': no such file",
    ),
    (
        "cache-sealed-row-edited",
        {"sealed/proofs": "proofs", "sealed/reports": "reports"},
        lambda w: _json_edit(w / CACHE, _violated_to_holds, reseal=False),
        REPORT,
        "check.json: its content does not match its digest",
    ),
    (
        "cache-row-mistyped-resealed",
        {"sealed/proofs": "proofs", "sealed/reports": "reports"},
        lambda w: _json_edit(w / CACHE, lambda d: d["lemmas"][0].__setitem__("robots", "two"), reseal=True),
        REPORT,
        "lemmas[0].robots='two'",
    ),
    (
        "cache-truncated",
        {"sealed/proofs": "proofs", "sealed/reports": "reports"},
        lambda w: _truncate(w / CACHE),
        REPORT,
        "is not a fatline check result",
    ),
    # the corpus: a link out of it, a file that is not a trace
    (
        "corpus-link-outside",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: _link(w / "reports" / "traces" / "paper-check-connectivity-n2.json", w / "precious.txt"),
        REPORT,
        "traces/paper-check-connectivity-n2.json is a link",
    ),
    (
        "corpus-foreign-json",
        {"legacy/proofs": "proofs", "legacy/reports": "reports"},
        lambda w: (w / "reports" / "traces" / "paper-check-from-a-user.json").write_bytes(PRECIOUS),
        REPORT,
        "is not a fatline trace",
    ),
]


def _npz_bytes(path: Path, change: Callable[[dict[str, np.ndarray]], None]) -> bytes:
    with np.load(path) as saved:
        arrays = {k: saved[k].copy() for k in saved.files}
    change(arrays)
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)
    return buffer.getvalue()


def _link(path: Path, target: Path) -> None:
    path.unlink(missing_ok=True)
    path.symlink_to(target)


@pytest.mark.parametrize(
    ("copies", "tamper", "argv", "fragment"), [c[1:] for c in TAMPERED], ids=[c[0] for c in TAMPERED]
)
def test_tampered_state_is_refused_never_shown(capsys, tmp_path, monkeypatch, made, copies, tamper, argv, fragment):
    work = tmp_path / "w"
    work.mkdir()
    (work / "precious.txt").write_bytes(PRECIOUS)
    for source, target in copies.items():
        shutil.copytree(made / source, work / target, symlinks=True)
    tamper(work)
    monkeypatch.chdir(work)
    before = _snapshot(work)
    _refused(capsys, argv, fragment)
    assert _snapshot(work) == before  # nothing overwritten, nothing copied, nothing left behind


def test_the_untampered_copies_are_accepted(capsys, tmp_path, monkeypatch, made):
    """The control: each artefact the cases above tamper with is taken as it is when nobody touched it."""
    for name in ("ck", "sw"):
        shutil.copytree(made / name, tmp_path / name)
    monkeypatch.chdir(tmp_path)
    assert main(CHECK_CKPT) == 1
    assert main(SWEEP_AGAIN) == 1
    capsys.readouterr()
    from fatline_verify.model.config import load_model
    from fatline_verify.prove.results import ProofResults
    from fatline_verify.report.build import contradicted_holds, read_check_cache

    for kind in ("legacy", "sealed"):
        proofs = made / kind / "proofs" / "paper"
        store = ProofResults(load_model("paper"), proofs, proofs / "traces", slots=3, timeout=60.0)
        assert any(r["verdict"] == "PROVED" for r in store.rows.values())
        cache = made / kind / "reports" / "paper" / "check.json"
        data = read_check_cache(cache)
        assert data is not None
        contradicted_holds(load_model("paper"), data, made / kind / "reports" / "traces", cache)


def test_a_legacy_sweep_whose_status_was_changed_is_refused(capsys, tmp_path, monkeypatch):
    """A sweep saved before digests (the shipped docs/sweep): its status must match the counts beside it."""
    shutil.copytree(ROOT / "docs" / "sweep" / "rma-fixed" / "paper", tmp_path / "dsw" / "paper")
    argv = ["sweep", "paper", "--lemma", "rma-fixed", "--out", "dsw", "--max-checks", "0", "-q"]
    monkeypatch.chdir(tmp_path)

    def flip(arrays: dict[str, np.ndarray]) -> None:
        status = arrays["rma-fixed"]
        status[int(np.flatnonzero(status == 2)[0])] = 1  # one reading that holds, shown as refuted

    _npz_edit(tmp_path / "dsw" / "paper" / "status.npz", flip)
    before = _snapshot(tmp_path)
    _refused(capsys, argv, "does not match the counts sweep.json records for rma-fixed")
    assert _snapshot(tmp_path) == before


def test_a_sweep_killed_between_its_manifest_and_its_status_rolls_forward(capsys, tmp_path, monkeypatch, made):
    """sweep.json names the new status's digest; the status itself is still the old one, the new one
    beside it under its pending name: the next run finishes the save instead of refusing or losing it."""
    shutil.copytree(made / "sw", tmp_path / "sw")
    out = tmp_path / SW
    new = (out / "status.npz").read_bytes()
    digest = json.loads((out / "sweep.json").read_text())["files"]["status.npz"]
    (out / f".status-{digest.removeprefix('sha256:')[:16]}.npz").write_bytes(new)
    _npz_edit(out / "status.npz", lambda a: a["connectivity"].__setitem__(slice(None), 0))  # the old, all open
    monkeypatch.chdir(tmp_path)
    assert main(SWEEP_AGAIN) == 1
    assert "refuted under all 6 readings" in capsys.readouterr().out
    assert (out / "status.npz").read_bytes() == new
    assert not list(out.glob(".status-*"))


def test_a_leftover_temporary_manifest_does_not_refuse_its_own_checkpoint(capsys, tmp_path, monkeypatch, made):
    shutil.copytree(made / "ck", tmp_path / "ck")
    for name in (".manifest.json.tmp", ".manifest.json.a1b2_c3d.tmp", ".level-00003.npz.x9y8z7.tmp"):
        (tmp_path / CK / name).write_bytes(b"half a write")
    monkeypatch.chdir(tmp_path)
    assert main(CHECK_CKPT) == 1
    assert "connectivity  2       VIOLATED" in capsys.readouterr().out


# --- concurrent runs --------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("argv", "held"),
    [
        (CHECK_CKPT, "ck"),
        (SWEEP_AGAIN, "sw/paper"),
        (["report", "paper", "--out", "reports", "-q"], "reports"),
    ],
    ids=["check-checkpoint", "sweep-out", "report-out"],
)
def test_a_second_run_into_a_held_directory_is_refused(capsys, tmp_path, monkeypatch, made, argv, held):
    for name in ("ck", "sw"):
        shutil.copytree(made / name, tmp_path / name)
    (tmp_path / "reports").mkdir()
    monkeypatch.chdir(tmp_path)
    before = _snapshot(tmp_path)
    with holding(tmp_path / held, name="test"):  # another run holds it
        _refused(capsys, argv, "in use by another fatline run")
    assert _snapshot(tmp_path) == before


def _open_rows(results: Path, lemma: str, k: int) -> list[str]:
    """Make the first ``k`` VIOLATED rows of ``lemma`` INCONCLUSIVE (their traces stay): what a redo finds."""
    from fatline_verify.prove.tasks import row_key

    data = json.loads(results.read_text())
    rows = [r for r in data["obligations"] if r["lemma"] == lemma and r["verdict"] == "VIOLATED" and r["trace"]][:k]
    for row in rows:
        row["verdict"] = "INCONCLUSIVE"
    results.write_text(json.dumps(seal(data), indent=1))  # as a run that left them open wrote it
    return [row_key(r) for r in rows]


def test_two_prove_runs_into_one_out_both_keep_their_rows(tmp_path):
    """Each run saves row by row; a save re-reads and merges under the directory's lock, so neither run's
    rows are lost to the other's save (before: the last writer won)."""
    shutil.copytree(ROOT / "proofs" / "paper", tmp_path / "proofs" / "paper")
    results = tmp_path / RESULTS
    mine = {lemma: _open_rows(results, lemma, 3) for lemma in ("no-collision", "connectivity")}
    runs = [
        subprocess.Popen(
            [*FATLINE, "prove", "paper", "--lemma", lemma, "--redo-inconclusive", "--out", "proofs", "-q", "--jobs=1"],
            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )
        for lemma in mine
    ]  # fmt: skip
    for run in runs:
        _, err = run.communicate(timeout=300)
        assert run.returncode == 1, err  # each replays its rows' counterexamples: VIOLATED again
        assert "Traceback" not in err
    from fatline_verify.prove.tasks import row_key

    data = json.loads(results.read_text())
    rows = {row_key(r): r for r in data["obligations"]}
    for keys in mine.values():
        for key in keys:
            assert rows[key]["verdict"] == "VIOLATED", key  # both runs' rows are there
    assert data["digest"].startswith("sha256:")
    assert not list((tmp_path / "proofs").rglob("*.tmp"))


# --- hostile input: files that are not files, values that are too big, names that are too long -------------


LONG = "a" * 300


def _world(root: Path) -> None:
    for name in ("README.md", "precious.txt"):
        (root / name).write_bytes(PRECIOUS)
    os.mkfifo(root / "fifo.json")
    os.mkfifo(root / "fifo.toml")
    (root / "zero.json").symlink_to("/dev/zero")
    (root / "zero.toml").symlink_to("/dev/zero")
    good = json.loads((ROOT / "reports" / "traces" / "paper-check-connectivity-n2.json").read_text())
    text = json.dumps(good)
    (root / "bigint.json").write_text(text.replace('"initial": [[0, 0]', f'"initial": [[{"9" * 5000}, 0]', 1))
    assert "9" * 5000 in (root / "bigint.json").read_text()
    (root / "nested.json").write_text('{"initial": ' + "[" * 100_000 + "]" * 100_000 + "}")
    (root / "nested.toml").write_text("a = " + "[" * 3000 + "]" * 3000 + "\n")
    (root / "delta.toml").write_text(f"[parameters]\ndelta = {'9' * 5000}\n")
    (root / "delta-long.toml").write_text(f"[parameters]\ndelta = {'9' * 1500}\n")
    (root / "radv.toml").write_text("[parameters]\nrad_v = 1000000\n")
    (root / "bigvalue.toml").write_text(f'[options]\nquadrants = "{"x" * 100_000}"\n')
    (root / "long.toml").write_text(f'name = "{LONG}"\n')


HOSTILE = [
    # files that are not regular files: refused, never waited on or read without end
    ("replay-fifo", ["replay", "fifo.json"], "not a regular file (a FIFO)"),
    ("replay-dev-zero", ["replay", "zero.json"], "not a regular file (a character device)"),
    ("check-model-fifo", ["check", "fifo.toml", "-q"], "model='fifo.toml': not a regular file"),
    ("check-model-dev-zero", ["check", "zero.toml", "-q"], "model='zero.toml': not a regular file"),
    ("prove-known-fifo", ["prove", "--known", "fifo.json", "--out", "p", "-q"], "not a regular file (a FIFO)"),
    # values too big
    ("replay-5000-digit-integer", ["replay", "bigint.json"], "an integer of 5,000 digits"),
    ("replay-100000-nested-arrays", ["replay", "nested.json"], "nested too deep"),
    ("check-toml-3000-nested-arrays", ["check", "nested.toml", "-q"], "nested too deep"),
    (
        "check-delta-5000-digits",
        ["check", "delta.toml", "-q"],
        "delta=99999999999999999999...: a number of 5,000 digits",
    ),
    ("check-delta-1500-digits", ["check", "delta-long.toml", "-q"], "delta=99999999999999999999...: a number of 1,500"),
    ("check-rad-v-huge", ["check", "radv.toml", "-q"], "rad_v=1000000: a robot sees"),
    ("check-value-100kb", ["check", "bigvalue.toml", "-q"], "quadrants='xxxx"),
    ("reach-robots-9", ["reach", "repaired", "--robots", "9", "-q"], "robots=9 window=9x9: more than"),
    # more workers than cores: refused (not capped), before any work
    ("check-workers-64", ["check", "--workers", "64", "-q"], "workers=64: expected at most"),
    ("sweep-workers-64", ["sweep", "--workers", "64", "-q"], "workers=64: expected at most"),
    # names the file system cannot take: before any search
    ("check-json-long-name", ["check", "--robots", "2", "--json", f"{LONG}.json", "-q"], "file name too long"),
    ("check-traces-long-name", ["check", "--robots", "2", "--traces", LONG, "-q"], "file name too long"),
    ("check-model-long-name", ["check", "long.toml", "--robots", "2", "-q"], f"name='{LONG[:100]}"),
    ("prove-model-long-name", ["prove", "long.toml", "--out", "p", "-q"], "file name too long"),
    ("prove-out-long-name", ["prove", "--out", LONG, "-q"], "file name too long"),
    ("report-out-long-name", ["report", "paper", "--out", LONG, "-q"], "file name too long"),
    ("sweep-model-long-name", ["sweep", "long.toml", "--robots", "2", "--window", "5x5", "-q"], "file name too long"),
    ("simulate-trace-long-name", ["simulate", "--init", "0,0 3,0", "--trace", f"{LONG}.json"], "file name too long"),
]


@pytest.mark.parametrize(("argv", "fragment"), [c[1:] for c in HOSTILE], ids=[c[0] for c in HOSTILE])
def test_hostile_input_is_one_line(capsys, tmp_path, monkeypatch, argv, fragment):
    _world(tmp_path)
    monkeypatch.chdir(tmp_path)
    before = _snapshot(tmp_path)
    line = _refused(capsys, argv, fragment)
    assert "expected" in line
    assert _snapshot(tmp_path) == before


def test_a_long_value_is_echoed_short(capsys, tmp_path, monkeypatch):
    _world(tmp_path)
    monkeypatch.chdir(tmp_path)
    line = _refused(capsys, ["check", "bigvalue.toml", "-q"], "characters)")
    assert "x" * 200 not in line and len(line) < 400


# --- a full disk --------------------------------------------------------------------------------------------


def test_a_failed_write_leaves_no_temporary_file_and_names_the_path(capsys, tmp_path, monkeypatch):
    """A write that fails (here: the disk fills as the file is renamed into place) is one line naming the
    file; the run's result was printed before; the temporary file is gone."""
    import fatline_verify.outputs as outputs

    monkeypatch.chdir(tmp_path)

    def full(src, dst):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(outputs.os, "replace", full)
    code = main(["simulate", "--init", "0,0 3,0", "--trace", "run.json"])
    out, err = capsys.readouterr()
    assert code == 2
    assert err.strip() == "fatline: error: run.json: no space left on device"
    assert "connectivity" in out  # the run was shown before its file was written
    assert list(tmp_path.iterdir()) == []


UNSHARE = shutil.which("unshare")


def _in_full_tmpfs(tmp_path: Path, script: str) -> subprocess.CompletedProcess[str]:
    """Run ``script`` (sh) with ``$M`` a 256 KiB tmpfs filled to the last byte, in a mount namespace of its
    own (nothing to unmount afterwards); skipped only where none can be mounted (under CI too)."""
    if UNSHARE is None:
        pytest.skip("no unshare: a tmpfs cannot be mounted here")
    mount = tmp_path / "m"
    mount.mkdir()
    prelude = (
        f'M={mount}; FATLINE="{" ".join(FATLINE)}"\n'
        'mount -t tmpfs -o size=256k tmpfs "$M" || exit 99\n'
        'dd if=/dev/zero of="$M/fill" bs=4k 2>/dev/null\n'
    )
    flags = ["-m"] if os.geteuid() == 0 else ["-r", "-m"]
    done = subprocess.run([UNSHARE, *flags, "sh", "-c", prelude + script], capture_output=True, text=True, timeout=300)
    if done.returncode == 99 or "unshare:" in done.stderr:
        pytest.skip(f"a tmpfs cannot be mounted here: {done.stderr.strip()[:200]}")
    return done


def test_check_on_a_full_disk_prints_its_table_then_one_line(tmp_path):
    done = _in_full_tmpfs(
        tmp_path,
        '$FATLINE check --robots 2 --traces "$M/t" --json "$M/out.json" -q; echo "exit=$?"\n'
        'echo "left:"; ls -A "$M" "$M/t" 2>/dev/null\n',
    )
    assert "exit=2" in done.stdout, done
    assert "connectivity  2       VIOLATED" in done.stdout  # the verdicts, before any file
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("fatline: error: "), done.stderr
    assert "paper-connectivity-n2.json: no space left on device" in lines[0]
    assert ".tmp" not in done.stdout.split("left:")[1]  # no temporary file left behind


def test_a_checkpoint_a_full_disk_stopped_resumes_once_there_is_room(tmp_path):
    done = _in_full_tmpfs(
        tmp_path,
        f'$FATLINE check --robots 2 --traces {tmp_path}/t --checkpoint "$M/ck" -q; echo "exit=$?"\n'
        'touch "$M/ck/n2/.manifest.json.tmp"; rm "$M/fill"\n'
        f'$FATLINE check --robots 2 --traces {tmp_path}/t --checkpoint "$M/ck" -q; echo "again=$?"\n',
    )
    assert "exit=2" in done.stdout, done
    first = done.stderr.strip().splitlines()
    assert len(first) == 1 and "no space left on device" in first[0], done.stderr
    assert "again=1" in done.stdout, done  # its own leftovers do not refuse it


# --- exit codes ---------------------------------------------------------------------------------------------


def test_a_sweep_with_nothing_refuted_and_something_inconclusive_exits_3(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    argv = ["sweep", "--vary", "quadrants", "--lemma", "no-collision,progress", "--robots", "2", "--window", "5x5"]
    code = main([*argv, "--max-states", "1", "--out", "s", "-q"])
    out = capsys.readouterr().out
    assert "inconclusive under" in out and "refuted under" not in out
    assert code == 3


# --- paths a result records, from anywhere ---------------------------------------------------------------------


def test_relative_paths_in_results_resolve_against_the_results_file(tmp_path, monkeypatch):
    """``proofs/paper/traces/X.json`` in a results file copied to ``ELSEWHERE/p2/paper/`` is
    ``ELSEWHERE/p2/paper/traces/X.json``, whatever the working directory."""
    from fatline_verify.outputs import resolve_recorded

    copy = tmp_path / "x" / "p2" / "paper"
    shutil.copytree(ROOT / "proofs" / "paper", copy)
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    rows = [r for r in json.loads((copy / "results.json").read_text())["obligations"] if r.get("trace")]
    assert rows and all(not Path(r["trace"]).is_absolute() for r in rows)
    for row in rows:
        found = resolve_recorded(row["trace"], copy)
        assert found is not None and found.parent == copy / "traces", row["trace"]
    assert resolve_recorded("proofs/paper/traces/none.json", copy) is None


@pytest.mark.slow
def test_report_from_another_directory_with_a_copied_proofs_directory(capsys, tmp_path, monkeypatch):
    """``report --proofs DIR`` run anywhere: the rows' traces are found beside the copied results."""
    base = tmp_path / "x"
    shutil.copytree(ROOT / "proofs" / "paper", base / "p2" / "paper")
    (base / "reports" / "paper").mkdir(parents=True)
    shutil.copyfile(ROOT / "reports" / "paper" / "check.json", base / "reports" / "paper" / "check.json")
    (base / "reports" / "traces").mkdir()
    for trace in (ROOT / "reports" / "traces").glob("paper-*.json"):
        if trace.name.startswith(("paper-check-", "paper-prove-")):
            shutil.copyfile(trace, base / "reports" / "traces" / trace.name)
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    code = main(["report", "paper", "--out", "../x/reports", "--proofs", "../x/p2", "-q"])
    _, err = capsys.readouterr()
    assert code == 0, err
    ours = (base / "reports" / "paper" / "README.md").read_bytes()
    assert ours == (ROOT / "reports" / "paper" / "README.md").read_bytes()
