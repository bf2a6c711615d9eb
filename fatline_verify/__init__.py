"""fatline-verify: formal verification of *Line Formation by Fat Robots under Limited Visibility*.

The library API comes first; :mod:`fatline_verify.cli` is a thin shell over it.
"""

__version__ = "0.1.0"
