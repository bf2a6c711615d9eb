"""The only place that imports z3: symbolic rules, obligations, SMT-LIB2 output, model decoding."""
