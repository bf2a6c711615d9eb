"""Traces: running a swarm, the versioned trace format and its replay."""
