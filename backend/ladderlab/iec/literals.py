"""Literal text <-> value, shared by the parser (decode) and the printer (encode).

Spec items: LEX-21..24 (numbers), LEX-30..35 (strings, ``$`` escapes),
LEX-40..46 (durations), LEX-50..52 (dates and times of day).
"""

from __future__ import annotations

import datetime as _dt
import re
from dataclasses import dataclass
from fractions import Fraction

from .elementary import LONG_TIME_TYPES, NS_PER_DAY

_EPOCH = _dt.datetime(1970, 1, 1)
_MS_PER_UNIT = {"d": 86_400_000, "h": 3_600_000, "m": 60_000, "s": 1000, "ms": 1}
_UNIT_RE = re.compile(r"(\d[\d_]*(?:\.\d+)?)(ms|us|ns|d|h|m|s)_?", re.IGNORECASE)
_ESCAPES = {"$": "$", "'": "'", '"': '"', "L": "\n", "N": "\n", "P": "\f", "R": "\r", "T": "\t"}
_ESCAPE_RE = {False: re.compile(r"\$([0-9A-Fa-f]{2}|.)"), True: re.compile(r"\$([0-9A-Fa-f]{4}|.)")}


@dataclass(frozen=True)
class LiteralForm:
    """One kind of prefixed literal as a user writes it: the prefixes that introduce it, what follows them, and
    examples (messages quote them when a literal is malformed; the browser shows them as hints)."""

    name: str
    prefixes: tuple[str, ...]
    rule: str
    examples: tuple[str, ...]

    def hint(self) -> str:
        """``a TIME literal is T# then ...: T#2s, TIME#1h30m``"""
        return f"{self.rule}, e.g. {', '.join(self.examples)}"


#: The prefixed literal forms (LEX-21, LEX-40..52), most common first.
LITERAL_FORMS = (
    LiteralForm(
        "TIME",
        ("T", "TIME", "LT", "LTIME"),
        "a duration is T# then numbers with the units d, h, m, s, ms (largest first, no spaces)",
        ("T#2s", "T#500ms", "TIME#1h30m", "T#-1.5s"),
    ),
    LiteralForm(
        "TIME_OF_DAY",
        ("TOD", "TIME_OF_DAY", "LTOD", "LTIME_OF_DAY"),
        "a time of day is TOD# then hours:minutes:seconds",
        ("TOD#08:30:00", "TOD#23:59:59.5"),
    ),
    LiteralForm("DATE", ("D", "DATE", "LD", "LDATE"), "a date is D# then year-month-day", ("D#2024-05-01",)),
    LiteralForm(
        "DATE_AND_TIME",
        ("DT", "DATE_AND_TIME", "LDT", "LDATE_AND_TIME"),
        "a date and time is DT# then year-month-day-hours:minutes:seconds",
        ("DT#2024-05-01-08:30:00",),
    ),
    LiteralForm("binary", ("2",), "a binary number is 2# then the digits 0 and 1", ("2#1010", "2#1111_0000")),
    LiteralForm("octal", ("8",), "an octal number is 8# then the digits 0 to 7", ("8#17",)),
    LiteralForm(
        "hexadecimal", ("16",), "a hexadecimal number is 16# then the digits 0-9 and A-F", ("16#FF", "16#1A2B")
    ),
)
_FORMS = {prefix: form for form in LITERAL_FORMS for prefix in form.prefixes}


def literal_form(prefix: str) -> LiteralForm | None:
    """The form a literal prefix (``T``, ``TOD``, ``16``; any case) introduces, or None."""
    return _FORMS.get(prefix.upper())


def decode_integer(text: str) -> tuple[int, int]:
    """``'16#FF'`` -> ``(255, 16)``; ``'12_548'`` -> ``(12548, 10)``."""
    text = text.replace("_", "")
    if "#" in text:
        base, digits = text.split("#", 1)
        return int(digits, int(base)), int(base)
    return int(text), 10


def decode_real(text: str) -> float:
    return float(text.replace("_", ""))


def decode_string(text: str) -> str:
    """Body of a quoted literal with its ``$`` escapes resolved (the lexer only admits valid ones)."""

    def one(match: re.Match[str]) -> str:
        code = match.group(1)
        return chr(int(code, 16)) if len(code) > 1 else _ESCAPES[code.upper()]

    return _ESCAPE_RE[text[0] == '"'].sub(one, text[1:-1])


def unheld_character(text: str, wide: bool) -> str | None:
    """The first character of ``text`` a STRING's byte cannot be (CODESYS's STRING: Latin-1, U+0000..U+00FF) or a
    WSTRING's WORD cannot (UCS-2: U+0000..U+D7FF and U+E000..U+FFFF); None when each has its byte or WORD."""
    for ch in text:
        code = ord(ch)
        if (code > 0xFF and not wide) or code > 0xFFFF or 0xD800 <= code <= 0xDFFF:
            return ch
    return None


def unheld_message(ch: str, wide: bool) -> str:
    """Why the character ``ch`` has no byte in a STRING (``wide`` False) or no WORD in a WSTRING
    (``unheld_character``)."""
    if wide:
        return (
            f"U+{ord(ch):04X} is no character a WSTRING holds: CODESYS's WSTRING is UCS-2, one WORD a character, "
            "U+0000..U+D7FF and U+E000..U+FFFF"
        )
    return (
        f"'{ch}' (U+{ord(ch):04X}) has no byte in CODESYS's STRING, which is Latin-1, one byte a character, "
        "U+0000..U+00FF (the code page of a CoDeSys 2.3 file, cp1251 say, is not modelled)"
    )


def textless_character(text: str) -> str | None:
    """The first character of ``text`` that neither a STRING nor a WSTRING holds (above U+FFFF, or a surrogate):
    any other may be a STRING's, its byte that of the file's code page (a CoDeSys 2.3 course's cp1251 'Пуск')."""
    return unheld_character(text, wide=True)


def textless_message(ch: str) -> str:
    """Why no STRING or WSTRING holds ``ch`` (``textless_character``)."""
    return (
        f"U+{ord(ch):04X} is no character a STRING or WSTRING holds: CODESYS's WSTRING is UCS-2 (U+0000..U+D7FF and "
        "U+E000..U+FFFF), a STRING one byte a character"
    )


def encode_string(value: str, wide: bool = False) -> str:
    quote = '"' if wide else "'"
    out = [quote]
    for ch in value:
        if ch == "$":
            out.append("$$")
        elif ch == quote:
            out.append("$" + quote)
        elif ch == "\n":
            out.append("$N")
        elif ch == "\r":
            out.append("$R")
        elif ch == "\t":
            out.append("$T")
        elif ch == "\f":
            out.append("$P")
        elif ord(ch) < 32 or ord(ch) == 127:
            out.append(f"${ord(ch):04X}" if wide else f"${ord(ch):02X}")
        else:
            out.append(ch)
    out.append(quote)
    return "".join(out)


def _prefix_and_body(text: str) -> tuple[str, str]:
    prefix, body = text.split("#", 1)
    return prefix.upper(), body


def _normalise_ms(value: float) -> int | float:
    rounded = round(value, 6)
    return int(rounded) if rounded == int(rounded) else rounded


def decode_duration(text: str) -> int | float:
    """``T#1h30m`` -> 5_400_000 ms; ``T#-14ms`` -> -14; clock style ``TIME#12:00:00`` (LEX-46) too."""
    return _normalise_ms(float(Fraction(decode_duration_ns(text), _NS_PER_MS)))


def decode_duration_ns(text: str) -> int:
    """``LTIME#1.5us`` -> 1500: a duration in whole nanoseconds, exactly (fractions below 1 ns round, ties to even)."""
    _, body = _prefix_and_body(text)
    sign = -1 if body.startswith("-") else 1
    body = body.lstrip("+-")
    if ":" in body:
        return sign * _clock_ns(body)
    total = sum(Fraction(n.replace("_", "")) * _NS_PER_UNIT[unit.lower()] for n, unit in _UNIT_RE.findall(body))
    return sign * round(total)


def _clock_ns(body: str) -> int:
    parts = body.split(":")
    hours, minutes = int(parts[0]), int(parts[1])
    seconds = Fraction(parts[2]) if len(parts) > 2 else Fraction(0)
    if not (0 <= hours < 24 and 0 <= minutes < 60 and 0 <= seconds < 60):
        raise ValueError("the time of day must lie between 00:00:00 and 23:59:59.999")
    return round(((hours * 60 + minutes) * 60 + seconds) * 1_000_000_000)


def _clock_ms(body: str) -> int:
    return round(Fraction(_clock_ns(body), _NS_PER_MS))


def decode_date(text: str) -> int:
    """``D#1970-01-02`` -> 86_400_000 (ms since 1970-01-01)."""
    _, body = _prefix_and_body(text)
    year, month, day = (int(p) for p in body.split("-"))
    return _ms_since_epoch(_dt.datetime(year, month, day))


def decode_tod(text: str) -> int:
    _, body = _prefix_and_body(text)
    return _clock_ms(body)


def decode_dt(text: str) -> int:
    _, body = _prefix_and_body(text)
    year, month, day, clock = body.split("-", 3)
    return _ms_since_epoch(_dt.datetime(int(year), int(month), int(day))) + _clock_ms(clock)


def _ms_since_epoch(moment: _dt.datetime) -> int:
    delta = moment - _EPOCH
    return (delta.days * 86_400 + delta.seconds) * 1000 + delta.microseconds // 1000


#: Literal prefix -> the type it makes (IEC 61131-3 ed. 3, 6.3.4-6.3.5: the L prefixes make the long types).
_KINDS = {
    **dict.fromkeys(("T", "TIME"), "TIME"),
    **dict.fromkeys(("LT", "LTIME"), "LTIME"),
    **dict.fromkeys(("D", "DATE"), "DATE"),
    **dict.fromkeys(("LD", "LDATE"), "LDATE"),
    **dict.fromkeys(("TOD", "TIME_OF_DAY"), "TIME_OF_DAY"),
    **dict.fromkeys(("LTOD", "LTIME_OF_DAY"), "LTIME_OF_DAY"),
    **dict.fromkeys(("DT", "DATE_AND_TIME"), "DATE_AND_TIME"),
    **dict.fromkeys(("LDT", "LDATE_AND_TIME"), "LDATE_AND_TIME"),
}
_NS_PER_MS = 1_000_000
_NS_PER_UNIT = {"d": 86_400 * 10**9, "h": 3_600 * 10**9, "m": 60 * 10**9, "s": 10**9, "ms": 10**6, "us": 1000, "ns": 1}
#: The prefix each type's literal is written with (``encode_time_literal``).
_WRITTEN = {
    "TIME": "T",
    "LTIME": "LTIME",
    "DATE": "D",
    "LDATE": "LDATE",
    "TIME_OF_DAY": "TOD",
    "LTIME_OF_DAY": "LTOD",
    "DATE_AND_TIME": "DT",
    "LDATE_AND_TIME": "LDT",
}


def literal_type(prefix: str) -> str | None:
    """The type a date/time literal prefix makes (``LTOD`` -> LTIME_OF_DAY), None for any other prefix."""
    return _KINDS.get(prefix.upper())


def decode_time_literal(text: str) -> tuple[str, int | float]:
    """Any of the date/time literal forms -> (canonical type name, value): milliseconds for TIME, DATE,
    TIME_OF_DAY and DATE_AND_TIME, whole nanoseconds for their long forms."""
    kind = _KINDS[text.split("#", 1)[0].upper()]
    short = LONG_TIME_TYPES.get(kind)
    if short == "TIME":
        return kind, decode_duration_ns(text)
    if short == "TIME_OF_DAY":
        return kind, _clock_ns(_prefix_and_body(text)[1])
    if short == "DATE_AND_TIME":
        _, body = _prefix_and_body(text)
        year, month, day, clock = body.split("-", 3)
        return kind, _ms_since_epoch(_dt.datetime(int(year), int(month), int(day))) * _NS_PER_MS + _clock_ns(clock)
    if short == "DATE":
        return kind, decode_date(text) * _NS_PER_MS
    if kind == "TIME":
        return kind, decode_duration(text)
    if kind == "DATE":
        return kind, decode_date(text)
    if kind == "TIME_OF_DAY":
        return kind, decode_tod(text)
    return kind, decode_dt(text)


def _clock_text(ms: int) -> str:
    seconds, millis = divmod(ms, 1000)
    minutes, seconds = divmod(seconds, 60)
    hours, minutes = divmod(minutes, 60)
    text = f"{hours:02d}:{minutes:02d}:{seconds:02d}"
    return text + f".{millis:03d}" if millis else text


def clock_text_ns(ns: int) -> str:
    """Nanoseconds since midnight -> ``12:30:00``, ``12:30:00.000000250`` (the fraction only when there is one)."""
    seconds, nanos = divmod(ns, 1_000_000_000)
    text = _clock_text(seconds * 1000)
    return text + f".{nanos:09d}".rstrip("0") if nanos else text


def date_text(ms: int) -> str:
    """Milliseconds since 1970-01-01 -> ``2024-05-01`` (the day it falls in)."""
    moment = _EPOCH + _dt.timedelta(milliseconds=ms)
    return f"{moment.year:04d}-{moment.month:02d}-{moment.day:02d}"


def encode_time_literal(kind: str, value: int | float) -> str:
    """The literal text of a TimeLit: ``T#1h30m``, ``LTIME#1s250ns``, ``LDT#2024-01-01-12:30:00``."""
    prefix = _WRITTEN[kind] + "#"
    short = LONG_TIME_TYPES.get(kind)
    if short is not None:  # nanoseconds
        ns = int(value)
        if short == "TIME":
            return prefix + encode_duration_ns(ns)
        if short == "TIME_OF_DAY":
            return prefix + clock_text_ns(ns)
        day = ns - ns % NS_PER_DAY
        if short == "DATE":
            return prefix + date_text(day // _NS_PER_MS)
        return prefix + date_text(day // _NS_PER_MS) + "-" + clock_text_ns(ns - day)
    if kind == "TIME":
        return prefix + encode_duration(value)
    if kind == "TIME_OF_DAY":
        return prefix + _clock_text(int(value))
    day_ms = int(value) - int(value) % 86_400_000
    if kind == "DATE":
        return prefix + date_text(day_ms)
    return prefix + date_text(day_ms) + "-" + _clock_text(int(value) - day_ms)


def encode_duration_ns(ns: int) -> str:
    """Nanoseconds -> ``1h30m``, ``-1s500us``, ``0s`` (every non-zero unit from d to ns, largest first)."""
    if ns == 0:
        return "0s"
    rest, parts = abs(ns), []
    for unit, size in _NS_PER_UNIT.items():
        count, rest = divmod(rest, size)
        if count:
            parts.append(f"{count}{unit}")
    return ("-" if ns < 0 else "") + "".join(parts)


def encode_duration(value: int | float) -> str:
    """Milliseconds -> ``1h30m``, ``-500ms``, ``0s``, ``1.5ms`` (largest unit first)."""
    if value == 0:
        return "0s"
    sign = "-" if value < 0 else ""
    rest = abs(value)
    whole = int(rest)
    fraction = _normalise_ms(rest - whole)
    parts = []
    for unit in ("d", "h", "m", "s"):
        count, whole = divmod(whole, int(_MS_PER_UNIT[unit]))
        if count:
            parts.append(f"{count}{unit}")
    if whole or fraction:
        parts.append(f"{_normalise_ms(whole + fraction)}ms")
    return sign + "".join(parts)
