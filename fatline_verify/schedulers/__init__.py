"""Schedulers: the transition systems (SSYNC, FSYNC, centralized, ASYNC) and the round's semantics."""
