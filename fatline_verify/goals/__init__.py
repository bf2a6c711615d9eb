"""Goals: when a swarm has done what its rule set is for, registered by name (:mod:`.registry`); this
package's own are in :mod:`.builtin`, their exact shape tests in :mod:`.shapes`."""

from .registry import Goal, register_goal

__all__ = ["Goal", "register_goal"]
