"""What the server and a simulation's process both need of a command, without the engine: the refusal
(``CommandError``) and the change filter of the values sent to clients (the server imports this at start;
``runner.py`` and the compiler are imported by the worker processes only: startup, issue 27)."""

from __future__ import annotations

from ..model.monitor import ErrorCode

_MISSING = object()


class CommandError(Exception):
    """A command the simulation refuses; ``code`` is an ``Error`` message code (bad_path, bad_value, bad_state)."""

    def __init__(self, code: ErrorCode, message: str) -> None:
        super().__init__(message)
        self.code: ErrorCode = code
        self.message = message


def changes(sent: dict[str, object], current: dict[str, object]) -> dict[str, object]:
    """The entries of ``current`` that are new or differ from ``sent``: another value, another type (TRUE is
    not 1), but a NaN that stays NaN has not changed. Runs for every watched value of every frame."""
    changed = {}
    for key, value in current.items():
        old = sent.get(key, _MISSING)
        if value == old and type(value) is type(old):
            continue
        if value != value and type(old) is float and old != old:  # NaN stays NaN
            continue
        changed[key] = value
    return changed
