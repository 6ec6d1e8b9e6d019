"""``python -m tarsim``: the command line."""

from tarsim.exercises.cli import cli

cli(prog_name="tarsim")
