"""``ladderlab doc PROJECT [--pou NAME]... -o FILE.pdf|.html``: the project's printable document (issue 28).

The document is drawn by the browser's print view (frontend/src/print, built into the server's static
folder as one script and one style sheet): the same layout and SVG drawing as the editors, never a second
renderer. This command puts the view, its styles and the document's data (simulation/document.py) into
one HTML file - ``.html`` is that file, which any browser opens offline - and for ``.pdf`` has the system's
Chromium print it (headless ``--print-to-pdf``, the browser the project's tests already drive). Chromium is
found as the browser tests find it (``chromium``, ``chromium-browser``, ``google-chrome`` on PATH, or
``$LADDERLAB_CHROMIUM``); without it a PDF cannot be made and the command says so (exit 2).
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from ..server import STATIC_DIR
from ..storage import load_project_path
from ..storage.atomic import write_atomic

PRINT_DIR = STATIC_DIR / "print"
CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
#: Virtual time Chromium gives the page to draw before it prints (the FBD canvases measure their nodes first).
RENDER_BUDGET_MS = 20_000
PRINT_TIMEOUT_S = 180


class DocError(Exception):
    """What the user must fix, in one line (exit 2)."""


def add_doc_command(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    doc = sub.add_parser("doc", help="print a project (or some POUs) as a PDF or HTML document")
    doc.add_argument("project", type=Path, help="project folder, project .json file or .st file")
    doc.add_argument("--pou", action="append", default=[], metavar="NAME", help="only this POU (repeatable)")
    doc.add_argument("-o", "--output", type=Path, required=True, metavar="FILE", help="FILE.pdf or FILE.html")
    doc.set_defaults(func=run_doc_command)


def run_doc_command(args: argparse.Namespace) -> int:
    from ..simulation.document import UnknownPou, print_document

    suffix = args.output.suffix.lower()
    if suffix not in (".pdf", ".html", ".htm"):
        print(f"ladderlab doc: {args.output}: the output must end in .pdf or .html", file=sys.stderr)
        return 2
    try:
        project = load_project_path(args.project)
        document = print_document(project, args.pou or None)
        html = document_html(document.model_dump_json(by_alias=True))
        if suffix == ".pdf":
            write_atomic(args.output, print_pdf(html))
        else:
            write_atomic(args.output, html.encode("utf-8"))
    except (DocError, UnknownPou) as error:
        print(f"ladderlab doc: {error}", file=sys.stderr)
        return 2
    print(f"wrote {args.output} ({', '.join(document.pous)})")
    return 0


def document_html(data: str) -> str:
    """The print view with its script, styles and ``data`` (the document as JSON) in one HTML file."""
    try:
        page = (PRINT_DIR / "print.html").read_text(encoding="utf-8")
        script = (PRINT_DIR / "print.js").read_text(encoding="utf-8")
        styles = (PRINT_DIR / "print.css").read_text(encoding="utf-8")
    except FileNotFoundError as error:
        raise DocError(f"the print view is not built ({error.filename} is missing): run 'make frontend'") from error
    head_end = page.index("</head>")
    head = page[:head_end]
    head = head.replace('<script type="module" crossorigin src="./print.js"></script>', "")
    head = head.replace('<link rel="stylesheet" crossorigin href="./print.css">', "")
    inline = (
        f"<style>\n{styles}\n</style>\n"
        f'<script id="ladderlab-document" type="application/json">{_in_script(data)}</script>\n'
        f'<script type="module">\n{_in_script(script)}\n</script>\n'
    )
    return head + inline + page[head_end:]


def _in_script(text: str) -> str:
    """``text`` safe inside a script element (nothing in it can close the element)."""
    return text.replace("</", "<\\/")


def find_chromium() -> str | None:
    configured = os.environ.get("LADDERLAB_CHROMIUM")
    if configured:
        return configured if Path(configured).is_file() else shutil.which(configured)
    return next((found for name in CHROMIUM_NAMES if (found := shutil.which(name))), None)


def print_pdf(html: str) -> bytes:
    """``html`` printed to PDF by the system's Chromium (headless)."""
    chromium = find_chromium()
    if chromium is None:
        raise DocError(
            "a PDF needs Chromium, which was not found (looked for "
            + ", ".join(CHROMIUM_NAMES)
            + " on PATH and $LADDERLAB_CHROMIUM); install it (Debian: apt-get install chromium) "
            "or write .html and print that from a browser"
        )
    with tempfile.TemporaryDirectory(prefix="ladderlab-doc-") as folder:
        page = Path(folder) / "document.html"
        pdf = Path(folder) / "document.pdf"
        page.write_text(html, encoding="utf-8")
        command = [
            chromium,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--no-first-run",
            f"--user-data-dir={Path(folder) / 'profile'}",
            "--no-pdf-header-footer",
            f"--virtual-time-budget={RENDER_BUDGET_MS}",
            f"--print-to-pdf={pdf}",
            page.as_uri(),
        ]
        try:
            done = subprocess.run(command, capture_output=True, timeout=PRINT_TIMEOUT_S, check=False)
        except subprocess.TimeoutExpired as error:
            raise DocError(f"Chromium did not print the document within {PRINT_TIMEOUT_S} s") from error
        if not pdf.is_file() or pdf.stat().st_size == 0:
            reason = done.stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or ["no output"]
            raise DocError(f"Chromium could not print the document (exit {done.returncode}): {reason[0]}")
        return pdf.read_bytes()
