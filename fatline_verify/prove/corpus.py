"""The counterexample corpus shipped with the prover (``corpus.json``, package data): the initial
configurations that break the shipped models' obligations, replayed before any search wherever
``fatline prove --out`` points, as Hypothesis replays its example database first.

A fresh ``fatline prove MODEL --out NEW`` would otherwise have the search alone, which within its
budget does not find every counterexample an earlier, longer run (or a person: ``docs/known/``) found.
An entry is only a candidate, like an earlier run's trace: it is believed only after the executable
model replays it (:func:`~fatline_verify.prove.replay.replay_known`: under the model being proved, its r
decides the obligation's case and breaks its claim from an initial configuration). Each row says what
decided it (``decided_by``: :data:`SEARCH`, :data:`CORPUS`, :data:`EARLIER` or :data:`GIVEN`);
``fatline prove --no-corpus`` leaves the corpus out.

An entry is small: the obligation's key, the initial positions in radii (exact strings), the index of
the robot its claim is about (the schedule of the obligation's one round follows from its form: r
alone, r and that robot, or every robot under FSYNC) or ``None`` for a claim about r alone (``seen``,
``x-nondecreasing``; ``closer`` tries every other robot), and the shipped models under which it
replays (tried first under a model of that name). The file is made again from the shipped proofs and
the hand-found traces by::

    python -m fatline_verify.prove.corpus --proofs proofs --known docs/known

(``tests/test_prove_corpus.py`` checks it is in step: every entry replays under each model it names,
under no other, and every shipped VIOLATED row of a per-case obligation has an entry.)
"""

from __future__ import annotations

import argparse
import functools
import sys
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..errors import FatlineError, InvalidInput, OutputFailed
from ..integrity import seal, sealed
from ..model.config import Model
from ..model.numbers import Point
from .replay import Known, Replayed, replay_known
from .smt.claims import CLAIM, CLOSER, ON_RMA, SEEN, X_NONDECREASING, Spec

TRACELESS = (CLOSER, SEEN, ON_RMA, X_NONDECREASING)
"""The forms whose counterexample is a configuration, not a trace."""
FORMS = frozenset(form for _, form in CLAIM)
"""Every per-case obligation's form."""
CORPUS_PATH = Path(__file__).with_name("corpus.json")
"""The shipped corpus (package data)."""
FORMAT = "fatline-prove-corpus"
VERSION = 1

SEARCH, CORPUS, EARLIER, GIVEN = "search", "corpus", "earlier", "given"
"""What decided a row (``decided_by``): the search (vacuity, lattices, linearization, reals, small
swarms, or the checker's search of the global form), the shipped corpus, an earlier run's
counterexample under ``--out`` (its own trace or row, a model's proved beside it, or the mirror image
of one), or a trace handed in with ``--known``."""
DECIDERS = (SEARCH, CORPUS, EARLIER, GIVEN)
WHERE = "the shipped counterexample corpus"
"""How a reason names the corpus (``..., from an initial configuration of 3 robots (the shipped
counterexample corpus, found under model paper, replayed first)``)."""


@dataclass(frozen=True, slots=True)
class Entry:
    """One counterexample of one obligation."""

    key: str
    """``lemma/form-case[.and.other]`` (:func:`~fatline_verify.prove.tasks.task_key`)."""
    initial: tuple[tuple[str, str], ...]
    """The initial positions in radii, exact (``"73/30"``), r first or as the trace had them."""
    focus: int | None
    """The robot the claim is about (index into ``initial``, r being 0; ``closer``: the robot r does
    not get closer to), or ``None`` for a claim about r alone."""
    models: tuple[str, ...]
    """The shipped models under which it replays."""
    sources: tuple[str, ...]
    """Where it was taken from (``proofs/paper``: that model's shipped row; ``docs/known/FILE``)."""

    def document(self) -> dict[str, Any]:
        """What :func:`~fatline_verify.prove.replay.replay_known` replays: a trace's initial positions and
        the robots of its violation, or for a claim without a trace its configuration (which, in the
        lattice units of the model proved, :func:`known_for` makes)."""
        initial = [[x, y] for x, y in self.initial]
        if not self.traced:
            return {"radii": initial, "focus": self.focus}
        return {"initial": initial, "violation": {"robots": [0, self.focus]}}

    @property
    def traced(self) -> bool:
        """Whether its obligation's counterexample is a trace (a round played), not a configuration
        (``closer``, ``seen``, ``on-rma``, ``x-nondecreasing``: a claim about r's decision alone)."""
        rest = self.key.split("/", 1)[1]
        return not any(rest.startswith(f"{form}-") for form in TRACELESS)

    def to_json(self) -> dict[str, Any]:
        return {
            "key": self.key,
            "initial": [list(p) for p in self.initial],
            "focus": self.focus,
            "models": list(self.models),
            "sources": list(self.sources),
        }


def _entry(raw: Any, where: str) -> Entry:
    """An entry of the file, its fields of the types written; else one line naming the field."""
    if not isinstance(raw, dict):
        raise InvalidInput(f"{where}={str(raw)[:40]!r}: expected an object")
    key, initial, focus, models, sources = (raw.get(k) for k in ("key", "initial", "focus", "models", "sources"))
    if not isinstance(key, str) or "/" not in key:
        raise InvalidInput(f"{where}.key={str(key)[:40]!r}: expected lemma/form-case")
    points = initial if isinstance(initial, list) else []
    if not points or not all(isinstance(p, list) and len(p) == 2 for p in points):
        raise InvalidInput(f"{where}.initial={str(initial)[:40]!r}: expected a list of [x, y] in radii")
    try:
        for p in points:
            Fraction(str(p[0])), Fraction(str(p[1]))
    except (ValueError, ZeroDivisionError):
        raise InvalidInput(f"{where}.initial={str(initial)[:40]!r}: expected exact numbers") from None
    if focus is not None and (not isinstance(focus, int) or isinstance(focus, bool) or not 0 < focus < len(points)):
        raise InvalidInput(f"{where}.focus={focus!r}: expected null or the index of a robot other than r")
    if not isinstance(models, list) or not all(isinstance(m, str) for m in models):
        raise InvalidInput(f"{where}.models={str(models)[:40]!r}: expected a list of model names")
    if not isinstance(sources, list) or not sources or not all(isinstance(m, str) for m in sources):
        raise InvalidInput(f"{where}.sources={str(sources)[:40]!r}: expected a list of where it was found")
    return Entry(key, tuple((str(x), str(y)) for x, y in points), focus, tuple(models), tuple(sources))


def read_corpus(path: Path = CORPUS_PATH) -> list[Entry]:
    """The entries of a corpus file, its digest checked (:mod:`fatline_verify.integrity`)."""
    from ..outputs import load_json

    where = path.as_posix()
    doc = load_json(path, what=where, expected="the corpus python -m fatline_verify.prove.corpus wrote")
    if doc.get("format") != FORMAT:
        raise InvalidInput(f"{where}: format={str(doc.get('format'))[:40]!r}: expected {FORMAT!r}")
    sealed(doc, path)
    entries = doc.get("entries")
    if not isinstance(entries, list):
        raise InvalidInput(f"{where}: entries={str(entries)[:40]!r}: expected a list")
    return [_entry(raw, f"{where}: entries[{k}]") for k, raw in enumerate(entries)]


@functools.cache
def shipped() -> dict[str, tuple[Entry, ...]]:
    """The shipped corpus by obligation key (read once per process); empty if the file is absent."""
    if not CORPUS_PATH.is_file():
        return {}
    by_key: dict[str, list[Entry]] = {}
    for entry in read_corpus(CORPUS_PATH):
        by_key.setdefault(entry.key, []).append(entry)
    return {key: tuple(entries) for key, entries in by_key.items()}


def known_for(model: Model, key: str, corpus: dict[str, tuple[Entry, ...]] | None = None) -> list[Known]:
    """The corpus's candidates for the obligation ``key`` under ``model``, in the order they are
    replayed: the shipped row's of a model of this name first (so a fresh run writes the shipped
    trace), then those that replay under a model of this name, then the rest (the prover adds the
    mirror obligation's, reflected: :func:`~fatline_verify.prove.prover.corpus_known`)."""
    corpus = shipped() if corpus is None else corpus
    own = f"proofs/{model.name}"
    entries = sorted(corpus.get(key, ()), key=lambda e: (own not in e.sources, model.name not in e.models))
    return [(_where(e, own), _document(model, e)) for e in entries]


def firing(case: str, model_name: str, corpus: dict[str, tuple[Entry, ...]] | None = None) -> list[tuple[Point, ...]]:
    """Configurations in which r decides ``case`` (a per-case obligation's name): the initial positions of the
    corpus's counterexamples of every obligation of that case, in radii, relative to r (r first, at the
    origin), ``model_name``'s own first. Candidates only: whoever uses one checks it (r's decision there
    depends on the model's readings)."""
    corpus = shipped() if corpus is None else corpus
    heads = {f"{form}-{case}" for form in FORMS}
    entries = [e for key, es in corpus.items() if key.split("/", 1)[1].split(".and.")[0] in heads for e in es]
    entries.sort(key=lambda e: model_name not in e.models)
    out: list[tuple[Point, ...]] = []
    for entry in entries:
        (x0, y0), *rest = ((Fraction(x), Fraction(y)) for x, y in entry.initial)
        out.append(((Fraction(0), Fraction(0)), *((x - x0, y - y0) for x, y in rest)))
    return out


def _where(entry: Entry, own: str) -> str:
    """``the shipped counterexample corpus, found under model paper`` (``own``, the model proved, if it
    is one of its sources, else its first)."""
    first = own if own in entry.sources else entry.sources[0]
    return f"{WHERE}, found under " + (f"model {first.split('/', 1)[1]}" if first.startswith("proofs/") else first)


def _document(model: Model, entry: Entry) -> dict[str, Any]:
    """The entry as :func:`replay_known` takes it; a claim without a trace as a configuration in
    ``model``'s lattice units."""
    doc = entry.document()
    if "radii" not in doc:
        return doc
    points = [model.to_lattice((Fraction(x), Fraction(y))) for x, y in entry.initial]
    return {"configuration": [f"{x},{y}" for x, y in points], "focus": entry.focus}


def replays(model: Model, spec: Spec, entry: Entry) -> bool:
    """Whether ``entry`` is a counterexample of ``spec`` under ``model`` (replayed by the executable
    model, from an initial configuration)."""
    return replay_known(model, spec, _document(model, entry)) is not None


# Making the corpus from the shipped proofs ------------------------------------------------------


def _radii(points: Iterable[Point]) -> tuple[tuple[str, str], ...]:
    return tuple((str(Fraction(x)), str(Fraction(y))) for x, y in points)


def candidates(proofs: Path, known: Sequence[Path]) -> list[tuple[Model, Spec, Entry]]:
    """Every counterexample of a per-case obligation in ``proofs/*/results.json`` (a VIOLATED row's
    trace, or its configuration), and every hit of a ``known`` trace (every robot tried as r) on an
    obligation such a row names, each with the model and obligation it was found for."""
    from ..model.config import load_model
    from ..outputs import read_json, resolve_recorded
    from ..trace.traces import initial_radii, load_trace
    from .small import given_counterexample
    from .tasks import NotEncodedModel, paper_part, row_key, task_key, tasks_for

    given = [(path, initial_radii(load_trace(str(path)))) for path in known]
    found: list[tuple[Model, Spec, Entry]] = []
    for results in sorted(proofs.glob("*/results.json")):
        doc = read_json(results) or {}
        try:
            model = load_model(str(doc.get("model", results.parent.name)))
            specs = {task_key(t): t for t in tasks_for(model, two_movers=True) if isinstance(t, Spec)}
        except (InvalidInput, NotEncodedModel):
            continue
        part = paper_part(model)
        source = f"proofs/{results.parent.name}"
        for row in doc.get("obligations", []):
            key = row_key(row)
            if row.get("verdict") != "VIOLATED" or key not in specs:
                continue
            entry = None
            trace = resolve_recorded(row["trace"], results.parent) if row.get("trace") else None
            if trace is not None and trace.is_file():
                t = read_json(trace) or {}
                points = _radii(initial_radii(t))
                entry = Entry(key, points, len(points) - 1, (), (source,))  # its own order, if that replays
                if not replays(part, specs[key], entry):
                    entry = Entry(key, points, int(t["violation"]["robots"][1]), (), (source,))
            elif row.get("configuration"):
                lattice = [tuple(Fraction(v) for v in str(p).split(",")) for p in row["configuration"]]
                points = _radii(model.from_lattice((p[0], p[1])) for p in lattice)
                entry = Entry(key, points, len(points) - 1, (), (source,))  # its own order, if that replays
                if not replays(part, specs[key], entry):
                    entry = Entry(key, points, None, (), (source,))
            if entry is not None:
                found.append((part, specs[key], entry))
            for path, radii in given:
                hit = given_counterexample(part, specs[key], radii)
                if hit is not None:
                    focus = hit.focus if hit.doc is not None else None
                    points = _radii(part.from_lattice(p) for p in hit.state)
                    found.append((part, specs[key], Entry(key, points, focus, (), (f"docs/known/{path.name}",))))
    return found


def build(proofs: Path, known: Sequence[Path]) -> list[Entry]:
    """The corpus: :func:`candidates` that replay, deduplicated (one entry per key, positions and
    focus), each naming every model proved under ``proofs`` under which it replays."""
    from ..model.config import load_model
    from .tasks import NotEncodedModel, paper_part, task_key, tasks_for

    models: list[tuple[str, Model, dict[str, Spec]]] = []
    for results in sorted(proofs.glob("*/results.json")):
        try:
            model = load_model(results.parent.name)
            specs = {task_key(t): t for t in tasks_for(model, two_movers=True) if isinstance(t, Spec)}
        except (InvalidInput, NotEncodedModel):
            continue
        models.append((model.name, paper_part(model), specs))
    unique: dict[tuple[str, tuple[tuple[str, str], ...], int | None], list[str]] = {}
    for part, spec, found in candidates(proofs, known):
        entry = _settled(part, spec, found)
        sources = unique.setdefault((entry.key, entry.initial, entry.focus), [])
        sources += [s for s in entry.sources if s not in sources]
    out = []
    for (key, initial, focus), sources in unique.items():
        entry = Entry(key, initial, focus, (), tuple(sources))
        names = tuple(name for name, part, specs in models if key in specs and replays(part, specs[key], entry))
        out.append(Entry(key, initial, focus, names, tuple(sources)))
    return out


SETTLE = 8
"""Replays at most, for an entry's order of robots to settle (:func:`_settled`)."""


def _settled(model: Model, spec: Spec, found: Entry) -> Entry:
    """``found`` replayed until the order of its robots is the one its replay writes (a fresh run then
    writes the trace or configuration it was made from); an error if it does not replay."""
    entry = found
    for _ in range(SETTLE):
        got = replay_known(model, spec, _document(model, entry))
        if got is None:
            where = found.sources[0]
            raise OutputFailed(f"{where}: {found.key}: its counterexample does not replay; expected one that does")
        again = _replayed(entry, model, got)
        if again == entry:
            break
        entry = again
    return entry


def _replayed(entry: Entry, model: Model, got: Replayed) -> Entry:
    """``entry`` in the order its replay puts the robots (r first, the robot the claim is about last),
    so that a trace written from the entry replays to the same entry again."""
    focus = got.focus
    return Entry(entry.key, _radii(model.from_lattice(p) for p in got.state), focus, (), entry.sources)


def corpus_document(entries: Sequence[Entry]) -> dict[str, Any]:
    """The file :func:`read_corpus` reads, sealed."""
    return seal(
        {
            "format": FORMAT,
            "version": VERSION,
            "made_by": "python -m fatline_verify.prove.corpus --proofs proofs --known docs/known",
            "entries": [e.to_json() for e in entries],
        }
    )


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m fatline_verify.prove.corpus``: make the corpus file from the shipped proofs."""
    from ..outputs import read_json, write_json

    p = argparse.ArgumentParser(prog="python -m fatline_verify.prove.corpus", description=main.__doc__)
    p.add_argument("--proofs", default="proofs", help="the proofs root (default: proofs)")
    p.add_argument("--known", default="docs/known", help="hand-found traces (default: docs/known)")
    p.add_argument("--out", default=str(CORPUS_PATH), help="the corpus file (default: the package's)")
    args = p.parse_args(argv)
    proofs, known_dir, out = Path(args.proofs), Path(args.known), Path(args.out)
    problem = ""
    if not proofs.is_dir():
        problem = f"proofs={args.proofs!r}: expected a directory of fatline prove results"
    elif not known_dir.is_dir():
        problem = f"known={args.known!r}: expected a directory of traces (docs/known)"
    elif out.exists() and (read_json(out) or {}).get("format") != FORMAT:
        problem = f"out={args.out!r}: exists and is not a corpus this command wrote; expected a new file or one"
    if problem:
        print(f"fatline: error: {problem}", file=sys.stderr)
        return 2
    try:
        entries = build(proofs, sorted(known_dir.glob("*.json")))
    except FatlineError as exc:
        print(f"fatline: error: {exc}", file=sys.stderr)
        return 2
    write_json(out, corpus_document(entries))
    keys = len({e.key for e in entries})
    print(f"{len(entries)} counterexamples of {keys} obligations written to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
