"""Towards a live rule set: reach (any rule set of given legs), pockets, the corpus under another model."""
