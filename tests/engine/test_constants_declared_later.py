"""Array bounds and STRING lengths from a POU's own ``VAR CONSTANT`` declared further down (issue 25 item 1; OSCAT's
FIFO_16 declares ``fifo : ARRAY[0..n] OF DWORD`` in VAR and ``n : INT := 16`` in the VAR CONSTANT block after it,
which CODESYS accepts: a declaration part is one scope, its constants known throughout). Constant expressions of
them (``n - 1``, ``m * 2``) are folded as anywhere else; a variable that is no constant still cannot size an array.
"""

from __future__ import annotations

from .test_references import build, simulation

LATER = "\nEND_VAR\nVAR CONSTANT\n  n : INT := 4; m : INT := n + 1;"


def test_bounds_and_lengths_from_constants_declared_after_them_scan_by_scan():
    sim = simulation(
        "fifo : ARRAY[0..n - 1] OF UDINT; s : STRING[m * 2]; i : INT;" + LATER,
        "fifo[i MOD n] := fifo[i MOD n] + 1;\ni := i + 1;\ns := CONCAT(s, 'ab');",
    )
    for scan in range(1, 7):
        sim.cycle(1)
        assert sim.read("Main.fifo") == [(scan + 3 - k) // 4 for k in range(4)]  # element k counts scans k, k + 4
        assert sim.read("Main.s") == ("ab" * scan)[:10]  # STRING[10]: 4 + 1 = 5, times 2
    assert sim.read("Main.n") == 4


def test_a_variable_declared_later_is_still_no_constant():
    result = build("PROGRAM Main\nVAR\n  a : ARRAY[0..n] OF INT;\n  n : INT := 3;\nEND_VAR\nEND_PROGRAM\n")
    assert [(d.code, d.message) for d in result.diagnostics if d.severity == "error"] == [
        ("ST-CONST-EXPR", "array bounds must be integer constants")
    ]
