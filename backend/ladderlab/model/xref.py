"""The cross-reference list (issue 28): where each variable and direct address is declared, read and written."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from .base import Model

AccessKind = Literal["declared", "read", "write", "call"]


class XrefAccess(Model):
    """One place a variable occurs: its declaration, a read, a write, or a call of an FB instance."""

    kind: AccessKind
    pou: str | None = Field(description="The POU, None for the global declarations (globals.st, gvls/).")
    gvl: str | None = Field(default=None, description="A global's declaration: its global variable list, if any.")
    network: str | None = Field(default=None, description="LD/FBD: the network's id.")
    network_number: int | None = Field(default=None, description="LD/FBD: the network's number as the editor shows it.")
    element: str | None = Field(default=None, description="LD/FBD: the element's id.")
    operand: str | None = Field(default=None, description="LD/FBD: the element's operand text, e.g. 'RunTimer.Q'.")
    line: int | None = Field(
        default=None, description="ST body line, or the declaration's line in its declarations text."
    )
    column: int | None = None
    path: str = Field(description="What was accessed, e.g. 'RunTimer.Q' or 'arr[i]' (indices as '[]').")


class XrefEntry(Model):
    """A variable: a global, or one POU's own."""

    name: str
    pou: str | None = Field(description="The POU that declares it, None for a global.")
    var_class: str
    type: str
    address: str | None = None
    comment: str | None = None
    accesses: list[XrefAccess]


class XrefList(Model):
    entries: list[XrefEntry]
