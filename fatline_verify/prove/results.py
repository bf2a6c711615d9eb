"""``proofs/MODEL/results.json``: one row per obligation, merged, saved as each obligation finishes.

Nothing is lost: a partial run (``prove --lemma``, a report that recomputes some rows) replaces only
the rows it recomputed and keeps every other row; an interrupted run has saved every row it
finished. Each row carries the fingerprint of what produced it (:func:`fatline_verify.prove.digests.row_digest`:
the sources of its kind of obligation, the model, the settings, the solver), and the digests of the
SMT-LIB it wrote (``smt2_sha256``; ``certificate_sha256`` for a linear certificate), which ``fatline
prove --emit`` and ``python -m fatline_verify.prove.certify`` regenerate and check. A row whose
fingerprint is not the current one is shown as STALE (:func:`stale_view`), never as current, and solved
again by the next ``fatline prove``. Counterexample traces are never
deleted: a trace that a later, weaker run no longer finds still replays, and stays.

Two runs into one ``--out`` at once both keep their rows: each save re-reads ``results.json`` under a
lock on its directory (:func:`fatline_verify.locks.holding`), merges its own new rows into what is
there and writes the whole. The file carries a digest of its content (:mod:`fatline_verify.integrity`),
checked on every read; a file without one (written before digests) is read, and gets one at its next
save. Either way a row is not believed against the evidence beside it: a PROVED row whose obligation
has a counterexample that replays (its trace, or its row's configuration) is refused.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..errors import InvalidInput, OutputFailed
from ..integrity import seal, sealed
from ..locks import holding
from ..model.config import Model
from ..outputs import Kind, is_output, load_json, read_json, resolve_recorded, write_json
from ..trace.traces import write_trace
from .digests import file_sha256, row_digest
from .prover import NotEncodedModel, ProofResult, Task, task_key, tasks_for, witness_path
from .smt.solving import solver_version
from .tasks import paper_part, row_key

VERDICTS = ("PROVED", "VIOLATED", "INCONCLUSIVE", "HOLDS_WITHIN_BOUNDS")
_KEY_FIELDS = ("lemma", "form", "verdict")
_SHOWN_FIELDS = ("rule", "slots", "seconds", "reason")
_OPTIONAL_FIELDS: dict[str, type | tuple[type, ...]] = {
    "rule": str,
    "case": str,
    "other": str,
    "slots": int,
    "seconds": (int, float),
    "timeout": (int, float),
    "reason": str,
    "smt2": str,
    "trace": (str, type(None)),
    "configuration": list,
    "any_size": bool,
    "fingerprint": (str, type(None)),
    "decided_by": str,
    "basis": str,
    "smt2_sha256": str,
    "certificate_sha256": str,
}
LOCK_WAIT = 120.0
"""Seconds a save waits for another run's save into the same directory before giving up."""


class ProofResults:
    """The merged results of one model's obligations, saved atomically after every change."""

    def __init__(self, model: Model, directory: Path, traces: Path, *, slots: int, timeout: float) -> None:
        self.model = model
        self.path = directory / "results.json"
        self.traces = traces
        self.slots, self.timeout = slots, timeout
        self._digests: dict[str, str] = {}
        """The current fingerprint of each obligation this store has been asked about, by key."""
        try:
            self._tasks = {task_key(t): t for t in tasks_for(model, two_movers=True)}
        except NotEncodedModel:
            self._tasks = {}
        self.rows: dict[str, dict[str, Any]] = self._read()
        self._mine: set[str] = set()
        """The rows this run produced: a save writes them over what another run saved meanwhile."""
        self._contradicted()

    def _read(self) -> dict[str, dict[str, Any]]:
        """The saved rows by key (none if there is no results file of this model): the file's digest
        checked, every row's fields of the types the tool writes."""
        if not self.path.is_file() or not is_output(self.path, Kind.PROVE):
            return {}
        where = self.path.as_posix()
        old = load_json(self.path, what=where, expected="the results.json fatline prove wrote")
        sealed(old, self.path)
        if old.get("model") != self.model.name:
            return {}
        obligations = old.get("obligations")
        if not isinstance(obligations, list):
            raise InvalidInput(f"{where}: obligations={str(obligations)[:40]!r}: expected a list of rows")
        try:
            own = {task_key(t) for t in tasks_for(self.model, two_movers=True)}
        except NotEncodedModel:
            own = set()
        rows = {}
        for k, row in enumerate(obligations):
            _check_row(row, f"{where}: obligations[{k}]", own)
            rows[row_key(row)] = {"fingerprint": old.get("fingerprint"), **row}
        return rows

    def _contradicted(self) -> None:
        """Refuse a PROVED row beside a counterexample of its claim that replays: the obligation's trace
        (where this store writes it, or where the row names it) or the row's own configuration."""
        from .prover import replay_known
        from .smt.claims import Spec

        proved = {key: row for key, row in self.rows.items() if row.get("verdict") == "PROVED"}
        if not proved:
            return
        try:
            specs = {task_key(t): t for t in tasks_for(self.model, two_movers=True) if isinstance(t, Spec)}
        except NotEncodedModel:
            return
        for key, row in proved.items():
            if key not in specs:
                continue
            candidates: list[tuple[str, dict[str, Any]]] = []
            paths = [witness_path(self.model, self.traces, key)]
            if row.get("trace"):
                found = resolve_recorded(row["trace"], self.path.parent)
                paths += [found] if found is not None else []
            for path in paths:
                doc = read_json(path) if path.is_file() and is_output(path, Kind.TRACE) else None
                if doc is not None:
                    candidates.append((path.as_posix(), doc))
            if row.get("configuration"):
                candidates.append(("its row's configuration", {"configuration": row["configuration"]}))
            for what, doc in candidates:
                if replay_known(paper_part(self.model), specs[key], doc, initial=False) is not None:
                    raise OutputFailed(
                        f"{self.path.as_posix()}: {key} is PROVED, but {what} replays a counterexample of it; "
                        "expected the file as fatline prove wrote it (move it away, or rerun prove for that lemma)"
                    )

    def witness_paths(self, tasks: list[Task]) -> list[Path]:
        """The trace files proving ``tasks`` may write (checked before the run)."""
        return [witness_path(self.model, self.traces, task_key(t)) for t in tasks]

    def digest(self, task: Task) -> str:
        """The current fingerprint of ``task``'s row (:func:`~fatline_verify.prove.digests.row_digest`); a
        later :meth:`add` of its result records it."""
        key = task_key(task)
        if key not in self._digests:
            self._digests[key] = row_digest(self.model, task, slots=self.slots, timeout=self.timeout)
        return self._digests[key]

    def _digest_of(self, key: str) -> str | None:
        """The current fingerprint of the obligation ``key`` (``None``: not an obligation of the model)."""
        if key in self._digests:
            return self._digests[key]
        task = self._tasks.get(key)
        return None if task is None else self.digest(task)

    def fresh(self, task: Task) -> dict[str, Any] | None:
        """The saved row of ``task`` if it was produced by the current code, model, settings and solver."""
        row = self.rows.get(task_key(task))
        return row if row is not None and row.get("fingerprint") == self.digest(task) else None

    def stale(self, keys: list[str] | None = None) -> list[str]:
        """The keys of the saved rows (of ``keys``, default every row of the model's obligations) whose
        fingerprint is not the current one."""
        wanted = [k for k in (self.rows if keys is None else keys) if k in self.rows]
        return [k for k in wanted if (d := self._digest_of(k)) is not None and self.rows[k].get("fingerprint") != d]

    def shown(self, keys: list[str] | None = None) -> list[dict[str, Any]]:
        """The rows of ``keys`` as every page and the terminal show them: a stale row as STALE
        (:func:`stale_view`), never with its old verdict."""
        stale = set(self.stale(keys))
        return [stale_view(row, self.model.name) if row_key(row) in stale else row for row in self.ordered(keys)]

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
        digest = self._digest_of(key)
        written = Path(r.smt2) if r.smt2 else None
        certificate = written.with_suffix(".linear.smt2") if written is not None else None
        self.rows[key] = {
            "fingerprint": digest,
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
            "decided_by": r.decided_by,
            **({"basis": r.basis} if r.basis else {}),
            **({"smt2_sha256": file_sha256(written)} if written is not None and written.is_file() else {}),
            **(
                {"certificate_sha256": file_sha256(certificate)}
                if certificate is not None and LINEARIZED in r.reason and certificate.is_file()
                else {}
            ),
        }
        self._mine.add(key)
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
        """Re-read ``results.json`` under the directory's lock, keep every row saved meanwhile (another
        run's), put this run's own rows over them, and write the whole (digest included)."""
        with holding(self.path.parent, name="out", wait=LOCK_WAIT):
            merged = self._read()
            for key, row in self.rows.items():
                if key in self._mine or key not in merged:
                    merged[key] = row
            self.rows = merged
            write_json(self.path, seal(self.document()))


LINEARIZED = "shown on its linearization after"
"""How a PROVED row's reason says its unsat came with a linear certificate (``.linear.smt2``) written
beside its obligation (:func:`fatline_verify.prove.search.linearized`)."""

STALE = "STALE"
"""The verdict a stale row is shown with."""


def stale_view(row: dict[str, Any], model: str) -> dict[str, Any]:
    """A row made by other code, another model file, other settings or another solver than the current
    ones, as it is shown: verdict STALE (so no count, lemma-level verdict or exit code takes it for
    current), its old verdict in ``stale_verdict`` and in the reason, with the command that solves it
    again."""
    reason = (
        f"stale: decided {row['verdict']} by other code, model, settings or solver than the current ones; "
        f"fatline prove {model} solves it again. Was: {row.get('reason', '')}"
    )
    return {**row, "verdict": STALE, "stale_verdict": row["verdict"], "reason": reason}


def _check_row(row: object, where: str, own: set[str]) -> None:
    """A results row has the fields the tool writes, of their types (a row of the model's own
    obligations also every field a page shows); else one line naming the row and the field."""
    if not isinstance(row, dict):
        raise InvalidInput(f"{where}={str(row)[:40]!r}: expected a row (an object)")
    for name in _KEY_FIELDS:
        if not isinstance(row.get(name), str):
            raise InvalidInput(f"{where}.{name}={str(row.get(name))[:40]!r}: expected text")
    if row["verdict"] not in VERDICTS:
        raise InvalidInput(f"{where}.verdict={row['verdict'][:40]!r}: expected one of {', '.join(VERDICTS)}")
    if not isinstance(row.get("case", row.get("rule")), str):
        raise InvalidInput(f"{where}: no case and no rule; expected the row fatline prove wrote")
    for name, kind in _OPTIONAL_FIELDS.items():
        value = row.get(name)
        if name in row and (not isinstance(value, kind) or (isinstance(value, bool) and kind is not bool)):
            raise InvalidInput(f"{where}.{name}={str(value)[:40]!r}: expected the type fatline prove writes")
    if row_key(row) in own:
        missing = [name for name in _SHOWN_FIELDS if name not in row]
        if missing:
            raise InvalidInput(f"{where}: no {missing[0]}; expected the row fatline prove wrote")


__all__ = ["STALE", "ProofResults", "stale_view", "witness_path"]
