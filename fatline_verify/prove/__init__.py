"""The prover: obligations per decision case, their search and results; smt/ is the only z3 importer."""
