"""A turning moment given as a formula in the crank angle θ, read safely.

Textbooks give an engine's turning moment as T = 15000 + 7500 sin 2θ − 5000 cos 2θ. The
file writes it as Python's arithmetic ("15000 + 7500*sin(2*theta) - 5000*cos(2*theta)"),
parsed by :mod:`ast` and evaluated by walking the tree: only numbers, θ (``theta`` or
``θ``, in radians), ``pi``, ``+ - * / **`` and ``sin``, ``cos`` are allowed, so no code of
the file's is ever run.
"""

from __future__ import annotations

import ast
import math
import operator
from dataclasses import dataclass

__all__ = ["Formula", "parse_formula"]

_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.Pow: operator.pow}
_UNARY = {ast.UAdd: operator.pos, ast.USub: operator.neg}
_FUNCTIONS = {"sin": math.sin, "cos": math.cos}
_NAMES = {"pi": math.pi, "π": math.pi}
_ANGLE = ("theta", "θ")
MAX_LENGTH = 500
"""The longest formula read: a sum of a dozen harmonics is some 200 characters."""


@dataclass(frozen=True)
class Formula:
    """T(θ) as the file writes it, evaluated by walking its parsed tree."""

    text: str
    tree: ast.expr

    def __call__(self, theta: float) -> float:
        """T (N·m) at crank angle ``theta`` (rad)."""
        return _value(self.tree, theta)


def parse_formula(text: str) -> Formula:
    """Parse ``text`` as a formula in θ.

    Raises
    ------
    ValueError
        One line saying what is not allowed (or not a formula), to be placed at the file's
        line by the caller.

    >>> parse_formula("100 + 50*sin(2*theta)")(math.pi / 4)
    150.0
    """
    if not isinstance(text, str) or not text.strip():
        raise ValueError("a turning moment formula is a string in theta, like "
                         "\"15000 + 7500*sin(2*theta)\"")
    if len(text) > MAX_LENGTH:
        raise ValueError(f"the formula is {len(text)} characters long; at most {MAX_LENGTH}")
    try:
        tree = ast.parse(text.strip(), mode="eval").body
    except SyntaxError as e:
        raise ValueError(f"the formula {text!r:.60} is not arithmetic ({e.msg}); write it "
                         "as 15000 + 7500*sin(2*theta)") from None
    for node in ast.walk(tree):
        _allowed(node)
    f = Formula(text, tree)
    try:
        f(0.0)
    except (ArithmeticError, ValueError) as e:
        raise ValueError(f"the formula {text!r:.60} cannot be evaluated at θ = 0: {e}") from None
    return f


def _allowed(node: ast.AST) -> None:
    """Refuse a node the formula may not hold."""
    if isinstance(node, ast.Call):
        if not (isinstance(node.func, ast.Name) and node.func.id in _FUNCTIONS
                and len(node.args) == 1 and not node.keywords):
            raise ValueError("a formula may call sin(…) and cos(…) only, each of one argument")
        return
    if (isinstance(node, (ast.BinOp, ast.UnaryOp, ast.Load)) or type(node) in _BINARY
            or type(node) in _UNARY):
        return
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return
    if isinstance(node, ast.Name) and node.id in (*_NAMES, *_ANGLE, *_FUNCTIONS):
        return
    what = node.id if isinstance(node, ast.Name) else type(node).__name__
    raise ValueError(f"a formula may hold numbers, theta, pi, + - * / **, sin and cos; not "
                     f"{what!r}")


def _value(node: ast.expr, theta: float) -> float:
    if isinstance(node, ast.Constant):
        return float(node.value)
    if isinstance(node, ast.Name):
        if node.id in _FUNCTIONS:
            raise ValueError(f"{node.id} is a function: write {node.id}(2*theta)")
        return theta if node.id in _ANGLE else _NAMES[node.id]
    if isinstance(node, ast.BinOp):
        v = _BINARY[type(node.op)](_value(node.left, theta), _value(node.right, theta))
        if not isinstance(v, float):        # a negative number to a fractional power
            raise ValueError("a negative number raised to a fractional power has no real value")
        return v
    if isinstance(node, ast.UnaryOp):
        return _UNARY[type(node.op)](_value(node.operand, theta))
    return _FUNCTIONS[node.func.id](_value(node.args[0], theta))
