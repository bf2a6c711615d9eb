"""``fatline sweep``: is the paper wrong under every reading of its text, or only under some?

:mod:`.space` is the product of readings, :mod:`.cover` judges one counterexample under all of
them at once, :mod:`.run` is the loop (check one open combination, cover with its witnesses) and
its saved state.
"""
