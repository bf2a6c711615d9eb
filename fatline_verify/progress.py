"""Progress on stderr, the one reporting layer for long runs (the engine only calls back).

On a terminal: a tqdm bar with the stage, done/total, %, rate and ETA. Off a terminal (a pipe, a
CI log): one plain line every few seconds (stage, counts, %, rate, ETA, memory), so a log shows a
long run moving without drowning in carriage returns, and a short run prints nothing.
``enabled=False`` (``-q``) prints nothing.
"""

from __future__ import annotations

import resource
import sys
import threading
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
        self.started = time.monotonic()
        self.done = 0
        self.total: int | None = None
        self.note = ""
        self._stop = threading.Event()
        self._ticker: threading.Thread | None = None
        if enabled and not self.tty:
            self._ticker = threading.Thread(target=self._tick, name="fatline-progress", daemon=True)
            self._ticker.start()

    # --- the callbacks -----------------------------------------------------------------------------
    def stage(self, label: str, total: int | None = None) -> None:
        """Start a new stage (ends the previous one)."""
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.close()
            self.bar = None
        self.label, self.total, self.done, self.note = label, total, 0, ""
        self.started = time.monotonic()
        if self.tty:
            from tqdm import tqdm

            self.bar = tqdm(total=total, desc=label, unit=self.unit, file=self.stream, leave=False, dynamic_ncols=True)

    def update(self, done: int, total: int | None = None, note: str = "") -> None:
        """``done`` of ``total`` units in the current stage; ``note`` is shown beside the counts."""
        if not self.enabled:
            return
        self.done, self.note = done, note
        if total is not None:
            self.total = total
        if self.bar is not None:
            if total is not None and self.bar.total != total:
                self.bar.total = total
            if note:
                self.bar.set_postfix_str(note, refresh=False)
            if done > self.bar.n:
                self.bar.update(done - self.bar.n)  # tqdm's own rate and ETA need real increments
            else:
                self.bar.refresh()

    def step(self, label: str) -> None:
        """One unit of the current stage done (``label`` names it)."""
        self.update(self.done + 1, note=label)

    def close(self) -> None:
        self._stop.set()
        if self._ticker is not None:
            self._ticker.join(timeout=1)
            self._ticker = None
        if self.bar is not None:
            self.bar.close()
            self.bar = None

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _tick(self) -> None:
        """Off a terminal: one line every ``every`` seconds while work goes on (a short run prints none)."""
        while not self._stop.wait(self.every):
            if self.label:
                self._line(f"{self.label}: {self._counts()}" + (f", {self.note}" if self.note else ""))

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
