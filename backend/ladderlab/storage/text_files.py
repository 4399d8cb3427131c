"""Bytes of a .st, .json or .xml file -> text, or a located error saying how to fix it.

Project files are UTF-8. Files exported by CoDeSys 2.3 (Russian courses especially) are usually
Windows-1251: read as UTF-8 they fail at the first Cyrillic letter. That is a located error (file,
byte offset, line and column) that says what to do, never a traceback; the CLI's ``--encoding cp1251``
reads such a file as it is.
"""

from __future__ import annotations

import codecs
import re

from ..model import Diagnostic
from .errors import ProjectLoadError

#: What a user can do about a file that is not UTF-8 (the CLI adds its option).
CLI_HINT = "re-save as UTF-8 or pass --encoding cp1251"
HINT = "re-save as UTF-8"

_XML_DECLARATION = re.compile(rb"^(\xef\xbb\xbf)?<\?xml[^>]*?encoding\s*=\s*[\"']([A-Za-z0-9._-]+)[\"']", re.DOTALL)


def check_encoding(name: str | None) -> str | None:
    """``name`` as a codec name Python knows (ValueError naming it otherwise); None stays None (UTF-8)."""
    if name is None:
        return None
    try:
        return codecs.lookup(name).name
    except LookupError:
        raise ValueError(f"unknown encoding {name!r} (e.g. utf-8, cp1251, latin-1)") from None


def decode_text(data: bytes, file: str, encoding: str | None = None, hint: str = HINT) -> str:
    """The text of a file: UTF-8 (a leading byte order mark dropped) unless ``encoding`` is given.

    Raises ProjectLoadError with a BAD-ENCODING diagnostic at the first byte that does not decode."""
    try:
        return data.decode(encoding) if encoding else data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise ProjectLoadError([_diagnostic(data, error, file, encoding, hint)]) from None


def xml_for_parser(data: bytes, file: str, encoding: str | None = None, hint: str = HINT) -> bytes:
    """XML bytes the parser reads right: with ``encoding``, the text re-encoded as UTF-8 (and declared so); else
    a document that declares another encoding as it is (the parser honours the declaration), and any other
    document checked to be UTF-8 (a located BAD-ENCODING error otherwise)."""
    declared = _XML_DECLARATION.match(data)
    if encoding:
        text = decode_text(data, file, encoding, hint)
        if declared:
            text = re.sub(r"encoding\s*=\s*[\"'][^\"']*[\"']", 'encoding="utf-8"', text, count=1)
        return text.encode("utf-8")
    if declared and _codec(declared.group(2).decode("ascii", "replace")) != "utf-8":
        return data  # another encoding, or one Python does not know: the parser reads or refuses it (XML-ENCODING)
    decode_text(data, file, None, hint)
    return data


def _codec(name: str) -> str | None:
    try:
        return codecs.lookup(name).name
    except LookupError:
        return None


def _diagnostic(data: bytes, error: UnicodeDecodeError, file: str, encoding: str | None, hint: str) -> Diagnostic:
    offset = error.start
    line_start = data.rfind(b"\n", 0, offset) + 1
    column = len(data[line_start:offset].decode(encoding or "utf-8", "replace")) + 1
    bad = data[offset : offset + 1].hex().upper()
    return Diagnostic(
        code="BAD-ENCODING",
        file=file,
        line=data.count(b"\n", 0, offset) + 1,
        column=column,
        message=f"not {encoding or 'UTF-8'} at byte {offset} (0x{bad}); {hint}",
    )
