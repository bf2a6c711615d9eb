"""Rule sets that play a table ``fatline synth`` found: one registered rule set per shipped table file."""
