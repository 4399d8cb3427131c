"""Printing a project and its cross references in a real browser against a real server (issue 28).

The motor example is printed from the Export bar's "Print project…" (a new tab with the print view, drawn
by the editors' own LD and FBD drawing); Chromium prints that page to PDF, which must have at least a page
per POU plus the title page, each POU starting on its own page with the operand names of its diagram; a
diagram saved as SVG holds its operands and wires, the page saved as HTML has no scripts or screen tools. The
Cross references panel lists the variables, filters them, and a click on a place opens the POU there;
"Find all references" from the LD and FBD context menus and from the ST editor (Shift+F12) shows one
variable's places. The README's picture of a printed page is taken here (docs/print-page.png, when pdftoppm is there).
Every page fails the test on a page error or a console error.
"""

from __future__ import annotations

import io
import itertools
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from .conftest import ARTIFACTS
from .steps import export_menu

expect = pytest.importorskip("playwright.sync_api", reason="playwright is not installed").expect

pytestmark = pytest.mark.browser
pypdf = pytest.importorskip("pypdf", reason="pypdf reads the printed PDF")

DOCS = Path(__file__).resolve().parents[2] / "docs"
#: What each POU's pages must show: its heading, the operands its diagram (or body) draws, its network comments.
PAGES = {
    "PROGRAM Main": ["Start", "Stop", "Motor", "RunTimer", "MotorRunning", "StartCounter", "ResetCount", "Lamp"]
    + ["Start/stop with seal-in", "MotorRunning after 5 s of Motor", "Blink the lamp while the motor runs"],
    "FUNCTION_BLOCK Blinker": ["Enable", "Period", "Half"],
    "PROGRAM Scaling": ["StartCount", "MUL", "ADD", "GT", "Speed", "HighSpeed"],
}


def watch_errors(page) -> list[str]:
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(f"page error: {error}"))
    page.on("console", lambda message: errors.append(message.text) if message.type == "error" else None)
    return errors


def orthogonal(path: str) -> bool:
    """Is the SVG path ``M x y L x y ...`` made of horizontal and vertical segments only (no curves)?"""
    number = r"-?\d+(?:\.\d+)?"
    if re.fullmatch(rf"\s*M\s*{number}[ ,]+{number}(?:\s*L\s*{number}[ ,]+{number})+\s*", path) is None:
        return False
    values = [float(v) for v in re.findall(number, path)]
    points = list(zip(values[::2], values[1::2]))
    return all(abs(a[0] - b[0]) < 0.01 or abs(a[1] - b[1]) < 0.01 for a, b in itertools.pairwise(points))


def open_pou(page, name: str) -> None:
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile(f"^{name}")).click()


def test_print_a_project_to_pdf_and_find_its_cross_references(page, server: str) -> None:
    errors = watch_errors(page)
    page.goto(server)  # the server's workspace starts with the motor example
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^motor")).click()
    open_pou(page, "Main")
    page.locator("svg.ld-network").nth(3).wait_for()

    # Print the whole project: the print view opens in a new tab.
    with page.context.expect_page() as opened:
        export_menu(page).get_by_role("button", name="Print project…").click()
    printed = opened.value
    errors += watch_errors(printed)
    printed.get_by_role("region", name="Title page").wait_for()
    printed.locator(".print-ld .print-network svg").first.wait_for()
    printed.locator(".print-fbd .react-flow__edge").first.wait_for()  # wires are drawn once nodes are measured
    assert printed.get_by_test_id("revision").inner_text() != ""
    wires = printed.locator(".print-fbd .react-flow__edge path.react-flow__edge-path")
    paths = [wires.nth(i).get_attribute("d") for i in range(wires.count())]
    assert len(paths) >= 6 and all(orthogonal(d) for d in paths), paths  # Scaling's wires, routed as the editor does
    pdf = printed.pdf(format="A4", landscape=True, print_background=True)
    (ARTIFACTS / "motor.pdf").write_bytes(pdf)
    reader = pypdf.PdfReader(io.BytesIO(pdf))
    texts = [p.extract_text() for p in reader.pages]
    assert len(texts) >= 1 + len(PAGES), f"{len(texts)} pages"
    assert "motor" in texts[0] and "Revision" in texts[0] and re.search(r"Date\s*\d{4}-\d{2}-\d{2}", texts[0])
    headings = [*PAGES, "Cross-reference list"]
    for heading, operands in PAGES.items():
        starts = [i for i, t in enumerate(texts) if t.lstrip().startswith(heading)]
        assert len(starts) == 1, f"{heading} must start exactly one page: {starts}"
        pou_pages = [texts[starts[0]]]
        for text in texts[starts[0] + 1 :]:
            if any(text.lstrip().startswith(h) for h in headings):
                break
            pou_pages.append(text)
        missing = [o for o in operands if not any(o in t for t in pou_pages)]
        assert missing == [], f"{heading}: {missing} not printed"
        assert not any("???" in t for t in pou_pages), f"{heading}: an empty pin prints the editor's ???"
    assert any("Cross-reference list" in t for t in texts[-2:])
    _readme_picture(pdf)

    # A diagram as SVG, the page as static HTML.
    with printed.expect_download() as download:
        printed.get_by_role("region", name="PROGRAM Scaling").get_by_role("button", name="Save diagram as SVG").click()
    svg = Path(download.value.path()).read_text(encoding="utf-8")
    assert download.value.suggested_filename == "Scaling.svg" and svg.startswith("<svg xmlns=")
    assert all(name in svg for name in ("StartCount", "HighSpeed", "react-flow__edge"))
    with printed.expect_download() as download:
        printed.get_by_role("button", name="Save as HTML").click()
    html = Path(download.value.path()).read_text(encoding="utf-8")
    assert download.value.suggested_filename == "motor.html" and "<script" not in html
    assert "PROGRAM Main" in html and "Cross-reference list" in html and "Print…" not in html

    # A selection: the POU check boxes reload the view with the POUs left.
    printed.get_by_role("group", name="POUs").get_by_label("Main").uncheck()
    printed.get_by_role("region", name="PROGRAM Main").wait_for(state="detached")
    assert printed.locator(".print-pou[data-pou]").count() == 2
    printed.close()

    # One POU: "Print Main…" prints the open POU alone (and the cross references of its variables).
    with page.context.expect_page() as opened:
        export_menu(page).get_by_role("button", name="Print Main…").click()
    alone = opened.value
    errors += watch_errors(alone)
    alone.get_by_role("region", name="PROGRAM Main").wait_for()
    expect(alone.locator(".print-pou[data-pou]")).to_have_count(1)
    alone.close()

    # The Cross references panel: filter, open a place.
    page.get_by_role("tab", name="Cross references").click()
    panel = page.get_by_role("table", name="Cross references")
    page.get_by_label("Filter cross references").fill("%IX0.1")
    panel.get_by_role("button", name="Stop (global)").wait_for()
    assert panel.locator("tr.xref-entry").count() == 1
    page.get_by_label("Filter cross references").fill("HighSpeed")
    panel.get_by_role("button", name="Scaling, network 1 (HighSpeed)").click()
    page.get_by_role("tab", name="Scaling").wait_for()

    # Find all references from the LD editor's context menu.
    open_pou(page, "Main")
    page.locator('[data-id="motor_on"]').first.click(button="right")
    page.get_by_role("menuitem", name="Find all references of Motor").click()
    expect(page.get_by_label("Filter cross references")).to_have_value("Motor")
    panel.get_by_role("button", name="Main, network 1 (Motor)").first.wait_for()
    panel.get_by_role("button", name="Main, network 2 (Motor)").wait_for()

    # ... from the FBD editor's context menu on an input node: read in Scaling, written by Main's counter
    # (CV => StartCount: the place names the CTU box by its instance).
    open_pou(page, "Scaling")
    page.locator('.fbd-node[data-node="count"]').click(button="right")
    page.get_by_role("menuitem", name="Find all references of StartCount").click()
    expect(page.get_by_label("Filter cross references")).to_have_value("StartCount")
    panel.get_by_role("button", name="Scaling, network 1 (StartCount)").wait_for()
    written = panel.get_by_role("row", name="StartCount write", exact=True)
    expect(written.get_by_role("button")).to_have_text("Main, network 3 (StartCounter)")

    # ... and with Shift+F12 on a variable in the ST editor.
    open_pou(page, "Blinker")
    body = page.get_by_label("Blinker body")
    body.wait_for()
    body.click()
    page.keyboard.press("Control+Home")
    for _ in range(6):  # line 7: IF Half.Q THEN - the cursor on "Half"
        page.keyboard.press("ArrowDown")
    page.keyboard.press("End")
    page.keyboard.press("Home")
    for _ in range(5):
        page.keyboard.press("ArrowRight")
    page.keyboard.press("Shift+F12")
    expect(page.get_by_label("Filter cross references")).to_have_value("Half")
    panel.get_by_role("button", name="Blinker, line 7").wait_for()
    page.screenshot(path=str(ARTIFACTS / "xref-panel.png"))
    assert errors == []


def _readme_picture(pdf: bytes) -> None:
    """docs/print-page.png: the printed LD page of the example, for the README (needs poppler's pdftoppm)."""
    if shutil.which("pdftoppm") is None:
        return
    source = ARTIFACTS / "motor.pdf"
    source.write_bytes(pdf)
    subprocess.run(
        ["pdftoppm", "-png", "-r", "70", "-f", "2", "-l", "2", "-singlefile", str(source), str(DOCS / "print-page")],
        check=True,
        timeout=60,
    )
