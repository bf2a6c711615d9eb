"""``python -m fatline_verify.cli``."""

from . import run

if __name__ == "__main__":  # spawned worker processes import this module as __mp_main__: they must not run
    run()
