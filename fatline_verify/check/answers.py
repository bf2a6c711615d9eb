"""The compiled engine's answers kept between runs: the model's decisions and collision answers.

The compiled engine asks the executable model about every snapshot and pair motion it has not seen
(:mod:`.compiled`); at 5 robots that is most of a check's search time, and every run asks the same
questions again. This module keeps the answers on disk, one file per model and robot count, under
``$FATLINE_ANSWERS`` (default ``~/.cache/fatline-verify/answers``; ``off`` keeps nothing). A file is
named by a SHA-256 of the model's mapping, the robot count and **every source file that decides for
the model** (:func:`fatline_verify.provenance.model_digest`: this package's, and the package of each
plug-in rule set, step lemma, scheduler or ``model.algorithm``), so any change of a rule, of a
plug-in, of the geometry or of the engine's packing is a new name and old answers are never read (a
model whose plug-in's source cannot be read keeps nothing); its content carries its own SHA-256
(:mod:`fatline_verify.integrity`), and a file that does not match it is ignored (the model is asked
again). The answers are the model's own integers,
stored exactly; a run with them equals a run without them (tests/test_store.py).
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import zipfile
from pathlib import Path

import numpy as np

from ..integrity import bytes_digest
from ..model.config import Model, model_to_mapping
from ..outputs import write_bytes
from ..provenance import model_digest, reusable

ENV = "FATLINE_ANSWERS"


def answers_dir() -> Path | None:
    """Where answers are kept (``None``: ``$FATLINE_ANSWERS`` is ``off``)."""
    where = os.environ.get(ENV, "")
    if where.lower() == "off":
        return None
    if where:
        return Path(where)
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "fatline-verify" / "answers"


def answers_path(model: Model, n: int) -> Path | None:
    """The file of ``model``'s answers for ``n`` robots (``None``: answers are not kept, by
    ``$FATLINE_ANSWERS=off`` or because a source that decides for the model cannot be read)."""
    where = answers_dir()
    if where is None:
        return None
    source = model_digest(model)
    if not reusable(source):
        return None
    name = json.dumps({"model": model_to_mapping(model), "robots": n, "source": source}, sort_keys=True)
    return where / f"{hashlib.sha256(name.encode()).hexdigest()[:32]}.npz"


def load_answers(path: Path | None) -> dict[str, np.ndarray] | None:
    """The saved answers (``decisions``: key, dx, dy, corner rows; ``pairs``: key, collides rows), or
    ``None`` when there are none or the file does not match the digest it carries."""
    if path is None or not path.is_file():
        return None
    try:
        data = path.read_bytes()
        head, _, body = data.partition(b"\n")
        if bytes_digest(body) != head.decode("ascii"):
            return None
        with np.load(io.BytesIO(body), allow_pickle=False) as saved:
            got = {name: saved[name] for name in ("decisions", "pairs")}
    except (OSError, ValueError, KeyError, UnicodeDecodeError, EOFError, zipfile.BadZipFile):
        return None
    if got["decisions"].ndim != 2 or got["decisions"].shape[1] != 4 or got["pairs"].ndim != 2:
        return None
    if got["pairs"].shape[1] != 2:
        return None
    return got


def save_answers(path: Path | None, decisions: np.ndarray, pairs: np.ndarray) -> None:
    """Keep the answers (rows as :func:`load_answers` gives them), atomically; a failure to write is
    not an error of the check (the answers are asked again next time)."""
    if path is None:
        return
    buffer = io.BytesIO()
    np.savez(buffer, decisions=np.ascontiguousarray(decisions), pairs=np.ascontiguousarray(pairs))
    body = buffer.getvalue()
    try:
        write_bytes(path, bytes_digest(body).encode("ascii") + b"\n" + body)
    except Exception:  # a cache that cannot be written is no cache, not a failed check
        return


__all__ = ["ENV", "answers_dir", "answers_path", "load_answers", "save_answers"]
