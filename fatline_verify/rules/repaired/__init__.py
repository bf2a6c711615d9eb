"""The repaired rule set: the paper's LineForm with named repairs (not the paper).

Each repair (``repair_*``, :mod:`.options`) acts on the paper's decision, after it (:mod:`.algorithm`);
the prover encodes the repaired rules by the legs they make (their move family, :mod:`.family`, proved by
:mod:`fatline_verify.prove.smt.family`).
"""
