"""Goals by name: when a swarm has done what its rule set is for ("form a straight line", "gather at a
point", "form a circle"), one registered entry each, like rule sets and lemmas.

A goal is judged three ways, and every engine asks this module which one it can use:

- :attr:`Goal.holds` ``(state, model) -> bool``: exact, on the executable model's positions (``int`` and
  :class:`~fractions.Fraction`, lattice units). Every goal has it; the scalar engine, ``simulate``,
  replay and the prover's replays use it.
- :attr:`Goal.positions` ``(pos, model) -> bool array``: optional, vectorised over ``(m, n, 2)`` integer
  arrays of lattice points (the ``fast`` engines). A goal without it is judged by ``holds`` state by
  state, and so is a state with a robot between lattice points (an asynchronous robot stopped halfway):
  :func:`judge_batch`.
- :attr:`Goal.kernel`: the number of this package's compiled kernel for the goal
  (:func:`fatline_verify.check.compiled_common.at_goal`); ``None``: the compiled engines run their
  kernels without the goal and judge it after each expansion by :func:`judge_batch` (one line says so,
  :func:`fallback_note`). A plug-in cannot name a kernel (the kernels are this package's code).

A model names its goal in ``[options] goal = "NAME"`` (the paper's three readings of "form a straight
line" are readings of the catalogue; every other registered goal is accepted by name and checked here);
a rule set may declare its own (``RuleSet(goal=...)``), which a model file that sets none takes. A goal
may declare parameters (``Goal(parameters={"eps": Param(...)})``), set in the model file's ``[goal]``
table and read by its checks as ``model.setting("goal")``.

Plug-in packages register goals from the same entry-point group as rule sets (``fatline.plugins``).
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import InvalidModel
from ..model import options
from ..model.seams import Param

Model = Any
"""A :class:`fatline_verify.model.config.Model` (not imported: the model package imports this one)."""
Point = tuple[Any, Any]

ROBOTS = ("discs", "points")
"""What a robot is: a disc of one radius (the paper's fat robots) or a point."""

KERNELS = {"vertical-line": 0, "any-line": 1, "line-meets-discs": 2, "point": 3}
"""The goals the compiled kernels judge, by their number (:func:`fatline_verify.check.compiled_common.at_goal`)."""

NAME = re.compile(r"[a-z][a-z0-9-]{0,39}")
"""A goal's name: lower-case letters, digits and '-' (as a plug-in's rule set or scheduler)."""

BUILTIN = "fatline_verify.goals.builtin"
"""The module that registers this package's goals."""

NO_KERNEL = -1
"""The kernel number of a goal the compiled kernels do not judge (judged after, by :func:`judge_batch`)."""


@dataclass(frozen=True, slots=True)
class Goal:
    """One registered goal: its name, what it says exactly, and its checks (see the module doc)."""

    name: str
    says: str
    """What a state at this goal is, exactly, in one or two sentences (``fatline explain``, docs)."""
    holds: Callable[[Sequence[Point], Model], bool] = field(repr=False, compare=False)
    """``holds(state, model)``: whether ``state`` (positions in lattice units, ``int`` or ``Fraction``) is at
    the goal; exact arithmetic only."""
    positions: Callable[[np.ndarray, Model], np.ndarray] | None = field(default=None, repr=False, compare=False)
    """``positions(pos, model)``: the same per state of an ``(m, n, 2)`` integer array of lattice points, one
    bool each; ``None``: judged by :attr:`holds`, state by state."""
    kernel: int | None = None
    """This package's compiled kernel for it (:data:`KERNELS`); ``None`` for every plug-in's."""
    parameters: dict[str, Param] = field(default_factory=dict, repr=False, compare=False)
    """Its own parameters, set in a model file's ``[goal]`` table (defaults filled)."""
    robots: tuple[str, ...] = ROBOTS
    """The robots it means something for: ``point`` only for point robots (discs at one point overlap)."""
    scaled: bool = False
    """This package's built-ins only: :attr:`positions` also takes ``unit=K`` (positions in ``1/K`` lattice
    units, as the asynchronous engines store them), so no state is handed to :attr:`holds`."""

    def __str__(self) -> str:
        return self.name


_REGISTRY: dict[str, Goal] = {}


def register_goal(goal: Goal) -> Goal:
    """Add ``goal`` (once per name: another under a taken name is refused, in one line). A plug-in's goal
    names no compiled kernel and no unknown kind of robot."""
    if not isinstance(goal.name, str) or not NAME.fullmatch(goal.name):
        raise ValueError(f"goal {goal.name!r}: expected a name of lower-case letters, digits and '-'")
    if goal.kernel is not None and KERNELS.get(goal.name) != goal.kernel:
        raise ValueError(
            f"goal {goal.name!r}: kernel={goal.kernel!r}: the compiled kernels are this package's "
            "(vertical-line, any-line, line-meets-discs, point); expected kernel=None (judged by positions or holds)"
        )
    bad = [r for r in goal.robots if r not in ROBOTS] if not isinstance(goal.robots, str) else [goal.robots]
    if bad or not goal.robots:
        raise ValueError(f"goal {goal.name!r}: robots={goal.robots!r}: expected a tuple of {', '.join(ROBOTS)}")
    if not callable(goal.holds) or (goal.positions is not None and not callable(goal.positions)):
        raise ValueError(f"goal {goal.name!r}: holds (and positions, if given) must be callables")
    from ..model.seams import declared

    declared(goal)  # a dict of name -> Param, or one line
    known = _REGISTRY.get(goal.name)
    if known is not None:
        if known is goal or (known.holds is goal.holds and known.positions is goal.positions):
            return known
        raise ValueError(f"goal {goal.name!r} is registered twice")
    _REGISTRY[goal.name] = goal
    from ..rules import registry as rules

    rules.claim("goal", goal.name)  # the plug-in package registering it, if any
    return goal


_BUILTIN: list[bool] = []
"""Whether this package's goals are registered (one import, not one a lookup: the scalar engine asks per state)."""


def _load(*, plugins: bool = True) -> None:
    """This package's goals, and (``plugins``) the installed plug-ins' (loaded with the rule sets)."""
    if not _BUILTIN:
        importlib.import_module(BUILTIN)  # by name, as the rule sets are: the goals import the model, not back
        _BUILTIN.append(True)
    if plugins:
        from ..rules import registry as rules

        rules.names()


def names() -> tuple[str, ...]:
    """Every registered goal's name (plug-ins loaded), built-ins first, in registration order."""
    _load()
    return tuple(_REGISTRY)


options.NAMED_BY["goal"] = names
"""A model's ``goal`` option names a registered goal (an error lists every one)."""


def get(name: str, where: str = "options.goal") -> Goal:
    """The goal called ``name``, or a one-line :class:`InvalidModel` naming ``where`` and every goal there is."""
    _load(plugins=False)
    if name not in _REGISTRY:
        _load()
    found = _REGISTRY.get(str(name))
    if found is None:
        raise InvalidModel(f"{where}={str(name)!r}: unknown goal; expected one of {', '.join(names())}")
    return found


def of(model: Model) -> Goal:
    """The goal ``model`` names (its ``goal`` option)."""
    return get(str(model.options.goal))


def holds(state: Sequence[Point], model: Model) -> bool:
    """Whether ``state`` is at ``model``'s goal, exactly (:attr:`Goal.holds`)."""
    return bool(of(model).holds(state, model))


def judge_batch(pos: np.ndarray, model: Model, unit: int = 1) -> np.ndarray:
    """Per state of ``pos`` (``(m, n, 2)`` integers in units of ``1/unit`` lattice unit), whether it is at
    ``model``'s goal: by the goal's vectorised check where it has one and every position is a lattice point
    (or the goal takes ``unit``), else by its exact :attr:`Goal.holds` on the positions as the executable
    model keeps them. The same answers either way (a differential test holds every built-in to it)."""
    goal = of(model)
    pos = np.asarray(pos, dtype=np.int64)
    m = len(pos)
    out = np.zeros(m, dtype=bool)
    if not m:
        return out
    if goal.positions is not None and goal.scaled:
        return np.asarray(goal.positions(pos, model, unit=unit), dtype=bool)  # type: ignore[call-arg]
    whole = (pos % unit == 0).all(axis=(1, 2)) if unit != 1 else np.ones(m, dtype=bool)
    on = np.flatnonzero(whole) if goal.positions is not None else np.zeros(0, dtype=np.int64)
    if len(on):
        got = np.asarray(goal.positions(pos[on] // unit, model), dtype=bool)  # type: ignore[misc]
        if got.shape != (len(on),):
            raise ValueError(f"goal {goal.name!r}: positions gave shape {got.shape}; expected ({len(on)},)")
        out[on] = got
    rest = np.setdiff1d(np.arange(m), on, assume_unique=True)
    for k in rest.tolist():
        state = tuple((_exact(int(x), unit), _exact(int(y), unit)) for x, y in pos[k].tolist())
        out[k] = bool(goal.holds(state, model))
    return out


def _exact(value: int, unit: int) -> int | Fraction:
    """``value / unit`` as the executable model keeps it: an ``int`` when whole, else a ``Fraction``."""
    return value // unit if value % unit == 0 else Fraction(value, unit)


LINES = ("vertical-line", "any-line", "line-meets-discs")
"""The paper's goals: its three readings of "form a straight line"."""


def missed(name: str) -> str:
    """How a text says a state is not at the goal called ``name``: "no line" for the paper's (as every
    shipped page and witness says it), else "not at the goal (NAME)"."""
    return "no line" if str(name) in LINES else f"not at the goal ({name})"


def outcome_words(name: str) -> dict[str, str]:
    """How a trace's text ends a run that met the goal called ``name``, deadlocked or cycled short of it:
    the paper's words for its lines (as every shipped page says it), the goal's name for the others."""
    if str(name) in LINES:
        return {
            "goal": f"goal reached: the robots form a line ({name})",
            "deadlock": "deadlock: no robot is enabled and the robots do not form a line",
            "cycle": "a fair cycle: the loop below repeats forever without forming the line",
        }
    return {
        "goal": f"goal reached: the robots are at the goal ({name})",
        "deadlock": f"deadlock: no robot is enabled and the robots are not at the goal ({name})",
        "cycle": f"a fair cycle: the loop below repeats forever without reaching the goal ({name})",
    }


def kernel_of(model: Model) -> int:
    """The compiled kernel number of ``model``'s goal, or :data:`NO_KERNEL` (judged by :func:`judge_batch`)."""
    kernel = of(model).kernel
    return NO_KERNEL if kernel is None else kernel


def fallback_note(model: Model, engine: str) -> str:
    """One line when ``engine`` cannot judge ``model``'s goal itself (empty when it can): what judges it."""
    goal = of(model)
    if engine == "compiled" and goal.kernel is None:
        by = "its vectorised check (numpy)" if goal.positions is not None else "its exact check, state by state"
        return f"goal {goal.name!r} has no compiled kernel: judged after each expansion by {by}"
    if engine == "fast" and goal.positions is None:
        return f"goal {goal.name!r} has no vectorised check: judged by its exact check, state by state"
    return ""


def require_for(model: Model, robots: str, rule_set: str) -> Goal:
    """``model``'s goal, refused in one line when it means nothing for ``robots`` (:attr:`Goal.robots`)."""
    goal = of(model)
    if robots not in goal.robots:
        raise InvalidModel(
            f"options.goal={goal.name!r}: a goal for {' or '.join(goal.robots)} only, and rule set {rule_set!r} "
            f"has robots={robots!r} ({'discs at one point overlap' if goal.name == 'point' else goal.says}); "
            f"expected another goal ({', '.join(g for g in names() if robots in _REGISTRY[g].robots)})"
        )
    return goal


__all__ = [
    "KERNELS",
    "LINES",
    "NO_KERNEL",
    "ROBOTS",
    "Goal",
    "fallback_note",
    "get",
    "holds",
    "judge_batch",
    "kernel_of",
    "missed",
    "names",
    "of",
    "outcome_words",
    "register_goal",
    "require_for",
]
