"""Geometry kernel, construction record, mechanism model and the graphical methods.

Needs only numpy; nothing here draws or reads files.
"""
