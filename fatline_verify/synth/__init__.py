"""``fatline synth``: search for an oblivious rule table of the repaired family's legs that is safe and live.

An oblivious rule is a table from a robot's view (what it sees within ``rad_v``, relative to itself)
to one of the legs of :mod:`fatline_verify.repair.reach` or to staying. :mod:`.encode` turns "this
table is safe and live on every swarm of ``n`` robots starting in the window" into SAT (python-sat),
lazily; :mod:`.table` holds a table and its file; :mod:`.replay` plays a table through the executable
model on its own, apart from the encoding.
"""
