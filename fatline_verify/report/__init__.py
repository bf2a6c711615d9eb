"""Reports: pictures of counterexamples, per-model pages, the cross-model matrix."""
