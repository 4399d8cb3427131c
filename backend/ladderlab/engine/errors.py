"""The two ways the runtime library reports trouble.

* ``PlcRuntimeError`` is a fault: division by zero, an index or MUX selector out
  of range, a subrange violation. It is raised (in the fast and the checked
  form alike); the engine catches it, stops the task and adds the location.
* ``PlcWarning`` is returned, never raised, by the checked form of a function
  (the one the code generator uses when ENO is wired or overflow checking is
  on): the function still produced a value, but ENO must be FALSE
  (spec POU-41, FUN-20, FUN-83, FUN-87, FUN-90).
"""

from __future__ import annotations

from typing import NamedTuple

DIVISION_BY_ZERO = "division_by_zero"
INDEX_RANGE = "index_out_of_range"
SUBRANGE = "subrange_violation"

OVERFLOW = "overflow"
DOMAIN = "domain_error"
INVALID_ARGUMENT = "invalid_argument"
TRUNCATED = "string_truncated"
NOT_A_NUMBER = "invalid_string"


class PlcRuntimeError(Exception):
    """A fault that stops the task; ``code`` is one of the constants above."""

    def __init__(self, code: str, message: str) -> None:
        super().__init__(message)
        self.code = code
        self.message = message


class PlcWarning(NamedTuple):
    """Why a checked function set ENO = FALSE; ``code`` is one of the constants above."""

    code: str
    message: str


def division_by_zero(dividend: object, divisor: object) -> PlcRuntimeError:
    return PlcRuntimeError(DIVISION_BY_ZERO, f"division by zero: {dividend} / {divisor}")


def index_out_of_range(index: int, low: int, high: int, what: str = "array index") -> PlcRuntimeError:
    return PlcRuntimeError(INDEX_RANGE, f"{what} {index} is outside {low}..{high}")


def check_index(index: int, low: int, high: int) -> int:
    """Offset of ``index`` in an array declared [low..high]; raises when outside."""
    if low <= index <= high:
        return index - low
    raise index_out_of_range(index, low, high)


def check_subrange(value: int, low: int, high: int) -> int:
    """``value`` unchanged when it lies in the subrange low..high; raises otherwise."""
    if low <= value <= high:
        return value
    raise PlcRuntimeError(SUBRANGE, f"{value} is outside the subrange {low}..{high}")


def check_member(value: int, values: tuple[int, ...], enumeration: str) -> int:
    """``value`` unchanged when it is the value of one of the enumeration's members; raises otherwise (an
    enumeration's values are its subrange: a pointer of its base type could write any other, docs/st.md)."""
    if value in values:
        return value
    raise PlcRuntimeError(SUBRANGE, f"{value} is none of the values of the enumeration {enumeration}")


def check_fit(value: int, low: int, high: int, text: str, type_name: str) -> int:
    """``value`` unchanged when it lies in low..high: the value of ``text``, a CODESYS register holding an operation
    of type ``type_name``, which every target gives alike only there (st/registers.py); raises otherwise."""
    if low <= value <= high:
        return value
    raise PlcRuntimeError(
        OVERFLOW,
        f"'{text}' is {value} here, outside {type_name} ({low}..{high}): CODESYS computes it in a register whose "
        "width and sign depend on the target, and so does what the program makes of this value",
    )


FOR_STEP_ZERO = "for_step_zero"
NULL_DEREFERENCE = "null_dereference"
DANGLING_REFERENCE = "dangling_reference"
WATCHDOG = "watchdog"
OUT_OF_MEMORY = "out_of_memory"


def null_dereference(what: str) -> PlcRuntimeError:
    """``r^`` where ``r`` is NULL (IEC 61131-3 ed. 3 6.4.4.10.3: an error)."""
    return PlcRuntimeError(NULL_DEREFERENCE, f"{what} is NULL: it refers to no variable, so '^' has nothing to reach")


def pointer_outside(what: str, position: int, length: int, size: int | None = None) -> PlcRuntimeError:
    """Pointer arithmetic or a dereference that would leave the array the pointer points into (or the single
    variable: ``length`` 1); ``position`` counts elements (of ``size`` bytes) from the array's first one."""
    elements = f"{length} element(s)" + (f" of {size} byte(s)" if size is not None else "")
    return PlcRuntimeError(
        INDEX_RANGE, f"{what} reaches element {position} of {elements}: outside the variable it points into"
    )


def pointer_outside_bytes(what: str, offset: int, size: int, whole: int) -> PlcRuntimeError:
    """A pointer seeing memory as another type (``POINTER TO BYTE`` over a STRING) that would read, write or move
    outside the ``whole`` bytes of the variable it points into; ``size``: the bytes an access covers (0: a move)."""
    reach = f"bytes {offset}..{offset + size - 1}" if size else f"byte {offset}"
    return PlcRuntimeError(INDEX_RANGE, f"{what} reaches {reach} of a {whole}-byte variable: outside it")


def pointer_nowhere(what: str, address: int) -> PlcRuntimeError:
    """Reading or writing through a pointer made from a number (CODESYS typing: ``pt := dw``) that lies in no
    variable (engine/codegen/addresses.py)."""
    return PlcRuntimeError(INDEX_RANGE, f"{what} reaches the address {address}, which lies in no variable")


def pointers_unordered(op: str, left: str, right: str) -> PlcRuntimeError:
    """``p < q`` with pointers into different variables (or NULL): LadderLab's variables have no addresses to order."""
    return PlcRuntimeError(
        INVALID_ARGUMENT, f"{left} {op} {right}: only pointers into one variable (an array, a STRING) can be ordered"
    )


def dangling_reference(text: str, call: str) -> PlcRuntimeError:
    """A reference to a variable of a FUNCTION call (or a VAR_TEMP of a PROGRAM / FUNCTION_BLOCK call; ``call``:
    ``FUNCTION F``), used after that call returned (IEC 61131-3 ed. 3 6.4.4.10: the variable no longer exists;
    CODESYS would read whatever reuses its memory)."""
    return PlcRuntimeError(
        DANGLING_REFERENCE, f"dangling reference: {text} refers to a variable of a call of {call} that has returned"
    )


def for_step_zero() -> PlcRuntimeError:
    """A FOR loop whose BY value is 0 at run time would never end (ST-31, ST-70)."""
    return PlcRuntimeError(FOR_STEP_ZERO, "FOR loop step (BY) is 0")
