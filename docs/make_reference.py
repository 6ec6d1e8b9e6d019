"""Write docs/reference/cli.md: every command's --help, as the installed tarsim prints it.

Run:  python docs/make_reference.py

The page is made from the commands themselves, so it cannot say what they do not do;
tests/test_docs_site.py fails when the page and the commands part.
"""

from __future__ import annotations

import sys
from pathlib import Path

from click.testing import CliRunner

PAGE = Path(__file__).resolve().parent / "reference" / "cli.md"

INTRO = """# Command line

Every command of `tarsim`, with the help it prints (`tarsim COMMAND --help`). FILE, wherever
a command takes one, is an exercise file (TOML) or the id of a bundled exercise
(`tarsim list`, and the [catalog](../catalog.md)). A command that fails prints one line
starting `Error:` and exits 1 (2 for a mistyped option, 3 for a check that failed), and
writes nothing half-way.

"""


def page() -> str:
    """The page's text, from the installed commands' help."""
    from tarsim.exercises.cli import cli

    runner = CliRunner()
    parts = [INTRO, "## tarsim\n\n```text\n", _help(runner, cli, []), "```\n"]
    for name in sorted(cli.commands):
        parts += [f"\n## tarsim {name}\n\n```text\n", _help(runner, cli, [name]), "```\n"]
    return "".join(parts)


def _help(runner, cli, args: list[str]) -> str:
    result = runner.invoke(cli, [*args, "--help"], prog_name="tarsim", terminal_width=90)
    if result.exit_code:
        sys.exit(f"tarsim {' '.join(args)} --help failed: {result.output}")
    return result.output


def main() -> None:
    """Write the page."""
    PAGE.parent.mkdir(parents=True, exist_ok=True)
    PAGE.write_text(page(), encoding="utf-8")
    print(f"wrote {PAGE}")


if __name__ == "__main__":
    main()
