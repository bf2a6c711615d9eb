"""``fatline prove MODEL --emit DIR``: the SMT-LIB2 of every obligation, regenerated from the code byte
for byte as the prover writes it, and checked against the digest its results row recorded
(``smt2_sha256``).

The obligation files are not kept in git: they follow from the code, the model and the settings
(:mod:`fatline_verify.prove.digests`), so a row's fingerprint and the file's digest say everything a
reader needs to trust that the file regenerated here is the one the row was decided on. Each
obligation is built as its kind's prover builds it (:func:`obligation_text`; ``tests/test_emit.py``
holds the two to the same bytes) but not solved: seconds for a model, where proving takes minutes.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..model.config import Model
from ..outputs import NotReadable, read_regular, write_text
from .digests import kind_of, text_sha256

MATCH, DIFFERS, NO_DIGEST, NO_ROW = "matches", "differs", "no digest", "no row"
"""How an emitted obligation compares with its results row."""


def obligation_path(task: Any) -> str:
    """Where the prover writes ``task``'s obligation under ``OUT/MODEL``: ``LEMMA/FORM-CASE.smt2``
    (Lemma 1's global form: ``connectivity/global.smt2``)."""
    if kind_of(task) == "global":
        return f"{task.lemma}/global.smt2"
    return f"{task.lemma}/{task.key.split('/', 1)[1]}.smt2"


def obligation_text(model: Model, task: Any, *, slots: int) -> tuple[str, str] | None:
    """``(path under OUT/MODEL, SMT-LIB2 text)`` of ``task`` as the prover writes it, or ``None`` for an
    obligation without a file (the liveness cases' coverage, a case the encoding refuses)."""
    from .smt.cases import Arith
    from .smt.solving import smt2

    kind = kind_of(task)
    name = obligation_path(task)
    if kind == "case":
        from .smt.claims import NotEncoded, argument, build
        from .tasks import PAPER_PART_NOTE, paper_part

        part = paper_part(model)
        try:
            full = build(Arith(None), part, task)
        except NotEncoded:
            return None
        note = PAPER_PART_NOTE if model.options.repaired else ""
        full.comment = argument(part, task, full) + (f"\n{note}" if note else "")
        return name, smt2(full)
    if kind == "leg":
        from ..rules import registry
        from .smt.family import argument as family_argument
        from .smt.family import build as build_family

        family = registry.family(model)
        # a family decided on the model's lattice (``lattice``) is built there, as prove_family builds it
        full = build_family(Arith(model.parameters.q if family.lattice else None), model, family, task)
        full.comment = family_argument(model, family, task, full)
        return name, smt2(full)
    if kind == "live":
        from .live import _case
        from .smt.liveness import ENABLED, build_enabled, build_measure, header

        case = _case(model, task)
        enabled = task.form == ENABLED
        q = model.parameters.q
        full = (build_enabled if enabled else build_measure)(Arith(None) if enabled else Arith(q), model, case)
        full.comment = header(model, task, case, full, lattice=None if enabled else q)
        return name, smt2(full)
    if kind == "global":
        from .smt import obligations as ob

        return name, ob.smt2(ob.build_global(model, slots))
    return None


@dataclass(frozen=True, slots=True)
class Emitted:
    """One obligation written by ``--emit``: its key, its file and how it compares with its row."""

    key: str
    path: Path
    status: str


def is_obligation(path: Path) -> bool:
    """Whether the existing file ``path`` looks like an obligation fatline wrote (its argument as a
    comment header, then SMT-LIB2): only such a file is rewritten by ``--emit``."""
    try:
        head = read_regular(path, limit=1 << 16, head=True).decode("utf-8", errors="replace")
    except (NotReadable, OSError):
        return False
    return (head.startswith(";") and "(set-logic " in head) or head.startswith("(set-logic ")


def emit(model: Model, tasks: list[Any], rows: dict[str, dict[str, Any]], out: Path, *, slots: int) -> list[Emitted]:
    """Write every obligation of ``tasks`` under ``out`` (``out/LEMMA/NAME.smt2``) and compare each file's
    digest with the ``smt2_sha256`` of its row in ``rows`` (by key)."""
    done: list[Emitted] = []
    for task in tasks:
        got = obligation_text(model, task, slots=slots)
        if got is None:
            continue
        name, text = got
        path = out / name
        write_text(path, text)
        row = rows.get(task.key)
        if row is None:
            status = NO_ROW
        elif not row.get("smt2_sha256"):
            status = NO_DIGEST
        else:
            status = MATCH if row["smt2_sha256"] == text_sha256(text) else DIFFERS
        done.append(Emitted(task.key, path, status))
    return done


def emit_lines(done: list[Emitted], out: Path) -> list[str]:
    """What ``--emit`` prints: a line per obligation that does not match its row, then the counts."""
    lines = [f"{e.status}: {e.key} ({e.path.as_posix()})" for e in done if e.status != MATCH]
    counts = {s: sum(e.status == s for e in done) for s in (MATCH, DIFFERS, NO_DIGEST, NO_ROW)}
    said = ", ".join(f"{n} {s}" for s, n in counts.items() if n)
    lines.append(
        f"{len(done)} obligations written to {out.as_posix()} (SMT-LIB2, each with its argument); against the "
        f"digests their results rows recorded: {said or 'none'}"
    )
    return lines


__all__ = [
    "DIFFERS",
    "MATCH",
    "NO_DIGEST",
    "NO_ROW",
    "Emitted",
    "emit",
    "emit_lines",
    "is_obligation",
    "obligation_path",
    "obligation_text",
]
