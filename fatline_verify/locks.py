"""One run at a time per output directory: an advisory lock on the directory itself.

``flock(2)`` on the directory's own file descriptor: nothing is written into the directory for it (no
lock file to refuse, commit or clean up), and the operating system lets go when the process ends,
however it ends, so a killed run never leaves a stale lock behind. A run that writes a whole
directory (``check --checkpoint``, a sweep's ``OUT/MODEL``, ``report --out``) holds its directory for
the whole run, and a second run into it is refused in one line before any work; ``prove`` holds its
``OUT/MODEL`` only while it re-reads, merges and rewrites ``results.json`` (so two runs into one
``--out`` both keep their rows). Where ``fcntl`` does not exist the lock is a no-op.
"""

from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Iterator
from pathlib import Path

from .errors import InvalidInput, OutputFailed
from .outputs import os_error_text

try:
    import fcntl
except ImportError:  # pragma: no cover - not POSIX
    fcntl = None  # type: ignore[assignment]


@contextlib.contextmanager
def holding(directory: Path, *, name: str, wait: float = 0.0) -> Iterator[None]:
    """Hold ``directory`` (created if missing) for the ``with`` block: exclusively, against every other
    process (and every other holder in this one). If another holds it, wait up to ``wait`` seconds,
    then refuse in one line naming ``name`` (the flag the directory came from)."""
    created = []  # removed again at the end if still empty (a refused run leaves no directory behind)
    for parent in [directory, *directory.parents]:
        if parent.exists():
            break
        created.append(parent)
    try:
        directory.mkdir(parents=True, exist_ok=True)
        fd = os.open(directory, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise OutputFailed(os_error_text(directory, exc)) from None
    try:
        if fcntl is not None:
            deadline = time.monotonic() + wait
            while True:
                try:
                    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                    break
                except BlockingIOError:
                    if time.monotonic() >= deadline:
                        raise InvalidInput(
                            f"{name}={directory.as_posix()!r}: in use by another fatline run; expected that run to "
                            "finish first, or another directory"
                        ) from None
                    time.sleep(0.05)
        yield
    finally:
        os.close(fd)  # closing the descriptor lets go of the lock
        for made in created:
            try:
                os.rmdir(made)
            except OSError:
                break


__all__ = ["holding"]
