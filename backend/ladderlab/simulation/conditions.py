"""Conditions of "run until": a BOOL variable, its negation, or a variable compared with a literal.

    Motor            NOT Alarm            Tank.Level >= 80.0         Main.State = 3
    Door.Pos <> 0    Main.T1.ET > T#2s    Light = TRUE

The right-hand side is read as a literal of the variable's type (``T#2s`` for TIME, an enumeration's
value name), exactly as a write would take it, so a condition cannot compare a variable with a value
it can never hold. The condition is checked after every scan; parsing fails with the user's words.
"""

from __future__ import annotations

import operator
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

from ..engine.paths import UnknownPath, coerce_for
from ..engine.simulation import Simulation

_COMPARE = re.compile(r"^\s*(?P<path>[^<>=]+?)\s*(?P<op><>|<=|>=|=|<|>)\s*(?P<value>.+?)\s*$")
_NOT = re.compile(r"^\s*NOT\s+(?P<path>.+?)\s*$", re.IGNORECASE)
#: Why a property monitored as 'call' is no condition (docs/st.md, "Properties online").
_CALLED = (
    "a property monitored as 'call', read by running its GET: a condition is checked after every scan, and "
    "would run it each time; use 'variable' or the variables its GET reads"
)
_OPERATORS: dict[str, Callable[[Any, Any], Any]] = {
    "=": operator.eq,
    "<>": operator.ne,
    "<": operator.lt,
    "<=": operator.le,
    ">": operator.gt,
    ">=": operator.ge,
}


class BadCondition(ValueError):
    """A condition that does not read: says why in the user's words."""


@dataclass(frozen=True)
class Condition:
    """``text`` as given; ``holds(sim)`` after a scan."""

    text: str
    path: str
    op: str
    value: object

    def holds(self, sim: Simulation) -> bool:
        current = sim.value(sim.location(self.path))
        return bool(_OPERATORS[self.op](current, self.value))


def parse_condition(text: str, sim: Simulation) -> Condition:
    """The condition ``text`` over the variables of ``sim``; BadCondition when it does not read."""
    if not isinstance(text, str) or not text.strip():
        raise BadCondition("a condition is a BOOL variable (Motor), NOT one, or a comparison (Tank.Level >= 80)")
    negated = _NOT.match(text)
    compared = None if negated else _COMPARE.match(text)
    literal: str | bool
    if negated:
        path, op, literal = negated.group("path"), "=", False
    elif compared:
        path, op, literal = compared.group("path"), compared.group("op"), compared.group("value")
    else:
        path, op, literal = text.strip(), "=", True
    try:
        location = sim.location(path)
    except (UnknownPath, ValueError) as error:
        raise BadCondition(f"{text.strip()!r}: {error}") from None
    if not location.elementary:
        raise BadCondition(f"{text.strip()!r}: {location.path} is not a single value to compare")
    if location.called:
        raise BadCondition(f"{text.strip()!r}: {location.path} is {_CALLED}")
    if (negated or not compared) and getattr(location.type, "name", None) != "BOOL":
        raise BadCondition(f"{text.strip()!r}: {location.path} is not a BOOL; compare it, e.g. {location.path} > 0")
    try:
        value = coerce_for(replace(location, refusal=""), literal)  # (a value to compare, never written)
    except ValueError as error:
        raise BadCondition(f"{text.strip()!r}: {error}") from None
    if op not in ("=", "<>") and isinstance(value, bool):
        raise BadCondition(f"{text.strip()!r}: a BOOL is compared with = or <>, not {op}")
    return Condition(text.strip(), location.path, op, value)
