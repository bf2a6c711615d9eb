"""Exact numbers at the boundary: parse and print integers and ``p/q`` fractions.

Inside the engine every coordinate is an ``int`` or a :class:`fractions.Fraction`; a float never
decides a predicate. This module is the only place text becomes a number and back.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction
from typing import TypeAlias

Number: TypeAlias = int | Fraction
Point: TypeAlias = tuple[Number, Number]

_EXACT = re.compile(r"^\s*[+-]?\d+(\s*/\s*\d+)?\s*$")
_DECIMAL = re.compile(r"^\s*[+-]?(\d+\.\d*|\.\d+|\d+)\s*$")


def normalize(value: Number) -> Number:
    """Return ``value`` as an ``int`` when it is integral, else as a reduced ``Fraction``."""
    if isinstance(value, Fraction) and value.denominator == 1:
        return int(value.numerator)
    return value


MAX_DIGITS = 1000
"""The most digits a number read from text may have (positions, parameters): far more than any model or
trace needs (the longest in the corpus has 119), and few enough that exact arithmetic on them stays fast."""


def _digits(value: object) -> int:
    """The digits of an integer, or of the longest run of digits in a text (without converting it)."""
    if isinstance(value, int):
        size = value.bit_length()
        return len(str(abs(value))) if size < 13_000 else int(size * 0.30103) + 1  # str() stops at 4,300 digits
    if isinstance(value, str):
        return max((len(run) for run in re.findall(r"\d+", value)), default=0)
    return 0


def parse_number(text: object, *, name: str, allow_decimal: bool = False) -> Number:
    """Parse an integer, ``"p/q"`` (or, if allowed, a finite decimal such as ``"2.01"``) exactly.

    A decimal means the number it writes: ``"3.3"`` is 33/10, never the binary float nearest to it.
    A TOML float (``delta = 2.1``) is read back through its shortest decimal, so it is 21/10 too.

    Raises ``ValueError`` with a one-line message naming ``name=text``; callers wrap it in the
    error class of their boundary.
    """
    if isinstance(text, bool):
        raise ValueError(f"{name}={text!r}: expected an integer or a fraction like 5/2")
    digits = _digits(text)
    if digits > MAX_DIGITS:
        head = text.strip()[:20] if isinstance(text, str) else str(text)[:20] if digits < 4000 else ""
        raise ValueError(f"{name}={head}...: a number of {digits:,} digits; expected at most {MAX_DIGITS} digits")
    if isinstance(text, int):
        return text
    if isinstance(text, float) and allow_decimal and math.isfinite(text):
        return normalize(Fraction(repr(text)))  # the shortest decimal that reads back as it: what was written
    if isinstance(text, str):
        if _EXACT.match(text):
            parts = text.replace(" ", "").split("/")
            if len(parts) == 2 and int(parts[1]) == 0:
                raise ValueError(f"{name}={text!r}: the denominator is zero")
            return normalize(Fraction(text.replace(" ", "")))
        if allow_decimal and _DECIMAL.match(text):
            return normalize(Fraction(text.strip()))
    expected = "an integer, a fraction like 5/2" + (" or a decimal like 2.01" if allow_decimal else "")
    raise ValueError(f"{name}={text!r}: expected {expected}")


def format_number(value: Number) -> int | str:
    """Render a number for JSON: an ``int`` stays an int, a fraction becomes ``"p/q"``."""
    value = normalize(value)
    if isinstance(value, int):
        return value
    return f"{value.numerator}/{value.denominator}"


def show(value: Number) -> str:
    """Human text for a number: ``3`` or ``5/2``."""
    return str(format_number(value))


def show_point(point: Point) -> str:
    """Human text for a point: ``(3, 5/2)``."""
    return f"({show(point[0])}, {show(point[1])})"
