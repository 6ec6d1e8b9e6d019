"""steps.md as a document: what a worked solution says, typed, and the one writer of it.

Every chapter says what its steps.md holds as :class:`Section` s: a heading said by a
catalogue phrase and the figures it is drawn in, then its blocks (numbered
:class:`Steps`, :class:`Bullets`, a :class:`Paragraph`, :class:`Notes`, a
:class:`Table`). :func:`markdown` writes them in a language. So no chapter spells
markdown of its own, and no heading is English turned into another language after the
fact: each is a phrase every catalogue says.

A step, a bullet, a paragraph or a table's cell is :data:`Said`: a
:class:`~tarsim.constructions.narration.Phrase` (or a recorded
:class:`~tarsim.constructions.record.Step`, which says its own), a
:class:`~tarsim.constructions.narration.Word` the catalogue says, or text already said in
the language being spoken (a number set in its digits, the file's own description).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import singledispatch
from typing import Union

from tarsim.constructions.narration import Phrase, Word, narrate, phrase, render
from tarsim.constructions.record import Construction, Step

__all__ = ["Said", "Section", "Steps", "Bullets", "Paragraph", "Notes", "Table", "Block",
           "title", "numbered", "said_steps", "markdown"]

Said = Union[Phrase, Step, Word, str]
"""What a line of steps.md says: a phrase, a step (its phrase), a catalogue's word, or words
already said."""


@dataclass(frozen=True)
class Steps:
    """Numbered steps: each its number and what it says. The numbers are given, not counted
    here, so a figure's circled numbers and steps.md's are one numbering
    (:meth:`~tarsim.constructions.record.Slice.numbered`)."""

    items: tuple[tuple[int, Said], ...]


@dataclass(frozen=True)
class Bullets:
    """Unnumbered points: a train's members, a solution's checked readings."""

    items: tuple[Said, ...]


@dataclass(frozen=True)
class Paragraph:
    """A sentence or a few standing alone: the file's description, a reading's words."""

    said: Said


@dataclass(frozen=True)
class Notes:
    """A position's notes, quoted. None at all still stand as the blank line they would end
    with, as steps.md has always set a position without notes."""

    items: tuple[Said, ...]


@dataclass(frozen=True)
class Table:
    """A table: its head (its cells, or one phrase that says the whole head row), and its
    rows.

    ``width`` is how many columns a head said as one phrase spans (its rule's dashes).
    """

    head: tuple[Said, ...] | Phrase
    rows: tuple[tuple[Said, ...], ...]
    width: int = 0


Block = Union[Steps, Bullets, Paragraph, Notes, Table]
"""What a section holds."""


@dataclass(frozen=True)
class Section:
    """A heading, said by a catalogue phrase, with the figures it is drawn in; then its
    blocks. A section with no heading is blocks that follow the one before (a table under
    the steps that fill it in). ``level`` 1 heads a part of the document (the solution's
    title, one position of several), 2 a figure's or a reading's part."""

    heading: Phrase | None = None
    blocks: tuple[Block, ...] = ()
    figures: tuple[str, ...] = ()
    """The stems of the figures the section is drawn in: "(`table.svg`)"."""
    level: int = 2

    def lines(self, lang: str) -> list[str]:
        """The section's lines in ``lang``: its heading, then each block, each followed by a
        blank line."""
        out = []
        if self.heading is not None:
            drawn = ", ".join(f"`{stem}.svg`" for stem in self.figures)
            out += ["#" * self.level + " " + narrate(self.heading, lang)
                    + (f" ({drawn})" if drawn else ""), ""]
        for block in self.blocks:
            out += _lines(block, lang) + [""]
        return out


def title(name: str, description: str | None = None) -> Section:
    """The document's first section: "<name>: worked solution", and the file's own
    description of the exercise under it, as the file words it."""
    return Section(phrase("md.title", name=name),
                   (Paragraph(description),) if description else (), level=1)


def numbered(items: Iterable[Said]) -> Steps:
    """Steps numbered 1, 2, … in order: a record's acts, or a method's sentences."""
    return Steps(tuple(enumerate(items, 1)))


def said_steps(construction: Construction) -> Steps:
    """Every act of a chapter's record that says something, in record order, numbered: the
    record is the figure's, drawn whole (a displacement diagram, a velocity diagram)."""
    return numbered(s for s in construction if s.phrase is not None)


def markdown(sections: Sequence[Section], lang: str) -> str:
    """steps.md: the sections in ``lang``, a blank line after each heading and between
    blocks (a document that ends on a heading keeps the blank line under it).

    >>> print(markdown([Section(phrase("md.results"), (Bullets(("ω3 = 2 rad/s",)),),
    ...                         figures=("centres",))], "en"), end="")
    ## Results (`centres.svg`)
    <BLANKLINE>
    - ω3 = 2 rad/s
    """
    lines = [line for s in sections for line in s.lines(lang)]
    if sections and sections[-1].blocks:
        lines.pop()                     # the blank line after the last block
    return "\n".join(lines) + "\n"


@singledispatch
def _lines(block: Block, lang: str) -> list[str]:
    """A block's lines in ``lang``, by its kind."""
    raise TypeError(f"steps.md has no block of the kind {type(block).__name__}")


@_lines.register
def _(block: Steps, lang: str) -> list[str]:
    return [f"{n}. {_said(item, lang)}" for n, item in block.items]


@_lines.register
def _(block: Bullets, lang: str) -> list[str]:
    return [f"- {_said(item, lang)}" for item in block.items]


@_lines.register
def _(block: Paragraph, lang: str) -> list[str]:
    return [_said(block.said, lang)]


@_lines.register
def _(block: Notes, lang: str) -> list[str]:
    return [f"> {_said(item, lang)}" for item in block.items]


@_lines.register
def _(block: Table, lang: str) -> list[str]:
    if isinstance(block.head, Phrase):
        head, width = narrate(block.head, lang), block.width
    else:                   # a blank corner cell is set "| |", over the rows' names
        cells = [_said(c, lang) for c in block.head]
        head, width = "|" + "".join(f" {c} |" if c else " |" for c in cells), len(cells)
    return [head, "|" + "---|" * width] + ["| " + " | ".join(_said(c, lang) for c in row) + " |"
                                           for row in block.rows]


def _said(item: Said, lang: str) -> str:
    """What ``item`` says in ``lang``."""
    return render(item, lang) if isinstance(item, Word) else narrate(item, lang)
