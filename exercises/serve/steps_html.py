"""steps.md as HTML, for the page: the few forms :func:`~..worked_document.markdown` writes.

steps.md is written by one writer in a handful of forms (headings, numbered steps,
bullets, quoted notes, paragraphs, tables, and a file's name in backquotes), so they are
set here as HTML rather than by a Markdown library the server would need only for this.
Every piece of text is escaped: a file's name or description is the user's own.
"""

from __future__ import annotations

import html
import re

__all__ = ["steps_html"]

_NUMBERED = re.compile(r"^(\d+)\. (.*)$")
_CODE = re.compile(r"`([^`]*)`")


def _inline(text: str) -> str:
    """A line's text, escaped, its backquoted names set as code."""
    return _CODE.sub(r"<code>\1</code>", html.escape(text, quote=False))


def steps_html(markdown: str) -> str:
    r"""The HTML of steps.md's ``markdown``.

    >>> print(steps_html("## Centres (`centres.svg`)\n\n1. I12 is O2.\n2. I14 < I24.\n"))
    <h2>Centres (<code>centres.svg</code>)</h2>
    <ol>
    <li value="1">I12 is O2.</li>
    <li value="2">I14 &lt; I24.</li>
    </ol>
    """
    out: list[str] = []
    open_block = ""                    # "ol", "ul", "blockquote" or "table" being set

    def close() -> None:
        nonlocal open_block
        if open_block:
            out.append(f"</{open_block}>")
        open_block = ""

    def start(tag: str, attrs: str = "") -> None:
        nonlocal open_block
        if open_block != tag:
            close()
            out.append(f"<{tag}{attrs}>")
            open_block = tag

    for line in markdown.splitlines():
        if not line.strip():
            close()
        elif line.startswith("#"):
            close()
            level = min(len(line) - len(line.lstrip("#")), 6)
            out.append(f"<h{level}>{_inline(line[level:].strip())}</h{level}>")
        elif m := _NUMBERED.match(line):
            start("ol")
            out.append(f'<li value="{m.group(1)}">{_inline(m.group(2))}</li>')
        elif line.startswith("- "):
            start("ul")
            out.append(f"<li>{_inline(line[2:])}</li>")
        elif line.startswith("> "):
            start("blockquote")
            out.append(f"<p>{_inline(line[2:])}</p>")
        elif line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            if open_block != "table":
                start("table")
                out.append("<tr>" + "".join(f"<th>{_inline(c)}</th>" for c in cells) + "</tr>")
            elif not set(line) <= set("|-"):                      # not the rule under the head
                out.append("<tr>" + "".join(f"<td>{_inline(c)}</td>" for c in cells) + "</tr>")
        else:
            close()
            out.append(f"<p>{_inline(line)}</p>")
    close()
    return "\n".join(out)
