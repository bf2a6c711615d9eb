"""The paper's rule set: NoMovement, getDestination and Scenarios 1-4 under every reading.

"The algorithm LineForm() is divided into two subroutines. One subroutine, NoMovement() identifies the
cases where the robot will not move, whereas the other subroutine getDestination() computes the
destination points" (:mod:`.algorithm`); the prover encodes it per decision case (:mod:`.cases`).
"""
