"""The IEC 61131-3 ed. 3 conversions of Table 22 beyond <SRC>_TO_<DST> (catalogue: ``iec.stdlib.ED3_CONVERSIONS``).

* BCD: ``WORD_BCD_TO_UINT(16#1234)`` = 1234 and ``UINT_TO_BCD_WORD(1234)`` = 16#1234, 4 bits a decimal digit,
  least significant digit in the low nibble; the overloaded ``BCD_TO_<int>`` takes any bit string and
  ``<int>_TO_BCD`` writes into the bit string of the integer's width. A nibble above 9, a BCD value that does not
  fit the integer, or a negative integer or one with more digits than the bit string holds is a runtime fault
  (the standard: "an error"), never a silent wrong value.
* ``REAL_TRUNC_INT`` ...: toward zero into the named integer type (as TRUNC).
* ``TO_<type>``: the <SRC>_TO_<type> conversion of whatever the argument is.
"""

from __future__ import annotations

from ...iec.elementary import ELEMENTARY
from ...iec.stdlib import ED3_CONVERSIONS
from ...iec.values import resolve
from ..errors import INVALID_ARGUMENT, OVERFLOW, PlcRuntimeError
from .build import HELPERS, Impl
from .conversions import conversion, value_type_name
from .functions import categories, reject, truncate


def bcd_decode(value: int, name: str, largest: int) -> int:
    """The number the BCD digits of ``value`` write; a fault for a nibble above 9 or a number above ``largest``."""
    result, scale, rest = 0, 1, value
    while rest:
        digit = rest & 0xF
        if digit > 9:
            raise PlcRuntimeError(INVALID_ARGUMENT, f"{name}(16#{value:X}): the digit 16#{digit:X} is not BCD (0..9)")
        result += digit * scale
        scale *= 10
        rest >>= 4
    if result > largest:
        raise PlcRuntimeError(OVERFLOW, f"{name}(16#{value:X}) = {result} does not fit its result (at most {largest})")
    return result


def bcd_encode(value: int, name: str, digits: int) -> int:
    """``value`` in BCD with at most ``digits`` digits; a fault for a negative value or one with more digits."""
    if value < 0 or value >= 10**digits:
        raise PlcRuntimeError(OVERFLOW, f"{name}({value}): BCD in {digits} digits holds 0..{10**digits - 1}")
    result, shift = 0, 0
    while value:
        value, digit = divmod(value, 10)
        result |= digit << shift
        shift += 4
    return result


HELPERS.update(ll__bcd_decode=bcd_decode, ll__bcd_encode=bcd_encode)


def ed3_conversion(name: str):
    """The registry's implement() for one ED3_CONVERSIONS entry."""
    kind, source, target = ED3_CONVERSIONS[name]

    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        actual = resolve(types[0]).name
        if source is not None and actual != source:
            raise reject(name, types)
        if kind == "to":
            goal = value_type_name(target)
            return conversion(actual, result if result and resolve(goal).category == "string" else goal)
        if kind == "trunc":
            return truncate(types, target)
        if kind == "bcd_to":
            if categories(types) not in (("bits",), ("bool",)):
                raise reject(name, types)
            return Impl(f"ll__bcd_decode(a0, {name!r}, {ELEMENTARY[target].max})")
        if categories(types) != ("int",):
            raise reject(name, types)
        return Impl(f"ll__bcd_encode(a0, {name!r}, {ELEMENTARY[target].bits // 4})")

    return implement


def ed3_conversions() -> dict[str, object]:
    """name -> implement() for every ED3_CONVERSIONS entry."""
    return {name: ed3_conversion(name) for name in ED3_CONVERSIONS}
