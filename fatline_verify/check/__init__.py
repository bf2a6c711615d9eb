"""The bounded model checker: initial configurations, exploration engines, liveness, witnesses."""
