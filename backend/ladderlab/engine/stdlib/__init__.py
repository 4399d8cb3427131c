"""The IEC 61131-3 standard library at run time: what generated code calls.

Functions are generic (ADD on INT wraps, on REAL rounds to float32), and the
code generator knows the resolved types, so it asks once per call site:

    add = make_function("ADD", ("INT", "INT"), "INT")          # fast: add(a, b)
    add_eno = make_function("ADD", ("INT", "INT"), "INT", checked=True)
    value, warning = add_eno(a, b)                              # ENO = warning is None
    template = function_template("ADD", ("INT", "INT"), "INT")  # or paste this inline

Arguments are positional in the IEC formal order (SEL: G, IN0, IN1; LIMIT: MN,
IN, MX; MUX: K, IN0..; MID: IN, L, P; INSERT: IN1, IN2, P; DELETE: IN, L, P;
REPLACE: IN1, IN2, L, P). Faults raise ``PlcRuntimeError`` in both forms. See
docs/runtime.md.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cache

from ...iec import values
from ...iec.stdlib import OPERATOR_OVERLOADS, long_time_name
from ..errors import PlcRuntimeError, PlcWarning
from . import codesys_dates
from . import functions as f
from .build import HELPERS, Impl, Specialised, specialise
from .conversions import conversion_function, conversion_names, convert, converter
from .ed3_conversions import ed3_conversions
from .fbs import STANDARD_FBS, FunctionBlock, pins
from .strings import concat, find_position, length, positional
from .timefuncs import TIME_FUNCTIONS, clock, time_lengths

Implement = Callable[[tuple[str, ...], "str | None"], Impl]


@dataclass(frozen=True)
class StandardFunction:
    """How to get a specialised callable: ``implement(arg_types, result_type)`` -> Impl.

    ``inputs`` is the number of inputs, or the minimum when ``extensible``
    (FUN-03). ``spec`` is the item of the spec that defines it.
    """

    name: str
    inputs: int
    extensible: bool
    implement: Implement
    spec: str

    def accepts(self, count: int) -> bool:
        return count >= self.inputs if self.extensible else count == self.inputs


def _operator(name: str, numeric: Implement) -> Implement:
    """ADD/SUB/MUL/DIV also act on time operands (FUN-85) and ADD on strings (FUN-82)."""

    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        cats = f.categories(types)
        overload = OPERATOR_OVERLOADS.get((name, cats))
        if overload:
            return TIME_FUNCTIONS[overload](types, result)
        if name == "ADD" and set(cats) == {"time"} and time_lengths(types) is not None:
            return f.chain("+", types, values.resolve(types[0]).name)
        if name == "ADD" and set(cats) == {"string"}:
            return concat(types, result)
        return numeric(types, result)

    return implement


def _table() -> dict[str, StandardFunction]:
    rows: list[tuple[str, int, bool, Implement, str]] = [
        ("ADD", 2, True, _operator("ADD", f.arithmetic("ADD", "+")), "FUN-30"),
        ("MUL", 2, True, _operator("MUL", f.arithmetic("MUL", "*")), "FUN-30"),
        ("SUB", 2, False, _operator("SUB", f.arithmetic("SUB", "-")), "FUN-30"),
        ("DIV", 2, False, _operator("DIV", f.divide), "FUN-31"),
        ("MOD", 2, False, f.modulo, "FUN-31"),
        ("EXPT", 2, False, f.expt, "FUN-33"),
        ("MOVE", 1, False, f.move, "FUN-32"),
        ("ABS", 1, False, f.absolute, "FUN-20"),
        ("TRUNC", 1, False, f.truncate, "FUN-11"),
        ("SHL", 2, False, f.shift("SHL"), "FUN-40"),
        ("SHR", 2, False, f.shift("SHR"), "FUN-40"),
        ("ROL", 2, False, f.shift("ROL"), "FUN-40"),
        ("ROR", 2, False, f.shift("ROR"), "FUN-40"),
        ("AND", 2, True, f.bitwise("AND", "&"), "FUN-50"),
        ("OR", 2, True, f.bitwise("OR", "|"), "FUN-50"),
        ("XOR", 2, True, f.bitwise("XOR", "^"), "FUN-50"),
        ("NOT", 1, False, f.negate, "FUN-50"),
        ("SEL", 3, False, f.select, "FUN-60"),
        ("MAX", 2, True, f.extreme("MAX", ">="), "FUN-60"),
        ("MIN", 2, True, f.extreme("MIN", "<="), "FUN-60"),
        ("LIMIT", 3, False, f.limiter, "FUN-60"),
        ("MUX", 3, True, f.multiplexer, "FUN-61"),
        ("GT", 2, True, f.comparison(">"), "FUN-70"),
        ("GE", 2, True, f.comparison(">="), "FUN-70"),
        ("EQ", 2, True, f.comparison("=="), "FUN-70"),
        ("LE", 2, True, f.comparison("<="), "FUN-70"),
        ("LT", 2, True, f.comparison("<"), "FUN-70"),
        ("NE", 2, False, f.comparison("!="), "FUN-70"),
        ("LEN", 1, False, length, "FUN-80"),
        ("CONCAT", 2, True, concat, "FUN-80"),
        ("FIND", 2, False, find_position, "FUN-81"),
    ]
    rows += [(name, 1, False, f.real_function(name), "FUN-20") for name in f.MATH_FUNCTIONS]
    rows.append(("ATAN2", 2, False, f.atan2, "FUN-20"))
    rows += [
        (name, inputs, False, positional(name), "FUN-81")
        for name, inputs in (("LEFT", 2), ("RIGHT", 2), ("MID", 3), ("INSERT", 3), ("DELETE", 3), ("REPLACE", 4))
    ]
    rows += [(name, 2, False, implement, "FUN-85") for name, implement in TIME_FUNCTIONS.items()]
    rows += [(long_time_name(name), 2, False, implement, "FUN-85") for name, implement in TIME_FUNCTIONS.items()]
    rows += [
        ("MULTIME", 2, False, TIME_FUNCTIONS["MUL_TIME"], "FUN-85"),
        ("DIVTIME", 2, False, TIME_FUNCTIONS["DIV_TIME"], "FUN-85"),
        ("TIME", 0, False, clock, "CODESYS"),
    ]
    rows += [(name, 1, False, implement, "CODESYS") for name, implement in codesys_dates.FUNCTIONS.items()]
    rows += [(name, 1, False, conversion_function(*pair), "FUN-10") for name, pair in conversion_names().items()]
    rows += [(name, 1, False, implement, "FUN-10") for name, implement in ed3_conversions().items()]
    return {name: StandardFunction(name, inputs, ext, implement, spec) for name, inputs, ext, implement, spec in rows}


#: Every standard function by IEC name (conversions in long and short spellings, MULTIME/DIVTIME aliases).
STANDARD_FUNCTIONS: dict[str, StandardFunction] = _table()

#: Globals that inline templates may name: put them in the generated module's namespace.
INLINE_NAMES: dict[str, object] = HELPERS


@cache
def specialised(name: str, arg_types: tuple[str, ...], result_type: str | None = None) -> Specialised:
    """Fast callable, checked callable and inline template for one call signature (cached)."""
    function = STANDARD_FUNCTIONS.get(name.upper())
    if function is None:
        raise ValueError(f"{name} is not a standard function")
    if not function.accepts(len(arg_types)):
        raise TypeError(
            f"{function.name} takes {function.inputs}{'+' if function.extensible else ''} inputs, not {len(arg_types)}"
        )
    return specialise(function.name, function.implement(tuple(arg_types), result_type), len(arg_types))


def make_function(name: str, arg_types, result_type: str | None = None, *, checked: bool = False) -> Callable:
    """A plain positional callable for ``name`` on these types.

    ``result_type`` is the resolved type of the result (needed where it decides
    wrapping, float32 rounding or the STRING[n] length; ignored by comparisons,
    selection and bit logic). ``checked=True`` gives the form returning
    ``(value, None | PlcWarning)`` for wired ENO. Raises ValueError for an
    unknown name or type, TypeError for a combination the function does not have.
    """
    built = specialised(name, tuple(arg_types), result_type)
    return built.checked if checked else built.fast


def function_template(name: str, arg_types, result_type: str | None = None) -> str | None:
    """Python source with ``{0}``.. placeholders to inline instead of calling, or None.

    Each placeholder occurs once, evaluated unconditionally and in order, so the
    arguments may be any expressions. Names in it come from ``INLINE_NAMES``.
    """
    return specialised(name, tuple(arg_types), result_type).template


__all__ = [
    "INLINE_NAMES",
    "STANDARD_FBS",
    "STANDARD_FUNCTIONS",
    "FunctionBlock",
    "PlcRuntimeError",
    "PlcWarning",
    "StandardFunction",
    "convert",
    "converter",
    "function_template",
    "make_function",
    "pins",
    "specialised",
]
