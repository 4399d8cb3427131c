"""Located diagnostics shared by every checker (model, ST, LD, FBD, storage).

One shape for all of them so the CLI, the server and the browser can show any
problem the same way and jump to where it is.
"""

from __future__ import annotations

from pydantic import ConfigDict, Field, field_validator

from . import codes
from .base import Model

Severity = codes.Severity


class Diagnostic(Model):
    """A problem found in a project, with as much location as applies."""

    model_config = ConfigDict(extra="forbid")

    severity: Severity = "error"
    code: str = Field(description="What kind of problem it is: an entry of docs/diagnostics.md (model/codes.py).")
    message: str
    file: str | None = None
    json_path: str | None = None
    pou: str | None = None
    network: str | None = Field(default=None, description="LD/FBD: the network's id (for the editor to reveal it).")
    element: str | None = Field(default=None, description="LD/FBD: the element's id.")
    pin: str | None = None
    place: str | None = Field(
        default=None,
        description='LD/FBD: where it is in the user\'s words, e.g. network 2 "Motor timer", TON RunTimer.PT.',
    )
    line: int | None = None
    column: int | None = None
    end_line: int | None = None
    end_column: int | None = None

    @field_validator("code")
    @classmethod
    def _recorded(cls, code: str) -> str:
        codes.record(code)  # the test suite's account of the codes it produced (model/codes.py)
        return code

    def location(self) -> str:
        """Human-readable location prefix, e.g. ``pous/Main.st:3:7`` or ``POU Main, network 1 "Start", coil Motor``."""
        parts: list[str] = []
        if self.file:
            where = self.file
            if self.line is not None:
                where += f":{self.line}"
                if self.column is not None:
                    where += f":{self.column}"
            parts.append(where)
        if self.json_path:
            parts.append(self.json_path)
        if self.pou:
            pou = f"POU {self.pou}"
            if not self.file and self.line is not None:
                pou += f" line {self.line}"
                if self.column is not None:
                    pou += f" column {self.column}"
            parts.append(pou)
        if self.place:
            parts.append(self.place)
            return ", ".join(parts)
        if self.network:
            parts.append(f"network {self.network}")
        if self.element:
            parts.append(f"element {self.element}")
        if self.pin:
            parts.append(f"pin {self.pin}")
        return ", ".join(parts)

    def format(self) -> str:
        where = self.location()
        prefix = f"{where}: " if where else ""
        return f"{prefix}{self.severity} {self.code}: {self.message}"


def has_errors(diagnostics: list[Diagnostic]) -> bool:
    return any(d.severity == "error" for d in diagnostics)
