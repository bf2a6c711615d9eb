"""Progress on stderr, the one reporting layer for long runs (the engine only calls back).

On a terminal: a tqdm bar with the stage, done/total, %, rate and ETA. Off a terminal (a pipe, a
CI log): one plain line every few seconds (stage, counts, %, rate, ETA, memory), so a log shows a
long run moving without drowning in carriage returns, and a short run prints nothing (``first``:
the seconds before the first line, for a command that should say at once what it is doing).
``enabled=False`` (``-q``) prints nothing.

A stage may count nothing (``timer=True``: a compile, a set-up; it shows its elapsed seconds, not
"0 states, 0/s"), or count units whose rate says nothing about what is left (``eta=False``: one
obligation solves in a tenth of a second, the next in a minute; it shows the elapsed seconds). A
``live`` note is computed whenever the stage is shown (the seconds spent on what is running now),
and a terminal's bar is redrawn every second while one is set.

The rate is never rounded to "0/s" (below one a second it reads "40 s each"), and the ETA is the time
the remaining units take at the rate the done ones took, counting down between updates and dropped
once overdue (:func:`estimate`): it converges, or there is none; it never grows while nothing moves.
Engines call back through :meth:`Progress.follow` ``(label, done, total, note)``: a stage per label.
"""

from __future__ import annotations

import resource
import sys
import threading
import time
from collections.abc import Callable
from typing import Any, TextIO


def estimate(
    done: int, total: int | None, started: float, last: float, now: float
) -> tuple[float | None, float | None]:
    """The rate and the seconds left of a stage that began at ``started`` and had ``done`` of ``total``
    units at ``last`` (the last update that moved), seen at ``now``. The rate is the average so far
    (``done`` over the seconds to ``now``: it falls while nothing moves); ``None`` before the first unit.
    The ETA is what the remaining units take at the rate they were done at (to ``last``), less the time
    since: it counts down between updates, and past its estimate it is ``None`` (no ETA, rather than one
    that grows while nothing moves); ``None`` too without a total."""
    if done <= 0 or now <= started:
        return None, None
    rate = done / (now - started)
    if not total or done >= total or last <= started:
        return rate, None
    left = (total - done) * (last - started) / done - (now - last)
    return rate, (left if left > 0 else None)


def duration_text(seconds: float) -> str:
    """``45 s``, ``12 min``, ``2.5 h``: a duration as a progress line shows it."""
    if seconds < 120:
        return f"{seconds:,.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:,.0f} min"
    return f"{seconds / 3600:,.1f} h"


def rate_text(rate: float) -> str:
    """``1,234/s``, ``2.5/s``, or below one a second ``40 s each``: never a rate that rounds to ``0/s``."""
    if rate >= 10:
        return f"{rate:,.0f}/s"
    if rate >= 1:
        return f"{rate:.1f}/s"
    return f"{duration_text(1 / rate)} each"


def peak_memory_mb() -> float:
    """This process's peak resident memory in MB (Linux reports KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


class Progress:
    """Stages of counted work; ``update`` is cheap enough to call per batch."""

    def __init__(
        self,
        *,
        enabled: bool = True,
        unit: str = "",
        stream: TextIO | None = None,
        every: float = 5.0,
        tty: bool | None = None,
        first: float | None = None,
    ) -> None:
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.unit = self.stage_unit = unit
        self.every = every
        self.first = every if first is None else first
        self.tty = self.stream.isatty() if tty is None else tty
        self.bar: Any = None
        self.label = ""
        self.started = self.last = time.monotonic()
        self.done = 0
        self.total: int | None = None
        self.note = ""
        self.eta = True
        self.timer = False
        self.live: Callable[[], str] | None = None
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._ticker: threading.Thread | None = None
        if enabled:
            self._ticker = threading.Thread(target=self._tick, name="fatline-progress", daemon=True)
            self._ticker.start()

    # --- the callbacks -----------------------------------------------------------------------------
    def stage(
        self,
        label: str,
        total: int | None = None,
        *,
        eta: bool = True,
        timer: bool = False,
        live: Callable[[], str] | None = None,
        unit: str | None = None,
    ) -> None:
        """Start a new stage (ends the previous one). ``timer``: it counts nothing, its elapsed time is
        shown; ``eta=False``: no rate and no ETA (the elapsed time instead); ``live``: a note computed
        whenever the stage is shown; ``unit``: this stage's unit (default: the bar's)."""
        if not self.enabled:
            return
        with self._lock:
            if self.bar is not None:
                self.bar.close()
                self.bar = None
            self.label, self.total, self.done, self.note = label, total, 0, ""
            self.eta, self.timer, self.live = eta, timer, live
            self.stage_unit = self.unit if unit is None else unit
            self.started = self.last = time.monotonic()
            if self.tty:
                from tqdm import tqdm

                fmt = None
                if timer:
                    fmt = "{desc} [{elapsed}]"
                elif not eta:
                    fmt = (
                        "{desc}: {n_fmt}"
                        + ("/{total_fmt}" if total else "")
                        + " "
                        + self.stage_unit
                        + " [{elapsed}]{postfix}"
                    )
                self.bar = tqdm(
                    total=total, desc=label, unit=self.stage_unit, file=self.stream, leave=False, dynamic_ncols=True,
                    bar_format=fmt,
                )  # fmt: skip
                if live is not None:
                    self.bar.set_postfix_str(live(), refresh=True)

    def update(self, done: int, total: int | None = None, note: str = "") -> None:
        """``done`` of ``total`` units in the current stage; ``note`` is shown beside the counts."""
        if not self.enabled:
            return
        with self._lock:
            if done != self.done:
                self.last = time.monotonic()
            self.done, self.note = done, note
            if total is not None:
                self.total = total
            if self.bar is not None:
                if total is not None and self.bar.total != total:
                    self.bar.total = total
                shown = self._note()
                if shown:
                    self.bar.set_postfix_str(shown, refresh=False)
                if done > self.bar.n:
                    self.bar.update(done - self.bar.n)  # tqdm's own rate and ETA need real increments
                else:
                    self.bar.refresh()

    def say(self, text: str) -> None:
        """A line at once (``fatline: text``; on a terminal above the bar): what a command is about to do,
        what it just did."""
        if not self.enabled:
            return
        with self._lock:
            if self.bar is not None:
                self.bar.write(f"fatline: {text}", file=self.stream)
            else:
                self._line(text)

    def follow(self, label: str, done: int, total: int = 0, note: str = "", unit: str | None = None) -> None:
        """An engine's callback ``(label, done, total, note[, unit])``: a new stage whenever ``label`` changes
        (one that starts counting nothing, ``total`` and ``done`` 0, shows its seconds), then its counts
        (``total`` 0: not known, so a rate and no ETA); ``unit``: the stage's, if not the bar's."""
        if label != self.label:
            self.stage(label, total or None, timer=not total and not done, unit=unit)
        if total or done:
            if self.timer:  # it began counting nothing and counts now: the same stage, with its counts shown
                started = self.started
                self.stage(label, total or None, eta=self.eta, live=self.live, unit=unit)
                self.started = self.last = started
            self.update(done, total or None, note)

    def step(self, label: str) -> None:
        """One unit of the current stage done (``label`` names it)."""
        self.update(self.done + 1, note=label)

    def close(self) -> None:
        self._stop.set()
        if self._ticker is not None:
            self._ticker.join(timeout=1)
            self._ticker = None
        with self._lock:
            if self.bar is not None:
                self.bar.close()
                self.bar = None

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _tick(self) -> None:
        """Off a terminal: a line after ``first`` seconds and then every ``every`` seconds while work
        goes on (a short run prints none). On a terminal: the bar redrawn every second while its stage
        has a live note or is a timer (tqdm redraws only on updates)."""
        if self.tty:
            while not self._stop.wait(1.0):
                with self._lock:
                    if self.bar is not None and (self.live is not None or self.timer):
                        if self.live is not None:
                            self.bar.set_postfix_str(self._note(), refresh=False)
                        self.bar.refresh()
            return
        wait = self.first
        while not self._stop.wait(wait):
            wait = self.every
            with self._lock:
                if self.label:
                    shown = self._note()
                    self._line(f"{self.label}: {self._counts()}" + (f", {shown}" if shown else ""))

    # --- rendering ---------------------------------------------------------------------------------
    def _note(self) -> str:
        live = self.live() if self.live is not None else ""
        return ", ".join(part for part in (self.note, live) if part)

    def _counts(self) -> str:
        now = time.monotonic()
        elapsed = max(now - self.started, 1e-9)
        memory = f", {peak_memory_mb():,.0f} MB"
        if self.timer:
            return f"{elapsed:,.0f} s" + memory
        unit = self.stage_unit
        text = f"{self.done:,}" + (f"/{self.total:,} ({100 * self.done / self.total:.0f}%)" if self.total else "")
        text += f" {unit}".rstrip()
        if not self.eta or not unit:
            return text + f", {elapsed:,.0f} s" + memory
        rate, left = estimate(self.done, self.total, self.started, self.last, now)
        text += f", {rate_text(rate)}" if rate is not None else f", {elapsed:,.0f} s"
        if left is not None:
            text += f", ETA {duration_text(left)}"
        return text + memory

    def _line(self, text: str) -> None:
        print(f"fatline: {text}", file=self.stream, flush=True)
