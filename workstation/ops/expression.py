"""PDAL expressions (``filters.expression``) parsed safely and evaluated on numpy arrays.

Grammar (C precedence, as PDAL's expression syntax documents), lowest first::

    or      := and ('||' and)*
    and     := equal ('&&' equal)*
    equal   := compare (('==' | '!=') compare)*
    compare := sum (('<' | '<=' | '>' | '>=') sum)*
    sum     := product (('+' | '-') product)*
    product := unary (('*' | '/') unary)*
    unary   := ('!' | '-') unary | NUMBER | NAME | '(' or ')'

Values are float64 arrays (PDAL computes in double precision); comparisons give booleans;
``!``, ``&&`` and ``||`` take booleans only (``Classification && X > 0`` is an error, as in
PDAL). Names are PDAL dimension names (``Classification``, ``ReturnNumber``, ``GpsTime``,
``Red`` ...; any case), canonical attribute names (``return_number``) or extra-byte names.
The text is tokenised and parsed by hand: nothing of it is ever evaluated as Python.
"""

from __future__ import annotations

import re
from typing import Callable

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.dims import DIMS
from workstation.core.errors import InvalidInputError, StageError

STAGE = "filter"
_TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
                    r"|(?P<op>&&|\|\||==|!=|<=|>=|[<>!()+\-*/]))")
_LEVELS = [("||",), ("&&",), ("==", "!="), ("<", "<=", ">", ">="), ("+", "-"), ("*", "/")]
_BOOL_OPS = {"||", "&&"}
_CMP_OPS = {"==", "!=", "<", "<=", ">", ">="}
_NUMPY = {"||": np.logical_or, "&&": np.logical_and, "==": np.equal, "!=": np.not_equal, "<": np.less,
          "<=": np.less_equal, ">": np.greater, ">=": np.greater_equal, "+": np.add, "-": np.subtract,
          "*": np.multiply, "/": np.divide}


def _pdal_names() -> dict[str, tuple[str, int | None]]:
    """PDAL dimension name -> (attribute, component or None); X, Y, Z -> ("xyz", 0/1/2)."""
    names = {"X": ("xyz", 0), "Y": ("xyz", 1), "Z": ("xyz", 2)}
    for d in DIMS.values():
        for i, p in enumerate(d.pdal):
            names[p] = (d.name, i if len(d.pdal) > 1 else None)
    return names


PDAL_NAMES = _pdal_names()


def _tokens(text: str) -> list[tuple[str, str, int]]:
    """(kind, text, position) tokens; an unknown character is an error pointing at it."""
    out, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            raise _syntax(text, len(text) - len(text[pos:].lstrip()), "unexpected character")
        kind = m.lastgroup
        out.append((kind, m.group(kind), m.start(kind)))
        pos = m.end()
    out.append(("end", "", len(text)))
    return out


def _syntax(text: str, pos: int, what: str) -> InvalidInputError:
    return InvalidInputError(f"{what} at character {pos + 1}:\n  {text}\n  {' ' * pos}^",
                             "PDAL syntax: Classification == 2 && (ReturnNumber == 1 || Z > 10.5)", field="expr")


class _Parser:
    """Recursive descent over the tokens; builds a tree of tuples ("num", v) | ("name", s, pos) |
    ("not"|"neg", node) | (op, left, right)."""

    def __init__(self, text: str):
        self.text, self.toks, self.i = text, _tokens(text), 0

    def peek(self):
        return self.toks[self.i]

    def take(self):
        tok = self.toks[self.i]
        self.i += 1
        return tok

    def parse(self):
        node = self.level(0)
        kind, tok, pos = self.peek()
        if kind != "end":
            raise _syntax(self.text, pos, f"unexpected '{tok}'")
        return node

    def level(self, k: int):
        if k == len(_LEVELS):
            return self.unary()
        node = self.level(k + 1)
        while self.peek()[0] == "op" and self.peek()[1] in _LEVELS[k]:
            op = self.take()[1]
            node = (op, node, self.level(k + 1))
        return node

    def unary(self):
        kind, tok, pos = self.take()
        if kind == "op" and tok in ("!", "-"):
            return ("not" if tok == "!" else "neg", self.unary(), pos)
        if kind == "num":
            return ("num", float(tok))
        if kind == "name":
            return ("name", tok, pos)
        if kind == "op" and tok == "(":
            node = self.level(0)
            k2, t2, p2 = self.take()
            if t2 != ")":
                raise _syntax(self.text, p2, "missing ')'")
            return node
        raise _syntax(self.text, pos, "expected a number, a dimension or '('" if kind != "end" else "unexpected end")


def _lookup(name: str, cloud: Cloud) -> tuple[str, int | None] | None:
    """(attribute, component) of a dimension name in ``cloud``; None when the cloud has none."""
    for cand in (name, *[k for k in PDAL_NAMES if k.lower() == name.lower()]):
        if cand in PDAL_NAMES and (PDAL_NAMES[cand][0] == "xyz" or PDAL_NAMES[cand][0] in cloud.attrs):
            return PDAL_NAMES[cand]
    for attr in cloud.attrs:
        if attr.lower() == name.lower() and cloud.attrs[attr].ndim == 1:
            return attr, None
    return None


def valid_names(cloud: Cloud) -> list[str]:
    """The dimension names an expression may use on ``cloud`` (PDAL spelling where known)."""
    names = ["X", "Y", "Z"]
    known = {a for a, _ in PDAL_NAMES.values()}
    for p, (attr, _) in PDAL_NAMES.items():
        if attr in cloud.attrs:
            names.append(p)
    names += [a for a in cloud.attrs if a not in known and cloud.attrs[a].ndim == 1]
    return names


def _evaluate(node, cloud: Cloud, text: str):
    """(value, is_bool) of a parse tree node on the cloud's arrays."""
    kind = node[0]
    if kind == "num":
        return np.float64(node[1]), False
    if kind == "name":
        found = _lookup(node[1], cloud)
        if found is None:
            raise InvalidInputError(f"unknown dimension '{node[1]}' in: {text}",
                                    "dimensions of this cloud: " + ", ".join(valid_names(cloud)), field="expr")
        attr, comp = found
        arr = cloud.xyz if attr == "xyz" else cloud.attrs[attr]
        return (arr if comp is None else arr[:, comp]).astype(np.float64, copy=False), False
    if kind in ("not", "neg"):
        val, is_bool = _evaluate(node[1], cloud, text)
        if is_bool != (kind == "not"):
            raise _syntax(text, node[2], "'!' needs a comparison" if kind == "not" else "'-' needs a number")
        return (np.logical_not(val), True) if kind == "not" else (np.negative(val), False)
    (a, a_bool), (b, b_bool) = _evaluate(node[1], cloud, text), _evaluate(node[2], cloud, text)
    if kind in _BOOL_OPS and not (a_bool and b_bool):
        raise InvalidInputError(f"'{kind}' joins comparisons, not numbers, in: {text}",
                                "write (Intensity > 0) && (Classification != 0), as PDAL requires", field="expr")
    if kind not in _BOOL_OPS and (a_bool or b_bool):
        raise InvalidInputError(f"'{kind}' takes numbers, not comparisons, in: {text}",
                                "join comparisons with && or ||", field="expr")
    with np.errstate(divide="ignore", invalid="ignore"):
        return _NUMPY[kind](a, b), kind in _BOOL_OPS or kind in _CMP_OPS


def compile_expression(text: str) -> Callable[[Cloud], np.ndarray]:
    """A function cloud -> (n,) bool mask for a PDAL expression (syntax checked now, names at use).

    Examples
    --------
    >>> c = Cloud(np.zeros((4, 3)), {"classification": [2, 2, 5, 2], "return_number": [1, 2, 1, 1]})
    >>> compile_expression("Classification == 2 && ReturnNumber == 1")(c).tolist()
    [True, False, False, True]
    >>> compile_expression("!(Classification == 2) || Z > 1")(c).tolist()
    [False, False, True, False]
    """
    if not text or not text.strip():
        raise InvalidInputError("the expression is empty", "e.g. --expr \"Classification == 2\"", field="expr")
    tree = _Parser(text).parse()

    def mask(cloud: Cloud) -> np.ndarray:
        val, is_bool = _evaluate(tree, cloud, text)
        if not is_bool:
            raise InvalidInputError(f"the expression gives numbers, not a condition: {text}",
                                    "compare it, e.g. Intensity * 2 > 100", field="expr")
        return np.broadcast_to(val, (cloud.n,)).copy()

    return mask


def filter_expression(cloud: Cloud, text: str) -> Cloud:
    """The points of ``cloud`` for which the PDAL expression ``text`` is true."""
    out = cloud[compile_expression(text)(cloud)]
    if out.n == 0:
        raise StageError(STAGE, f"no point matches: {text}", "check the values with ws info")
    return out.with_history(STAGE, {"expression": text})
