"""Generated Python names for IEC names: safe by construction.

The IR carries canonical IEC names, but nothing a user typed may reach the
generated source unchecked. Every generated name is a fixed ASCII prefix plus
either the name itself, when it is a plain identifier (``MOTOR`` -> ``v_MOTOR``,
readable in ``--emit-python``), or an injective escape of it (``w`` prefixes:
every character outside ``[A-Z0-9]`` becomes ``_`` and six hex digits), so any
string - a hidden slot named ``N1.E2`` included - yields a valid identifier and
two different names never meet. Prefixes keep the kinds apart:

=========  ==========================================
``v_``     a variable slot (POU slot, global, field)
``P_``     the class of a PROGRAM or FUNCTION_BLOCK
``f_``     a user FUNCTION
``S_``     the class of a structure type
``fb_``    a standard FB class
``fn_``    a specialised standard function
``ll_``    the engine's own helpers and temporaries
=========  ==========================================

Text that only appears in comments goes through :func:`comment_text`.
"""

from __future__ import annotations

import re
from functools import lru_cache

_PLAIN = re.compile(r"[A-Z0-9_]+\Z")
_ALNUM = re.compile(r"[A-Z0-9]")
# Only escapes are cached: a plain name costs less to check than a cache lookup, and a cache over every name of a
# large program misses on each (a 50,000-network POU has 200,000 slots) and pays for its evictions. A long-running
# server compiles many programs, so the cache keeps the most recent escapes only.
_NAMES_KEPT = 1 << 16


def escape(name: str) -> str:
    """``name`` upper-cased if it is a plain identifier, else the injective escape (starting with ``w``)."""
    upper = name.upper()
    if upper.isascii() and (upper.isidentifier() or _PLAIN.match(upper)):  # (an ASCII identifier is plain)
        return upper
    return _escaped(upper)


@lru_cache(maxsize=_NAMES_KEPT)
def _escaped(upper: str) -> str:
    return "w" + "".join(c if _ALNUM.match(c) and c.isascii() else f"_{ord(c):06X}" for c in upper)


def slot(name: str) -> str:
    """Attribute / local name of a variable slot or structure field."""
    return "v_" + escape(name)


def pou_class(name: str) -> str:
    return "P_" + escape(name)


def function(name: str) -> str:
    return "f_" + escape(name)


def execute_function(name: str) -> str:
    """The body of a PROGRAM / FUNCTION_BLOCK (its class's ``execute``; a derived FB's ``SUPER^()`` calls it)."""
    return "ll_x_" + escape(name)


def dispatch_table(method: str) -> str:
    """The table of a method's implementations by instance class (``ll_virtual``, a METHOD's dynamic dispatch)."""
    return "ll_vt_" + escape(method)


def struct_class(name: str) -> str:
    return "S_" + escape(name)


def std_fb(name: str) -> str:
    return "fb_" + escape(name)


def comment_text(text: object) -> str:
    """User text as it may appear in a generated comment: one line, ASCII, quoted."""
    return ascii(str(text))


_CHUNK = re.compile(r"ll_k\d+_")


def chunk_function(number: int, key: str) -> str:
    """The function holding part ``number`` of a long POU body (``key``: the POU's escaped name)."""
    return f"ll_k{number}_{key}"


def is_chunk_function(name: str) -> bool:
    """A chunk is part of its POU's body, not a call of its own (the debugger's step over/out counts calls)."""
    return _CHUNK.match(name) is not None
