"""IL's words and the test whether a body is IL, without the parser (storage splits files with them; lark is
imported only by a parse: ``il_parser.py``)."""

from __future__ import annotations

import re

from .comments import blank_nested_comments

#: Operators whose ``(`` defers them (IL-13, IL-06, IL-24), and their N (negated operand) forms.
DEFERRABLE = frozenset(
    {"AND", "ANDN", "&", "&N", "OR", "ORN", "XOR", "XORN", "ADD", "SUB", "MUL", "DIV", "MOD"}
    | {"GT", "GE", "EQ", "NE", "LE", "LT"}
)
#: Every operator word of the IL tables (IL-03, IL-20..IL-24); other words are function names (IL-04, IL-30).
OPERATORS = DEFERRABLE | {
    "LD",
    "LDN",
    "ST",
    "STN",
    "S",
    "R",
    "NOT",
    "JMP",
    "JMPC",
    "JMPCN",
    "CAL",
    "CALC",
    "CALCN",
    "RET",
    "RETC",
    "RETCN",
}
#: FB input operators (IL-24, IEC 61131-3 ed. 2 Table 52): ``PV C10`` calls C10 with PV := the accumulator.
FB_INPUT_OPERATORS = frozenset({"S1", "R1", "CLK", "CU", "CD", "PV", "IN", "PT"})

_COMMENT_OR_STRING = re.compile(r"'(?:[^'$\n]|\$.)*'|\"(?:[^\"$\n]|\$.)*\"|(//[^\n]*)")


def blank_comments(text: str) -> str:
    """``(* *)`` (nested too) and ``//`` comments -> spaces, strings untouched (IL-03)."""
    text = blank_nested_comments(text)
    return _COMMENT_OR_STRING.sub(lambda m: " " * len(m.group(1)) if m.group(1) else m.group(0), text)


_IL_START = re.compile(
    r"[ \t]*(?:[A-Za-z_][A-Za-z0-9_]*[ \t]*:(?!=)[ \t]*(?:\n|$)"  # a label on its own line (ST has none)
    r"|(?:[A-Za-z_][A-Za-z0-9_]*[ \t]*:(?!=)[ \t]*)?(?P<word>[A-Za-z_][A-Za-z0-9_]*)(?P<rest>[^\n]*))",
)
_NOT_AN_OPERAND = re.compile(r"\s*(?::=|\(|\.|\[|\^|;|$)")


def looks_like_il(body: str) -> bool:
    """Whether a POU body is IL: its first instruction is an IL operator (IL-01) or it starts with a label."""
    for line in blank_comments(body).split("\n"):
        if not line.strip():
            continue
        match = _IL_START.match(line)
        if match is None:
            return False
        word = match.group("word")
        if word is None:
            return True
        rest = match.group("rest")
        if rest.rstrip().endswith(";"):  # an ST statement (``r REF= x;``): no IL instruction ends with ';'
            return False
        if word.upper() in ("NOT", "RET", "RETC", "RETCN") and not rest.strip():
            return True
        return word.upper() in OPERATORS | FB_INPUT_OPERATORS and _NOT_AN_OPERAND.match(rest) is None
    return False
