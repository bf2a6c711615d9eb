"""Rule sets: what a robot decides from what it sees, one package each, registered."""
