"""CODESYS typing: a narrow operation whose register value the target would decide builds, checked when it runs
(st/registers.py, ``ast.Fit``; issue 25, OSCAT's CODE, ARRAY_AVG, FIX, SH_2, BUFFER_TO_STRING ...).

CODESYS computes ``+ - *`` in a register of at least 32 bits ("Operators": "at least with 32-bit temporary values
on x86 and ARM systems"; "the computational result depends on the target system hardware"). Where a typed
conversion, SHR, a FOR loop's bound or a comparison uses such a value uncut, the target decides what it gives - but
only for a value outside the operation's own type: inside it, cutting it changes nothing, and a conversion, SHR
(floor(value / 2^N), IEC 61131-3 / CODESYS "SHR", arithmetic on a signed type) or a comparison of that one value is
the same on every target. So the values below are the IEC conversions and arithmetic of in-range values, worked
out by hand; a value outside the type stops the task with the located fault ``overflow``, naming the operation.
"""

from __future__ import annotations

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

from .ed3_support import program

VARIANTS = ("fast", "debug")

#: OSCAT's shapes: CODE's INT_TO_DWORD(pos - 1), ARRAY_AVG's UINT_TO_REAL(stop + 1), FIX's SHR(N + 1, 1),
#: SH_2's FOR ... TO M - 2, BUFFER_TO_STRING's MIN(start, size - 1) and BAND_B's X > BYTE#255 - B (all uncut).
TEXT = program(
    "pos : INT := 5; offset : DWORD; stop : UINT := 4; avg : REAL; n : INT := 5; half : INT; neg : INT := -4;"
    "neg_half : INT; m : INT := 4; count : INT; k : INT; start : UINT := 9; size : UINT := 6; first : UINT;"
    "x : BYTE := 200; b : BYTE := 100; above : BOOL;",
    """offset := INT_TO_DWORD(pos - 1);
avg := 10.0 / UINT_TO_REAL(stop + 1);
half := SHR(n + 1, 1);
neg_half := SHR(neg + 1, 1);
count := 0;
FOR k := 0 TO m - 2 DO count := count + 1; END_FOR;
first := MIN(start, size - 1);
above := x > BYTE#255 - b;""",
)


def _simulation(text: str, variant: str = "fast"):
    project, diagnostics = source_to_project(text, "codesys")
    assert project is not None and not [d for d in diagnostics if d.severity == "error"], diagnostics
    result = build_project(project.model_copy(update={"typing": "codesys"}), variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


@pytest.mark.parametrize("variant", VARIANTS)
def test_values_of_the_operations_own_type_give_what_every_target_gives(variant):
    """INT_TO_DWORD(5 - 1) = 4; 10.0 / UINT_TO_REAL(4 + 1) = 2.0; SHR(5 + 1, 1) = 3; SHR(-4 + 1, 1): -3 shifted
    arithmetically = -2 (floor(-1.5)); FOR k := 0 TO 4 - 2 runs 3 times; MIN(9, 6 - 1) = 5; 200 > 255 - 100 TRUE."""
    sim = _simulation(TEXT, variant)
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    names = ("offset", "avg", "half", "neg_half", "count", "first", "above")
    assert [sim.read(f"Main.{name}") for name in names] == [4, 2.0, 3, -2, 3, 5, True]


@pytest.mark.parametrize(
    ("declared", "start", "operation", "value", "line"),
    [
        ("pos : INT := 5", "-32768", "pos - 1", -32769, 6),  # INT_TO_DWORD: 16#FFFF_7FFF or, cut, 16#7FFF
        ("stop : UINT := 4", "65535", "stop + 1", 65536, 7),  # UINT_TO_REAL: 65536.0 or, cut, 0.0
        ("m : INT := 4", "-32767", "m - 2", -32769, 11),  # the FOR loop's end: no iteration, or 32767 of them
        ("size : UINT := 6", "0", "size - 1", -1, 12),  # a signed register gives -1, an unsigned one 2^32 - 1
    ],
)
def test_a_value_outside_the_operations_type_stops_the_task_where_it_is(declared, start, operation, value, line):
    """Outside the operation's own type the register's value decides, and that is the target's choice: the task
    stops with the located fault ``overflow`` naming the operation and its value, before anything uses it."""
    sim = _simulation(TEXT.replace(declared, f"{declared.rpartition(' ')[0]} {start}", 1))
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "overflow"
    assert (sim.fault.pou, sim.fault.origin.line) == ("MAIN", line)
    assert sim.fault.message.startswith(f"'{operation}' is {value} here, outside ")
