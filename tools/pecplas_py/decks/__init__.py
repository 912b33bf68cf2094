"""Deck generators: the decks of input/ (scenes S1-S6, examples, sweeps) and test/data/ (footing,
joint patches, Katona patches, Hertz), written through pecplas_py.deck."""
