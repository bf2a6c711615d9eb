"""Checkpoints of a breadth-first search: one file per level, written atomically, and a manifest.

docs/checker.md, "Shards, workers, checkpoints, memory": after each BFS level, the visited shards, the
frontier and the counters are written atomically under ``--checkpoint DIR``; running the same command
again continues to the identical result, and a run killed at any instant loses at most one level of
work. The visited set is the union of the levels' keys and the frontier is the last level, so the level
files are the shards: ``level-00000.npz`` holds the initial keys, ``level-L.npz`` the states first
reached at depth L (keys, parents, actions) and the expansion of level L-1 (per state: enabled, goal;
per transition: source, action, successor key, flags). Each file is written to a temporary name and
renamed, then ``manifest.json`` (likewise) records how many levels are complete; a level file beyond
the manifest is the remains of a killed write and is written again. The manifest names the run — model,
robots, bound, a digest of the initial keys, ``after_violation`` — and a directory holding another run
is refused; the engine and the number of workers are not part of it (they do not change the result),
nor are the limits: a run stopped by ``--max-states`` resumes further with a larger one.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import __version__
from ..errors import InvalidInput
from ..model.config import Model, model_to_mapping
from .shard import COLUMNS

if TYPE_CHECKING:
    from .search import _Records

FORMAT = "fatline-checkpoint"
VERSION = 2
MANIFEST = "manifest.json"
_LEVEL = ("keys", "parent", "paction")
_EXPANSION = COLUMNS


def _atomic(path: Path, write: Any) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    with open(tmp, "wb") as fh:
        write(fh)
    os.replace(tmp, path)


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

    # --- reading ---------------------------------------------------------------------------------
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
            doc = json.loads(path.read_text())
        except (OSError, ValueError):
            doc = None
        if not isinstance(doc, dict) or doc.get("format") != FORMAT:
            raise InvalidInput(
                f"checkpoint={self.directory.as_posix()!r}: {MANIFEST} was not written by fatline check; expected a "
                "checkpoint directory or an empty one"
            )
        if doc.get("version") != VERSION or doc.get("run") != self.run:
            theirs = doc.get("run", {})
            raise InvalidInput(
                f"checkpoint={self.directory.as_posix()!r}: holds another search (robots={theirs.get('robots')}, "
                f"bound={theirs.get('bound')}, model {theirs.get('model', {}).get('name')!r}); expected the same "
                "command that wrote it, or an empty directory"
            )
        return doc

    def load(self, rec: _Records) -> bool:
        """Fill ``rec`` with the saved levels; False when there is nothing to resume."""
        if self.directory is None:
            return False
        doc = self._manifest()
        if doc is None or doc["levels"] < 0:
            return False
        for level in range(doc["levels"] + 1):
            if not self._level_path(level).is_file():
                raise InvalidInput(
                    f"checkpoint={self.directory.as_posix()!r}: {MANIFEST} records {doc['levels'] + 1} levels but "
                    f"{self._level_path(level).name} is missing; expected the directory as fatline check left it, or "
                    "an empty one"
                )
            with np.load(self._level_path(level), allow_pickle=False) as data:
                if level:
                    rec.add_expansion_arrays(*(data[f] for f in _EXPANSION))
                rec.add_level(*(data[f] for f in _LEVEL))
        return True

    # --- writing ---------------------------------------------------------------------------------
    def _level_path(self, level: int) -> Path:
        assert self.directory is not None
        return self.directory / f"level-{level:05d}.npz"

    def _write_manifest(self, levels: int) -> None:
        assert self.directory is not None
        doc = {"format": FORMAT, "version": VERSION, "run": self.run, "levels": levels}
        _atomic(self.directory / MANIFEST, lambda fh: fh.write((json.dumps(doc, indent=1) + "\n").encode()))

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
        _atomic(self._level_path(level), lambda fh: np.savez(fh, **arrays))
        self._write_manifest(level)


def _ours(name: str) -> bool:
    return name == MANIFEST or re.fullmatch(r"\.?level-\d{5}\.npz(\.tmp)?", name) is not None


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
            probe = sub / ".level-00000.npz.tmp"
            probe.write_bytes(b"")
            probe.unlink()
        except OSError as exc:
            raise InvalidInput(f"{label}: cannot write there ({exc.strerror}); expected a writable directory") from None


__all__ = ["FORMAT", "Checkpoint", "claim_checkpoint"]
