"""The linear certificates a results file's rows recorded, regenerated where they are missing, and each
held to its row's digest (``certificate_sha256``, and ``smt2_sha256`` for the obligation beside it).

A certificate (``.linear.smt2``) is the linear problem the linearization ended with when it found a
per-case obligation unsat (:mod:`fatline_verify.prove.smt.linearize`). It is not kept in git: the
search that writes it spends a deterministic budget (z3's resource count), so the same code, model,
settings and solver write the same bytes, which the row's digest checks. Regenerating one runs that
obligation's search again (:func:`fatline_verify.prove.search.prove_spec`, each in its own process as
``fatline prove`` runs it) into a scratch directory, compares both files with the row's digests, and
only then puts them beside ``results.json`` (never over a file that is there).
"""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..outputs import Kind, is_output, load_json

UNHURRIED = 10.0
"""A regenerating check is stopped by the wall clock at this many times its budget (the prover: 1.5),
so that only z3's resource count stops it: on a loaded machine a clock stop changes the search's path
and so the certificate's cuts, not its verdict."""


def prove_unhurried(model: Any, task: Any, **kwargs: Any) -> Any:
    """:func:`fatline_verify.prove.search.prove_spec` with the wall clock out of the way (:data:`UNHURRIED`):
    the budgets are as the prover's (z3's resource count, the same on every machine), only the clock's
    stop is later. Runs in a process of its own (it sets the clock for that process)."""
    from .search import prove_spec
    from .smt import linearize, solving

    def unhurried(seconds: float) -> int:
        return int(1000 * (UNHURRIED * seconds + solving.WALL_SLACK))

    solving.wall_ms = unhurried  # type: ignore[assignment]
    linearize.wall_ms = unhurried  # type: ignore[assignment]
    return prove_spec(model, task, **kwargs)


@dataclass(frozen=True, slots=True)
class Wanted:
    """A row's certificate: where it belongs, the digests its row recorded, and how to regenerate it."""

    key: str
    obligation: Path
    certificate: Path
    smt2_sha256: str
    certificate_sha256: str
    model: Any
    task: Any
    timeout: float


def wanted(results: Path) -> list[Wanted]:
    """Every certificate the rows of ``results`` (a ``results.json`` fatline prove wrote) recorded."""
    from ..model.config import load_model
    from .emit import obligation_path
    from .tasks import NotEncodedModel, row_key, task_key, tasks_for

    if not is_output(results, Kind.PROVE):
        return []
    data = load_json(results, what=results.as_posix(), expected="the results.json fatline prove wrote")
    rows = [r for r in data.get("obligations", []) if isinstance(r, dict) and r.get("certificate_sha256")]
    if not rows:
        return []
    model = load_model(str(data.get("model")))
    try:
        tasks = {task_key(t): t for t in tasks_for(model, two_movers=True)}
    except NotEncodedModel:
        return []
    out = []
    for row in rows:
        task = tasks.get(row_key(row))
        if task is None:
            continue
        obligation = results.parent / obligation_path(task)
        out.append(
            Wanted(
                row_key(row),
                obligation,
                obligation.with_suffix(".linear.smt2"),
                str(row.get("smt2_sha256", "")),
                str(row["certificate_sha256"]),
                model,
                task,
                float(row.get("timeout", 60.0)),
            )
        )
    return out


def regenerate(missing: list[Wanted], jobs: int, failed: Callable[[Path, str], None]) -> int:
    """Solve each obligation of ``missing`` again into a scratch directory and put its obligation and
    certificate in place when both match the row's digests; ``failed(path, why)`` for each that does not.
    Returns how many were put in place."""
    from ..fresh import run_fresh
    from .digests import file_sha256
    from .tasks import PAPER_PART_NOTE, paper_part

    if not missing:
        return 0
    placed = 0
    with tempfile.TemporaryDirectory(prefix="fatline-certify-") as tmp:
        calls = []
        for k, w in enumerate(missing):
            note = PAPER_PART_NOTE if w.model.options.repaired else ""
            kwargs = {"timeout": w.timeout, "out": Path(tmp) / str(k), "note": note}
            calls.append((prove_unhurried, (paper_part(w.model), w.task), kwargs))
        answers: dict[int, Any] = {}
        run_fresh(calls, max(1, jobs), lambda k, answer: answers.__setitem__(k, answer))
        for k, w in enumerate(missing):
            smt2 = Path(answers[k].smt2) if answers.get(k) is not None and answers[k].smt2 else None
            certificate = smt2.with_suffix(".linear.smt2") if smt2 is not None else None
            if certificate is None or not certificate.is_file():
                failed(w.certificate, f"solved again, {answers[k].verdict.value} without a certificate ({w.key})")
                continue
            if file_sha256(certificate) != w.certificate_sha256 or file_sha256(smt2) != w.smt2_sha256:
                failed(
                    w.certificate,
                    f"regenerated, but not the bytes its row recorded ({w.key}): the row is stale, or a check of the "
                    "run that made it was stopped by the wall clock",
                )
                continue
            for made, target in ((smt2, w.obligation), (certificate, w.certificate)):
                if not target.exists():
                    target.parent.mkdir(parents=True, exist_ok=True)
                    shutil.copyfile(made, target)
            placed += 1
    return placed


__all__ = ["UNHURRIED", "Wanted", "prove_unhurried", "regenerate", "wanted"]
