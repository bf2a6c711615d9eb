"""What produced a results row, digested per obligation: the row's ``fingerprint``.

A row of ``proofs/MODEL/results.json`` is current only while everything that decided it is as it was:

- **the sources of its kind of obligation** (:data:`KINDS`): every module of this package that the
  kind's entry modules import (at the top or inside a function; not under ``TYPE_CHECKING``), followed
  transitively, but neither the prover's dispatch (:data:`HUBS`: which obligations there are, how a
  row is stored), nor another kind's own builder modules (:attr:`Kind.own`: reached only through
  dispatch, e.g. :mod:`~fatline_verify.prove.basis`'s branch per kind), nor the rule-set packages of
  ``fatline_verify.rules`` other than the paper's (every obligation encodes the paper's cases) and the
  model's own rule set's, nor the move families' language (:data:`INFRASTRUCTURE`) for a model whose rule
  set declares no family. So an edit to the repaired rule set's legs stales only the leg rows, an
  edit to the repaired rules only the repaired model's rows, an edit to the shared search (the
  solver's budget, the replay, the executable model) every row that runs it.
  Each file counts by its code (:func:`_code`: its syntax tree without docstrings and comments), not its
  bytes: a docstring or a comment edited stales nothing;
- **the model**: its name, readings and parameters (:func:`fatline_verify.model.config.model_to_mapping`);
- **the settings**: ``slots`` (the global form), ``--timeout``, ``--coverage``'s sample;
- **the solver**: z3's distribution name and version (read from its metadata: z3 itself is not loaded,
  so the report pages can tell a stale row without it);
- **the plug-ins that decide for the model** (:func:`fatline_verify.provenance.plugin_settings`).

Data files are not in it: the shipped counterexample corpus (``corpus.json``, made again from
``proofs/``) only adds candidates that are replayed before any search, each believed only if it
replays, and a model file is read into the model's mapping above.

Replaces the hand-bumped ``ENCODING_VERSION``: a row made by other code reads as stale
(:func:`fatline_verify.prove.results.stale_view`) wherever it is shown, and ``fatline prove`` solves
it again (``--fresh``: every row). A new obligation builder module joins its kind's :attr:`Kind.own`
(``tests/test_digests.py`` lists each kind's sources).
"""

from __future__ import annotations

import ast
import functools
import hashlib
import importlib.metadata
import json
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..provenance import PACKAGE, _file_digest

ROOT = Path(__file__).resolve().parents[1]
"""This package's directory: module names resolve under it."""


@dataclass(frozen=True, slots=True)
class Kind:
    """A kind of obligation: the modules that decide its rows (``entries``, followed transitively) and
    its own builder modules (``own``: left out of every other kind's sources)."""

    entries: tuple[str, ...]
    own: frozenset[str] = frozenset()
    decides: bool = False
    """Its rows run the model's own rule set's ``decide`` (a replay, a view): every module of that rule
    set's package is an entry too, whether the kind's modules import it or find it by name."""


def _m(*names: str) -> tuple[str, ...]:
    return tuple(f"{PACKAGE}.prove.{name}" for name in names)


KINDS: dict[str, Kind] = {
    "case": Kind(_m("search", "basis", "candidates"), frozenset(_m("smt.claims", "candidates"))),
    "leg": Kind(_m("family", "basis"), frozenset(_m("smt.family")), decides=True),
    "views": Kind(_m("family"), decides=True),
    "live": Kind(_m("live"), frozenset(_m("live", "smt.liveness", "smt.live_rules", "deadlock"))),
    "coverage": Kind(_m("refine"), frozenset(_m("refine"))),
    "global": Kind(_m("prover")),
}
"""The kinds of obligation (:func:`kind_of`): a decision case of the paper's rules, a move family's
obligation (the repaired rule set's legs among them), the row holding ``decide`` to its family on views, a
liveness obligation, the liveness cases' coverage of ``decide``, Lemma 1's global form."""

HUBS = frozenset(_m("prover", "tasks", "results"))
"""The prover's dispatch: which obligations a model has and how a row is kept. Neither digested nor
followed (they import every kind's builders); an entry module is always followed."""


def kind_of(task: Any) -> str:
    """The kind (:data:`KINDS`) of a task of :func:`fatline_verify.prove.tasks.tasks_for`."""
    from .smt.claims import Spec
    from .smt.family import FamilySpec
    from .smt.liveness import LiveSpec
    from .tasks import CoverageSpec, GlobalTask, ViewsSpec

    kinds: tuple[tuple[type, str], ...] = (
        (Spec, "case"),
        (FamilySpec, "leg"),
        (ViewsSpec, "views"),
        (LiveSpec, "live"),
        (CoverageSpec, "coverage"),
        (GlobalTask, "global"),
    )
    for cls, name in kinds:
        if isinstance(task, cls):
            return name
    raise TypeError(f"task={task!r}: expected an obligation of tasks_for")


def _path(module: str) -> Path | None:
    """The source file of ``module`` (this package only), ``None`` if there is none."""
    base = ROOT.joinpath(*module.split(".")[1:])
    for path in (base / "__init__.py", base.with_suffix(".py")):
        if path.is_file():
            return path
    return None


@functools.lru_cache(maxsize=1024)
def _parsed(path: Path, stamp: str) -> ast.Module:
    """The syntax tree of ``path`` (``stamp``: its bytes' digest, so an edited file is parsed again)."""
    return ast.parse(path.read_text(encoding="utf-8"))


def _import_statements(body: list[ast.stmt]) -> Iterator[ast.Import | ast.ImportFrom]:
    """The import statements of ``body`` and of every block nested in it (functions, classes, branches,
    loops, ``try`` and ``with``; imports are statements, so no expression is searched), but not those under
    ``if TYPE_CHECKING:`` (its ``else`` is followed)."""
    for node in body:
        if isinstance(node, ast.Import | ast.ImportFrom):
            yield node
        elif isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING":
            yield from _import_statements(node.orelse)
        else:
            for name in ("body", "orelse", "finalbody", "handlers", "cases"):
                for block in getattr(node, name, ()):
                    if isinstance(block, ast.stmt):
                        yield from _import_statements([block])
                    else:  # an except handler or a match case: its own body
                        yield from _import_statements(block.body)


@functools.cache
def _imports(module: str, stamp: str) -> frozenset[str]:
    """The modules of this package ``module`` imports (each parent package too); ``stamp``: its file's
    digest, so an edited file is parsed again."""
    path = _path(module)
    assert path is not None
    package = module if path.name == "__init__.py" else module.rsplit(".", 1)[0]
    found: set[str] = set()
    for node in _import_statements(_parsed(path, stamp).body):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split(".")[0] == PACKAGE)
            continue
        if node.level:
            parts = package.split(".")
            name = ".".join(parts[: len(parts) - node.level + 1] + ([node.module] if node.module else []))
        elif node.module and node.module.split(".")[0] == PACKAGE:
            name = node.module
        else:
            continue
        found.add(name)
        found.update(f"{name}.{a.name}" for a in node.names if _path(f"{name}.{a.name}") is not None)
    out: set[str] = set()
    for name in found:
        parts = name.split(".")
        out.update(".".join(parts[:k]) for k in range(1, len(parts) + 1) if _path(".".join(parts[:k])))
    return frozenset(out)


INFRASTRUCTURE = frozenset({"family"})
"""Packages of ``fatline_verify.rules`` that are no rule set: the move families' language and enforcement,
followed like any module."""


def _rule_packages() -> frozenset[str]:
    """Every rule-set package of ``fatline_verify.rules`` (a directory with an ``__init__.py``, not
    :data:`INFRASTRUCTURE`)."""
    rules = ROOT / "rules"
    return frozenset(
        f"{PACKAGE}.rules.{p.name}"
        for p in rules.iterdir()
        if (p / "__init__.py").is_file() and p.name not in INFRASTRUCTURE
    )


def _own_rules(model: Any) -> frozenset[str]:
    """The rule-set packages ``model``'s rows may depend on: the paper's, and its own rule set's."""
    from ..provenance import _module_of
    from ..rules import registry

    module = _module_of(registry.of(model).decide)
    return frozenset(p for p in _rule_packages() if p.endswith(".paper") or module.startswith(f"{p}."))


def _family_module(model: Any) -> str | None:
    """The module that declares ``model``'s rule set's move family (``""``: a family given as an object,
    whose module is its class's; ``None``: it declares none). One that declares none never runs the
    family language or its admission: the ``in-family`` lemma's test and the registry's look-up stop at
    its ``family=None``, so an edit to :data:`INFRASTRUCTURE` stales no row of its models. One that
    declares a family holds every replayed decision to it: the declaring module is followed for every kind."""
    from ..provenance import _module_of
    from ..rules import registry

    declared = registry.of(model).family
    if declared is None:
        return None
    return _module_of(declared) if callable(declared) else ""


_WALKS: dict[tuple[str, frozenset[str], str | None], tuple[list[Path], tuple[str, ...]]] = {}
""":func:`kind_sources`'s answers, each with the digests of the files it read (an edit walks again)."""


def kind_sources(kind: str, model: Any) -> list[Path]:
    """The source files whose code a ``kind`` row of ``model`` is keyed by, sorted (see the module
    docstring for what is followed and what is left out)."""
    own, family = _own_rules(model), _family_module(model)
    known = _WALKS.get((kind, own, family))
    if known is not None and tuple(_file_digest(p) for p in known[0]) == known[1]:
        return list(known[0])
    paths = _walk(kind, own, family)
    _WALKS[kind, own, family] = (paths, tuple(_file_digest(p) for p in paths))
    return list(paths)


def _walk(kind: str, own: frozenset[str], family: str | None) -> list[Path]:
    spec = KINDS[kind]
    others = frozenset().union(*(k.own for name, k in KINDS.items() if name != kind))
    skipped_rules = _rule_packages() - own
    if family is None:
        skipped_rules |= {f"{PACKAGE}.rules.{p}" for p in INFRASTRUCTURE}

    def left_out(module: str) -> bool:
        if module in spec.entries:
            return False
        return module in HUBS or module in others or any(module.startswith(p) for p in skipped_rules)

    seen: set[str] = set()
    todo = list(spec.entries)
    if family and family.startswith(f"{PACKAGE}."):
        todo.append(family)
    if spec.decides:
        for package in sorted(own):
            directory = ROOT.joinpath(*package.split(".")[1:])
            todo += [f"{package}.{p.stem}" if p.stem != "__init__" else package for p in directory.glob("*.py")]
    while todo:
        module = todo.pop()
        if module in seen or left_out(module):
            continue
        seen.add(module)
        path = _path(module)
        if path is not None:
            todo += _imports(module, _file_digest(path))
    return sorted(p for p in (_path(m) for m in seen) if p is not None)


def _canonical(node: Any) -> Any:
    """``node`` as nested tuples of names and values: fields in their declared order, without positions,
    without fields that are ``None`` or empty (so a field a newer Python adds, empty here, changes nothing),
    and without docstrings (:func:`_statements`)."""
    if isinstance(node, ast.AST):
        out = []
        for name in node._fields:
            value = getattr(node, name, None)
            if name == "body" and isinstance(value, list):
                value = _statements(value)
            if value is None or value == []:
                continue
            out.append((name, _canonical(value)))
        return (type(node).__name__, tuple(out))
    if isinstance(node, list):
        return tuple(_canonical(v) for v in node)
    return (type(node).__name__, repr(node))


def _statements(body: list[Any]) -> list[Any]:
    """``body`` without its bare string statements (docstrings of modules, classes, functions and
    attributes: they do nothing when the code runs; nothing a row rests on reads ``__doc__``)."""
    return [s for s in body if not (isinstance(s, ast.Expr) and isinstance(s.value, ast.Constant) and _text(s.value))]


def _text(constant: ast.Constant) -> bool:
    return isinstance(constant.value, str)


@functools.cache
def _code(path: Path, stamp: str) -> str:
    """SHA-256 of the code of ``path`` (``stamp``: its bytes' digest, so an edited file is read again): its
    syntax tree without docstrings, comments, layout or positions. A row is keyed by what its sources
    *do*: an edit to a docstring, a comment or the formatting leaves every row current."""
    return hashlib.sha256(repr(_canonical(_parsed(path, stamp))).encode()).hexdigest()


def _sources_digest(paths: Iterable[Path]) -> str:
    h = hashlib.sha256()
    for path in paths:
        code = _code(path, _file_digest(path))
        h.update(path.relative_to(ROOT).as_posix().encode() + b"\0" + code.encode() + b"\0")
    return h.hexdigest()


def solver_name() -> str:
    """The solver the rows were decided by, with its version, from its distribution's metadata."""
    try:
        return f"z3-solver {importlib.metadata.version('z3-solver')}"
    except importlib.metadata.PackageNotFoundError:
        return "z3-solver (version unknown)"


def row_digest(model: Any, task: Any, *, slots: int, timeout: float) -> str:
    """The fingerprint of ``task``'s row for ``model`` under these settings (16 hex digits): its kind's
    sources, the model, the settings, the solver and the plug-ins (see the module docstring)."""
    from ..model.config import model_to_mapping
    from ..provenance import plugin_settings

    kind = kind_of(task)
    settings: dict[str, Any] = {"timeout": timeout}
    if kind == "global":
        settings["slots"] = slots
    if kind == "coverage":
        settings["views"] = task.views
    data = {
        "kind": kind,
        "sources": _sources_digest(kind_sources(kind, model)),
        "model": model_to_mapping(model),
        "settings": settings,
        "solver": solver_name(),
        **plugin_settings(model),
    }
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()[:16]


def file_sha256(path: Path) -> str:
    """``sha256:HEX`` of a written obligation or certificate (how a row records it)."""
    return "sha256:" + hashlib.sha256(path.read_bytes()).hexdigest()


def text_sha256(text: str) -> str:
    """``sha256:HEX`` of an obligation's text as :func:`fatline_verify.outputs.write_text` writes it."""
    return "sha256:" + hashlib.sha256(text.encode("utf-8")).hexdigest()


__all__ = ["HUBS", "KINDS", "Kind", "file_sha256", "kind_of", "kind_sources", "row_digest", "solver_name"]
