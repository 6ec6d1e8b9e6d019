"""How ``tarsim grade`` grades a class that has an answer key: the share of correct items
it credits and of wrong items it names as the key does, per exporting program.

Run:  python benchmarks/grading_corpus.py [--class DIR] [--show N]

The class is tests/data/grading/class/ unless ``--class`` names another made by
``python tests/grading_corpus.py --seed S --out DIR`` (a class not seen before). Each
drawing is graded through the library (``exercises.grading.grade.grade``) against its
exercise at the position its key entry asks, the exercise solved once. For each program
and in all it prints:

- **correct items credited**: of the items the key marks ``correct``, the share the grade
  gives ``correct`` or ``follows from an earlier error`` (an item it does not grade, or a
  file it skips, is not credited);
- **wrong items named**: of the items the key gives any other verdict, the share the grade
  gives that same verdict (then per verdict);
- **not graded**: items the key has and the grade lacks (silently not graded, or in a
  skipped file);
- **invented**: items the grade has and the key does not, that score nothing (penalties);
- **skipped**: files the grade refused, or that crashed it;
- **other position named**: drawings of another position than the one asked whose grade
  names the position they match.

Item names are compared as a course writes them: ``a₂`` or ``a2`` is the crank pin's tip
``a``, ``b₅`` the ram's ``b``, ``a′₄`` and ``a4'`` are ``a4′``, ``13`` is ``I13``.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import tarsim  # noqa: E402
from tarsim.constructions.errors import TarsimError  # noqa: E402
from tarsim.exercises.grading.grade import grade  # noqa: E402
from tarsim.exercises.linkages.solution import solve_positions  # noqa: E402
from tests.loop_kinematics import read_exercise  # noqa: E402

__all__ = ["score", "canonical", "CREDITED", "CLASS"]

CLASS = Path(__file__).resolve().parents[1] / "tests" / "data" / "grading" / "class"
CREDITED = ("correct", "follows from an earlier error")
"""The verdicts that score an item."""

_PLAIN = str.maketrans({**{chr(0x2080 + d): str(d) for d in range(10)},
                        "'": "′", "’": "′", "ʹ": "′", "`": "′", "_": None, " ": None})


def _links_of(exercise: str) -> dict[str, set[int]]:
    """The links each of the exercise's points belongs to (the block's A is link 3's too)."""
    ex = read_exercise(exercise)
    out: dict[str, set[int]] = {}
    for number, points in ex.links.items():
        for p in points:
            out.setdefault(p.lower(), set()).add(number)
    for s in ex.slides:
        out.setdefault(s["point"].lower(), set()).add(s["link"])
    return out


def canonical(name: str, items: set[str], links: dict[str, set[int]]) -> str:
    """An item's name as the key spells it: ``items`` are the key's names for the drawing,
    ``links`` each point's links.

    >>> canonical("a₂′", {"a′", "a4′"}, {"a": {2, 3}}), canonical("13", set(), {})
    ('a′', 'I13')
    """
    t = name.strip().translate(_PLAIN)
    m = re.fullmatch(r"[Ii]?(\d)(\d)", t)
    if m:
        return f"I{min(m[1], m[2])}{max(m[1], m[2])}"
    prime = "′" in t
    t = t.replace("′", "").lower()
    mark = "′" if prime else ""
    if t + mark in items:
        return t + mark
    m = re.fullmatch(r"([a-z])(\d+)", t)
    if m and int(m[2]) in links.get(m[1], ()) and m[1] + mark in items:
        return m[1] + mark                      # the point named by its own link: a₂, b₅
    return t + mark


_FIELDS = ("files", "skipped", "correct", "credited", "wrong", "named", "not_graded",
           "invented", "other_position", "position_named")


def _tally() -> Counter:
    return Counter(dict.fromkeys(_FIELDS, 0))


def score(class_dir: str | Path = CLASS, show: int = 0) -> dict:
    """Grade every drawing of the class in ``class_dir`` against its key.json; return the
    counts per program and in all (``{"programs": {name: counts}, "all": counts}``), each
    counts a dict of: files, skipped, correct, credited, wrong, named, not_graded, invented,
    other_position, position_named, and ``verdicts`` {the key's verdict: [items, given it
    (credited, for "correct"), not graded]}. Items of a drawing of another position than
    the one asked are not counted: its grade is held to naming the position it matches."""
    class_dir = Path(class_dir)
    key = json.loads((class_dir / "key.json").read_text(encoding="utf-8"))
    solved: dict[str, tuple] = {}
    programs: dict[str, Counter] = {}
    verdicts: dict[str, dict[str, list[int]]] = {}
    misses: list[str] = []
    for name, entry in sorted(key["files"].items()):
        exercise = entry["exercise"]
        if exercise not in solved:
            ex = tarsim.load(exercise)
            solved[exercise] = (ex, solve_positions(ex), _links_of(exercise))
        ex, positions, links = solved[exercise]
        c = programs.setdefault(entry["program"], _tally())
        v = verdicts.setdefault(entry["program"], {})
        c["files"] += 1
        expected = entry["items"]
        if "position_matched" in entry:
            c["other_position"] += 1
        got = {}
        try:
            g = grade(ex, class_dir / name, position=entry["position"] - 1, positions=positions)
        except TarsimError as e:
            c["skipped"] += 1
            misses.append(f"{name}: skipped: {e}")
        else:
            for item in g.items:
                got.setdefault(canonical(item.name, set(expected), links), item.verdict)
            if "position_matched" in entry:
                said = g.as_json().get("position_matched") or _named_position(g.notes)
                c["position_named"] += said == entry["position_matched"]
        if "position_matched" in entry:
            continue                     # its items are graded at a position not asked
        for item, want in expected.items():
            have = got.get(item)
            counts = v.setdefault(want, [0, 0, 0])
            counts[0] += 1
            given = have in CREDITED if want == "correct" else have == want
            counts[1] += given
            c["correct" if want == "correct" else "wrong"] += 1
            c["credited" if want == "correct" else "named"] += given
            if have is None:
                c["not_graded"] += 1
                counts[2] += 1
                misses.append(f"{name}: {item} ({want}) not graded")
            elif not given:
                misses.append(f"{name}: {item} {want}, graded {have}")
        for item, have in got.items():
            if item not in expected and have not in CREDITED:
                c["invented"] += 1
                misses.append(f"{name}: {item} invented ({have})")
    every = _tally()
    every_verdicts: dict[str, list[int]] = {}
    for program, c in programs.items():
        every.update(+c)
        for want, counts in verdicts[program].items():
            both = every_verdicts.setdefault(want, [0, 0, 0])
            for k, n in enumerate(counts):
                both[k] += n
    result = {"programs": {p: {**c, "verdicts": verdicts[p]} for p, c in programs.items()},
              "all": {**every, "verdicts": every_verdicts}}
    if show:
        result["misses"] = misses[:show]
    return result


def _named_position(notes: list[str]) -> int | None:
    """The position a grade's notes say the drawing matches, if they say one."""
    for note in notes:
        m = re.search(r"match\w*[^.;]*?position (\d+)", note, re.IGNORECASE)
        if m:
            return int(m[1])
    return None


def _share(part: int, whole: int) -> str:
    return f"{100 * part / whole:.1f} %" if whole else "–"


def main(argv: list[str] | None = None) -> None:
    """Print the class's scores."""
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--class", dest="folder", type=Path, default=CLASS)
    args.add_argument("--show", type=int, default=0, help="list this many misses")
    a = args.parse_args(argv)
    result = score(a.folder, a.show)
    print(f"class: {a.folder}")
    print("| program | files | skipped | correct items credited | wrong items named | "
          "not graded | invented | other position named |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    rows = sorted(result["programs"].items()) + [("all", result["all"])]
    for program, c in rows:
        print(f"| {program} | {c['files']} | {c['skipped']} | "
              f"{c['credited']}/{c['correct']} ({_share(c['credited'], c['correct'])}) | "
              f"{c['named']}/{c['wrong']} ({_share(c['named'], c['wrong'])}) | "
              f"{c['not_graded']} | {c['invented']} | "
              f"{c['position_named']}/{c['other_position']} |")
    print("\n| verdict the key gives | items | given it (credited) | not graded |\n"
          "|---|---:|---:|---:|")
    for want, (n, right, lost) in sorted(result["all"]["verdicts"].items()):
        print(f"| {want} | {n} | {right} ({_share(right, n)}) | {lost} |")
    for line in result.get("misses", []):
        print(line)


if __name__ == "__main__":
    main()
