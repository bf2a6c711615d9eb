"""Checkpoints of a breadth-first search: one file per level, written atomically, and a manifest.

docs/checker.md, "Shards, workers, checkpoints, memory": after each BFS level, the visited shards, the
frontier and the counters are written atomically under ``--checkpoint DIR``; running the same command
again continues to the identical result, and a run killed at any instant loses at most one level of
work. The visited set is the union of the levels' keys and the frontier is the last level, so the level
files are the shards: ``level-00000.npz`` holds the initial keys, ``level-L.npz`` the states first
reached at depth L (keys, parents, actions) and the expansion of level L-1 (per state: enabled, goal;
the summary of its transitions: counts and the least violating one per flag bit). Each file is written
to a temporary name (unique to the process) and renamed, then ``manifest.json`` (likewise, last) records
how many levels are complete and the SHA-256 of every level file; a level file beyond the manifest is
the remains of a killed write and is written again, and a level file (or a manifest) whose content does
not match its digest is refused in one line, never searched on from (a flipped bit in a transition's
flags would otherwise be a verdict nobody computed). The manifest names the run — model, robots, bound,
a digest of the initial keys, ``after_violation`` — and a directory holding another run is refused; the
engine and the number of workers are not part of it (they do not change the result), nor are the limits:
a run stopped by ``--max-states`` resumes further with a larger one.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import re
import tempfile
import zipfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import __version__
from ..errors import InvalidInput, OutputFailed
from ..integrity import bytes_digest, is_digest, seal, sealed
from ..model.config import Model, model_to_mapping
from ..outputs import MAX_READ, NotReadable, os_error_text, parse_json, read_regular, write_bytes
from ..resources import machine_memory
from .shard import COLUMNS, SUMMARY_LENGTH

if TYPE_CHECKING:
    from .search import _Records

FORMAT = "fatline-checkpoint"
VERSION = 4
"""4: a level's transitions as a summary (the compact store); 3: every transition's columns; 3 and
earlier: refused (3 has no summaries; 2 no digests, not trusted)."""
MANIFEST = "manifest.json"
_LEVEL = ("keys", "parent", "paction")
_EXPANSION = COLUMNS


class Checkpoint:
    """The checkpoint directory of one search (``directory=None``: no checkpoint, every method is a no-op)."""

    def __init__(
        self,
        directory: Path | None,
        model: Model,
        n: int,
        bound: tuple[int, int],
        initial: np.ndarray,
        after_violation: str,
    ) -> None:
        self.directory = directory
        self.run = {
            "tool": __version__,
            "model": model_to_mapping(model),
            "robots": n,
            "bound": list(bound),
            "initial": hashlib.sha256(np.ascontiguousarray(initial).tobytes()).hexdigest(),
            "initial_count": len(initial),
            "after_violation": after_violation,
        }
        self.digests: dict[str, str] = {}

    # --- reading ---------------------------------------------------------------------------------
    def _where(self, name: str = "") -> str:
        assert self.directory is not None
        return f"checkpoint={(self.directory / name if name else self.directory).as_posix()!r}"

    def _manifest(self) -> dict[str, Any] | None:
        assert self.directory is not None
        path = self.directory / MANIFEST
        if not path.exists():
            stray = sorted(self.directory.glob("level-*.npz")) if self.directory.is_dir() else []
            if stray:
                raise InvalidInput(
                    f"checkpoint={self.directory.as_posix()!r}: holds {stray[0].name} but no {MANIFEST}; expected a "
                    "checkpoint directory written by fatline check, or an empty one"
                )
            return None
        try:
            doc = parse_json(read_regular(path))
        except (NotReadable, ValueError) as exc:
            raise InvalidInput(
                f"{self._where(MANIFEST)}: {exc}; expected the manifest fatline check wrote (or an empty directory)"
            ) from None
        if not isinstance(doc, dict) or doc.get("format") != FORMAT:
            raise InvalidInput(
                f"checkpoint={self.directory.as_posix()!r}: {MANIFEST} was not written by fatline check; expected a "
                "checkpoint directory or an empty one"
            )
        if doc.get("version") != VERSION:
            raise InvalidInput(
                f"{self._where(MANIFEST)}: version={str(doc.get('version'))[:20]!r} (written by another version of "
                f"fatline, whose level files version {VERSION} does not read); "
                "expected an empty directory to start afresh"
            )
        if not sealed(doc, self.directory / MANIFEST):
            raise OutputFailed(
                f"{(self.directory / MANIFEST).as_posix()}: no digest; expected the manifest as fatline check wrote it"
            )
        if doc.get("run") != self.run:
            run = doc.get("run")
            theirs: dict[str, Any] = run if isinstance(run, dict) else {}
            model: dict[str, Any] = theirs["model"] if isinstance(theirs.get("model"), dict) else {}
            raise InvalidInput(
                f"checkpoint={self.directory.as_posix()!r}: holds another search (robots={theirs.get('robots')}, "
                f"bound={theirs.get('bound')}, model {model.get('name')!r}); expected the same "
                "command that wrote it, or an empty directory"
            )
        levels, files = doc.get("levels"), doc.get("files")
        if (
            not isinstance(levels, int)
            or isinstance(levels, bool)
            or levels < -1
            or not isinstance(files, dict)
            or any(not is_digest(files.get(self._level_path(k).name)) for k in range(levels + 1))
        ):
            raise InvalidInput(
                f"{self._where(MANIFEST)}: levels={str(levels)[:20]!r} without a digest of each level file; expected "
                "the manifest as fatline check wrote it"
            )
        return doc

    def load(self, rec: _Records) -> bool:
        """Fill ``rec`` with the saved levels; False when there is nothing to resume. Every level file
        must have the digest the manifest records for it."""
        if self.directory is None:
            return False
        doc = self._manifest()
        if doc is None or doc["levels"] < 0:
            return False
        self.digests = dict(doc["files"])
        for level in range(doc["levels"] + 1):
            path = self._level_path(level)
            if not path.is_file():
                raise InvalidInput(
                    f"checkpoint={self.directory.as_posix()!r}: {MANIFEST} records {doc['levels'] + 1} levels but "
                    f"{path.name} is missing; expected the directory as fatline check left it, or "
                    "an empty one"
                )
            try:
                data = read_regular(path, limit=max(MAX_READ, machine_memory()))  # a level the search held
            except NotReadable as exc:
                raise InvalidInput(
                    f"{self._where(path.name)}: {exc}; expected a level file fatline check wrote"
                ) from None
            if bytes_digest(data) != self.digests[path.name]:
                raise OutputFailed(
                    f"{path.as_posix()}: its content does not match the digest {MANIFEST} records (changed since "
                    "fatline check wrote it); expected the directory as fatline check left it, or an empty one"
                )
            arrays = self._arrays(path, data, level)
            if level:
                rec.add_expansion_arrays(*(arrays[f] for f in _EXPANSION))
            rec.add_level(*(arrays[f] for f in _LEVEL))
        return True

    def _arrays(self, path: Path, data: bytes, level: int) -> dict[str, np.ndarray]:
        """The columns of one level file, each one-dimensional, those of a level (and of an expansion)
        of one length."""
        names = _LEVEL + (_EXPANSION if level else ())
        try:
            with np.load(io.BytesIO(data), allow_pickle=False) as saved:
                arrays = {f: saved[f] for f in names}
        except (KeyError, ValueError, OSError, EOFError, zipfile.BadZipFile) as exc:
            raise InvalidInput(
                f"{self._where(path.name)}: not a level file ({exc.__class__.__name__}); expected the directory as "
                "fatline check left it, or an empty one"
            ) from None
        same = [("keys", "parent", "paction")] + ([("enabled", "goal")] if level else [])
        if (
            any(a.ndim != 1 for a in arrays.values())
            or any(len({len(arrays[f]) for f in group}) > 1 for group in same)
            or (level and arrays["summary"].shape != (SUMMARY_LENGTH,))
        ):
            raise InvalidInput(
                f"{self._where(path.name)}: its columns do not fit together; expected the directory as fatline check "
                "left it, or an empty one"
            )
        return arrays

    # --- writing ---------------------------------------------------------------------------------
    def _level_path(self, level: int) -> Path:
        assert self.directory is not None
        return self.directory / f"level-{level:05d}.npz"

    def _write_manifest(self, levels: int) -> None:
        """Record ``levels`` complete levels and the digest of each (written last, after the level files)."""
        assert self.directory is not None
        files = {self._level_path(k).name: self.digests[self._level_path(k).name] for k in range(levels + 1)}
        doc = seal({"format": FORMAT, "version": VERSION, "run": self.run, "levels": levels, "files": files})
        write_bytes(self.directory / MANIFEST, (json.dumps(doc, indent=1) + "\n").encode())

    def start(self, rec: _Records) -> None:
        """A fresh search: claim the directory, then save the initial level."""
        if self.directory is None:
            return
        self.directory.mkdir(parents=True, exist_ok=True)
        self._manifest()  # refuses a directory holding something else
        self._write_manifest(-1)
        self.save_level(rec, 0)

    def save_level(self, rec: _Records, level: int) -> None:
        """Save level ``level`` (and the expansion that reached it), then record it as complete."""
        if self.directory is None:
            return
        arrays = {f: getattr(rec, f)[level] for f in _LEVEL}
        if level:
            arrays |= {f"{f}": getattr(rec, f)[level - 1] for f in _EXPANSION}
        buffer = io.BytesIO()
        np.savez(buffer, **arrays)
        data = buffer.getvalue()
        write_bytes(self._level_path(level), data)
        self.digests[self._level_path(level).name] = bytes_digest(data)
        self._write_manifest(level)


def _ours(name: str) -> bool:
    """A file a checkpoint writes: the manifest, a level file, or the temporary file of either (the
    remains of a killed write, or of a write a full disk stopped: ``.NAME.tmp`` or ``.NAME.XXXXXXXX.tmp``)."""
    return (
        name == MANIFEST
        or re.fullmatch(r"level-\d{5}\.npz", name) is not None
        or re.fullmatch(r"\.(manifest\.json|level-\d{5}\.npz)(\.[A-Za-z0-9_]+)?\.tmp", name) is not None
    )


def claim_checkpoint(root: Path, counts: range) -> None:
    """Refuse, before any work, a ``--checkpoint`` directory the searches of ``counts`` cannot use: one
    that holds anything but their ``n<robots>`` directories, a ``n<robots>`` that holds anything but
    checkpoint files, or one that cannot be created and written."""
    label = f"checkpoint={root.as_posix()!r}"
    if root.exists() and not root.is_dir():
        raise InvalidInput(f"{label}: is a file; expected a directory for the search's checkpoints")
    if root.is_dir():
        foreign = [p.name for p in root.iterdir() if not (p.is_dir() and re.fullmatch(r"n\d+", p.name))]
        if foreign:
            raise InvalidInput(f"{label}: holds {sorted(foreign)[0]!r}, not a checkpoint; expected an empty directory")
    for n in counts:
        sub = root / f"n{n}"
        if sub.exists() and not sub.is_dir():
            raise InvalidInput(f"{label}: {sub.name} is a file; expected the checkpoint directory of {n} robots")
        if sub.is_dir():
            foreign = [p.name for p in sub.iterdir() if not _ours(p.name)]
            if foreign:
                raise InvalidInput(
                    f"{label}: {sub.name}/{sorted(foreign)[0]} is not a checkpoint file; expected an empty directory"
                )
        try:
            sub.mkdir(parents=True, exist_ok=True)
            fd, probe = tempfile.mkstemp(prefix=".level-00000.npz.", suffix=".tmp", dir=sub)
            os.close(fd)
            os.unlink(probe)
        except OSError as exc:
            raise InvalidInput(
                f"{label}: cannot write there ({os_error_text(None, exc)}); expected a writable directory"
            ) from None


__all__ = ["FORMAT", "Checkpoint", "claim_checkpoint"]
