"""Hostile runs: concurrent runs that lose nothing, input that is not what it claims (files that are
not files, values too big, names too long), a full disk, exit codes, recorded paths from anywhere
(issue 29). Every refusal is one line ``fatline: error: ...`` on stderr, exit 2, and every file that
existed before the command is byte-identical after it.
"""

from __future__ import annotations

import errno
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from fatline_verify.cli import main
from fatline_verify.integrity import seal
from fatline_verify.locks import holding
from tests.hostile import CHECK_CKPT, FATLINE, PRECIOUS, RESULTS, ROOT, SWEEP_AGAIN, refused, snapshot

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
    before = snapshot(tmp_path)
    with holding(tmp_path / held, name="test"):  # another run holds it
        refused(capsys, argv, "in use by another fatline run")
    assert snapshot(tmp_path) == before


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
    ("prove-jobs-64", ["prove", "--jobs", "64", "--out", "p", "-q"], "jobs=64: expected at most"),
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
    before = snapshot(tmp_path)
    line = refused(capsys, argv, fragment)
    assert "expected" in line
    assert snapshot(tmp_path) == before


def test_prove_jobs_are_held_to_the_cores(capsys, tmp_path, monkeypatch):
    """``prove --jobs`` above the cores is refused as ``check --workers`` is (one check, ``check_cores``),
    whatever this machine has: here it is told it has 2. The default is the cores, so it passes."""
    import fatline_verify.cli.common as common
    from fatline_verify.cli import build_parser

    assert build_parser().parse_args(["prove"]).jobs == common.cores()
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(common, "cores", lambda: 2)
    line = refused(capsys, ["prove", "--jobs", "3", "--out", "p", "-q"], "jobs=3: expected at most 2, the cores")
    assert "INCONCLUSIVE" in line
    assert not (tmp_path / "p").exists()
    common.check_cores("jobs", 2, "as many as the cores")  # does not raise


def test_a_long_value_is_echoed_short(capsys, tmp_path, monkeypatch):
    _world(tmp_path)
    monkeypatch.chdir(tmp_path)
    line = refused(capsys, ["check", "bigvalue.toml", "-q"], "characters)")
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


def test_a_large_read_limit_allocates_only_what_the_file_holds(tmp_path):
    """A checkpoint level is read with the machine's memory as its limit; one ``read(limit + 1)`` asked
    the allocator for that many bytes at once, which a kernel that does not overcommit refuses (a
    MemoryError on resume). The limit is a bound, not a buffer size: a limit far beyond any memory reads
    a small file whole, and a file one byte over a small limit is still refused."""
    from fatline_verify.outputs import NotReadable, read_regular

    path = tmp_path / "level.bin"
    path.write_bytes(b"x" * 3000)
    assert read_regular(path, limit=2**62) == b"x" * 3000
    assert read_regular(path, limit=3000) == b"x" * 3000
    with pytest.raises(NotReadable, match="too large"):
        read_regular(path, limit=2999)
    assert read_regular(path, limit=10, head=True) == b"x" * 10
