"""The ``fatline`` command: a thin shell over the library.

One module per command (``register(sub)`` adds its parser and handler); handlers take parsed
arguments and return an exit code. Every bad input is one line on stderr and exit 2, before any
work starts; an interrupt exits 130 and keeps what was finished.
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Sequence

from ..errors import FatlineError
from . import check, cover, info, prove, reach, regress, replay, report, simulate, sweep, synth
from .common import EXIT_BAD, EXIT_INTERRUPTED, EXIT_OK, ArgumentError, Parser, error_line

COMMANDS = (info, check, prove, cover, reach, synth, sweep, simulate, replay, regress, report)
"""Each command module registers its own subcommand(s); the order is the order of ``--help``."""

DESCRIPTION = "Verify 'Line Formation by Fat Robots under Limited Visibility' (Sil & Gan Chaudhuri)."


def build_parser() -> Parser:
    """The whole command line."""
    from .. import __version__
    from .common import EPILOG

    parser = Parser(prog="fatline", description=DESCRIPTION, epilog=EPILOG)
    parser.add_argument("--version", action="version", version=f"fatline-verify {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND", parser_class=Parser)
    for command in COMMANDS:
        command.register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point: parse, dispatch, turn every expected error into one line."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except ArgumentError as exc:
        print(error_line(str(exc)), file=sys.stderr)
        return EXIT_BAD
    except SystemExit as exc:  # --help and --version
        return int(exc.code or 0)
    from ..resources import return_freed_memory

    return_freed_memory()  # a search's freed buffers leave the process (fatline_verify/resources.py)
    try:
        return int(args.handler(args))
    except FatlineError as exc:
        print(error_line(str(exc)), file=sys.stderr)
        return EXIT_BAD
    except KeyboardInterrupt:
        print("fatline: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        # the reader went away (``fatline ... | head``): not an error of ours
        with contextlib.suppress(OSError):
            sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - silence the flush at exit
        return EXIT_OK
    except OSError as exc:  # the file system said no (a full disk, a name too long): one line naming the path
        from ..outputs import os_error_text

        if os.environ.get("FATLINE_DEBUG"):
            raise
        print(error_line(os_error_text(exc.filename, exc)), file=sys.stderr)
        return EXIT_BAD
    except Exception as exc:  # a bug of the tool: one line, the traceback on request
        if os.environ.get("FATLINE_DEBUG"):
            raise
        print(
            f"fatline: internal error: {exc.__class__.__name__}: {exc} (set FATLINE_DEBUG=1 for the traceback)",
            file=sys.stderr,
        )
        return EXIT_BAD


def run() -> None:
    """Console-script wrapper."""
    sys.exit(main())


__all__ = ["build_parser", "main", "run"]
