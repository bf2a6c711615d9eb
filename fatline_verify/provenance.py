"""The sources that decide for a model, digested: what names a cached answer so it is never reused
after the code that gave it changed.

Two parts, kept apart because the caches key on them differently:

- :func:`source_digest`: every Python source file of this package, and the shipped rule tables (JSON files
  whose entries are a rule set's decisions; read once a process). The compiled engine's kept answers
  (:mod:`fatline_verify.check.answers`) are named by it; the report's check cache is not (it is keyed by
  ``CHECKER_VERSION``, bumped by hand); the prover's rows are keyed by the sources of their own kind of
  obligation only (:mod:`fatline_verify.prove.digests`).
- :func:`plugin_digest`: the sources of every object that decides for the model and is not defined in
  this package: the rule set's ``decide`` and its liveness encoding (a callable, or the module of a
  ``"module:function"``), ``model.algorithm`` when set, every registered step lemma's checks, the
  model's round scheduler when it is a plug-in, and its goal's checks when they are a plug-in's. Each
  contributes its name in its module and every ``*.py`` file (relative path and bytes) of the
  top-level package that defines it (or its single module's file). It is empty when nothing outside
  this package decides, so a built-in model's fingerprints are as they were; every cache adds it
  (:func:`plugin_settings`, :func:`model_digest`).

A deciding object whose behaviour its source does not fix, or whose source cannot be read, gets a new
random token on every call (:data:`UNREADABLE`): a digest that never matches a cache, so nothing
computed with it is reused, not even in the same process; :func:`reusable` says so, and the answers
cache keeps nothing for such a model. That is an object defined in a REPL, in ``python -c`` or by
``exec`` (its module has no file), in a module shipped without its ``.py`` files, a closure (its
captured values) or a ``functools.partial`` (its bound arguments).

What is not seen: code a plug-in imports from *another* top-level package (only the package that
defines each deciding object is read), and data files a plug-in reads at run time.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import inspect
import secrets
import sys
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

PACKAGE = __name__.split(".")[0]
"""This package's top-level name: objects defined under it are covered by :func:`source_digest`."""

UNREADABLE = "unreadable:"
"""The prefix of a digest some of whose deciding sources could not be read (:func:`reusable`)."""

_FILES: dict[Path, tuple[int, int, str]] = {}
"""Each file's SHA-256 by path, with the ``(mtime_ns, size)`` it was read at: read again when either moves."""


def _file_digest(path: Path) -> str:
    """SHA-256 of ``path``'s bytes, read again only when its modification time or size changed."""
    st = path.stat()
    known = _FILES.get(path)
    if known is not None and known[:2] == (st.st_mtime_ns, st.st_size):
        return known[2]
    digest = hashlib.sha256(path.read_bytes()).hexdigest()
    _FILES[path] = (st.st_mtime_ns, st.st_size, digest)
    return digest


def _tree_digest(root: Path, files: Iterable[Path]) -> str:
    """SHA-256 of ``files`` (under ``root``): each one's path relative to ``root`` and its bytes, sorted."""
    h = hashlib.sha256()
    for path in sorted(files):
        h.update(path.relative_to(root).as_posix().encode() + b"\0" + _file_digest(path).encode() + b"\0")
    return h.hexdigest()


DATA = ("rules/table/tables/*.json",)
"""Data files of this package that decide for a model, as globs under it: the shipped tables, each a rule
set (:mod:`fatline_verify.rules.table`) whose decisions are the file's."""


@functools.cache
def source_digest() -> str:
    """SHA-256 of every Python source file of this package and of every data file that decides
    (:data:`DATA`), path and bytes, read once a process."""
    root = Path(__file__).resolve().parent
    return _tree_digest(root, [*root.rglob("*.py"), *(f for pattern in DATA for f in root.glob(pattern))])


def _module_of(obj: Any) -> str:
    """The name of the module that defines ``obj`` (a function, a class, an instance of a class, a
    ``functools.partial`` of one; a ``"module:function"`` string names it); ``""`` when none is known."""
    if isinstance(obj, str):
        return obj.partition(":")[0]
    while isinstance(obj, functools.partial):
        obj = obj.func
    module = getattr(inspect.getmodule(obj), "__name__", None)
    if module is None:
        module = getattr(obj, "__module__", None) or getattr(type(obj), "__module__", None)
    return module if isinstance(module, str) else ""


def _name_in_module(obj: Any) -> str | None:
    """``obj``'s qualified name in its module, or ``None`` when its behaviour is not fixed by its
    source: a closure (its captured values) or a ``functools.partial`` (its bound arguments)."""
    if isinstance(obj, str):
        return obj.partition(":")[2]
    if isinstance(obj, functools.partial) or getattr(obj, "__closure__", None):
        return None
    name = getattr(obj, "__qualname__", None) or type(obj).__qualname__
    return name if isinstance(name, str) else None


def _top_digest(top: str) -> str | None:
    """The digest of the top-level package (every ``*.py`` under each of its directories) or single
    module called ``top``; ``None`` when its source files cannot be found."""
    module = sys.modules.get(top)
    if module is not None:
        file, dirs = getattr(module, "__file__", None), getattr(module, "__path__", None)
    else:
        try:
            spec = importlib.util.find_spec(top)
        except (ImportError, ValueError):
            return None
        if spec is None:
            return None
        file, dirs = (spec.origin if spec.has_location else None), spec.submodule_search_locations
    if dirs is not None:
        roots = [Path(d).resolve() for d in dirs]
        parts = [(root, sorted(root.rglob("*.py"))) for root in roots if root.is_dir()]
        if not any(files for _, files in parts):
            return None
        return hashlib.sha256("".join(_tree_digest(root, files) for root, files in parts).encode()).hexdigest()
    if isinstance(file, str) and file.endswith(".py") and Path(file).is_file():
        path = Path(file).resolve()
        return _tree_digest(path.parent, [path])
    return None


def deciders(model: Any) -> Iterator[tuple[str, Any]]:
    """Every object that decides for ``model``, named by what it is (``"rules"``, ``"liveness"``,
    ``"algorithm"``, ``"lemma NAME"``, ``"scheduler"``, ``"goal"``): this package's own included."""
    from .lemmas.registry import judged
    from .model.options import Scheduler
    from .rules import registry
    from .schedulers.activation import round_scheduler

    rule_set = registry.of(model)
    yield "rules", rule_set.decide
    if rule_set.liveness is not None:
        yield "liveness", rule_set.liveness.encoding
    if model.algorithm is not None:
        yield "algorithm", model.algorithm
    for lemma in judged(model):  # the step lemmas judged for it (in-family only for a rule set with a family)
        yield f"lemma {lemma.name}", lemma.violators
        yield f"lemma {lemma.name}", lemma.batch
    if not isinstance(model.options.scheduler, Scheduler):
        yield "scheduler", round_scheduler(model.options.scheduler)
    from .goals import registry as goals

    goal = goals.of(model)
    if _module_of(goal.holds).split(".")[0] != PACKAGE:  # a plug-in's goal (this package's are in its sources)
        yield "goal", goal.holds
        if goal.positions is not None:
            yield "goal", goal.positions


def plugin_digest(model: Any) -> str:
    """SHA-256 of the sources of every object that decides for ``model`` and is not defined in this
    package (:func:`deciders`), one top-level package or module each; ``""`` when there is none (a
    built-in model with no plug-in lemma installed). A source that cannot be read makes the digest
    :data:`UNREADABLE` and a random token, new on every call (never a cache's)."""
    outside = [obj for _, obj in deciders(model) if _module_of(obj).split(".")[0] != PACKAGE]
    if not outside:
        return ""
    names = {(_module_of(obj), _name_in_module(obj)) for obj in outside}
    tops = {module.split(".")[0] for module, _ in names}
    digests = {top: _top_digest(top) if top else None for top in tops}
    if any(name is None for _, name in names) or None in digests.values():
        return UNREADABLE + secrets.token_hex(16)
    h = hashlib.sha256()
    for module, name in sorted(names):  # type: ignore[type-var]  # no None left
        h.update(f"{module}:{name}\0".encode())
    for top, digest in sorted(digests.items()):
        h.update(f"{top}\0{digest}\0".encode())
    return h.hexdigest()


def reusable(digest: str) -> bool:
    """Whether a cache may keep what was computed under ``digest`` (every deciding source was read)."""
    return not digest.startswith(UNREADABLE)


def model_digest(model: Any) -> str:
    """The digest of every source that decides for ``model``: this package's and the plug-ins'
    (:data:`UNREADABLE` and a new token when a plug-in's cannot be read)."""
    plugins = plugin_digest(model)
    if not reusable(plugins):
        return plugins
    return hashlib.sha256(f"{source_digest()}\0{plugins}".encode()).hexdigest()


def plugin_settings(model: Any) -> dict[str, str]:
    """The plug-ins' digest as a fingerprint setting (``{"plugins": digest}``), or nothing when no
    plug-in decides for ``model``: a built-in model's fingerprints are keyed by this package's own
    sources where each cache reads them, not here."""
    digest = plugin_digest(model)
    return {"plugins": digest} if digest else {}


__all__ = [
    "DATA",
    "PACKAGE",
    "UNREADABLE",
    "deciders",
    "model_digest",
    "plugin_digest",
    "plugin_settings",
    "reusable",
    "source_digest",
]
