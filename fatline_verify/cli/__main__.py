"""``python -m fatline_verify.cli``."""

from . import run

run()
