"""Tests for exercises.toml_depth: a TOML text's depth measured before tomllib reads it.

The pass must measure what tomllib builds: for any document, written in any of TOML's
ways (headers, arrays of tables, dotted keys, inline tables, arrays over several lines,
quoted keys, the four kinds of string, comments), the depth it refuses at is the depth of
the tree tomllib returns, never less (a deep file let through) and never more (a good
file refused). Strings and comments full of dots, brackets, braces and quotes must not
move it.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tarsim.constructions.errors import InputError
from tarsim.exercises import toml_depth
from tarsim.exercises.toml_depth import MOST_DEPTH, check_depth

ROOT = Path(__file__).parent.parent


def depth(value, at: int = 0) -> int:
    """How deep ``value``, sitting ``at`` deep, reaches: a scalar where it sits, a table or
    an array one below it, empty or not. The document itself sits at 0."""
    if isinstance(value, dict):
        children = value.values()
    elif isinstance(value, list):
        children = value
    else:
        return at
    return max((depth(c, at + 1) for c in children), default=at + 1)


def document_depth(tree: dict) -> int:
    return max((depth(v, 1) for v in tree.values()), default=0)


def measured(text: str, monkeypatch) -> int:
    """The least MOST_DEPTH that ``text`` passes, found by bisection."""
    low, high = 0, 200
    while low < high:
        mid = (low + high) // 2
        monkeypatch.setattr(toml_depth, "MOST_DEPTH", mid)
        try:
            check_depth(text, "f.toml")
            high = mid
        except InputError:
            low = mid + 1
    monkeypatch.setattr(toml_depth, "MOST_DEPTH", MOST_DEPTH)
    return low


# ----- what it refuses, and where ---------------------------------------------------------------
DEEP = MOST_DEPTH + 1


@pytest.mark.parametrize("text, line, column", [
    ("a = 1\n" + "k." * MOST_DEPTH + "k = 1\n", 2, 2 * MOST_DEPTH),       # the 32nd dot
    ("[" + ".".join(["t"] * MOST_DEPTH) + "]\nx = 1\n", 1, 2 * MOST_DEPTH + 1),  # its ]
    ("[[" + ".".join(["t"] * (MOST_DEPTH - 1)) + "]]\n", 1, 2 * MOST_DEPTH),  # an entry deeper
    ("x = " + "[" * DEEP + "]" * DEEP + "\n", 1, 4 + MOST_DEPTH),          # the 32nd [
    ("x = " + "{ a = " * DEEP + "1" + " }" * DEEP + "\n", 1, 6 * MOST_DEPTH - 1),  # 32nd {
    # Headers, keys, inline tables and arrays add up: 10 + 10 + 1 + 11 = 32 is the deepest.
    ("[" + ".".join(["h"] * 10) + "]\n" + ".".join(["k"] * 10) + " = { i = "
     + "[" * 12 + "]" * 12 + " }\n", 2, 20 + 8 + 11 + 1),
])
def test_too_deep_is_refused_at_its_line_and_column(text, line, column):
    with pytest.raises(InputError) as info:
        check_depth(text, "f.toml")
    assert str(info.value) == (
        f"f.toml:{line}:{column}: nests arrays or tables too deeply to read: past {MOST_DEPTH} "
        "keys, tables and arrays deep (an exercise needs 4)")


@pytest.mark.parametrize("inside", [
    'x = "{}"', "x = '{}'", 'x = """\n{}\n"""', "x = '''\n{}\n'''", "# {}",
    '"{}" = 1', "'{}' = 1", "[\"{}\"]", 'x = [ # {}\n 1 ]',
])
def test_dots_brackets_and_braces_in_strings_and_comments_do_not_count(inside):
    deep = "a." * 50 + "[" * 50 + "{" * 50 + "]" * 50 + "}" * 50
    text = inside.format(deep)
    assert depth(tomllib.loads(text)) <= 3         # a string or a comment: nothing deep
    check_depth(text, "f.toml")


@pytest.mark.parametrize("text", [
    'x = """a\\"""b"""\n' + "k." * DEEP + "k = 1",        # an escaped quote does not close
    'x = """a\\\\"""\n' + "k." * DEEP + "k = 1",          # an escaped backslash does
    'x = """a"""""\n' + "k." * DEEP + "k = 1",            # two quotes before the closing three
    "x = '''a'''''\n" + "k." * DEEP + "k = 1",
    'x = "a\\"#"\n' + "k." * DEEP + "k = 1",
    # A quote left over after the closing three would open a string that hides the rest.
    'x = 1\ny = ["""a"""", ' + "[" * DEEP + "]" * DEEP + "]",
    "x = 1\ny = ['''a'''', " + "[" * DEEP + "]" * DEEP + "]",
])
def test_a_string_ends_where_toml_ends_it(text):
    tomllib.loads(text)                              # valid TOML: the key is read as a key
    with pytest.raises(InputError, match=r"^f\.toml:2:"):
        check_depth(text, "f.toml")


def test_every_bundled_and_test_file_is_read(monkeypatch):
    """None of the project's own TOML files comes near the bound: the deepest is 4 (a
    [[link]] entry's lengths = { O2A = … }), and the pass measures each as tomllib builds
    it. crash-8 is nested 500 deep on purpose, and crash-6 is not UTF-8."""
    files = [p for folder in ("exercises/catalog", "tests/data", "tests/reproducers")
             for p in sorted((ROOT / folder).rglob("*.toml"))
             if not p.name.startswith(("crash-8-", "crash-6-"))]
    assert len(files) > 60
    deepest = 0
    for path in files:
        text = path.read_text(encoding="utf-8")
        check_depth(text, str(path))
        assert measured(text, monkeypatch) == document_depth(tomllib.loads(text)), path
        deepest = max(deepest, document_depth(tomllib.loads(text)))
    assert deepest == 4


# ----- any document, any way of writing it ------------------------------------------------------
NASTY = '.[]{}#="\'\n\\'
"""What a string or a comment may hold to fool a pass that does not follow them."""
TEXT = st.text(alphabet=st.one_of(st.sampled_from(NASTY), st.characters()), max_size=12)
KEYS = st.text(alphabet=st.one_of(st.sampled_from(NASTY), st.characters()), min_size=1,
               max_size=6)
SCALARS = st.one_of(st.integers(-2**63, 2**63 - 1), st.booleans(),
                    st.floats(allow_nan=False, width=64), TEXT)
TREES = st.recursive(
    SCALARS,
    lambda inner: st.one_of(st.lists(inner, max_size=3),
                            st.dictionaries(KEYS, inner, max_size=3)),
    max_leaves=25)


def _basic(s: str, *, multiline: bool = False) -> str:
    # Up to two quotes may end a multi-line string unescaped, running into its closing three.
    ending = len(s) - len(s.rstrip('"')) if multiline else 0
    ending = ending if ending <= 2 else 0
    s = s[:len(s) - ending]
    out = []
    for c in s:
        if c in '"\\':
            out.append("\\" + c)
        elif c == "\n" and multiline:
            out.append(c)
        elif ord(c) < 32 or ord(c) == 127:
            out.append(f"\\u{ord(c):04x}")
        else:
            out.append(c)
    body = "".join(out)
    if multiline and body.startswith("\n"):
        body = "\\n" + body[1:]                    # a newline right after """ is trimmed
    body += '"' * ending
    return f'"""{body}"""' if multiline else f'"{body}"'


def _fits_literal(s: str, *, multiline: bool) -> bool:
    bad = {chr(c) for c in range(32) if c != 9} | {"\x7f"}
    if multiline:
        bad.discard("\n")
        return "'''" not in s and not s.startswith("\n") and not bad & set(s)
    return "'" not in s and not bad & set(s)


def _string(draw, s: str) -> str:
    ways = ["basic", "multi"]
    ways += ["literal"] if _fits_literal(s, multiline=False) else []
    ways += ["multi-literal"] if _fits_literal(s, multiline=True) else []
    way = draw(st.sampled_from(ways))
    if way == "literal":
        return f"'{s}'"
    if way == "multi-literal":
        return f"'''{s}'''"
    return _basic(s, multiline=way == "multi")


def _key(draw, k: str) -> str:
    if re.fullmatch(r"[A-Za-z0-9_-]+", k) and draw(st.booleans()):
        return k
    if _fits_literal(k, multiline=False) and draw(st.booleans()):
        return f"'{k}'"
    return _basic(k)                                 # a key is never a multi-line string


def _path(draw, keys: list[str]) -> str:
    dot = draw(st.sampled_from([".", " . ", ". "]))
    return dot.join(_key(draw, k) for k in keys)


def _comment(draw) -> str:
    return " # " + draw(st.text(alphabet=NASTY.replace("\n", "") + "ab", max_size=8))


def _float(x: float) -> str:
    if x != x or x in (float("inf"), float("-inf")):
        return repr(x)
    text = repr(x)
    return text if any(c in text for c in ".en") else text + ".0"


def _value(draw, v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return _float(v)
    if isinstance(v, str):
        return _string(draw, v)
    if isinstance(v, list):
        sep = draw(st.sampled_from([", ", ",\n  ", "," + "  # [{.\"'\n  "]))
        return "[" + sep.join(_value(draw, x) for x in v) + "]"
    return "{" + ", ".join(f"{_path(draw, keys)} = {_value(draw, x)}"
                           for keys, x in _dotted(draw, [], v)) + "}"


def _dotted(draw, prefix: list[str], table: dict):
    """(keys, value) pairs that write ``table`` as dotted keys under ``prefix``."""
    for k, v in table.items():
        if isinstance(v, dict) and v and draw(st.booleans()):
            yield from _dotted(draw, prefix + [k], v)
        else:
            yield prefix + [k], v


def _table(draw, path: list[str], table: dict, lines: list[str], *, headers: bool) -> None:
    """Write ``table``'s body, then (if ``headers``) the tables it holds under [headers]."""
    later = []
    for k, v in table.items():
        if headers and isinstance(v, dict) and draw(st.booleans()):
            later.append((k, v))
        elif headers and isinstance(v, list) and v and all(isinstance(x, dict) for x in v) \
                and draw(st.booleans()):
            later.append((k, v))
        else:
            for keys, x in _dotted(draw, [k], v) if isinstance(v, dict) and v else [([k], v)]:
                lines.append(f"{_path(draw, keys)} = {_value(draw, x)}"
                             + (_comment(draw) if draw(st.booleans()) else ""))
    for k, v in later:
        if isinstance(v, dict):
            lines.append(f"[{_path(draw, path + [k])}]")
            _table(draw, path + [k], v, lines, headers=True)
        else:
            for entry in v:
                # Headers under an entry ([a.b] after [[a]]) are counted as written, one
                # short of the entry's own level: entries hold theirs inline here.
                lines.append(f"[[{_path(draw, path + [k])}]]")
                _table(draw, path + [k], entry, lines, headers=False)


@st.composite
def documents(draw):
    tree = draw(st.dictionaries(KEYS, TREES, max_size=4))
    lines: list[str] = []
    _table(draw, [], tree, lines, headers=True)
    return tree, "\n".join(lines) + "\n"


@pytest.mark.slow
@settings(max_examples=400, suppress_health_check=[HealthCheck.too_slow,
                                                   HealthCheck.function_scoped_fixture])
@given(documents())
def test_the_depth_measured_is_the_depth_tomllib_builds(monkeypatch, doc):
    tree, text = doc
    assert tomllib.loads(text) == tree               # the document says what it should
    assert measured(text, monkeypatch) == document_depth(tree), text
