"""Published algorithms besides the paper's, each encoded from its published text (issue 39, item 5).

One module per algorithm, each registering one rule set with the setting it claims (its lemmas, its own
readings as parameters): :mod:`.ando` (Ando, Oasa, Suzuki, Yamashita 1999: point convergence, limited
visibility). Their models are ``models/<name>.toml``; their pages ``docs/published/<name>.md`` give the
claim, the encoding, the readings, the verdicts and what the tool could not express. Each is registered
exactly as a plug-in's would be (``RuleSet`` and ``register``, nothing private), so a copy of a module in
an installed package with a ``fatline.plugins`` entry point would work the same.
"""
