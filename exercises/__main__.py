"""``python -m tarsim``: the command line."""

from .cli import cli

cli(prog_name="tarsim")
