"""A sweep's saved state, saved after every step and read back on a rerun with the same settings.

The files of ``OUT/MODEL``: ``status.npz`` (per lemma, each combination's status), ``known.npz`` (per
robot count and bounds, every state the checks so far expanded: the spread closures start from them,
so a resumed run closes what a fresh one would), the witnesses under ``traces/``, and ``sweep.json``,
the manifest, written last: the settings, the counts, the checks, the check under way (``pending``:
the combinations picked and the lemmas already closed from the first), and the SHA-256 digest of
every other file (:mod:`fatline_verify.integrity`). Each ``.npz`` is written under a name of its own
first and renamed into place after the manifest, so a run killed anywhere leaves the old sweep or the
new one (:func:`roll_forward`); a file that does not match its digest is refused, never read as a
verdict.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import zipfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import InvalidInput, OutputFailed
from ..integrity import bytes_digest, file_digest, matches, seal, sealed
from ..lemmas.properties import CHECKED, Lemma
from ..outputs import Kind, NotReadable, load_json, os_error_text, read_regular, write_bytes, write_json

if TYPE_CHECKING:
    from .run import Sweep

OPEN, REFUTED, HOLDS, INCONCLUSIVE = 0, 1, 2, 3
"""A combination's status for one lemma."""

FORMAT = Kind.SWEEP.value
VERSION = 1
STATUS_FILE = "status.npz"
KNOWN_FILE = "known.npz"
ARRAYS = (STATUS_FILE, KNOWN_FILE)
"""The files saved under a name of their own first (:func:`staged`), then renamed into place."""

Where = tuple[int, tuple[int, int], tuple[int, int]]
"""A robot count, the exploration bound and the window."""


def staged(out: Path, name: str, digest: str) -> Path:
    """Where a save puts a new ``name`` before ``sweep.json`` names it (named by its digest)."""
    stem = name.removesuffix(".npz")
    return out / f".{stem}-{digest.removeprefix('sha256:')[:16]}.npz"


def roll_forward(out: Path, name: str, digest: object) -> None:
    """Finish a save killed between writing ``sweep.json`` and renaming the ``name`` it records."""
    if isinstance(digest, str) and not matches(out / name, digest) and matches(staged(out, name, digest), digest):
        os.replace(staged(out, name, digest), out / name)


def _npz(arrays: dict[str, np.ndarray]) -> bytes:
    buffer = io.BytesIO()
    np.savez_compressed(buffer, **arrays)  # type: ignore[arg-type]
    return buffer.getvalue()


def known_arrays(known: dict[Where, np.ndarray]) -> dict[str, np.ndarray]:
    """The known states as arrays: ``where`` (one row n, bound, window per entry) and ``k0``, ``k1``, ..."""
    items = sorted(known.items())
    where = np.array([[n, *bound, *window] for (n, bound, window), _ in items], dtype=np.int64).reshape(-1, 5)
    return {"where": where, **{f"k{i}": keys for i, (_, keys) in enumerate(items)}}


def save(sweep: Sweep) -> None:
    """Save the sweep: each array file under a name of its own, then ``sweep.json`` (the manifest, last:
    the digests of the arrays and of every witness trace), then the arrays renamed into place. Killed
    anywhere, the next run finds the old sweep or the new one, never a status without its witnesses."""
    out = sweep.out
    out.mkdir(parents=True, exist_ok=True)
    blobs = {
        STATUS_FILE: _npz({lemma.value: sweep.status[lemma] for lemma in sweep.lemmas}),
        KNOWN_FILE: _npz(known_arrays(sweep.known)),
    }
    files: dict[str, str] = {}
    for name, raw in blobs.items():
        files[name] = digest = bytes_digest(raw)
        if not matches(out / name, digest):
            write_bytes(staged(out, name, digest), raw)
    for w in sweep.witnesses:
        files[w["trace"]] = file_digest(out / w["trace"])
    write_json(sweep.json_path, seal({**sweep.to_json(), "files": files}))
    for name in blobs:
        if staged(out, name, files[name]).exists():
            try:
                os.replace(staged(out, name, files[name]), out / name)
            except OSError as exc:
                raise OutputFailed(os_error_text(out / name, exc)) from None
    for stale in [*out.glob(".status-*.npz"), *out.glob(".known-*.npz")]:  # saves killed before their manifest
        with contextlib.suppress(OSError):
            stale.unlink()


def resume(sweep: Sweep) -> bool:
    """Load a saved sweep with the same settings; ``False`` if there is none. A saved sweep with other
    settings is refused (it is not this sweep's to overwrite), and so is one whose files do not match
    the digests ``sweep.json`` records (or, for a sweep saved before digests, whose ``status.npz`` does
    not match the counts ``sweep.json`` records): never a verdict nobody computed."""
    out = sweep.out
    if not sweep.json_path.exists():
        return False
    where = f"out={str(out)!r}: sweep.json"
    data = load_json(sweep.json_path, what=where, expected="the sweep.json fatline sweep wrote (or a new --out)")
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise InvalidInput(f"out={str(out)!r}: sweep.json there is not a fatline sweep; expected a new --out")
    digests = data.get("files") if sealed(data, sweep.json_path) else None
    if data.get("fingerprint") != sweep.fingerprint():
        raise InvalidInput(
            f"out={str(out)!r}: holds a sweep with other settings (model, --vary, --lemma or bounds); "
            "expected another --out, or the same settings to resume it"
        )
    witnesses, checks, replays = data.get("witnesses"), data.get("checks"), data.get("replays", 0)
    pending = _pending(sweep, data.get("pending"))
    traces = (
        {w["trace"] for w in witnesses} if isinstance(witnesses, list) and all(map(_witness_ok, witnesses)) else None
    )
    if (
        traces is None
        or not isinstance(checks, list)
        or not isinstance(replays, int)
        or pending is None
        or (
            digests is not None
            and (
                not isinstance(digests, dict)
                or set(digests) not in ({STATUS_FILE, *traces}, {STATUS_FILE, KNOWN_FILE, *traces})
            )
        )
    ):
        raise InvalidInput(
            f"{where}: witnesses, checks, replays, pending or files malformed; expected the file fatline sweep wrote"
        )
    if digests is not None:
        for name in ARRAYS:
            roll_forward(out, name, digests.get(name))
        for name, digest in digests.items():
            if not matches(out / name, digest):
                raise OutputFailed(
                    f"{(out / name).as_posix()}: its content does not match the digest sweep.json records "
                    "(changed since fatline sweep wrote it); expected the sweep as fatline left it, or a new --out"
                )
    status = _read_status(sweep)
    known = _read_known(sweep, digests[KNOWN_FILE]) if digests is not None and KNOWN_FILE in digests else {}
    sweep.status.update(status)
    sweep.known.clear()
    sweep.known.update(known)
    assert isinstance(witnesses, list)  # checked above
    sweep.witnesses = list(witnesses)
    sweep.checks = list(checks)
    sweep.replays = replays
    sweep.pending, sweep.absorbed = pending
    if digests is None:  # saved before digests: its counts must be the ones sweep.json records
        _agrees(sweep, data)
    return True


def _witness_ok(w: object) -> bool:
    """A witness entry names a trace inside ``traces/`` of one of the sweep's lemmas."""
    if not isinstance(w, dict) or w.get("lemma") not in {lemma.value for lemma in CHECKED}:
        return False
    trace = w.get("trace")
    return isinstance(trace, str) and re.fullmatch(rf"traces/{re.escape(w['lemma'])}-\d+\.json", trace) is not None


def _pending(sweep: Sweep, value: object) -> tuple[list[dict[str, int]], list[Lemma]] | None:
    """The check under way as saved (``None`` in the file: none), or ``None`` if malformed: combinations
    of this sweep's space, and lemmas of this sweep, each once, closed from the first."""
    if value is None:
        return [], []
    if not isinstance(value, dict) or set(value) != {"combos", "absorbed"}:
        return None
    combos, absorbed = value["combos"], value["absorbed"]
    names, sizes = sweep.space.names, sweep.space.sizes
    mine = {lemma.value: lemma for lemma in sweep.lemmas}
    if (
        not isinstance(combos, list)
        or not combos
        or not isinstance(absorbed, list)
        or len(set(map(str, absorbed))) != len(absorbed)
        or not all(isinstance(a, str) and a in mine for a in absorbed)
    ):
        return None
    for combo in combos:
        if not isinstance(combo, dict) or list(combo) != list(names):
            return None
        if not all(type(v) is int and 0 <= v < size for v, size in zip(combo.values(), sizes, strict=True)):
            return None
    return [dict(c) for c in combos], [mine[a] for a in absorbed]


def _read_status(sweep: Sweep) -> dict[Lemma, np.ndarray]:
    out = sweep.out
    try:
        raw = read_regular(out / STATUS_FILE)
        with np.load(io.BytesIO(raw), allow_pickle=False) as saved:
            loaded = {lemma: saved[lemma.value] for lemma in sweep.lemmas}
    except (NotReadable, KeyError, ValueError, OSError, EOFError, zipfile.BadZipFile) as exc:
        raise InvalidInput(
            f"out={str(out)!r}: status.npz cannot be read ({exc}); expected the sweep as fatline left it"
        ) from None
    status = {}
    for lemma, got in loaded.items():
        if got.shape != sweep.status[lemma].shape or got.dtype.kind not in "iu" or (len(got) and got.max() > 3):
            raise InvalidInput(f"out={str(out)!r}: status.npz does not match sweep.json")
        status[lemma] = got.astype(np.uint8)
    return status


def _read_known(sweep: Sweep, digest: str) -> dict[Where, np.ndarray]:
    """``known.npz``, its bytes checked against ``digest`` as read (not only before)."""
    path = sweep.out / KNOWN_FILE
    bad = f"{path.as_posix()}: not the known states fatline sweep saved; expected the sweep as fatline left it"
    try:
        raw = read_regular(path)
        if bytes_digest(raw) != digest:
            raise OutputFailed(
                f"{path.as_posix()}: its content does not match the digest sweep.json records "
                "(changed since fatline sweep wrote it); expected the sweep as fatline left it, or a new --out"
            )
        with np.load(io.BytesIO(raw), allow_pickle=False) as saved:
            arrays = {name: saved[name] for name in saved.files}
    except (NotReadable, KeyError, ValueError, OSError, EOFError, zipfile.BadZipFile) as exc:
        raise InvalidInput(f"{bad} ({exc})") from None
    where = arrays.pop("where", None)
    if where is None or where.dtype != np.int64 or where.ndim != 2 or where.shape[1] != 5:
        raise InvalidInput(bad)
    if set(arrays) != {f"k{i}" for i in range(len(where))}:
        raise InvalidInput(bad)
    known: dict[Where, np.ndarray] = {}
    for i, row in enumerate(where.tolist()):
        keys = arrays[f"k{i}"]
        n, bw, bh, ww, wh = row
        if keys.ndim != 1 or keys.dtype.kind not in "iuV" or min(row) < 1:
            raise InvalidInput(bad)
        if keys.dtype.kind in "iu" and len(keys) > 1 and not bool(np.all(keys[1:] > keys[:-1])):
            raise InvalidInput(bad)
        known[(n, (bw, bh), (ww, wh))] = keys
    if len(known) != len(where):
        raise InvalidInput(bad)
    return known


def _agrees(sweep: Sweep, data: dict[str, Any]) -> None:
    """A sweep saved before digests: each lemma's counts (and first readings where it holds) in
    ``status.npz`` must be those ``sweep.json`` records beside them."""
    recorded = {s.get("lemma"): s for s in data.get("lemmas", []) if isinstance(s, dict)}
    for lemma in sweep.lemmas:
        mine, theirs = sweep.lemma_summary(lemma), recorded.get(lemma.value, {})
        keys = ("refuted", "holds", "inconclusive", "open", "holds_under")
        if any(mine[k] != theirs.get(k) for k in keys):
            raise OutputFailed(
                f"{(sweep.out / STATUS_FILE).as_posix()}: does not match the counts sweep.json records for "
                f"{lemma.value} (changed since fatline sweep wrote it); expected the sweep as fatline left it, "
                "or a new --out"
            )
