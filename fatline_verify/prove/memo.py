"""Answers a run's obligations share: a question asked by several obligations is answered once.

The basis queries (:mod:`fatline_verify.prove.basis`) of one case are the same text under every lemma
that asks about it: "does scenario-3.down-3-after-up ever fire" is asked by ``rma-fixed/seen``,
``rma-fixed/on-rma`` and ``approach/x-nondecreasing`` alike (on the paper's model: 88 vacuity queries,
30 distinct texts; the slowest seven, each asked three times, spend their whole budget). Each
obligation runs in a fresh process (:mod:`fatline_verify.fresh`), so the run keeps the answers in a
directory of its own, one file per question, named by the digest of everything the answer depends on:
the query's SMT-LIB text, the procedure and its budget, and z3's version. A process asking a question
another is answering waits for it (an exclusive lock per question, released by the operating system if
its holder dies), then reads its answer.

So an answer read here is the answer the reader would have computed: the same text in a fresh z3
context, by the same procedure, within the same deterministic budget (z3's resource count). The
directory lives as long as one ``prove`` call: a later run, ``--fresh`` or not, asks again. Where
there is no ``fcntl`` (not POSIX), nothing is shared and every question is asked where it arises.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

T = TypeVar("T", bool, str)


def key_of(*parts: str) -> str:
    """The digest naming a question: every part it depends on, in order."""
    import z3

    digest = hashlib.sha256()
    for part in (*parts, z3.get_version_string()):
        digest.update(part.encode())
        digest.update(b"\0")
    return digest.hexdigest()


def remembered(memo: Path | None, key: str, compute: Callable[[], T]) -> T:
    """The answer to the question ``key``: read from ``memo`` if an obligation of this run answered it,
    else ``compute()``, written there for the others. Without ``memo``, ``compute()``."""
    try:
        import fcntl
    except ImportError:  # not POSIX: no lock to wait on, so nothing shared
        return compute()
    if memo is None:
        return compute()
    answer = memo / f"{key}.json"
    with open(memo / f"{key}.lock", "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when this process ends, however it ends
        try:
            if answer.exists():
                value: T = json.loads(answer.read_text())["answer"]
                return value
            value = compute()
            partial = answer.with_suffix(f".{os.getpid()}.part")
            partial.write_text(json.dumps({"answer": value}))
            partial.replace(answer)
            return value
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


__all__ = ["key_of", "remembered"]
