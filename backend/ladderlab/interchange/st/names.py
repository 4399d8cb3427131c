"""Names the ST export invents (temporaries, edge triggers, ENO flags, the network state): never a user's name.

A generated name is built from a readable hint (an element id, a network id)
turned into an IEC identifier: letters, digits and single underscores, starting
with a letter, at most 64 characters (LEX-13, DIA-03). It must not clash, case
insensitively, with anything the exported text can see: the POU's variables,
the globals, POU and type names, the standard functions and function blocks,
and the keywords (a name that does not parse as a plain variable is skipped).
"""

from __future__ import annotations

import re
from functools import lru_cache

from ...iec import stdlib
from ...model.names import MAX_NAME_LENGTH
from ...st import ast
from ...st.parser import parse_expression
from ...st.symbols import CheckResult

_NOT_IDENTIFIER = re.compile(r"[^A-Za-z0-9]+")


def identifier(hint: str) -> str:
    """``hint`` as an IEC identifier: runs of other characters become one ``_``, a leading digit gets ``n``."""
    text = _NOT_IDENTIFIER.sub("_", hint).strip("_") or "x"
    if text[0].isdigit():
        text = "n" + text
    return text[: MAX_NAME_LENGTH - 8].rstrip("_")


@lru_cache(maxsize=4096)
def _is_plain_name(name: str) -> bool:
    """Does ``name`` parse as a variable (not a keyword or a literal such as ``TRUE``)?"""
    parsed = parse_expression(name)
    return parsed.ok and isinstance(parsed.ast, ast.Name)


class Names:
    """Fresh identifiers for one exported POU; ``taken`` are upper-case names already in use."""

    def __init__(self, taken: set[str]):
        self._taken = set(taken)

    @classmethod
    def for_pou(cls, checked: CheckResult, pou: str) -> Names:
        """Everything a POU's text can refer to: its symbols, the globals, POUs, types and the standard library."""
        info = checked.pou(pou)
        taken = set(info.symbols) if info is not None else set()
        taken |= set(checked.globals) | set(checked.pous) | set(checked.types)
        taken |= set(stdlib.FUNCTIONS) | set(stdlib.FUNCTION_BLOCKS)
        return cls(taken)

    def fresh(self, hint: str) -> str:
        """A new name built from ``hint`` (``hint``, ``hint_2``, ``hint_3`` ...), reserved from now on."""
        stem = identifier(hint)
        candidate, number = stem, 1
        while candidate.upper() in self._taken or not _is_plain_name(candidate):
            number += 1
            candidate = f"{stem}_{number}"
        self._taken.add(candidate.upper())
        return candidate
