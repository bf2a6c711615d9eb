"""A rule set designed to be certified safe and live (issue 32), not the paper's algorithm.

Each robot moves right toward the greatest x it sees, diagonally right, or along its vertical; never
left, so the right-most vertical stays where it is and no robot passes it. A robot makes a move only if
the move clears, and keeps in view (or reachable through edges that hold), every robot it sees wherever
that robot's own rules might move it this round, as far as it can tell (:func:`.algorithm.region`): the
robots left of it that may move, the moves of higher rank of the robots on its own vertical, and the rest
at rest (they check the pair themselves). Two movers that do not see each other are more than ``rad_v``
apart and move at most one radius.

The measure: ``(sum (x_max - x), sum y)``, lexicographic, falls on every move but a parking (a robot that
sees only its own vertical closing up under the robot above it). The rules, the safety argument, the
measure and what remains for the prover are in :mod:`.algorithm`; ``models/certified.toml`` names the rule
set; ``tests/test_certified.py`` holds its golden verdicts and decision-level tests.
"""
