"""What the browser is built from, written by ``make schema`` (``python -m ladderlab.cli.shared``).

``shared_schema/`` holds the JSON Schemas of the project files and the websocket messages, the server's OpenAPI
document (the browser's API client is generated from it), the IEC vocabulary (``st/vocabulary.py``) and the
diagnostics catalogue joined with its entries in docs/diagnostics.md; the catalogue's table at the top of that
page is written here too. ``frontend/scripts/gen-types.mjs`` turns them into ``frontend/src/generated/``. A test
fails when any of them is stale (tests/foundation/test_model.py).
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import tempfile
from pathlib import Path
from typing import Any

from ..model.codes import AREAS, CODES
from ..model.schema import schema_texts
from ..st.vocabulary import vocabulary

SCHEMA_DIR = "shared_schema"
DIAGNOSTICS_DOC = "docs/diagnostics.md"
_TABLE_START = "<!-- catalogue: written by `make schema` from backend/ladderlab/model/codes.py -->"
_TABLE_END = "<!-- end of catalogue -->"
_SECTION = re.compile(r"^### (.+)$", re.MULTILINE)
_EXAMPLE = re.compile(r"^Example:\n\n```(\w*)\n(.*?)\n```\n(.*?)(?=^Fix:)", re.MULTILINE | re.DOTALL)
_FIX = re.compile(r"^Fix: (.*?)(?:\n\n|\Z)", re.MULTILINE | re.DOTALL)


def _json(data: Any) -> str:
    return json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def anchor(heading: str) -> str:
    """The id a Markdown renderer (GitHub's) gives a heading: ``LD-MISSING-PIN, FBD-MISSING-PIN`` ->
    ``ld-missing-pin-fbd-missing-pin``."""
    return re.sub(r"[^a-z0-9 -]", "", heading.lower()).replace(" ", "-")


def doc_entries(text: str) -> dict[str, dict[str, str]]:
    """Code -> its entry in docs/diagnostics.md: the example (language, text, note after it), the fix, the anchor.

    A section is ``### CODE`` (or ``### LD-X, FBD-X`` for one entry of several codes), then ``Example:`` and a
    fenced block, an optional note, and a ``Fix:`` paragraph; ValueError names a section without them."""
    entries: dict[str, dict[str, str]] = {}
    sections = list(_SECTION.finditer(text))
    for i, section in enumerate(sections):
        end = sections[i + 1].start() if i + 1 < len(sections) else len(text)
        body = text[section.end() : end].split("\n## ")[0]
        example, fix = _EXAMPLE.search(body), _FIX.search(body)
        if example is None or fix is None:
            raise ValueError(
                f"{DIAGNOSTICS_DOC}: '### {section.group(1)}' needs 'Example:' with a code block and 'Fix:'"
            )
        entry = {
            "anchor": anchor(section.group(1)),
            "example_language": example.group(1),
            "example": example.group(2),
            "example_note": " ".join(example.group(3).split()),
            "fix": " ".join(fix.group(1).split()),
        }
        for code in (c.strip() for c in section.group(1).split(",")):
            if code in entries:
                raise ValueError(f"{DIAGNOSTICS_DOC}: {code} has two sections")
            entries[code] = entry
    return entries


def catalogue_table(entries: dict[str, dict[str, str]]) -> str:
    rows = ["| Code | Severity | Summary |", "| --- | --- | --- |"]
    for area in AREAS:
        for code in (c for c in CODES.values() if c.area == area):
            link = f"[{code.code}](#{entries[code.code]['anchor']})" if code.code in entries else code.code
            rows.append(f"| {link} | {code.severity} | {code.summary} |")
    return "\n".join(rows)


def with_catalogue(doc: str) -> str:
    """docs/diagnostics.md with its catalogue table written from model/codes.py."""
    start, end = doc.index(_TABLE_START) + len(_TABLE_START), doc.index(_TABLE_END)
    return doc[:start] + "\n" + catalogue_table(doc_entries(doc)) + "\n" + doc[end:]


def diagnostics(doc: str) -> dict[str, Any]:
    """``shared_schema/diagnostics.json``: each code's severity, summary and area with its documented entry."""
    entries = doc_entries(doc)
    return {
        "doc": DIAGNOSTICS_DOC,
        "areas": AREAS,
        "codes": {
            code.code: {
                "severity": code.severity,
                "summary": code.summary,
                "area": code.area,
                **entries.get(code.code, {}),
            }
            for code in CODES.values()
        },
    }


def openapi() -> dict[str, Any]:
    """The server's OpenAPI document (the app is assembled, never started)."""
    from ..server.app import create_app
    from ..storage import Workspace

    with tempfile.TemporaryDirectory() as folder:
        return create_app(Workspace(Path(folder))).openapi()


def shared_texts(root: Path) -> dict[str, str]:
    """Path relative to the repository ``root`` -> the text that belongs there."""
    doc = (root / DIAGNOSTICS_DOC).read_text(encoding="utf-8")
    texts = {f"{SCHEMA_DIR}/{name}": text for name, text in schema_texts().items()}
    texts[f"{SCHEMA_DIR}/openapi.json"] = _json(openapi())
    texts[f"{SCHEMA_DIR}/iec.json"] = _json(vocabulary())
    texts[f"{SCHEMA_DIR}/diagnostics.json"] = _json(diagnostics(doc))
    texts[DIAGNOSTICS_DOC] = with_catalogue(doc)
    return texts


def stale(root: Path) -> list[str]:
    """The shared files that differ from what ``make schema`` would write."""
    return [
        rel
        for rel, text in shared_texts(root).items()
        if not (root / rel).is_file() or (root / rel).read_text(encoding="utf-8") != text
    ]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m ladderlab.cli.shared", description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?", type=Path, default=Path("."), help="the repository (default: here)")
    parser.add_argument("--check", action="store_true", help="exit 1 when a file is stale instead of writing")
    args = parser.parse_args(argv)
    if args.check:
        found = stale(args.root)
        for rel in found:
            print(f"stale: {rel} (run `make schema`)", file=sys.stderr)
        return 1 if found else 0
    for rel, text in shared_texts(args.root).items():
        path = args.root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        if not path.is_file() or path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")
            print(f"wrote {rel}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
