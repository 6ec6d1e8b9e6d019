"""The phrase catalogues, one module per language (see :mod:`..narration`)."""
