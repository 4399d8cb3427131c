"""Vendor compatibility libraries: TwinCAT's Tc2_Math and Tc2_Utilities (issue 25: code brought from TwinCAT).

Expected values come from Beckhoff's documentation (the F_BA_RoundLREAL table of Tc3_BA2, which rounds through
LREAL_TO_FMTSTR; the special strings of LREAL_TO_FMTSTR), IEEE 754 arithmetic, and Python's ``decimal`` module as
an exact reference for the digits of a binary LREAL - never from running the library.
"""

from __future__ import annotations

import json
import math
from decimal import ROUND_DOWN, ROUND_HALF_UP, Decimal, localcontext
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.cli import main
from ladderlab.engine.simulation import Simulation
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.project import export_project_st
from ladderlab.model import Project
from ladderlab.simulation.build import build_project
from ladderlab.simulation.library import user_entries
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import load_project_path
from ladderlab.storage.project_folder import project_files
from tests.ir.diagram_support import box, contact, ld_pou, rung

LIBRARIES = ["Tc2_Math", "Tc2_Utilities"]


def _project(source: str, libraries: list[str]) -> Project:
    project, diagnostics = source_to_project(source, "p")
    assert project is not None and not diagnostics
    return project.model_copy(update={"libraries": libraries})


def _run(body: str, declarations: str, libraries: list[str] = LIBRARIES) -> Simulation:
    source = f"PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n"
    build = build_project(_project(source, libraries))
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    sim = build.simulation()
    sim.cycle(1)
    return sim


def _value(expression: str, type_name: str = "LREAL") -> object:
    return _run(f"r := {expression};", f"r : {type_name};").read("Main.r")


@pytest.mark.parametrize(
    ("expression", "expected"),
    [
        ("LTRUNC(2.8)", 2.0),
        ("LTRUNC(-2.8)", -2.0),
        ("LTRUNC(5.0)", 5.0),
        ("LTRUNC(1.5E300)", 1.5e300),  # beyond every integer type: already an integer, unchanged
        ("LTRUNC(9.3E18)", 9.3e18),
        ("LMOD(7.0, 3.5)", 0.0),
        ("MODABS(720.0, 360.0)", 0.0),
        ("MODABS(-360.0, 360.0)", 0.0),  # never the range's bound
        ("FRAC(5.0)", 0.0),
    ],
)
def test_tc2_math_exact_results(expression: str, expected: float) -> None:
    assert _value(expression) == expected


@pytest.mark.parametrize(
    ("expression", "expected"),
    [
        ("LMOD(400.56, 360.0)", 40.56),  # the sign of the dividend
        ("LMOD(-400.56, 360.0)", -40.56),
        ("LMOD(400.56, -360.0)", 40.56),
        ("MODABS(400.56, 360.0)", 40.56),
        ("MODABS(-400.56, 360.0)", 319.44),  # wrapped into [0, 360)
        ("MODABS(-400.56, -360.0)", 319.44),  # the modulo's magnitude
        ("FRAC(2.8)", 0.8),
        ("FRAC(-2.8)", -0.8),  # the sign of the input
    ],
)
def test_tc2_math_results_within_the_rounding_of_an_lreal(expression: str, expected: float) -> None:
    assert _value(expression) == pytest.approx(expected, abs=1e-9)


def test_ltrunc_keeps_the_sign_of_a_negative_fraction_and_by_zero_gives_nan() -> None:
    sim = _run(
        "t := LTRUNC(-0.9); m := LMOD(1.5, zero); a := MODABS(1.5, zero); f := FRAC(1.0 / zero);",
        "t : LREAL; m : LREAL; a : LREAL; f : LREAL; zero : LREAL;",
    )
    assert sim.read("Main.t") == 0.0 and math.copysign(1.0, sim.read("Main.t")) == -1.0
    assert all(math.isnan(sim.read(f"Main.{name}")) for name in "maf")  # a NaN, not a trap


# Beckhoff's table for F_BA_RoundLREAL, which rounds through LREAL_TO_FMTSTR (Tc3_BA2 documentation).
BECKHOFF_ROUNDING = ["12346", "12346.0", "12345.99", "12345.988", "12345.9877", "12345.98765"]


@pytest.mark.parametrize("precision", range(6))
def test_lreal_to_fmtstr_rounds_as_beckhoffs_table(precision: int) -> None:
    assert _value(f"LREAL_TO_FMTSTR(12345.987654321, {precision}, TRUE)", "STRING") == BECKHOFF_ROUNDING[precision]
    assert _value(f"LREAL_TO_FMTSTR(-12345.987654321, {precision}, TRUE)", "STRING") == (
        "-" + BECKHOFF_ROUNDING[precision]
    )


@pytest.mark.parametrize(
    ("arguments", "expected"),
    [
        ("0.0, 0, TRUE", "0"),  # "if in = 0 and iPrecision = 0 then string '0' is returned"
        ("123.456, 2, FALSE", "123.45"),  # without bRound the digits are cut
        ("2.5, 0, TRUE", "3"),  # half away from zero
        ("-2.5, 0, TRUE", "-3"),
        ("0.996, 2, TRUE", "1.00"),  # the carry reaches the whole digits
        ("1.5, -3, TRUE", "2"),  # a negative precision is none
        ("1.5, 100, FALSE", "1.500000000000000"),  # at most 15 decimals
        ("9007199254740993.0, 0, TRUE", "9007199254740992"),  # the LREAL nearest the literal
        ("1.0 / zero, 2, TRUE", "#INF"),
        ("-1.0 / zero, 2, TRUE", "-#INF"),
        ("zero / zero, 2, TRUE", "#QNAN"),
        ("-zero, 2, TRUE", "0.00"),  # the sign only for negative values
        ("1.0E20, 0, TRUE", "#OVF"),
    ],
)
def test_lreal_to_fmtstr_cases_of_the_documentation(arguments: str, expected: str) -> None:
    sim = _run(f"s := LREAL_TO_FMTSTR({arguments});", "s : STRING; zero : LREAL;")
    assert sim.read("Main.s") == expected


def _exact(x: float, precision: int, rounding: bool) -> str:
    """The independent reference: the exact decimal value of the binary LREAL, cut or rounded half up."""
    with localcontext() as context:
        context.prec = 400
        digits = (
            Decimal(x).copy_abs().quantize(Decimal(1).scaleb(-precision), ROUND_HALF_UP if rounding else ROUND_DOWN)
        )
    return ("-" if x < 0 else "") + f"{digits:f}"


@pytest.fixture(scope="module")
def formatter() -> Simulation:
    build = build_project(
        _project(
            "PROGRAM Main\nVAR x : LREAL; p : INT; r : BOOL; s : STRING; END_VAR\n"
            "s := LREAL_TO_FMTSTR(x, p, r);\nEND_PROGRAM\n",
            ["Tc2_Utilities"],
        )
    )
    assert build.compiled is not None
    return build.simulation()


@settings(max_examples=300, deadline=None)
@given(
    x=st.one_of(
        st.floats(min_value=-1e15, max_value=1e15, allow_nan=False),
        st.decimals(min_value=-(10**6), max_value=10**6, places=6).map(float),
        st.floats(min_value=-1e-3, max_value=1e-3),
    ),
    precision=st.integers(0, 15),
    rounding=st.booleans(),
)
def test_lreal_to_fmtstr_gives_the_digits_of_the_exact_binary_value(
    formatter: Simulation, x: float, precision: int, rounding: bool
) -> None:
    formatter.write("Main.x", x)
    formatter.write("Main.p", precision)
    formatter.write("Main.r", rounding)
    formatter.cycle(1)
    assert formatter.read("Main.s") == _exact(x, precision, rounding)


def test_a_pou_of_the_project_shadows_a_library_function_but_not_inside_the_library() -> None:
    source = (
        "FUNCTION LTRUNC : LREAL\nVAR_INPUT in : LREAL; END_VAR\nLTRUNC := 123.0;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR shadowed : LREAL; library : LREAL; END_VAR\n"
        "shadowed := LTRUNC(2.8);\nlibrary := MODABS(-400.56, 360.0);\nEND_PROGRAM\n"
    )
    build = build_project(_project(source, ["Tc2_Math"]))
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    sim = build.simulation()
    sim.cycle(1)
    assert sim.read("Main.shadowed") == 123.0
    assert sim.read("Main.library") == pytest.approx(319.44, abs=1e-9)


def test_a_library_function_the_project_does_not_use_is_unknown_with_a_hint() -> None:
    build = build_project(_project("PROGRAM Main\nVAR r : LREAL; END_VAR\nr := FRAC(2.5);\nEND_PROGRAM\n", []))
    assert [d.format() for d in build.diagnostics] == [
        "Main/body:3:6, POU Main: error ST-UNKNOWN-POU: unknown function 'FRAC': it is in the Tc2_Math library, "
        "which the project does not use: add it in the project's Library manager (--library Tc2_Math for a .st file)"
    ]


def test_a_project_folder_keeps_its_libraries_and_refuses_an_unknown_one(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    project = _project("PROGRAM Main\nVAR r : LREAL; END_VAR\nr := FRAC(2.5);\nEND_PROGRAM\n", ["Tc2_Math"])
    for name, text in project_files(project).items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text, encoding="utf-8")
    assert json.loads((tmp_path / "project.json").read_text())["libraries"] == ["Tc2_Math"]
    assert load_project_path(tmp_path).libraries == ["Tc2_Math"]
    meta = json.loads((tmp_path / "project.json").read_text())
    (tmp_path / "project.json").write_text(json.dumps({**meta, "libraries": ["Tc2_Foo"]}), encoding="utf-8")
    assert main(["check", str(tmp_path)]) == 2
    assert capsys.readouterr().err.strip() == (
        "project.json, $.libraries[0]: error BAD-FILE: expected 'Tc2_Math' or 'Tc2_Utilities', got 'Tc2_Foo'"
    )


def test_the_command_line_adds_a_library_to_a_st_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "main.st"
    path.write_text("PROGRAM Main\nVAR s : STRING; END_VAR\ns := LREAL_TO_FMTSTR(2.5, 1, TRUE);\nEND_PROGRAM\n")
    assert main(["run", str(path), "--library", "Tc2_Utilities", "--watch", "Main.s"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].split() == ["0", "10", '"2.5"']


def test_an_ld_box_calls_a_library_function_and_the_box_picker_offers_it() -> None:
    pou = ld_pou(
        "Main",
        "VAR run : BOOL := TRUE; r : LREAL; END_VAR",
        rung(
            "N1", contact("C1", "run"), box("B1", "MODABS", en=True, outputs={"OUT": "r"}, value="-1.5", modulo="1.0")
        ),
    )
    project = Project(name="p", pous=[pou], libraries=["Tc2_Math"])
    build = build_project(project)
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    sim = build.simulation()
    sim.cycle(1)
    assert sim.read("Main.r") == 0.5  # -1.5 wrapped into [0, 1)
    offered = {(e.name, e.source) for e in user_entries(project)}
    assert {("LTRUNC", "library"), ("MODABS", "library"), ("FRAC", "library"), ("LMOD", "library")} <= offered


def test_the_st_export_names_the_libraries_and_runs_with_them(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    project = _project("PROGRAM Main\nVAR r : LREAL; END_VAR\nr := LMOD(-7.5, 2.0);\nEND_PROGRAM\n", LIBRARIES)
    text = export_project_st(project).text
    assert text.splitlines()[0] == (
        "(* Uses the vendor libraries Tc2_Math, Tc2_Utilities: ladderlab check/run ... --library Tc2_Math "
        "--library Tc2_Utilities *)"
    )
    path = tmp_path / "exported.st"
    path.write_text(text, encoding="utf-8")
    assert main(["run", str(path), "--library", "Tc2_Math", "--watch", "Main.r"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].split() == ["0", "10", "-1.5"]  # the sign of the dividend


def test_plcopen_xml_carries_the_libraries_and_reports_one_it_does_not_ship() -> None:
    project = _project("PROGRAM Main\nVAR r : LREAL; END_VAR\nr := MODABS(-7.5, 2.0);\nEND_PROGRAM\n", ["Tc2_Math"])
    document = export_plcopen(project)
    imported = import_plcopen(document)
    assert imported.project is not None and imported.diagnostics == []
    assert imported.project.libraries == ["Tc2_Math"]
    build = build_project(imported.project)
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    sim = build.simulation()
    sim.cycle(1)
    assert sim.read("Main.r") == 0.5  # Beckhoff: MODABS(-7.5, 2.0) is the positive remainder 0.5

    foreign = document.replace(b'name="Tc2_Math"', b'name="Tc2_System"')
    imported = import_plcopen(foreign, file="p.xml")
    assert imported.project is not None and imported.project.libraries == []
    [warning] = imported.diagnostics
    assert (warning.code, warning.severity) == ("PLCOPEN-UNSUPPORTED", "warning")
    assert warning.message.startswith("library 'Tc2_System' is not one LadderLab ships (Tc2_Math, Tc2_Utilities)")
