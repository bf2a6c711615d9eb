"""Memory: the machine's, the share a search may use (``--max-memory``), and sizes as text.

A search holds packed keys and compact columns (:class:`fatline_verify.check.search.Exploration`);
it stops cleanly before a step of a level whose peak, from the level's real figures, would pass the
budget (:mod:`fatline_verify.check.guard`). Without ``--max-states``
the budget is the only limit on states.
"""

from __future__ import annotations

import os
import re

from .errors import InvalidInput

BYTES_PER_STATE = 128
"""A generous estimate of a search's bytes per state and its level's temporaries (the compact store
holds 18 bytes a state, plus 8 for the visited set while the search runs)."""

PEAK_FACTOR = 1.25
"""A margin over the held arrays plus what a level adds at its peak (its working copies, priced from
its real figures: :mod:`fatline_verify.check.guard`) for what the prices miss (the process itself,
the engine's caches); the memory guard keeps their product within ``--max-memory``."""

DEFAULT_SHARE = 0.5
"""The share of the machine's memory a search may use unless ``--max-memory`` says otherwise."""

_UNITS = {"": 1, "K": 2**10, "M": 2**20, "G": 2**30, "T": 2**40}


def machine_memory() -> int:
    """Physical memory in bytes (Linux and other POSIX systems; 8 GiB where it cannot be read)."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):
        return 8 * 2**30


def default_max_memory() -> int:
    return int(machine_memory() * DEFAULT_SHARE)


def parse_size(text: str, name: str = "max-memory") -> int:
    """``"512M"``, ``"1.5G"``, ``"2000000"`` (bytes) -> bytes; a one-line error otherwise."""
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([KMGT]?)(?:i?B)?\s*", text, flags=re.IGNORECASE)
    if not m:
        raise InvalidInput(f"{name}={text!r}: expected a size such as 512M, 4G or 1.5G")
    size = int(float(m.group(1)) * _UNITS[m.group(2).upper()])
    if size < 2**20:
        raise InvalidInput(f"{name}={text!r}: expected at least 1M")
    total = machine_memory()
    if size > total:
        raise InvalidInput(f"{name}={text!r}: expected at most this machine's memory, {format_size(total)}")
    return size


def format_size(size: int) -> str:
    """Bytes as a short size with a binary unit (``1.5G``, ``512M``)."""
    for unit in ("T", "G", "M", "K"):
        if size >= _UNITS[unit]:
            value = size / _UNITS[unit]
            return f"{value:.1f}{unit}" if value < 10 and value != int(value) else f"{round(value)}{unit}"
    return f"{size}B"


def current_rss() -> int:
    """This process's resident memory now, in bytes (0 where it cannot be read)."""
    try:
        with open("/proc/self/statm") as fh:
            return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


MMAP_THRESHOLD = 128 * 2**10
"""Buffers at least this large get pages of their own from the kernel and give them back when freed
(:func:`return_freed_memory`)."""


def return_freed_memory() -> bool:
    """Have the C allocator map every buffer of :data:`MMAP_THRESHOLD` bytes or more on its own and unmap
    it when it is freed; whether it could (glibc only; elsewhere nothing changes).

    glibc raises its threshold for that after each such buffer is freed (up to 32 MB), so a search's
    batch temporaries of a few megabytes then come from the heap, whose freed holes stay resident: at
    n = 6 on the SPIN reading the process peaked at 364 MB, 313 MB with the threshold fixed (what
    ``MALLOC_MMAP_THRESHOLD_`` sets; setting it also stops the raising)."""
    global _RETURNING
    if _RETURNING is not None:
        return _RETURNING
    _RETURNING = False
    try:
        if not os.confstr("CS_GNU_LIBC_VERSION"):
            return False
        import ctypes

        libc = ctypes.CDLL(None)
        _RETURNING = bool(libc.mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD))
    except (ValueError, OSError, AttributeError):
        pass
    return _RETURNING


_M_MMAP_THRESHOLD = -3
"""glibc's ``mallopt`` parameter number (malloc.h)."""
_RETURNING: bool | None = None


__all__ = [
    "BYTES_PER_STATE",
    "default_max_memory",
    "format_size",
    "machine_memory",
    "parse_size",
    "return_freed_memory",
]
