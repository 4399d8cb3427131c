"""Declarative catalogue of the IEC standard functions and function blocks (spec §5, §6).

What the checker needs to type a call and what the editor's box picker shows:
pin names and types, generic families, extensibility and a short description.
Every function and FB also has the implicit ``EN : BOOL`` input and
``ENO : BOOL`` output (POU-40); they are not listed per entry.

Pin types are elementary type names (canonical spelling, e.g. TIME_OF_DAY) or
generic families (ANY_NUM ...). Pins with ``generic=True`` share one type
variable T: all actual arguments on them must have the same type, and a
``result`` of ``"T"`` is that type (FUN-02). The run-time implementations with
the same names are in ``ladderlab.engine.stdlib``.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from .elementary import ALIASES, ELEMENTARY, SHORT_TO_LONG, canonical_type_name

T = "T"


@dataclass(frozen=True)
class Pin:
    name: str
    type: str
    generic: bool = False
    edge: str | None = None  # R_EDGE on counter inputs (SFB-03)


@dataclass(frozen=True)
class StdFunction:
    name: str
    inputs: tuple[Pin, ...]
    result: str
    group: str
    description: str
    spec: str
    extensible: bool = False  # more inputs like the last one may follow: IN3, IN4, ... (FUN-03)

    def input_name(self, position: int) -> str | None:
        """Formal name of the input at ``position`` (0-based), extending IN1..INn / IN0..INn for extensible ones."""
        if position < len(self.inputs):
            return self.inputs[position].name
        if not self.extensible:
            return None
        last = self.inputs[-1].name
        stem = last.rstrip("0123456789")
        return f"{stem}{int(last[len(stem) :]) + position - len(self.inputs) + 1}"

    def pin(self, name: str) -> Pin | None:
        upper = name.upper()
        for pin in self.inputs:
            if pin.name == upper:
                return pin
        last = self.inputs[-1]
        stem = last.name.rstrip("0123456789")
        if self.extensible and upper.startswith(stem) and upper[len(stem) :].isdigit():
            return Pin(upper, last.type, last.generic)
        return None


@dataclass(frozen=True)
class StdFunctionBlock:
    name: str
    inputs: tuple[Pin, ...]
    outputs: tuple[Pin, ...]
    description: str
    spec: str
    group: str = field(default="function block")


def _g(name: str, family: str) -> Pin:
    return Pin(name, family, generic=True)


def _fn(
    name: str,
    inputs: Iterable[Pin],
    result: str,
    group: str,
    description: str,
    spec: str,
    extensible: bool = False,
) -> StdFunction:
    return StdFunction(name, tuple(inputs), result, group, description, spec, extensible)


#: Every type name a <SRC>_TO_<DST> conversion may name: the elementary types, their short spellings and WSTRING.
CONVERSION_SPELLINGS = [*ELEMENTARY, *ALIASES, "WSTRING"]


def _conversions() -> list[StdFunction]:
    spellings = CONVERSION_SPELLINGS
    rows = [
        _fn(
            f"{a}_TO_{b}",
            [Pin("IN", canonical_type_name(a))],
            canonical_type_name(b),
            "conversion",
            f"convert {a} to {b}",
            "FUN-10",
        )
        for a in spellings
        for b in spellings
        if canonical_type_name(a) != canonical_type_name(b)
    ]
    rows.append(_fn("TRUNC", [Pin("IN", "ANY_REAL")], "DINT", "conversion", "truncate toward zero", "FUN-11"))
    return rows


_INTEGERS = [name for name, t in ELEMENTARY.items() if t.category == "int"]
_BIT_STRINGS = [name for name, t in ELEMENTARY.items() if t.category == "bits"]
#: The bit string as wide as each integer type: what ``<int>_TO_BCD`` writes into.
BCD_WIDTH = {
    name: _BIT_STRINGS[_BIT_STRINGS.index("BYTE") + (ELEMENTARY[name].bits // 16).bit_length()] for name in _INTEGERS
}


def bcd_digits(bit_string: str) -> int:
    """Decimal digits a bit string holds in BCD (4 bits a digit): BYTE 2, WORD 4, DWORD 8, LWORD 16."""
    return ELEMENTARY[bit_string].bits // 4


def _ed3_table() -> dict[str, tuple[str, str | None, str]]:
    table: dict[str, tuple[str, str | None, str]] = {}
    for bits in _BIT_STRINGS:
        for integer in _INTEGERS:
            if 10 ** bcd_digits(bits) - 1 <= (ELEMENTARY[integer].max or 0):  # every BCD value of the bits fits
                table[f"{bits}_BCD_TO_{integer}"] = ("bcd_to", bits, integer)
            table[f"{integer}_TO_BCD_{bits}"] = ("to_bcd", integer, bits)
        table[f"TO_BCD_{bits}"] = ("to_bcd", None, bits)
    for integer in _INTEGERS:
        table[f"BCD_TO_{integer}"] = ("bcd_to", None, integer)
        table[f"{integer}_TO_BCD"] = ("to_bcd", integer, BCD_WIDTH[integer])
        table[f"TRUNC_{integer}"] = ("trunc", None, integer)
        for real in ("REAL", "LREAL"):
            table[f"{real}_TRUNC_{integer}"] = ("trunc", real, integer)
    for name in CONVERSION_SPELLINGS:
        table[f"TO_{name}"] = ("to", None, canonical_type_name(name))
    return table


#: IEC 61131-3 ed. 3 Table 22 conversions besides <SRC>_TO_<DST> (FUN-10): name -> (kind, source or None, target).
#: kind: "bcd_to" (BCD bit string -> integer), "to_bcd" (integer -> BCD bit string), "trunc" (real -> integer,
#: toward zero; the overloaded TRUNC_<int> takes either real), "to" (the overloaded TO_<type>: any elementary
#: source). A None source is generic.
ED3_CONVERSIONS = _ed3_table()

_CONVERSION_TEXT = {
    "bcd_to": ("ANY_BIT", "the BCD number IN as an integer (an invalid BCD digit stops the task)"),
    "to_bcd": ("ANY_INT", "IN in BCD (a negative IN or one with too many digits stops the task)"),
    "trunc": ("ANY_REAL", "IN truncated toward zero"),
    "to": ("ANY_ELEMENTARY", "IN converted (as <type>_TO_"),
}


def _ed3_conversions() -> list[StdFunction]:
    rows = []
    for name, (kind, source, target) in ED3_CONVERSIONS.items():
        family, text = _CONVERSION_TEXT[kind]
        text = f"{text}{target})" if kind == "to" else text
        rows.append(_fn(name, [Pin("IN", source or family)], target, "conversion", text, "FUN-10"))
    return rows


_MATH = {
    "SQRT": "square root",
    "LN": "natural logarithm",
    "LOG": "base-10 logarithm",
    "EXP": "natural exponential",
    "SIN": "sine (radians)",
    "COS": "cosine (radians)",
    "TAN": "tangent (radians)",
    "ASIN": "arc sine",
    "ACOS": "arc cosine",
    "ATAN": "arc tangent",
}


def _numeric() -> list[StdFunction]:
    rows = [_fn("ABS", [_g("IN", "ANY_NUM")], T, "numeric", "absolute value", "FUN-20")]
    rows += [_fn(name, [_g("IN", "ANY_REAL")], T, "numeric", text, "FUN-20") for name, text in _MATH.items()]
    rows.append(  # IEC 61131-3 ed. 3 Table 23
        _fn(
            "ATAN2", [_g("Y", "ANY_REAL"), _g("X", "ANY_REAL")], T, "numeric", "arc tangent of Y/X in -pi..pi", "FUN-20"
        )
    )
    two = [_g("IN1", "ANY_NUM"), _g("IN2", "ANY_NUM")]
    rows += [
        _fn("ADD", two, T, "arithmetic", "sum IN1 + IN2 + ... (operator +)", "FUN-30", extensible=True),
        _fn("MUL", two, T, "arithmetic", "product IN1 * IN2 * ... (operator *)", "FUN-30", extensible=True),
        _fn("SUB", two, T, "arithmetic", "difference IN1 - IN2 (operator -)", "FUN-30"),
        _fn("DIV", two, T, "arithmetic", "quotient IN1 / IN2, integers truncate (operator /)", "FUN-31"),
        _fn("MOD", [_g("IN1", "ANY_INT"), _g("IN2", "ANY_INT")], T, "arithmetic", "remainder (operator MOD)", "FUN-31"),
        _fn("EXPT", [_g("IN1", "ANY_REAL"), Pin("IN2", "ANY_NUM")], T, "arithmetic", "power IN1 ** IN2", "FUN-33"),
        _fn("MOVE", [_g("IN", "ANY")], T, "arithmetic", "copy IN to the output (assignment)", "FUN-32"),
    ]
    return rows


def _bits() -> list[StdFunction]:
    shift = [_g("IN", "ANY_BIT"), Pin("N", "ANY_INT")]
    rows = [
        _fn("SHL", shift, T, "bit shift", "shift IN left by N bits, zero-filled", "FUN-40"),
        _fn("SHR", shift, T, "bit shift", "shift IN right by N bits, zero-filled", "FUN-40"),
        _fn("ROL", shift, T, "bit shift", "rotate IN left by N bits", "FUN-40"),
        _fn("ROR", shift, T, "bit shift", "rotate IN right by N bits", "FUN-40"),
    ]
    two = [_g("IN1", "ANY_BIT"), _g("IN2", "ANY_BIT")]
    rows += [
        _fn("AND", two, T, "bitwise", "logical / bitwise AND (operator AND, &)", "FUN-50", extensible=True),
        _fn("OR", two, T, "bitwise", "logical / bitwise OR (operator OR)", "FUN-50", extensible=True),
        _fn("XOR", two, T, "bitwise", "logical / bitwise exclusive OR (operator XOR)", "FUN-50", extensible=True),
        _fn("NOT", [_g("IN", "ANY_BIT")], T, "bitwise", "logical / bitwise complement (operator NOT)", "FUN-50"),
    ]
    return rows


def _selection_and_comparison() -> list[StdFunction]:
    two_any = [_g("IN1", "ANY"), _g("IN2", "ANY")]
    rows = [
        _fn(
            "SEL",
            [Pin("G", "BOOL"), _g("IN0", "ANY"), _g("IN1", "ANY")],
            T,
            "selection",
            "IN0 when G is FALSE, IN1 when G is TRUE",
            "FUN-60",
        ),
        _fn("MAX", two_any, T, "selection", "largest input", "FUN-60", extensible=True),
        _fn("MIN", two_any, T, "selection", "smallest input", "FUN-60", extensible=True),
        _fn(
            "LIMIT",
            [_g("MN", "ANY"), _g("IN", "ANY"), _g("MX", "ANY")],
            T,
            "selection",
            "IN clamped to MN..MX",
            "FUN-60",
        ),
        _fn(
            "MUX",
            [Pin("K", "ANY_INT"), _g("IN0", "ANY"), _g("IN1", "ANY")],
            T,
            "selection",
            "the input numbered K (IN0, IN1, ...)",
            "FUN-61",
            extensible=True,
        ),
    ]
    compare = {
        "GT": "decreasing: IN1 > IN2 > ...",
        "GE": "non-increasing: IN1 >= IN2 >= ...",
        "EQ": "all equal: IN1 = IN2 = ...",
        "LE": "non-decreasing: IN1 <= IN2 <= ...",
        "LT": "increasing: IN1 < IN2 < ...",
    }
    rows += [
        _fn(name, two_any, "BOOL", "comparison", text, "FUN-70", extensible=True) for name, text in compare.items()
    ]
    rows.append(_fn("NE", two_any, "BOOL", "comparison", "not equal: IN1 <> IN2", "FUN-70"))
    return rows


def _strings() -> list[StdFunction]:
    """The string functions take STRING or WSTRING (ANY_STRING, IEC 61131-3 ed. 3 Table 29): the string inputs
    of one call share the type, a string result is that type at its default length."""
    n, s = "ANY_INT", T

    def g(name: str) -> Pin:
        return _g(name, "ANY_STRING")

    return [
        _fn("LEN", [g("IN")], "INT", "string", "length of IN", "FUN-80"),
        _fn("LEFT", [g("IN"), Pin("L", n)], s, "string", "the leftmost L characters of IN", "FUN-81"),
        _fn("RIGHT", [g("IN"), Pin("L", n)], s, "string", "the rightmost L characters of IN", "FUN-81"),
        _fn(
            "MID",
            [g("IN"), Pin("L", n), Pin("P", n)],
            s,
            "string",
            "L characters of IN from position P (1-based)",
            "FUN-81",
        ),
        _fn("CONCAT", [g("IN1"), g("IN2")], s, "string", "IN1, IN2, ... joined", "FUN-80", extensible=True),
        _fn(
            "INSERT",
            [g("IN1"), g("IN2"), Pin("P", n)],
            s,
            "string",
            "IN2 inserted into IN1 after position P",
            "FUN-81",
        ),
        _fn(
            "DELETE",
            [g("IN"), Pin("L", n), Pin("P", n)],
            s,
            "string",
            "IN without the L characters from position P",
            "FUN-81",
        ),
        _fn(
            "REPLACE",
            [g("IN1"), g("IN2"), Pin("L", n), Pin("P", n)],
            s,
            "string",
            "IN1 with L characters from position P replaced by IN2",
            "FUN-81",
        ),
        _fn(
            "FIND",
            [g("IN1"), g("IN2")],
            "INT",
            "string",
            "position of IN2 in IN1 (1-based, 0 if absent)",
            "FUN-81",
        ),
    ]


_LONG_WORDS = {"TIME": "LTIME", "TOD": "LTOD", "DT": "LDT", "DATE": "LDATE"}


def long_time_name(name: str) -> str:
    """The IEC 3rd edition name of a date and time function on the long types: ADD_TOD_TIME -> ADD_LTOD_LTIME."""
    operation, *operands = name.split("_")
    return "_".join([operation, *(_LONG_WORDS[word] for word in operands)])


def _long(type_name: str) -> str:
    return SHORT_TO_LONG.get(type_name, type_name)


def _date_and_time() -> list[StdFunction]:
    tod, dt = "TIME_OF_DAY", "DATE_AND_TIME"
    table = [
        ("ADD_TIME", "TIME", "TIME", "TIME", "T1 + T2"),
        ("SUB_TIME", "TIME", "TIME", "TIME", "T1 - T2"),
        ("MUL_TIME", "TIME", "ANY_NUM", "TIME", "duration times a number"),
        ("DIV_TIME", "TIME", "ANY_NUM", "TIME", "duration divided by a number"),
        ("ADD_TOD_TIME", tod, "TIME", tod, "time of day plus a duration (wraps at midnight)"),
        ("ADD_DT_TIME", dt, "TIME", dt, "date and time plus a duration"),
        ("SUB_DATE_DATE", "DATE", "DATE", "TIME", "duration between two dates"),
        ("SUB_TOD_TIME", tod, "TIME", tod, "time of day minus a duration"),
        ("SUB_TOD_TOD", tod, tod, "TIME", "duration between two times of day"),
        ("SUB_DT_TIME", dt, "TIME", dt, "date and time minus a duration"),
        ("SUB_DT_DT", dt, dt, "TIME", "duration between two dates and times"),
        ("CONCAT_DATE_TOD", "DATE", tod, dt, "a date and a time of day joined"),
    ]
    rows = [
        _fn(name, [Pin("IN1", a), Pin("IN2", b)], result, "date and time", text, "FUN-85")
        for name, a, b, result, text in table
    ]
    rows += [  # IEC 61131-3 ed. 3 Table 35: the same functions on the long types (ADD_LTOD_LTIME ...)
        _fn(
            long_time_name(name),
            [Pin("IN1", _long(a)), Pin("IN2", _long(b))],
            _long(result),
            "date and time",
            text,
            "FUN-85",
        )
        for name, a, b, result, text in table
    ]
    clock = "CODESYS: the time since the PLC started (the virtual clock)"
    rows.append(_fn("TIME", [], "TIME", "date and time", clock, "CODESYS"))  # OSCAT's T_PLC_MS reads it
    rows += [
        _fn(
            "MULTIME",
            [Pin("IN1", "TIME"), Pin("IN2", "ANY_NUM")],
            "TIME",
            "date and time",
            "duration times a number (= MUL_TIME)",
            "FUN-85",
        ),
        _fn(
            "DIVTIME",
            [Pin("IN1", "TIME"), Pin("IN2", "ANY_NUM")],
            "TIME",
            "date and time",
            "duration divided by a number (= DIV_TIME)",
            "FUN-85",
        ),
    ]
    return rows


#: CV/PV types of the IEC 3rd edition typed counters CTU_INT .. CTUD_ULINT (spec ST-23 uses CTD_DINT).
TYPED_COUNTER_TYPES = ("INT", "DINT", "LINT", "UDINT", "ULINT")


def _counters(suffix: str, i: str) -> list[StdFunctionBlock]:
    b = "BOOL"
    return [
        StdFunctionBlock(
            f"CTU{suffix}",
            (Pin("CU", b, edge="R_EDGE"), Pin("R", b), Pin("PV", i)),
            (Pin("Q", b), Pin("CV", i)),
            "up counter: Q when CV >= PV",
            "SFB-13",
        ),
        StdFunctionBlock(
            f"CTD{suffix}",
            (Pin("CD", b, edge="R_EDGE"), Pin("LD", b), Pin("PV", i)),
            (Pin("Q", b), Pin("CV", i)),
            "down counter: Q when CV <= 0",
            "SFB-14",
        ),
        StdFunctionBlock(
            f"CTUD{suffix}",
            (Pin("CU", b, edge="R_EDGE"), Pin("CD", b, edge="R_EDGE"), Pin("R", b), Pin("LD", b), Pin("PV", i)),
            (Pin("QU", b), Pin("QD", b), Pin("CV", i)),
            "up/down counter",
            "SFB-15",
        ),
    ]


def _function_blocks() -> list[StdFunctionBlock]:
    b, i, t = "BOOL", "INT", "TIME"

    def timer(name: str, text: str) -> StdFunctionBlock:
        return StdFunctionBlock(name, (Pin("IN", b), Pin("PT", t)), (Pin("Q", b), Pin("ET", t)), text, "SFB-16..18")

    return [
        StdFunctionBlock("SR", (Pin("S1", b), Pin("R", b)), (Pin("Q1", b),), "bistable, set dominant", "SFB-10"),
        StdFunctionBlock("RS", (Pin("S", b), Pin("R1", b)), (Pin("Q1", b),), "bistable, reset dominant", "SFB-10"),
        StdFunctionBlock("R_TRIG", (Pin("CLK", b),), (Pin("Q", b),), "TRUE for one call on a rising edge", "SFB-11"),
        StdFunctionBlock("F_TRIG", (Pin("CLK", b),), (Pin("Q", b),), "TRUE for one call on a falling edge", "SFB-12"),
        *_counters("", i),
        *(fb for cv_type in TYPED_COUNTER_TYPES for fb in _counters(f"_{cv_type}", cv_type)),
        timer("TP", "pulse timer: Q TRUE for PT after a rising edge of IN"),
        timer("TON", "on-delay timer: Q TRUE once IN has been TRUE for PT"),
        timer("TOF", "off-delay timer: Q stays TRUE for PT after IN falls"),
        *_sfc_blocks(),
    ]


#: The inputs of ACTION_CONTROL, one per action qualifier (IEC 61131-3 ed. 2, figure 15: S0 is S), in its order.
ACTION_CONTROL_QUALIFIERS = ("N", "R", "S0", "L", "D", "P", "P1", "P0", "SD", "DS", "SL")


def _sfc_blocks() -> list[StdFunctionBlock]:
    """The blocks an SFC is lowered to (docs/sfc.md): IEC's action control, and the step's flag and time."""
    b = "BOOL"
    return [
        StdFunctionBlock(
            "ACTION_CONTROL",
            (*(Pin(q, b) for q in ACTION_CONTROL_QUALIFIERS), Pin("T", "TIME")),
            (Pin("Q", b), Pin("A", b)),
            "SFC action control: Q the action flag, A runs the action (Q and the final run)",
            "SFC-05",
            group="SFC",
        ),
        StdFunctionBlock(
            "SFC_STEP",
            (Pin("X", b),),
            (Pin("T", "TIME"),),
            "SFC step: X active, T the time since its first active scan",
            "SFC-06",
            group="SFC",
        ),
    ]


#: Every standard function by upper-case name.
FUNCTIONS: dict[str, StdFunction] = {
    f.name: f
    for f in (
        *_conversions(),
        *_ed3_conversions(),
        *_numeric(),
        *_bits(),
        *_selection_and_comparison(),
        *_strings(),
        *_date_and_time(),
    )
}
#: Every standard function block by upper-case name.
FUNCTION_BLOCKS: dict[str, StdFunctionBlock] = {fb.name: fb for fb in _function_blocks()}


#: Vendor system functions (not IEC's) a project may define itself: its own POU of that name is called instead
#: (IronPLC's ``allow_time_as_function_name``: a user ``FUNCTION TIME``).
REDEFINABLE = frozenset({"TIME"})
#: Seed 000's names for MUL_TIME and DIV_TIME (IEC 61131-3 ed. 3 has only those), which CODESYS does not have: under
#: CODESYS typing a project may define them as well (OSCAT BASIC's MULTIME, "multiplies a time by a real number").
CODESYS_REDEFINABLE = frozenset({"MULTIME", "DIVTIME"})


def function(name: str) -> StdFunction | None:
    return FUNCTIONS.get(name.upper())


def function_block(name: str) -> StdFunctionBlock | None:
    return FUNCTION_BLOCKS.get(name.upper())


#: (operator, argument categories) -> the standard function behind + - * / on time operands (FUN-85, ST-21).
OPERATOR_OVERLOADS: dict[tuple[str, tuple[str, ...]], str] = {
    ("ADD", ("time", "time")): "ADD_TIME",
    ("SUB", ("time", "time")): "SUB_TIME",
    ("ADD", ("tod", "time")): "ADD_TOD_TIME",
    ("SUB", ("tod", "time")): "SUB_TOD_TIME",
    ("SUB", ("tod", "tod")): "SUB_TOD_TOD",
    ("ADD", ("dt", "time")): "ADD_DT_TIME",
    ("SUB", ("dt", "time")): "SUB_DT_TIME",
    ("SUB", ("date", "date")): "SUB_DATE_DATE",
    ("SUB", ("dt", "dt")): "SUB_DT_DT",
    ("MUL", ("time", "int")): "MUL_TIME",
    ("MUL", ("time", "real")): "MUL_TIME",
    ("DIV", ("time", "int")): "DIV_TIME",
    ("DIV", ("time", "real")): "DIV_TIME",
}
