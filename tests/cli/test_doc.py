"""``ladderlab doc`` (issue 28): the printable document of a project as one HTML file or, through the system's
Chromium, a PDF with a page per POU at least, each POU from its own page with its operands."""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pytest

from ladderlab.cli import main
from ladderlab.cli.doc import PRINT_DIR, find_chromium
from tests.ir.diagram_support import blk, fbd_pou, inp, net, out, project

MOTOR = Path(__file__).resolve().parents[2] / "examples" / "motor"
built = pytest.mark.skipif(not (PRINT_DIR / "print.js").is_file(), reason="the print view is not built (make frontend)")


def embedded(html: str) -> dict:
    found = re.search(r'<script id="ladderlab-document" type="application/json">(.*?)</script>', html, re.S)
    assert found is not None
    return json.loads(found.group(1).replace("<\\/", "</"))


@built
def test_html_is_one_file_with_the_view_its_styles_and_the_document(tmp_path: Path, capsys) -> None:
    out = tmp_path / "motor.html"
    assert main(["doc", str(MOTOR), "-o", str(out)]) == 0
    assert capsys.readouterr().out.strip() == f"wrote {out} (Main, Blinker, Scaling)"
    html = out.read_text(encoding="utf-8")
    assert 'src="./print.js"' not in html and 'href="./print.css"' not in html  # nothing to fetch
    assert len(re.findall(r'<script (?:id|type)="', html)) == 2 and "<style>" in html and " src=" not in html
    document = embedded(html)
    assert document["pous"] == ["Main", "Blinker", "Scaling"]
    assert document["project"]["name"] == "motor" and len(document["revision"]) == 16
    assert [s["name"] for s in document["symbols"]["Main"]] == [
        "RunTimer",
        "StartCounter",
        "Blink",
        "MotorRunning",
        "Lamp",
    ]
    assert {e["name"] for e in document["library"]} == {"TON", "CTU", "Blinker", "MUL", "ADD", "GT"}
    # a script element cannot be ended from inside: the data's "</" is written "<\/"
    assert "</script" not in html.split('type="application/json">')[1].split("</script>")[0]


@built
def test_only_the_pous_asked_for(tmp_path: Path, capsys) -> None:
    out = tmp_path / "main.html"
    assert main(["doc", str(MOTOR), "--pou", "scaling", "--pou", "MAIN", "-o", str(out)]) == 0
    assert embedded(out.read_text(encoding="utf-8"))["pous"] == ["Main", "Scaling"]


def test_refusals_are_one_line_with_exit_2(tmp_path: Path, capsys, monkeypatch) -> None:
    assert main(["doc", str(MOTOR), "--pou", "Nope", "-o", str(tmp_path / "x.html")]) == 2
    assert capsys.readouterr().err.strip() == "ladderlab doc: the project has no POU 'Nope'"
    assert main(["doc", str(MOTOR), "-o", str(tmp_path / "x.docx")]) == 2
    assert "must end in .pdf or .html" in capsys.readouterr().err
    monkeypatch.setenv("LADDERLAB_CHROMIUM", str(tmp_path / "no-such-browser"))
    if (PRINT_DIR / "print.js").is_file():
        assert main(["doc", str(MOTOR), "-o", str(tmp_path / "x.pdf")]) == 2
        err = capsys.readouterr().err
        assert err.startswith("ladderlab doc: a PDF needs Chromium, which was not found") and "Traceback" not in err
        assert not (tmp_path / "x.pdf").exists()


@built
@pytest.mark.skipif(find_chromium() is None, reason="Chromium is not installed")
def test_pdf_has_a_page_per_pou_with_the_operands_of_its_diagram(tmp_path: Path, capsys) -> None:
    pypdf = pytest.importorskip("pypdf")
    out = tmp_path / "motor.pdf"
    assert main(["doc", str(MOTOR), "-o", str(out)]) == 0
    texts = [page.extract_text() for page in pypdf.PdfReader(io.BytesIO(out.read_bytes())).pages]
    assert len(texts) >= 4  # the title page, then Main, Blinker and Scaling each from a new page
    starts = {
        h: [i for i, t in enumerate(texts) if t.lstrip().startswith(h)] for h in ("PROGRAM Main", "PROGRAM Scaling")
    }
    assert all(len(pages) == 1 for pages in starts.values()), starts
    main_pages = " ".join(texts[starts["PROGRAM Main"][0] : starts["PROGRAM Main"][0] + 2])
    assert all(name in main_pages for name in ("Start", "Stop", "Motor", "RunTimer", "StartCounter", "Lamp"))
    scaling = texts[starts["PROGRAM Scaling"][0]]
    assert all(name in scaling for name in ("StartCount", "MUL", "ADD", "GT", "Speed", "HighSpeed"))


@built
@pytest.mark.skipif(find_chromium() is None, reason="Chromium is not installed")
def test_page_breaks_never_cut_a_network(tmp_path: Path, capsys) -> None:
    """Issue 28: a POU of more networks than a page holds is printed over several pages, and every network (its
    label, comment and operands, each drawn once; global, so no declarations table lists them) stands on one
    page. FBD networks are drawn in HTML, which a page break could cut (an LD network is one SVG)."""
    pypdf = pytest.importorskip("pypdf")
    # networks of 1 to 6 inputs stacked into an OR, so the page ends fall at different heights
    names = {k: [f"In{k:02d}{b}" for b in "abcdef"[: 1 + k * 5 % 6]] for k in range(1, 21)}
    networks = [
        net(
            f"n{k}",
            [inp(f"i{k}_{i}", name, 0, 60 * i) for i, name in enumerate(operands)]
            + [blk(f"or{k}", "OR", x=160, y=0), out(f"o{k}", f"Out{k:02d}", x=320, y=0)],
            [(f"i{k}_{i}.OUT", f"or{k}.IN{i + 1}") for i in range(len(operands))] + [(f"or{k}.OUT", f"o{k}.IN")],
        ).model_copy(update={"comment": f"Net{k:02d} marker", "label": f"Step{k:02d}"})
        for k, operands in names.items()
    ]
    globals_ = "VAR_GLOBAL " + " ".join(f"{', '.join(n)}, Out{k:02d} : BOOL;" for k, n in names.items()) + " END_VAR"
    source = tmp_path / "tall.json"
    source.write_text(project(fbd_pou("Tall", "", *networks), globals=globals_).model_dump_json(), encoding="utf-8")
    pdf = tmp_path / "tall.pdf"
    assert main(["doc", str(source), "-o", str(pdf)]) == 0
    texts = [page.extract_text() for page in pypdf.PdfReader(io.BytesIO(pdf.read_bytes())).pages]
    pou_pages = [i for i, t in enumerate(texts) if any(f"Net{k:02d} marker" in t for k in names)]
    assert len(pou_pages) >= 3, f"the networks fill {len(pou_pages)} pages: nothing to cut"
    for k, operands in names.items():
        marker = [i for i in pou_pages if f"Net{k:02d} marker" in texts[i]]
        assert len(marker) == 1, f"network {k}'s comment on pages {marker}"
        drawn = {
            name: [i for i in pou_pages if name in texts[i]] for name in [*operands, f"Out{k:02d}", f"Step{k:02d}:"]
        }
        assert all(pages == marker for pages in drawn.values()), f"network {k} cut: {marker} {drawn}"
