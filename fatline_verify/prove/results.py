"""``proofs/MODEL/results.json``: one row per obligation, merged, saved as each obligation finishes.

Nothing is lost: a partial run (``prove --lemma``, a report that recomputes some rows) replaces only
the rows it recomputed and keeps every other row; an interrupted run has saved every row it
finished. Each row carries the fingerprint of what produced it (model, slots, budget, encoding), so
a reader can tell an up-to-date row from a stale one, row by row. Counterexample traces are never
deleted: a trace that a later, weaker run no longer finds still replays, and stays.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..model.config import Model
from ..outputs import Kind, is_output, read_json, write_json
from ..trace.traces import write_trace
from .prover import NotEncodedModel, ProofResult, Task, prove_fingerprint, task_key, tasks_for, witness_path
from .smt.solving import solver_version
from .tasks import row_key


class ProofResults:
    """The merged results of one model's obligations, saved atomically after every change."""

    def __init__(self, model: Model, directory: Path, traces: Path, *, slots: int, timeout: float) -> None:
        self.model = model
        self.path = directory / "results.json"
        self.traces = traces
        self.slots, self.timeout = slots, timeout
        self.fingerprint = prove_fingerprint(model, slots, timeout)
        self.rows: dict[str, dict[str, Any]] = {}
        old = read_json(self.path) if self.path.is_file() and is_output(self.path, Kind.PROVE) else None
        if old and old.get("model") == model.name:
            for row in old.get("obligations", []):
                self.rows[row_key(row)] = {"fingerprint": old.get("fingerprint"), **row}

    def witness_paths(self, tasks: list[Task]) -> list[Path]:
        """The trace files proving ``tasks`` may write (checked before the run)."""
        return [witness_path(self.model, self.traces, task_key(t)) for t in tasks]

    def fresh(self, task: Task) -> dict[str, Any] | None:
        """The saved row of ``task`` if it was produced with the current settings."""
        row = self.rows.get(task_key(task))
        return row if row is not None and row.get("fingerprint") == self.fingerprint else None

    def verdict(self, task: Task) -> str | None:
        """The saved verdict of ``task`` (whatever settings produced it), ``None`` without a row."""
        row = self.rows.get(task_key(task))
        return None if row is None else str(row.get("verdict"))

    def add(self, r: ProofResult) -> None:
        """Record one finished obligation (its trace first, then the row), and save."""
        key = r.key
        trace = None
        if r.witness is not None:
            path = witness_path(self.model, self.traces, key)
            write_trace(r.witness, path)
            trace = path.as_posix()
        self.rows[key] = {
            "fingerprint": self.fingerprint,
            "lemma": r.lemma,
            "form": r.form,
            "rule": r.rule,
            "case": r.case,
            "other": r.other,
            "verdict": r.verdict.value,
            "slots": r.slots,
            "timeout": self.timeout,
            "any_size": r.any_size,
            "seconds": round(r.seconds, 2),
            "reason": r.reason,
            "smt2": r.smt2,
            "trace": trace,
            "configuration": list(r.configuration),
        }
        self.save()

    def ordered(self, keys: list[str] | None = None) -> list[dict[str, Any]]:
        """The rows of ``keys`` (default: every row), the model's own obligations first, in task order."""
        try:
            order = [task_key(t) for t in tasks_for(self.model, two_movers=True)]
        except NotEncodedModel:
            order = []
        wanted = list(self.rows) if keys is None else keys
        rank = {k: i for i, k in enumerate(order)}
        return [self.rows[k] for k in sorted(wanted, key=lambda k: rank.get(k, len(order))) if k in self.rows]

    def document(self, keys: list[str] | None = None) -> dict[str, Any]:
        """``results.json`` (or, with ``keys``, the part of it one run produced)."""
        rows = self.ordered(keys)
        prints = {row.get("fingerprint") for row in rows}
        return {
            "format": Kind.PROVE.value,
            "model": self.model.name,
            "solver": solver_version(),
            "fingerprint": prints.pop() if len(prints) == 1 else None,
            "obligations": rows,
        }

    def save(self) -> None:
        write_json(self.path, self.document())


__all__ = ["ProofResults", "witness_path"]
