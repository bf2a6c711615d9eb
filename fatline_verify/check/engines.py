"""The exploration engines by name: ``scalar`` (the executable model, every system), ``fast``
(vectorised) and ``compiled`` (numba), each for the transition systems it implements.

The engines only generate successors (:class:`~fatline_verify.schedulers.base.Engine`); the systems
know nothing of them. A system's :attr:`~fatline_verify.schedulers.base.TransitionSystem.family`
picks its row of :data:`BUILDERS`, and a name a system has no engine for is refused before any work.
"""

from __future__ import annotations

from collections.abc import Callable

from ..errors import InvalidInput
from ..schedulers.base import ENGINES, Engine, TransitionSystem, unknown_engine


def _scalar(system: TransitionSystem) -> Engine:
    from .scalar import ScalarEngine

    return ScalarEngine(system)


def _fast(system: TransitionSystem) -> Engine:
    from .fast import FastEngine

    return FastEngine(system)  # type: ignore[arg-type]


def _compiled(system: TransitionSystem) -> Engine:
    from .compiled import CompiledEngine

    return CompiledEngine(system)  # type: ignore[arg-type]


def _compiled_async(system: TransitionSystem) -> Engine:
    from .compiled_async import CompiledAsyncEngine

    return CompiledAsyncEngine(system)


def _fast_async(system: TransitionSystem) -> Engine:
    from .fast_async import FastAsyncEngine

    return FastAsyncEngine(system)  # type: ignore[arg-type]


BUILDERS: dict[str, dict[str, Callable[[TransitionSystem], Engine]]] = {
    "rounds": {"compiled": _compiled, "fast": _fast, "scalar": _scalar},
    "async": {"compiled": _compiled_async, "fast": _fast_async, "scalar": _scalar},
}
"""Per system family, the engines it has, by name."""


def engine_for(system: TransitionSystem, name: str) -> Engine:
    """The engine ``name`` over ``system`` (one of :data:`~fatline_verify.schedulers.base.ENGINES`)."""
    if name not in ENGINES:
        raise unknown_engine(name)
    builders = BUILDERS.get(system.family, {"scalar": _scalar})
    if name not in builders:
        have = " or ".join(sorted(builders))
        raise InvalidInput(f"engine={name!r}: scheduler={system.kind.value} has no {name} engine; expected {have}")
    return builders[name](system)


__all__ = ["BUILDERS", "engine_for"]
