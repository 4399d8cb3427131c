"""Split ST source text into POUs, TYPE blocks and VAR_GLOBAL blocks, and compose POU files.

Storage must read and write ``pous/<name>.st`` before (and independently of) the
full ST parser, and must never lose a character of what the user typed, so this
is a small comment- and string-aware keyword scanner, not a parser: it only
finds where blocks start and end.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..model import Pou
from ..model.project import Language, Method, PouAction, PouKind, Property
from ..st.il_words import looks_like_il
from ..st.pragmas import attributed_headers, with_call_after_init, without_call_after_init, without_monitoring

_TOKEN = re.compile(
    r"""
    (?P<comment>\(\*.*?\*\)|//[^\n]*|\{[^}]*\})
  | (?P<string>'(?:\$.|[^'$])*'|"(?:\$.|[^"$])*")
  | (?P<word>[A-Za-z_][A-Za-z0-9_]*)
  | (?P<other>[^\sA-Za-z_'"({/]+|[({/])
    """,
    re.VERBOSE | re.DOTALL,
)

POU_KEYWORDS: dict[str, PouKind] = {"PROGRAM": "program", "FUNCTION_BLOCK": "function_block", "FUNCTION": "function"}
POU_END = {
    "program": "END_PROGRAM",
    "function_block": "END_FUNCTION_BLOCK",
    "function": "END_FUNCTION",
    "plant": "END_PROGRAM",  # a plant is a PROGRAM in IEC text; its file name says it is a plant
}
POU_HEADER = {**{kind: keyword for keyword, kind in POU_KEYWORDS.items()}, "plant": "PROGRAM"}
VAR_SECTIONS = {
    "VAR",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_EXTERNAL",
    "VAR_TEMP",
    "VAR_GLOBAL",
    "VAR_ACCESS",
    "VAR_CONFIG",
}


class StTextError(ValueError):
    """The text's block structure cannot be recognised; ``line``/``column`` are 1-based."""

    def __init__(self, message: str, text: str, offset: int) -> None:
        self.line = text.count("\n", 0, offset) + 1
        self.column = offset - (text.rfind("\n", 0, offset) + 1) + 1
        super().__init__(f"line {self.line}, column {self.column}: {message}")
        self.reason = message


@dataclass
class Word:
    upper: str
    start: int
    end: int


def _words(text: str) -> list[Word]:
    """Identifier/keyword tokens outside comments, strings and pragmas."""
    return [Word(m.group("word").upper(), m.start(), m.end()) for m in _TOKEN.finditer(text) if m.lastgroup == "word"]


def _line_end(text: str, offset: int) -> int:
    """Offset just past the end of the line holding ``offset`` (excluding the newline)."""
    nl = text.find("\n", offset)
    return len(text) if nl < 0 else nl


@dataclass
class StFile:
    """What a ``.st`` file holds: TYPE blocks, VAR_GLOBAL blocks and POUs, in source order."""

    types: str
    globals: str
    pous: list[Pou]


def split_source(text: str) -> StFile:
    """Split a whole ST file into its TYPE text, VAR_GLOBAL text and POUs."""
    words = _words(text)
    types: list[str] = []
    globals_: list[str] = []
    pous: list[Pou] = []
    i = 0
    while i < len(words):
        w = words[i]
        if w.upper == "TYPE":
            j = _find(words, i + 1, {"END_TYPE"}, text, w.start, "TYPE without END_TYPE")
            types.append(text[w.start : words[j].end])
            i = j + 1
        elif w.upper == "VAR_GLOBAL":
            j = _find(words, i + 1, {"END_VAR"}, text, w.start, "VAR_GLOBAL without END_VAR")
            globals_.append(text[w.start : words[j].end])
            i = j + 1
        elif w.upper in POU_KEYWORDS:
            kind = POU_KEYWORDS[w.upper]
            j = _find(words, i + 1, {POU_END[kind]}, text, w.start, f"{w.upper} without {POU_END[kind]}")
            pous.append(_split_pou(text, words[i : j + 1]))
            i = j + 1
        elif w.upper == "CONFIGURATION":
            j = _find(words, i + 1, {"END_CONFIGURATION"}, text, w.start, "CONFIGURATION without END_CONFIGURATION")
            i = j + 1
        else:
            raise StTextError(f"unexpected '{text[w.start : w.end]}' outside any POU or TYPE block", text, w.start)
    return StFile("\n\n".join(types), "\n\n".join(globals_), pous)


def _find(words: list[Word], start: int, targets: set[str], text: str, at: int, message: str) -> int:
    for j in range(start, len(words)):
        if words[j].upper in targets:
            return j
    raise StTextError(message, text, at)


def parse_pou_text(text: str, language: str = "st", plant: bool = False) -> Pou:
    """Read one ``pous/<name>.st`` or ``.il`` file: exactly one POU, nothing around it but comments.

    A ``.il`` file's POU is IL; in a ``.st`` file a POU whose body is IL is IL too (docs/il.md), so a
    stored ST POU whose body reads as IL does not round-trip and is kept as ``.st.json``. ``plant``: a
    ``pous/<name>.plant.st`` file, whose POU must be a PROGRAM (it becomes a plant)."""
    parsed = split_source(text)
    if len(parsed.pous) != 1 or parsed.types or parsed.globals:
        raise StTextError("a POU file must hold exactly one PROGRAM, FUNCTION_BLOCK or FUNCTION", text, 0)
    pou = parsed.pous[0]
    if pou.kind == "function_block" and _attributed(text):
        pou = pou.model_copy(update={"declarations": with_call_after_init(pou.declarations)})
    if language == "il":
        pou = pou.model_copy(update={"language": "il"})
    if not plant:
        return pou
    if pou.kind != "program":
        raise StTextError(
            f"a .plant.st file holds a plant, written as a PROGRAM, not a {POU_HEADER[pou.kind]}", text, 0
        )
    return pou.model_copy(update={"kind": "plant"})


def _attributed(text: str) -> bool:
    """Whether {attribute 'call_after_init'} stands above the file's POU header (as ``compose_pou_text`` writes it)."""
    headers = attributed_headers(text)
    first = next(iter(_words(text)), None)
    if not headers or first is None:
        return False
    line = text.count("\n", 0, first.start) + 1
    return (line, first.start - (text.rfind("\n", 0, first.start) + 1) + 1) in headers


def _split_pou(text: str, words: list[Word]) -> Pou:
    """Cut one POU (``words`` from its keyword to its END_ keyword) into header, declarations and body."""
    head, end = words[0], words[-1]
    kind = POU_KEYWORDS[head.upper]
    if len(words) < 3:
        raise StTextError(f"{head.upper} needs a name", text, head.start)
    name = text[words[1].start : words[1].end]
    header_end = _line_end(text, words[1].end)
    return_type = None
    if kind == "function":
        after_name = text[words[1].end : header_end]
        if ":" not in after_name:
            raise StTextError(f"FUNCTION {name} needs a return type ': TYPE' on its first line", text, head.start)
        return_type = after_name.split(":", 1)[1].strip()
    inner_start = min(header_end + 1, len(text))
    decl_end = inner_start
    k = 2
    while k < len(words) - 1 and words[k].start < header_end:
        k += 1
    while k < len(words) - 1 and words[k].upper in VAR_SECTIONS:
        close = _find(words, k + 1, {"END_VAR"}, text, words[k].start, f"{words[k].upper} without END_VAR")
        decl_end = _line_end(text, words[close].end)
        k = close + 1
    footer_start = text.rfind("\n", 0, end.start) + 1
    declarations = text[inner_start:decl_end] if decl_end > inner_start else ""
    body_start = min(decl_end + 1, footer_start) if declarations else inner_start
    body = text[body_start : max(footer_start - 1, body_start)]
    language: Language = "il" if looks_like_il(body) else "st"
    return Pou(name=name, kind=kind, language=language, return_type=return_type, declarations=declarations, body=body)


def compose_pou_text(pou: Pou) -> str:
    """The complete IEC text of an ST or IL POU, as stored in ``pous/<name>.st`` / ``.il``; a function block's
    ABSTRACT / FINAL, EXTENDS, IMPLEMENTS and METHODs (after its VAR blocks, IEC 61131-3 ed. 3), and a program's
    METHODs and PROPERTYs (CODESYS), included."""
    modifier = "ABSTRACT " if pou.abstract else "FINAL " if pou.final else ""
    header = f"{POU_HEADER[pou.kind]} {modifier}{pou.name}"
    if pou.kind == "function":
        header += f" : {pou.return_type}"
    if pou.extends:
        header += f" EXTENDS {pou.extends}"
    if pou.implements:
        header += f" IMPLEMENTS {', '.join(pou.implements)}"
    assert isinstance(pou.body, str), "only ST POUs are stored as text"
    attribute, declarations = without_call_after_init(pou.declarations)  # above the header, as CODESYS writes it
    parts = [*([attribute] if attribute else []), header]
    if declarations:
        parts.append(declarations)
    parts += [_method_text(method) for method in pou.methods]
    parts += [_property_text(prop) for prop in pou.properties]
    parts += [_action_text(action) for action in pou.actions]
    if pou.body:
        parts.append(pou.body)
    parts.append(POU_END[pou.kind])
    return "\n".join(parts) + "\n"


def method_header(method: Method) -> str:
    """A method's first line as ST writes it: ``METHOD PRIVATE FINAL Name : INT`` (also CODESYS's header text in
    PLCopen)."""
    modifiers = [method.access, *(["FINAL"] if method.final else []), *(["ABSTRACT"] if method.abstract else [])]
    return f"METHOD {' '.join(modifiers)} {method.name}" + (f" : {method.return_type}" if method.return_type else "")


def _method_text(method: Method) -> str:
    attribute, declarations = without_call_after_init(method.declarations)
    lines = [*([attribute] if attribute else []), method_header(method)]
    return "\n".join([*lines, *_texts(declarations, method.body), "END_METHOD"])


def _action_text(action: PouAction) -> str:
    return "\n".join([f"ACTION {action.name}:", *_texts(action.body), "END_ACTION"])


def _property_text(prop: Property) -> str:
    attribute, parts = "", [f"PROPERTY {prop.access} {prop.name} : {prop.type}"]
    for kind, accessor in (("GET", prop.get), ("SET", prop.set)):
        if accessor is not None:
            declarations = accessor.declarations
            if not attribute:  # the monitoring attribute heading its accessor: above PROPERTY, as CODESYS writes it
                attribute, declarations = without_monitoring(declarations)
            parts += [kind, *_texts(declarations, accessor.body), f"END_{kind}"]
    return "\n".join([*([attribute] if attribute else []), *parts, "END_PROPERTY"])


def _texts(*texts: str) -> list[str]:
    """A method's or accessor's declarations and body, without the blank lines a ``.st`` import pads them with."""
    return [text.strip("\n") for text in texts if text.strip()]


def round_trips(pou: Pou) -> bool:
    """Whether ``pou`` survives compose -> parse unchanged (else storage keeps it as JSON)."""
    try:
        return parse_pou_text(compose_pou_text(pou), pou.language, plant=pou.kind == "plant") == pou
    except StTextError:
        return False
