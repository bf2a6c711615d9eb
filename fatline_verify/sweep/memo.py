"""What the executable model computes of one question under every reading, remembered across checks.

:func:`fatline_verify.sweep.cover.cover` replays a question (a state's expansion, say) under a
combination through :class:`fatline_verify.sweep.cover.Recorder`, which notes the varied options it
read, in order. The model is deterministic, so the first option it reads is the same under every
reading, the next one depends only on the value of the first, and so on: the reads form a decision
tree whose leaves are the question's answers. :class:`Memo` keeps that tree per question, grown only
where a set of combinations asks for a branch not yet replayed. A sweep asks about the same states
under check after check (every check starts from the same initial configurations), so after the
first checks nearly every answer comes from the tree: a few numpy partitions instead of thousands of
replays.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterator
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..model.config import Model
from .cover import Recorder
from .space import Space

NODE = 200
"""Bytes of one tree node, about (its object and its place in the parent's dict)."""


def _bytes(answer: Any) -> int:
    """Bytes of an answer's arrays, about."""
    if isinstance(answer, np.ndarray):
        return int(answer.nbytes)
    return sum(int(v.nbytes) for v in (getattr(answer, "followed", None),) if isinstance(v, np.ndarray)) + NODE


@dataclass(slots=True)
class _Node:
    """A point of a decision tree: the option read next (its column in the space) and a child per
    reading, or a leaf holding the answer."""

    option: int = -1
    children: dict[int, _Node] = field(default_factory=dict)
    answer: Any = None
    leaf: bool = False


@dataclass
class Memo:
    """Answers of questions under the combinations of ``space``, each a decision tree over the reads."""

    space: Space
    limit: int = 0
    """Bytes the trees may hold, about (0: no bound); past it they are forgotten at the next question
    (the same answers, replayed again as asked)."""
    trees: dict[Hashable, _Node] = field(default_factory=dict)
    replays: int = 0
    size: int = 0
    """Bytes the trees hold, about: the answers' arrays and a node's overhead."""
    forgotten: int = 0

    def answers(
        self, question: Hashable, compute: Callable[[Model], Any], among: np.ndarray
    ) -> Iterator[tuple[np.ndarray, Any]]:
        """For ``among`` (combination numbers), pairs (the combinations, their answer) that partition
        it; ``compute(model)`` answers the question under a model (it is replayed, through a
        :class:`Recorder`, only where the tree does not know the branch yet)."""
        if self.limit and self.size > self.limit:
            self.trees.clear()
            self.size = 0
            self.forgotten += 1
        root = self.trees.setdefault(question, _Node())
        digits = self.space.digits
        stack: list[tuple[_Node, np.ndarray, tuple[int, ...]]] = [(root, among, ())]
        while stack:
            node, inside, above = stack.pop()
            if not len(inside):
                continue
            if node.leaf:
                yield inside, node.answer
                continue
            if node.option < 0:  # never reached: replay here, which grows the path to one leaf
                self._grow(node, above, int(inside[0]), compute)
                stack.append((node, inside, above))
                continue
            column = digits[inside, node.option]
            for value in np.unique(column):
                child = node.children.setdefault(int(value), _Node())
                stack.append((child, inside[column == value], (*above, node.option)))

    def _grow(self, node: _Node, above: tuple[int, ...], index: int, compute: Callable[[Model], Any]) -> None:
        """Replay at combination ``index`` and record its reads below ``node``, whose ancestors read the
        options ``above`` (the replay reads them first: every one has the value the path says)."""
        combo = self.space.combo(index)
        recorder = Recorder(self.space.options(combo), self.space.names)
        answer = compute(replace(self.space.base, options=recorder))  # type: ignore[arg-type]
        self.replays += 1
        names = self.space.names
        path = tuple(names.index(name) for name in recorder.reads)
        if path[: len(above)] != above:
            raise AssertionError(f"reads {path} do not extend the tree's path {above}: the replay is not deterministic")
        here = node
        for column in path[len(above) :]:
            here.option = column
            here = here.children.setdefault(combo[names[column]], _Node())
        here.leaf, here.answer = True, answer
        self.size += NODE * (1 + len(path) - len(above)) + _bytes(answer)
