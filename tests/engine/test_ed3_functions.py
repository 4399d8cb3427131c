"""IEC 61131-3 ed. 3 standard functions LadderLab takes beyond the 2nd edition: the string functions on WSTRING
(ANY_STRING, Table 29) and ATAN2 (Table 23). Expected values from the standard's definitions (1-based positions,
``math.atan2``'s quadrants), stored as REAL (binary32) where the result is REAL."""

from __future__ import annotations

import math
import struct

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project


def f32(x: float) -> float:
    return struct.unpack("<f", struct.pack("<f", x))[0]


def run(declarations: str, body: str) -> dict:
    project, diagnostics = source_to_project(f"PROGRAM Main\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n", "p")
    assert diagnostics == []
    build = build_project(project)
    assert [d.format() for d in build.diagnostics] == []
    sim = build.simulation()
    sim.cycle(1)
    assert sim.fault is None
    return {name.split(".")[1].lower(): value for name, value in sim.snapshot().items()}


def errors(declarations: str, body: str) -> list[str]:
    project, _ = source_to_project(f"PROGRAM Main\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n", "p")
    return [d.format() for d in build_project(project).diagnostics if d.severity == "error"]


def test_the_string_functions_take_wstrings():
    values = run(
        'w : WSTRING[20] := "abcdef"; n, f : INT; l, r, m, c, i, d, x : WSTRING[20];',
        'n := LEN(w); l := LEFT(w, 2); r := RIGHT(w, 2); m := MID(w, 3, 2); c := CONCAT(w, "gh", "!");\n'
        'i := INSERT(w, "XY", 2); d := DELETE(w, 2, 3); x := REPLACE(w, "Z", 3, 2); f := FIND(w, "cd");',
    )
    assert values == {
        "w": "abcdef",
        "n": 6,
        "l": "ab",
        "r": "ef",
        "m": "bcd",  # MID(IN, L, P): 3 characters from position 2
        "c": "abcdefgh!",
        "i": "abXYcdef",  # after the 2nd character
        "d": "abef",  # DELETE(IN, L, P): 2 characters from position 3
        "x": "aZef",  # REPLACE(IN1, IN2, L, P): 3 characters from position 2 become IN2
        "f": 3,
    }


def test_a_string_result_is_as_long_as_the_default_string_not_its_first_input():
    """CONCAT of two STRING[3] is 6 characters before the store cuts it to the target's length."""
    values = run(
        "a : STRING[3] := 'abc'; b : STRING[3] := 'def'; s : STRING; t : STRING[4];", "s := CONCAT(a, b); t := s;"
    )
    assert (values["s"], values["t"]) == ("abcdef", "abcd")


def test_strings_and_wstrings_do_not_mix():
    assert errors("s : STRING; w : WSTRING; r : STRING;", "r := CONCAT(s, w);") == [
        "Main/body:3:16, POU Main: error ST-TYPE-MISMATCH: CONCAT needs inputs of one type: got STRING and WSTRING; "
        "convert one of them with a *_TO_* function"
    ]


@pytest.mark.parametrize(
    ("y", "x"), [(1.0, 1.0), (0.0, 1.0), (1.0, 0.0), (-1.0, -1.0), (1.0, -1.0), (-0.0, -1.0), (0.0, 0.0)]
)
def test_atan2_gives_the_angle_of_the_point_in_its_quadrant(y, x):
    values = run(
        f"y : REAL := {y!r}; x : REAL := {x!r}; r : REAL; l : LREAL;",
        f"r := ATAN2(y, x); l := ATAN2(Y := REAL_TO_LREAL(y), X := {x!r});",
    )
    assert values["r"] == f32(math.atan2(f32(y), f32(x)))
    assert values["l"] == math.atan2(y, x)
    assert math.copysign(1.0, values["l"]) == math.copysign(1.0, math.atan2(y, x))


def test_atan2_takes_reals_only():
    assert errors("i : INT; r : REAL;", "r := ATAN2(i, r);")[0].endswith(
        "error ST-TYPE-MISMATCH: ATAN2 needs inputs of one type: got INT and REAL; convert one of them with a *_TO_* "
        "function"
    )
