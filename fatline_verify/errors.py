"""The error hierarchy: one root, one class per kind of bad input.

Every message names the offending ``name=value`` and what was expected, on one line, so the CLI
can print it as it is and exit 2 (1 for :class:`TraceDidNotReproduce`).
"""

from __future__ import annotations


class FatlineError(Exception):
    """Root of every error the tool raises on purpose."""


class InvalidModel(FatlineError):
    """A model file or model value is malformed: unknown key, option or reading, bad parameter."""


class InvalidInput(FatlineError):
    """A command-line value is malformed: an ``--init`` position, a bound, a robot count."""


class InvalidTrace(FatlineError):
    """A trace file is malformed: not JSON, not the schema, or names an unknown option."""


class ForbiddenRound(InvalidTrace):
    """A trace's round activates robots its scheduler never activates together (more than ``k`` under a
    scheduler that allows at most ``k``): the file does not record a run of its model."""


class Unsupported(FatlineError):
    """A reading that is selectable but not implemented by the requested engine."""


class TraceDidNotReproduce(FatlineError):
    """Replay recomputed a value that differs from the recorded one; names the first difference."""


class OutputFailed(FatlineError):
    """A file could not be written or read back as written (a full disk, a name too long, a file changed
    since the tool wrote it); the message names the path."""
