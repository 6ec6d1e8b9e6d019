"""Mechanism and exercise files, the bundled catalog, and the ``tarsim`` command line."""
