"""Progress on stderr, the one reporting layer for long runs (the engine only calls back).

On a terminal: a tqdm bar with the stage, done/total, %, rate and ETA. Off a terminal (a pipe, a
CI log): one plain line every few seconds and one when a stage ends, so a log shows the run moving
without drowning in carriage returns. ``enabled=False`` (``-q``) prints nothing.
"""

from __future__ import annotations

import resource
import sys
import time
from typing import Any, TextIO


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
    ) -> None:
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.unit = unit
        self.every = every
        self.tty = self.stream.isatty() if tty is None else tty
        self.bar: Any = None
        self.label = ""
        self.started = self.last = time.monotonic()
        self.done = 0
        self.total: int | None = None

    # --- the callbacks -----------------------------------------------------------------------------
    def stage(self, label: str, total: int | None = None) -> None:
        """Start a new stage (ends the previous one)."""
        if not self.enabled:
            return
        self._end_stage()
        self.label, self.total, self.done = label, total, 0
        self.started = self.last = time.monotonic()
        if self.tty:
            from tqdm import tqdm

            self.bar = tqdm(total=total, desc=label, unit=self.unit, file=self.stream, leave=False, dynamic_ncols=True)
        else:
            self._line(f"{label}: started" + (f", {total:,} {self.unit}".rstrip() if total else ""))

    def update(self, done: int, total: int | None = None, note: str = "") -> None:
        """``done`` of ``total`` units in the current stage; ``note`` is shown beside the counts."""
        if not self.enabled:
            return
        self.done = done
        if total is not None:
            self.total = total
        if self.bar is not None:
            if total is not None and self.bar.total != total:
                self.bar.total = total
            self.bar.n = done
            if note:
                self.bar.set_postfix_str(note, refresh=False)
            self.bar.refresh()
            return
        now = time.monotonic()
        if now - self.last >= self.every:
            self.last = now
            self._line(f"{self.label}: {self._counts()}" + (f", {note}" if note else ""))

    def step(self, label: str, note: str = "") -> None:
        """One unit of the current stage done (``label`` names it)."""
        if not self.enabled:
            return
        self.done += 1
        if self.bar is not None:
            self.bar.n = self.done
            self.bar.set_postfix_str(label, refresh=False)
            self.bar.refresh()
        else:
            self._line(f"{self.label}: {self._counts()}: {label}" + (f" {note}" if note else ""))

    def close(self) -> None:
        self._end_stage()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- rendering ---------------------------------------------------------------------------------
    def _counts(self) -> str:
        elapsed = max(time.monotonic() - self.started, 1e-9)
        rate = self.done / elapsed
        text = f"{self.done:,}" + (f"/{self.total:,} ({100 * self.done / self.total:.0f}%)" if self.total else "")
        text += f" {self.unit}".rstrip() + f", {rate:,.0f}/s" if self.unit else f", {elapsed:.0f} s"
        if self.total and self.done and self.done < self.total:
            text += f", ETA {(self.total - self.done) / rate:,.0f} s"
        return text + f", {peak_memory_mb():,.0f} MB"

    def _line(self, text: str) -> None:
        print(f"fatline: {text}", file=self.stream, flush=True)

    def _end_stage(self) -> None:
        if self.bar is not None:
            self.bar.close()
            self.bar = None
        elif self.label and not self.tty:
            self._line(f"{self.label}: done, {self._counts()}")
        self.label = ""
