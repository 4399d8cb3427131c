"""Issue 19 item 5: every diagnostic code is declared once (model/codes.py) and documented (docs/diagnostics.md).

The sources are scanned for codes - string literals shaped like one (``ST-TYPE-MISMATCH``), any constant passed
as ``code=``, and codes built at run time (``f"{lang}-MISSING-PIN"``) - and each must be catalogued. Whether
every catalogued code is produced by some test is checked at the end of a whole run (tests/diagnostic_codes.py).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path
from typing import get_args

from ladderlab.cli.shared import DIAGNOSTICS_DOC, doc_entries
from ladderlab.model.codes import CODES, DIAGRAM_LANGUAGES
from ladderlab.model.diagnostics import Diagnostic
from ladderlab.model.monitor import ErrorCode
from tests.diagnostic_codes import produced_codes
from tests.support import ROOT

BACKEND = ROOT / "backend" / "ladderlab"
CODE_SHAPE = re.compile(r"[A-Z][A-Z0-9]*(?:-[A-Z][A-Z0-9]*)+")
#: Spec item ids (FUN-81, SFB-10) end in a number and are not codes; neither are websocket close codes (1008) and
#: the websocket protocol's refusal codes (bad_path ...: model/monitor.py, shown with the request they refuse).
PROTOCOL_CODES = frozenset(get_args(ErrorCode))


def literal_codes(path: Path) -> set[str]:
    """String constants shaped like a code, and any constant given as ``code=``."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and CODE_SHAPE.fullmatch(node.value):
            found.add(node.value)
        value = node.value if isinstance(node, ast.keyword) and node.arg == "code" else None
        if isinstance(value, ast.Constant) and isinstance(value.value, str) and value.value not in PROTOCOL_CODES:
            found.add(value.value)
    return found


def built_codes(path: Path) -> set[str]:
    """Codes assembled from a prefix at run time, as patterns: ``f"{ops.lang}-MISSING-PIN"`` -> ``*-MISSING-PIN``."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.JoinedStr):
            text = "".join(v.value if isinstance(v, ast.Constant) else "*" for v in node.values)
            if re.fullmatch(r"\*(?:-[A-Z][A-Z0-9]*)+", text):
                found.add(text)
    return found


def sources() -> list[Path]:
    """The backend's modules but the catalogue itself."""
    return [p for p in sorted(BACKEND.rglob("*.py")) if p != BACKEND / "model" / "codes.py"]


def test_every_code_in_the_sources_is_catalogued():
    used = {code: path for path in sources() for code in literal_codes(path)}
    missing = sorted(f"{code} ({path.relative_to(ROOT)})" for code, path in used.items() if code not in CODES)
    assert missing == [], "add these to backend/ladderlab/model/codes.py and docs/diagnostics.md"


def test_every_code_built_at_run_time_is_catalogued_for_each_diagram_language():
    patterns = {pattern for path in sources() for pattern in built_codes(path)}
    assert patterns, "the scan finds the diagram codes built from the language prefix"
    missing = sorted(
        f"{lang}{pattern[1:]}"
        for pattern in patterns
        for lang in DIAGRAM_LANGUAGES
        if f"{lang}{pattern[1:]}" not in CODES
    )
    assert missing == []


def test_the_scan_tells_codes_from_other_strings(tmp_path):
    sample = tmp_path / "sample.py"
    sample.write_text(
        'report("ST-TYPE-MISMATCH", "x")\nSPEC = "FUN-81"\nDiagnostic(code="EXISTS", message="m")\n'
        'ops.report(at, f"{ops.lang}-NO-INSTANCE", "m")\nname = f"{a}-{b}"\n',
        encoding="utf-8",
    )
    assert literal_codes(sample) == {"ST-TYPE-MISMATCH", "EXISTS"}
    assert built_codes(sample) == {"*-NO-INSTANCE"}


def test_catalogue_entries_are_well_formed():
    for code, entry in CODES.items():
        assert entry.code == code
        assert CODE_SHAPE.fullmatch(code) or (code.isalpha() and code.isupper()), code
        assert entry.summary[0].isupper() and entry.summary.endswith("."), code
        assert len(entry.summary) <= 100, f"{code}: the summary is one short line"


def test_a_diagnostic_records_its_code_in_this_run():
    """What the end-of-run check counts: making a Diagnostic notes its code (in every process of the run)."""
    Diagnostic(code="ST-NO-EFFECT", message="this statement does nothing")
    assert "ST-NO-EFFECT" in produced_codes()


def test_every_code_has_an_entry_in_the_docs_and_every_entry_a_code():
    """docs/diagnostics.md: a section per code (``### CODE``) with an example that triggers it and the fix."""
    entries = doc_entries((ROOT / DIAGNOSTICS_DOC).read_text(encoding="utf-8"))
    assert sorted(set(CODES) - set(entries)) == [], "document these codes"
    assert sorted(set(entries) - set(CODES)) == [], "these sections name no catalogued code"
    assert all(entry["example"].strip() and entry["fix"] for entry in entries.values())
