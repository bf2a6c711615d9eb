"""Content digests (SHA-256) of the files the tool reads back, checked on load.

A result read back is shown as a verdict, so a file changed after the tool wrote it (a flipped bit, a
hand edit, half a save) must not be: each JSON file the tool reads back carries ``"digest"``, the
SHA-256 of its own content (canonical JSON: keys sorted, no spaces, the digest itself left out, so
re-indenting the file does not matter but any value does); a save that spans several files writes one
manifest last, naming the digest of every other file (:func:`file_digest`). A mismatch is a one-line
refusal naming the file (:class:`~fatline_verify.errors.OutputFailed`), never a verdict.

A digest stored beside the data detects corruption and edits that do not recompute it; it is not a
signature. So verdicts are also re-derived from evidence where that is cheap (a VIOLATED row needs a
trace that replays, and no PROVED or HOLDS row may stand beside a replaying counterexample of its
claim): see :mod:`fatline_verify.prove.results` and :mod:`fatline_verify.report.build`.

Files written before digests existed (the committed ``proofs/*/results.json``, ``reports/*/check.json``
and ``docs/sweep``) carry none: they are read as before, checked against their evidence, and get a
digest with their next save.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

from .errors import OutputFailed

FIELD = "digest"
PREFIX = "sha256:"


def _canonical(data: dict[str, Any]) -> bytes:
    body = {k: v for k, v in data.items() if k != FIELD}
    return json.dumps(body, sort_keys=True, separators=(",", ":"), ensure_ascii=True).encode()


def json_digest(data: dict[str, Any]) -> str:
    """``sha256:HEX`` of the document's content, its own ``digest`` field left out."""
    return PREFIX + hashlib.sha256(_canonical(data)).hexdigest()


def seal(data: dict[str, Any]) -> dict[str, Any]:
    """The document with its digest, placed right after ``format`` (first if there is none)."""
    body = {k: v for k, v in data.items() if k != FIELD}
    out: dict[str, Any] = {}
    if "format" not in body:
        out[FIELD] = json_digest(body)
    for key, value in body.items():
        out[key] = value
        if key == "format":
            out[FIELD] = json_digest(body)
    return out


def sealed(data: dict[str, Any], where: Path | str) -> bool:
    """Whether ``data`` carries a digest (``False``: written before digests existed); a digest that
    does not match its content is :class:`OutputFailed` naming ``where``."""
    if FIELD not in data:
        return False
    if data[FIELD] != json_digest(data):
        raise OutputFailed(
            f"{Path(where).as_posix()}: its content does not match its digest (changed since fatline wrote it); "
            "expected the file as fatline left it (move it away to recompute it)"
        )
    return True


def bytes_digest(data: bytes) -> str:
    return PREFIX + hashlib.sha256(data).hexdigest()


def file_digest(path: Path) -> str:
    """``sha256:HEX`` of a file's bytes."""
    with path.open("rb") as fh:
        return PREFIX + hashlib.file_digest(fh, "sha256").hexdigest()


def matches(path: Path, digest: object) -> bool:
    """Whether the file at ``path`` is a regular file whose bytes have ``digest``."""
    try:
        return path.is_file() and file_digest(path) == digest
    except OSError:
        return False


def is_digest(value: object) -> bool:
    return isinstance(value, str) and value.startswith(PREFIX) and len(value) == len(PREFIX) + 64


__all__ = ["bytes_digest", "file_digest", "is_digest", "json_digest", "matches", "seal", "sealed"]
