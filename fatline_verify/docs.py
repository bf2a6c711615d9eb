"""``python -m fatline_verify.docs [PATH]``: write the readings catalogue (default ``docs/readings.md``,
run from the repository root) from ``options.py``, so the file the reports link to never goes stale.

The file carries the report's text marker, so it is rewritten freely but a file of another kind at
``PATH`` is not overwritten (docs/commands.md, "Outputs: nothing destroyed by default").
"""

from __future__ import annotations

import sys
from pathlib import Path

from .errors import FatlineError
from .outputs import Kind, claim_file, write_text
from .text import READINGS_DOC, readings_markdown


def write_readings(path: str | Path = READINGS_DOC) -> Path:
    """Write :func:`~fatline_verify.text.readings_markdown` to ``path``; return the path."""
    target = claim_file(path, name="path", kind=Kind.PAGE)
    write_text(target, readings_markdown())
    return target


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    try:
        print(f"wrote {write_readings(*args[:1])}")
    except FatlineError as exc:
        print(f"fatline: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
