"""The IEC vocabulary the browser reads (``shared_schema/iec.json``, written by ``make schema``).

One source for every list of IEC words and forms the frontend needs - elementary types, generic families,
implicit widenings, standard functions and function blocks with their pins, keywords, literal forms and the
text of values - so the declarations table, the FBD wire check, the ST highlighter and completion and the
online values cannot disagree with the checker (issue 19 item 2, issue 22 item 3). It is built here, in the
ST front end, because the keywords and literal forms are the grammar's own.

``value_texts`` are test vectors, not rules: the browser formats monitored values itself (it gets numbers), and
its test checks that it writes each of these inputs as the engine's TO_STRING does (``iec.value_text``).
"""

from __future__ import annotations

from typing import Any

from ..iec import stdlib
from ..iec.elementary import ALIASES, ELEMENTARY, GENERIC, STRING_TYPES
from ..iec.literals import LITERAL_FORMS
from ..iec.value_text import format_value
from ..iec.values import f32
from ..model.fbd import EXECUTED_ELEMENTS
from . import types as t
from .libraries import library_catalogue
from .parser import SFC_WORDS, TEST_KEYWORDS, grammar_keywords, literal_patterns
from .testfile import SIGNATURES

#: Values the browser must write exactly as the engine does: (type, value in the value model).
VALUE_SAMPLES: list[tuple[str, Any]] = [
    ("BOOL", True),
    ("BOOL", False),
    ("INT", -32768),
    ("TIME", 0),
    ("TIME", 1),
    ("TIME", 999),
    ("TIME", 1000),
    ("TIME", 5_400_000),
    ("TIME", 90_061_001),
    ("TIME", -1500),
    ("TIME", 2_147_483_647),
    ("TIME", -2_147_483_648),
    ("TIME_OF_DAY", 0),
    ("TIME_OF_DAY", 41_932_350),
    ("TIME_OF_DAY", 86_399_999),
    ("TIME_OF_DAY", 45_296_100),
    ("DATE", 0),
    ("DATE", 1_056_153_600_000),
    ("DATE_AND_TIME", 1_056_195_532_350),
    ("DATE_AND_TIME", 253_402_300_799_999),
    ("REAL", f32(50.4)),
    ("REAL", f32(0.1)),
    ("REAL", f32(1e20)),
    ("REAL", f32(16_777_217.0)),
    ("REAL", f32(-2.5e-6)),
    ("LREAL", 0.1),
    ("LREAL", 1e-7),
    ("LREAL", 123456789.125),
    ("LTIME", 0),
    ("LTIME", 1500),
    ("LTIME", -5_400_000_000_001),
    ("LTIME", 90_061_001_002_003),
    ("LTIME_OF_DAY", 45_000_000_000_250),
    ("LTIME_OF_DAY", 86_399_999_999_999),
    ("LDATE", 1_704_067_200_000_000_000),
    ("LDATE_AND_TIME", 1_704_112_200_000_000_000),
    ("LDATE_AND_TIME", 1_056_195_532_350_000_000),
]


def _order(names: frozenset[str]) -> list[str]:
    """Members of a family in the order of the elementary table (stable, and how people list them)."""
    return [name for name in ELEMENTARY if name in names]


def _pin(pin: stdlib.Pin) -> dict[str, Any]:
    return {"name": pin.name, "type": pin.type, "generic": pin.generic}


def _widenings() -> dict[str, list[str]]:
    """Elementary type -> the types it converts to implicitly without loss (the checker's ``assignable``)."""
    out: dict[str, list[str]] = {}
    for source in ELEMENTARY:
        targets = [
            target for target in ELEMENTARY if t.assignable(t.Elementary(target), t.Elementary(source)) == "widen"
        ]
        if targets:
            out[source] = targets
    return out


def vocabulary() -> dict[str, Any]:
    functions = [f for f in stdlib.FUNCTIONS.values() if f.group != "conversion" or f.name == "TRUNC"]
    patterns = literal_patterns()
    return {
        "elementary": [
            {"name": e.name, "category": e.category, "bits": e.bits, "signed": e.signed} for e in ELEMENTARY.values()
        ],
        "strings": list(STRING_TYPES),
        "aliases": dict(ALIASES),
        # ANY_STRING is not in GENERIC: the checker tells strings by their own type (st/types.py in_family)
        "generic": {
            **{family: _order(members) for family, members in GENERIC.items()},
            "ANY_STRING": list(STRING_TYPES),
        },
        "widening": _widenings(),
        "conversions": {
            "pattern": "{from}_TO_{to}",
            "types": [*ELEMENTARY, *ALIASES],
            "description": "every elementary type converts to every other one with a function named so (FUN-10)",
        },
        "functions": [
            {
                "name": f.name,
                "group": f.group,
                "inputs": [_pin(p) for p in f.inputs],
                "result": f.result,
                "extensible": f.extensible,
                "description": f.description,
            }
            for f in functions
        ],
        "function_blocks": [
            {
                "name": fb.name,
                "inputs": [_pin(p) for p in fb.inputs],
                "outputs": [_pin(p) for p in fb.outputs],
                "description": fb.description,
            }
            for fb in stdlib.FUNCTION_BLOCKS.values()
        ],
        "libraries": library_catalogue(),
        "cfc_executed_elements": list(EXECUTED_ELEMENTS),
        "keywords": sorted(grammar_keywords() - TEST_KEYWORDS),
        "sfc_words": sorted(SFC_WORDS),
        "test_keywords": sorted(TEST_KEYWORDS),
        "test_verbs": [{"name": verb, "signature": signature} for verb, signature in SIGNATURES.items()],
        "literals": [
            {"name": form.name, "prefixes": list(form.prefixes), "rule": form.rule, "examples": list(form.examples)}
            for form in LITERAL_FORMS
        ],
        "literal_patterns": patterns,
        "value_texts": [
            {"type": type_name, "value": value, "text": format_value(value, type_name)}
            for type_name, value in VALUE_SAMPLES
        ],
    }
