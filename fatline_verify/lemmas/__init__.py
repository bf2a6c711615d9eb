"""The lemmas: where each is judged and how it is violated, and the typed verdicts."""
