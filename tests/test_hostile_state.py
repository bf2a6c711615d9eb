"""Hostile state: saved files that cannot lie (issue 29; concurrent runs, hostile input and a full disk:
``test_hostile_runs.py``).

Every refusal is one line ``fatline: error: ...`` on stderr, exit 2, no verdict on stdout, and every
file that existed before the command is byte-identical after it. The artefacts tampered with are made
once per session (``made``: a checkpoint and a sweep by the tool itself; copies of the committed prover
results and report cache, as written before digests and as the tool writes them now, with their
digest; :func:`tests.hostile.make_artefacts`).
"""

from __future__ import annotations

import io
import json
import shutil
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from fatline_verify.cli import main
from fatline_verify.integrity import bytes_digest, seal
from tests.hostile import CHECK_CKPT, PRECIOUS, PROVE, REPORT, RESULTS, ROOT, SWEEP_AGAIN, refused, snapshot


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
    before = snapshot(work)
    refused(capsys, argv, fragment)
    assert snapshot(work) == before  # nothing overwritten, nothing copied, nothing left behind


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
    before = snapshot(tmp_path)
    refused(capsys, argv, "does not match the counts sweep.json records for rma-fixed")
    assert snapshot(tmp_path) == before


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
