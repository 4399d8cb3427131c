"""IL parse entry point: body text -> ``IlInstruction`` list plus located diagnostics, never an exception.

The lark grammar (``il.lark``) splits lines into labels, operators, the deferral ``(``
and raw operand text; the operand text is parsed here with the ST expression parser
(IL operands and argument lists are ST operands and arguments), padded so every span
is the position in the body text. Comments are blanked first, keeping lines and columns.
"""

from __future__ import annotations

import functools
import pathlib
import re
from dataclasses import dataclass, field

from lark import Lark, Token, Transformer
from lark.exceptions import UnexpectedInput

from ..model.diagnostics import Diagnostic
from . import ast
from .il_words import DEFERRABLE, blank_comments, looks_like_il
from .lark_cache import cached_lark
from .parser import parse_expression, syntax_diagnostic

GRAMMAR = pathlib.Path(__file__).with_name("il.lark")


@dataclass
class IlInstruction:
    """One IL line's instruction. ``operands`` are ST expressions; ``call`` is the parsed ``name(args)``
    of ``CAL inst(...)`` and function call forms 2/3; ``deferred`` is the ``(`` modifier."""

    operator: str  # upper case; ")" closes a deferred operation
    labels: list[tuple[str, ast.Span]]
    span: ast.Span
    deferred: bool = False
    operands: list[ast.Expr] = field(default_factory=list)
    call: ast.Call | None = None
    written: str = ""  # the operator as the user wrote it
    broken: bool = False  # its operands did not parse (already reported): checked no further


@dataclass
class IlBody:
    instructions: list[IlInstruction]
    trailing_labels: list[tuple[str, ast.Span]] = field(default_factory=list)  # labels after the last instruction


@dataclass
class IlParseResult:
    body: IlBody | None
    diagnostics: list[Diagnostic]

    @property
    def ok(self) -> bool:
        return not any(d.severity == "error" for d in self.diagnostics)


class _Lines(Transformer):
    def label(self, children):
        token = children[0]
        return ("label", token.value.split(":")[0].strip(), _token_span(token))

    def operation(self, children):
        operator, defer, operands = children
        return ("op", operator, defer, operands)

    def close(self, children):
        return ("close", _token_span(children[0]))

    def start(self, children):
        return children


@functools.cache
def _parser() -> Lark:
    return cached_lark("il", GRAMMAR.read_text(encoding="utf-8"), lexer="contextual", maybe_placeholders=True)


def parse_il(text: str, *, file: str | None = None, pou: str | None = None) -> IlParseResult:
    """An IL body (the text between the declarations and END_*)."""
    diagnostics: list[Diagnostic] = []
    blanked = blank_comments(text)
    try:
        tree = _Lines().transform(_parser().parse(blanked + "\n"))
    except UnexpectedInput as error:
        line, column = getattr(error, "line", 1), getattr(error, "column", 1)
        found = blanked.split("\n")[line - 1][column - 1 :].split()[:1] if line > 0 else []
        what = f"'{found[0]}'" if found else "the end of the line"
        diagnostics.append(
            syntax_diagnostic(
                f"IL syntax error: unexpected {what}",
                ast.Span(line, column, line, column + 1),
                file,
                pou,
                code="IL-PARSE",
            )
        )
        return IlParseResult(None, diagnostics)
    instructions: list[IlInstruction] = []
    labels: list[tuple[str, ast.Span]] = []
    for item in _flatten(tree):
        if item[0] == "label":
            labels.append((item[1], item[2]))
            continue
        if item[0] == "close":
            instructions.append(IlInstruction(")", labels, item[1], written=")"))
        else:
            instructions.append(_operation(item, labels, blanked, file, pou, diagnostics))
        labels = []
    return IlParseResult(IlBody(instructions, labels), diagnostics)


def _flatten(tree):
    for item in tree:
        if isinstance(item, tuple):
            yield item
        elif isinstance(item, list):
            yield from _flatten(item)


def _token_span(token: Token) -> ast.Span:
    return ast.Span(token.line, token.column, token.end_line, token.end_column)


def _operation(item, labels, text, file, pou, diagnostics) -> IlInstruction:
    _, operator, defer, operands = item
    word = operator.value.upper()
    last = operands if operands is not None else defer if defer is not None else operator
    end_column = last.column + len(last.value.rstrip())
    span = ast.Span(operator.line, operator.column, operator.line, end_column)
    instruction = IlInstruction(word, labels, span, deferred=False, written=operator.value)
    parsed: list[ast.Expr] | None = []
    if defer is not None and word in DEFERRABLE:
        instruction.deferred = True
        parsed = _operand_list(operands, file, pou, diagnostics) if operands is not None else []
    elif defer is not None or _is_call_text(word, operands):
        # a call: ``Fun(args)`` (IL-31) or ``CAL inst(args)`` (IL-33): parse the operator's text as an ST call
        start = operator if word not in ("CAL", "CALC", "CALCN") else operands
        call = _parse_piece(text, start, operands if operands is not None else defer, file, pou, diagnostics)
        if isinstance(call, ast.Call):
            instruction.call = call
        elif call is not None:
            diagnostics.append(
                syntax_diagnostic(
                    f"'{operator.value}(' needs ')' after its arguments",
                    _token_span(operator),
                    file,
                    pou,
                    code="IL-PARSE",
                )
            )
            parsed = None
        else:
            parsed = None
    elif operands is not None:
        parsed = _operand_list(operands, file, pou, diagnostics)
    if parsed is None:
        instruction.broken = True
    else:
        instruction.operands = parsed
    return instruction


def _is_call_text(word: str, operands: Token | None) -> bool:
    return word in ("CAL", "CALC", "CALCN") and operands is not None and "(" in operands.value


def _operand_list(token: Token, file, pou, diagnostics) -> list[ast.Expr] | None:
    """``a, b, 3`` -> expressions: parsed as the arguments of a call so commas inside brackets stay put."""
    # an operand follows its operator and a blank, so the head "X(" fits in the two columns before it
    padded = "\n" * (token.line - 1) + " " * (token.column - 3) + "X(" + token.value.rstrip() + ")"
    result = parse_expression(padded, file=file, pou=pou)
    diagnostics += result.diagnostics
    if result.ast is None or not isinstance(result.ast, ast.Call) or not result.ok:
        return None
    if any(arg.name is not None for arg in result.ast.args):
        diagnostics.append(
            syntax_diagnostic(
                "IL operands are values, not 'name := value' assignments",
                _token_span(token),
                file,
                pou,
                code="IL-PARSE",
            )
        )
        return None
    return [arg.value for arg in result.ast.args]


def _parse_piece(text: str, start: Token, end: Token, file, pou, diagnostics):
    lines = text.split("\n")
    line = lines[start.line - 1]
    piece = line[start.column - 1 : end.end_column - 1].rstrip() if start.line == end.line else line[start.column - 1 :]
    padded = "\n" * (start.line - 1) + " " * (start.column - 1) + piece
    result = parse_expression(padded, file=file, pou=pou)
    diagnostics += result.diagnostics
    return result.ast if result.ok else None


# ---------------------------------------------------------------- IL POUs in IEC source files

_BODY_BOUNDS = re.compile(
    r"'(?:[^'$\n]|\$.)*'|\"(?:[^\"$\n]|\$.)*\"|\(\*[\s\S]*?\*\)|//[^\n]*"
    r"|\b(END_VAR|END_FUNCTION_BLOCK|END_FUNCTION|END_PROGRAM)\b",
    re.IGNORECASE,
)


def blank_il_bodies(text: str) -> tuple[str, set[str]]:
    """``text`` with the bodies of its IL POUs blanked (lines and columns kept), and those POUs' names (upper case).

    An IEC source file may hold IL POUs beside ST POUs, TYPEs and a CONFIGURATION; the ST parser then reads
    the declarations of every POU, and the IL bodies are taken from the original text (``st/project_text.py``).
    """
    from .parser import split_units

    names: set[str] = set()
    pieces: list[str] = []
    copied = 0
    offsets = _line_offsets(text)
    for unit in split_units(text):
        if unit.pou is None:
            continue
        start = offsets[unit.line - 1] + unit.column - 1
        bounds = _body_bounds(unit.text)
        if bounds is None:
            continue
        body_start, body_end = start + bounds[0], start + bounds[1]
        if looks_like_il(text[body_start:body_end]):
            names.add(unit.pou.upper())
            pieces += [text[copied:body_start], re.sub(r"[^\n]", " ", text[body_start:body_end])]
            copied = body_end
            continue
        for action_start, action_end in _il_sfc_parts(text[body_start:body_end]):  # textual SFC (docs/sfc.md)
            start_at, end_at = body_start + action_start, body_start + action_end
            pieces += [text[copied:start_at], re.sub(r"[^\n]", " ", text[start_at:end_at])]
            copied = end_at
    pieces.append(text[copied:])
    return "".join(pieces), names


#: The head of a textual SFC transition whose condition is IL (``TRANSITION [name] [(PRIORITY := n)] FROM a TO b:``,
#: B.1.6's ``transition_condition ::= ':' simple_instruction_list``); its instructions follow, up to END_TRANSITION.
IL_TRANSITION_HEAD = r"\bTRANSITION\b(?:[^:;]|:=)*?\bTO\b\s*(?:[A-Za-z_]\w*|\([^)]*\))\s*:(?!=)"

_SFC_PART_BOUNDS = re.compile(
    r"'(?:[^'$\n]|\$.)*'|\"(?:[^\"$\n]|\$.)*\"|\(\*[\s\S]*?\*\)|//[^\n]*"
    rf"|\b(ACTION)\s+[A-Za-z_]\w*\s*:|\b(END_ACTION)\b|({IL_TRANSITION_HEAD})|\b(END_TRANSITION)\b",
    re.IGNORECASE,
)


def _il_sfc_parts(body: str) -> list[tuple[int, int]]:
    """The offsets of the bodies of the ``ACTION name: ... END_ACTION`` in a textual SFC body that are IL (an SFC
    action written in IL, SFC-02), and of the IL conditions of its transitions (``TRANSITION ... TO b: ...
    END_TRANSITION``, a named transition in IL): ``st/sfc_text.py`` reads them from the original text."""
    found: list[tuple[int, int]] = []
    opened: list[int] = []
    transition: int | None = None
    for match in _SFC_PART_BOUNDS.finditer(body):
        if match.group(1):
            opened.append(match.end())
        elif match.group(2) and opened:
            start = opened.pop()
            if looks_like_il(body[start : match.start()]):
                found.append((start, match.start()))
        elif match.group(3):
            transition = match.end()
        elif match.group(4) and transition is not None:
            if looks_like_il(body[transition : match.start()]):
                found.append((transition, match.start()))
            transition = None
    return sorted(found)


def _body_bounds(unit: str) -> tuple[int, int] | None:
    """Offsets in a POU unit of its body: after the header line or the last END_VAR, up to END_<kind>."""
    first_line = unit.find("\n")
    start = first_line + 1 if first_line >= 0 else len(unit)
    for match in _BODY_BOUNDS.finditer(unit):
        keyword = (match.group(1) or "").upper()
        if keyword == "END_VAR":
            start = match.end()
        elif keyword:
            return start, match.start()
    return None


def _line_offsets(text: str) -> list[int]:
    offsets = [0]
    for index, char in enumerate(text):
        if char == "\n":
            offsets.append(index + 1)
    return offsets
