"""Runtime errors stop the task with a fault naming POU, origin and values (TYP-24, FUN-31, ST-70, issue 4)."""

from __future__ import annotations

from ladderlab.engine.compile import compile_program
from ladderlab.engine.simulation import Simulation
from ladderlab.ir import nodes as ir
from ladderlab.ir import types as t

from .irbuild import (
    INT,
    STRING,
    add,
    array,
    assign,
    c,
    call,
    div,
    fb,
    fbcall,
    for_,
    function,
    ix,
    network,
    pou,
    prog,
    slot,
    v,
)


def _faulted(program, scans=1):
    sim = Simulation(program)
    sim.cycle(scans)
    assert sim.fault is not None
    return sim, sim.fault


def test_division_by_zero_reports_line_and_operand_values():
    a, b, x = v("A", INT), v("B", INT), v("X", INT)
    main = pou(
        "MAIN",
        [slot("A", INT, initial=7), slot("B", INT, initial=2), slot("X", INT)],
        [assign(b, add(b, c(-1, INT))), assign(x, div(a, b))],
    )
    sim, fault = _faulted(prog(main), scans=3)
    assert (fault.kind, fault.code, fault.message) == ("runtime_error", "division_by_zero", "division by zero: 7 / 0")
    assert (fault.pou, fault.origin.line, fault.origin.column, fault.instance) == ("MAIN", 2, 1, "MAIN")
    assert fault.values == {"X": 7, "A": 7, "B": 0} and (fault.scan, fault.time_ms, fault.task) == (1, 20, "DEFAULT")
    assert fault.text() == (
        "division by zero: 7 / 0 at POU MAIN, line 2 column 1 (instance MAIN), task DEFAULT, "
        "scan 1, t = 20 ms; X = 7; A = 7; B = 0"
    )
    diagnostic = fault.diagnostic()
    assert (diagnostic.code, diagnostic.pou, diagnostic.line, diagnostic.severity) == (
        "ENGINE-RUNTIME",
        "MAIN",
        2,
        "error",
    )
    assert sim.scan_count == 3 and sim.read("MAIN.B") == 0  # the stopped task no longer runs: B stays 0


def test_index_out_of_range_in_an_fb_instance_names_the_instance_and_index():
    arr = array(INT, (1, 10))
    i = v("I", INT)
    user = pou(
        "FILL",
        [slot("I", INT, "VAR_INPUT"), slot("ARR", arr)],
        [assign(v("ARR", INT, ix(i)), i)],
        kind="function_block",
    )
    main = pou(
        "MAIN",
        [slot("F1", fb("FILL")), slot("K", INT, initial=9)],
        [assign(v("K", INT), add(v("K", INT), c(1, INT))), fbcall(v("F1", fb("FILL")), {"I": v("K", INT)})],
    )
    sim, fault = _faulted(prog(main, user), scans=2)
    assert (fault.code, fault.message) == ("index_out_of_range", "array index 11 is outside 1..10")
    assert (fault.pou, fault.instance, fault.origin.line, fault.values) == ("FILL", "MAIN.F1", 1, {"I": 11})
    assert sim.read("MAIN.F1.ARR[10]") == 10


def test_subrange_violation_and_values_of_array_elements():
    pct = t.Subrange(INT, 0, 100)
    arr = array(INT, (0, 2))
    main = pou(
        "MAIN",
        [slot("P", pct), slot("ARR", arr, initial=(50, 60, 70)), slot("J", INT, initial=1)],
        [assign(v("P", pct), add(v("ARR", INT, ix(v("J", INT))), v("ARR", INT, ix(c(2, INT)))))],
    )
    _, fault = _faulted(prog(main))
    assert (fault.code, fault.message) == ("subrange_violation", "130 is outside the subrange 0..100")
    assert fault.values == {"P": 0, "ARR[J]": 60, "J": 1, "ARR[2]": 70}


def test_fault_inside_a_function_reads_its_locals():
    x = v("X", INT)
    inv = function(
        "INV",
        INT,
        [slot("X", INT, "VAR_INPUT"), slot("ONE", INT, initial=100)],
        [assign(v("INV", INT), div(v("ONE", INT), x))],
    )
    main = pou("MAIN", [slot("R", INT)], [assign(v("R", INT), call("INV", c(0, INT), type=INT, user=True))])
    _, fault = _faulted(prog(main, inv))
    assert (fault.pou, fault.instance, fault.origin.line) == ("INV", None, 1)
    assert fault.values == {"INV": 0, "ONE": 100, "X": 0}


def test_for_step_zero_at_run_time_st70():
    i, step = v("I", INT), v("STEP", INT)
    main = pou("MAIN", [slot("I", INT), slot("STEP", INT)], [for_(i, c(1, INT), c(3, INT), [], step=step)])
    _, fault = _faulted(prog(main))
    assert (fault.code, fault.message, fault.values) == (
        "for_step_zero",
        "FOR loop step (BY) is 0",
        {"I": 1, "STEP": 0},
    )


def test_fault_in_a_diagram_points_at_network_and_element():
    x = v("X", INT)
    blocks = [network("N7", [ir.Assign(x, div(c(1, INT), x), ir.Origin("?", element="E3"))])]
    _, fault = _faulted(prog(pou("MAIN", [slot("X", INT)], blocks)))
    assert (fault.origin.network, fault.origin.element) == ("N7", "E3")
    assert fault.where() == "POU MAIN, network N7, element E3"


def test_unexpected_exceptions_in_generated_code_are_internal_faults():
    """Anything raised in generated code becomes a fault; the caller's process never sees it."""
    text, n = v("T", STRING), v("N", INT)
    main = pou(
        "MAIN", [slot("T", STRING, initial="12"), slot("N", INT)], [assign(n, call("STRING_TO_INT", text, type=INT))]
    )
    compiled = compile_program(prog(main))
    (name,) = [k for k in compiled.generated.bound if k.startswith("fn_STRING_TO_INT")]

    def broken(value):
        raise OverflowError("simulated defect")

    compiled.generated.bound[name] = broken
    sim = Simulation(compiled)
    sim.cycle()
    assert (sim.fault.kind, sim.fault.code) == ("internal_error", "OverflowError")
    assert sim.fault.message == "internal error: OverflowError: simulated defect" and sim.fault.origin.line == 1
