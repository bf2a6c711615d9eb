"""The vectorised engine of the asynchronous system: a whole batch of event states at once, with numpy.

It computes exactly what the scalar engine computes through :meth:`AsyncSystem.successors
<fatline_verify.schedulers.asynchronous.AsyncSystem.successors>`, with the tricks of the round engine
(:mod:`fatline_verify.check.fast`):

- An idle robot's decision depends only on its snapshot of the *current* positions (a moving robot is
  seen where it is now). Positions are in ``1/K`` lattice units, so a snapshot is the sorted cell codes
  of the visible robots' offsets in those units; snapshots are de-duplicated with ``np.unique`` and only
  those never seen before go through the model's own rule, on the offsets divided by ``K`` (exact
  ``Fraction``), like :meth:`AsyncSystem.decide`. Results are cached for the whole search.
- Whether a move step collides with a resting robot depends only on the robot's offset from the
  mover's start and on the mover's relative path and progress; near pairs are keyed and only new keys
  go through :func:`fatline_verify.model.geometry.subpath`, :func:`~fatline_verify.model.geometry.path_point_dist2`
  and :func:`fatline_verify.schedulers.round.collides`.

A move step may end between points of the ``1/K`` lattice (the successor is then not exact and is not
explored) yet still needs its violation flags; positions after a move are therefore computed in units
of ``1/K^2`` lattice unit, where every point of every path at every step is an integer.
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt
from typing import Any

import numpy as np

from ..goals.registry import judge_batch
from ..lemmas.properties import Lemma
from ..model.config import Model
from ..model.geometry import path_point_dist2, subpath
from ..model.lattice import KeyTable, connected_within, goal_positions
from ..model.numbers import Point, normalize
from ..schedulers.asynchronous import CORNER_H, CORNER_NONE, CORNER_V, current_positions
from ..schedulers.base import Expansion
from ..schedulers.round import collides

_SWEEP_BITS = 14
"""Bits per signed coordinate of a sweep key (offsets and paths within +-8191 units of ``1/K``)."""


class FastAsyncEngine:
    """Vectorised engine of the asynchronous system; produces exactly the scalar engine's expansion."""

    name = "fast"

    def __init__(self, system: Any) -> None:
        self.system = system
        self.model: Model = system.model
        model = self.model
        self.K: int = system.K
        self.rigid: bool = system.rigid
        self.rule = system.rule
        self.view2 = model.view2 * self.K * self.K  # squared visibility in units of 1/K
        self.reach = isqrt(self.view2)
        self.side = 2 * self.reach + 1
        self.cell_bits = int(self.side * self.side).bit_length()
        self.near = 2 * model.radius * self.K  # beyond this gap on an axis a robot cannot be hit
        self.decisions = KeyTable(5)  # dest x K, dest y K (0 when off the lattice), corner, moves, on lattice
        self.sweeps = KeyTable(1)  # collides?
        self.points: dict[int, Point] = {}  # cell code -> offset in lattice units

    def _point(self, code: int) -> Point:
        """The offset of snapshot cell ``code`` in lattice units (exact; shared by every snapshot)."""
        p = self.points.get(code)
        if p is None:
            K = self.K
            dx, dy = code // self.side - self.reach, code % self.side - self.reach
            p = self.points[code] = (normalize(Fraction(dx, K)), normalize(Fraction(dy, K)))
        return p

    # --- decisions --------------------------------------------------------------------------
    def _snapshots(self, pos: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Per state and robot, the snapshot key and its sorted cell codes ``(m, n, n - 1)`` (the
        sentinel ``side^2`` for no robot)."""
        m, n, _ = pos.shape
        rel = pos[:, None, :, :] - pos[:, :, None, :]  # rel[s, i, j] = p_j - p_i
        visible = (rel * rel).sum(axis=-1) <= self.view2
        visible[:, np.arange(n), np.arange(n)] = False
        sentinel = self.side * self.side
        codes = np.where(visible, (rel[..., 0] + self.reach) * self.side + rel[..., 1] + self.reach, sentinel)
        codes = np.sort(codes, axis=2)[:, :, : n - 1]
        if self.cell_bits * max(n - 1, 1) <= 63:
            key = np.zeros((m, n), dtype=np.int64)
            for k in range(n - 1):
                key = (key << self.cell_bits) | codes[:, :, k]
            return key, codes
        raw = np.ascontiguousarray(codes.astype(">u8"))  # wide snapshots: fixed-width byte keys
        return raw.view(np.dtype((np.void, 8 * (n - 1)))).reshape(m, n), codes

    def _decide(self, codes: np.ndarray) -> np.ndarray:
        """Decision rows of snapshots given by their cell codes ``(r, n - 1)``."""
        K, sentinel = self.K, self.side * self.side
        out = np.zeros((len(codes), 5), dtype=np.int64)
        for r, row in enumerate(codes.tolist()):
            view = tuple(self._point(c) for c in row if c != sentinel)
            d = self.rule(view, self.model)
            fx, fy = Fraction(d.destination[0]) * K, Fraction(d.destination[1]) * K
            exact = fx.denominator == 1 and fy.denominator == 1
            corner = CORNER_NONE
            if len(d.path) == 3:
                corner = CORNER_H if d.path[1][1] == d.path[0][1] else CORNER_V
            out[r] = (int(fx) if exact else 0, int(fy) if exact else 0, corner, int(d.moves), int(exact))
        return out

    # --- collisions -------------------------------------------------------------------------
    def _sweep_keys(self, fields: list[np.ndarray], corner: np.ndarray, k: np.ndarray) -> np.ndarray:
        half = 1 << (_SWEEP_BITS - 1)
        key = np.zeros(fields[0].shape, dtype=np.int64)
        for f in fields:
            if f.size and (f.min() < -half or f.max() >= half):
                raise ValueError(
                    f"a move or offset exceeds {half - 1} units of 1/{self.K}; "
                    f"the fast engine packs {_SWEEP_BITS} bits each"
                )
            key = (key << _SWEEP_BITS) | (f + half)
        return (key << 2 | corner) << 4 | k  # type: ignore[no-any-return]

    def _sweep_rows(
        self, ox: np.ndarray, oy: np.ndarray, d: np.ndarray, corner: np.ndarray, k: np.ndarray
    ) -> np.ndarray:
        """Whether the step ``k -> k + 1`` of a path from the origin to ``d`` (units of ``1/K``) hits a
        robot at rest at ``(ox, oy)``."""
        K = self.K
        out = np.zeros(len(ox), dtype=np.int64)
        for r in range(len(ox)):
            row = np.array([[0, 0, d[r, 0], d[r, 1], corner[r], k[r]]], dtype=np.int64)
            path = self.system.from_array(row)[0].path  # the executable model's own path
            swept = subpath(path, Fraction(int(k[r]), K), Fraction(int(k[r]) + 1, K))
            point = (normalize(Fraction(int(ox[r]), K)), normalize(Fraction(int(oy[r]), K)))
            out[r] = collides(path_point_dist2(swept, point), self.model)
        return out

    def _collisions(self, pos: np.ndarray, src: np.ndarray, robot: np.ndarray, states: np.ndarray) -> np.ndarray:
        """Per move step ``(src, robot)``, whether its swept sub-path hits another robot's current position."""
        t = len(src)
        n = pos.shape[1]
        if not t or n < 2:
            return np.zeros(t, dtype=bool)
        mover = states[src, robot]  # (t, 6)
        s = mover[:, 0:2]
        d = mover[:, 2:4] - s
        off = pos[src] - s[:, None, :]  # (t, n, 2) every robot's offset from the mover's start
        lo, hi = np.minimum(d, 0), np.maximum(d, 0)
        gap = np.maximum(np.maximum(lo[:, None, :] - off, off - hi[:, None, :]), 0)
        near = (gap <= self.near).all(axis=-1)
        near[np.arange(t), robot] = False
        ti, j = np.nonzero(near)
        hit = np.zeros(t, dtype=bool)
        if not len(ti):
            return hit
        ox, oy = off[ti, j, 0], off[ti, j, 1]
        dd, corner, k = d[ti], mover[ti, 4], mover[ti, 5]
        keys = self._sweep_keys([ox, oy, dd[:, 0], dd[:, 1]], corner, k)
        rows = self.sweeps.lookup(keys, lambda f: self._sweep_rows(ox[f], oy[f], dd[f], corner[f], k[f]))
        np.logical_or.at(hit, ti, rows[:, 0] != 0)
        return hit

    # --- the expansion ----------------------------------------------------------------------
    def expand(self, states: np.ndarray) -> Expansion:
        states = np.asarray(states, dtype=np.int64)
        m, n, _ = states.shape
        K = self.K
        pos, _ = current_positions(states, K)  # stored states are on the lattice
        start, end, k = states[..., 0:2], states[..., 2:4], states[..., 5]
        moving = (start != end).any(axis=-1)
        idle = ~moving

        dec = np.zeros((m, n, 5), dtype=np.int64)
        if idle.any():
            keys, codes = self._snapshots(pos)
            flat = codes[idle]
            dec[idle] = self.decisions.lookup(keys[idle], lambda first: self._decide(flat[first]))
        look = idle & (dec[..., 3] != 0)

        bits = 1 << np.arange(n, dtype=np.int64)
        enabled = ((moving | look) * bits).sum(axis=1)
        goal = ~moving.any(axis=1)
        if goal.any():
            goal[goal] = judge_batch(start[goal], self.model, K)

        present = np.zeros((m, n, 2), dtype=bool)
        present[..., 0] = moving | look
        if not self.rigid:
            present[..., 1] = moving & (k >= 1)
        src, robot, slot = np.nonzero(present)  # rows, then robots, then move before stop: the scalar order
        t = len(src)
        action = bits[robot] | np.where(slot == 1, np.int64(1) << n, 0)
        is_move = (slot == 0) & moving[src, robot]
        is_look = (slot == 0) & ~moving[src, robot]
        is_stop = slot == 1

        after = states[src]  # a copy: fancy indexing
        exact = np.ones(t, dtype=bool)
        flags = np.zeros(t, dtype=np.int64)
        here = pos[src, robot]  # (t, 2)

        # look: the robot starts a move from where it is (nothing moves yet)
        li = np.nonzero(is_look)[0]
        if len(li):
            dl = dec[src[li], robot[li]]
            after[li, robot[li], 0:2] = here[li]
            after[li, robot[li], 2:4] = here[li] + dl[:, 0:2]
            after[li, robot[li], 4] = dl[:, 2]
            after[li, robot[li], 5] = 0
            exact[li] = dl[:, 4] != 0

        # stop: the robot is idle where it is
        si = np.nonzero(is_stop)[0]
        if len(si):
            after[si, robot[si], 0:2] = here[si]
            after[si, robot[si], 2:4] = here[si]
            after[si, robot[si], 4:6] = 0

        # move: one step along the path, positions in units of 1/K^2 (always integers)
        mi = np.nonzero(is_move)[0]
        if len(mi):
            ms, mr = src[mi], robot[mi]
            mover = states[ms, mr]
            k1 = mover[:, 5] + 1
            fine = np.concatenate([mover[:, 0:4] * K, mover[:, 4:5], k1[:, None]], axis=1)
            new_pos, _ = current_positions(fine, K)  # (t_m, 2) in 1/K^2 units
            exact[mi] = (new_pos % K == 0).all(axis=-1)
            done = k1 == K
            row = mover.copy()
            row[:, 5] = k1
            row[done, 0:2] = mover[done, 2:4]
            row[done, 4:6] = 0
            after[mi, mr] = row

            before = pos[ms] * K
            moved = before.copy()
            moved[np.arange(len(mi)), mr] = new_pos
            hit = self._collisions(pos, ms, mr, states)
            lost = connected_within(pos, self.view2)[ms] & ~connected_within(moved, self.view2 * K * K)
            rma = before[..., 0].max(axis=1)
            xb, xa = before[np.arange(len(mi)), mr, 0], new_pos[:, 0]
            crossed = (xa > rma) | ((xb == rma) & (xa != rma))
            flags[mi] = (
                np.where(hit, Lemma.NO_COLLISION.flag, 0)
                | np.where(lost, Lemma.CONNECTIVITY.flag, 0)
                | np.where(crossed, Lemma.RMA_FIXED.flag, 0)
            )

        after[~exact] = 0
        return Expansion(enabled, goal, src.astype(np.int64), action.astype(np.int64), after, flags, exact)


__all__ = ["FastAsyncEngine", "connected_within", "goal_positions"]
