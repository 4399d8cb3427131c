"""The debug variant: probes (ON-09), breakpoints (ON-03), stepping (ON-04, ON-05); the fast variant has no hooks."""

from __future__ import annotations

import re

import pytest

from ladderlab.engine.compile import emit_python
from ladderlab.engine.simulation import ProbeView, Simulation

from .irbuild import (
    BOOL,
    INT,
    TIME,
    add,
    and_,
    array,
    assign,
    c,
    call,
    div,
    fb,
    fbcall,
    function,
    if_,
    ix,
    jump,
    m,
    network,
    not_,
    pou,
    probe,
    prog,
    slot,
    v,
    while_,
)

A, B, X, Y = v("A", INT), v("B", INT), v("X", INT), v("Y", INT)


def _st_program():
    """MAIN (ST): line 1 A := A + 1; line 2 B := DOUBLE(A); line 3 X := X + 1. DOUBLE: line 1 and 2."""
    double = function(
        "DOUBLE",
        INT,
        [slot("N", INT, "VAR_INPUT"), slot("T", INT)],
        [assign(v("T", INT), add(v("N", INT), v("N", INT))), assign(v("DOUBLE", INT), v("T", INT))],
    )
    main = pou(
        "MAIN",
        [slot("A", INT), slot("B", INT), slot("X", INT)],
        [assign(A, add(A, c(1, INT))), assign(B, call("DOUBLE", A, type=INT, user=True)), assign(X, add(X, c(1, INT)))],
    )
    return prog(main, double)


def _ld_program():
    """MAIN (LD): N1 coil OUT1 := IN1 AND NOT IN2; N2 jumps over N3 when SKIP; N3 counts; probes per element."""
    in1, in2, out1, skip, n = v("IN1", BOOL), v("IN2", BOOL), v("OUT1", BOOL), v("SKIP", BOOL), v("N", INT)
    flow = v("__E2", BOOL)
    blocks = [
        network(
            "N1",
            [
                probe("E1", in1),
                assign(flow, and_(in1, not_(in2))),
                probe("E2", flow),
                assign(out1, flow),
                probe("E3", flow),
            ],
        ),
        network("N2", [probe("E4", skip), jump("END", skip)]),
        network("N3", [assign(n, add(n, c(1, INT))), probe("E5", c(True, BOOL)), probe("E5.OUT", n)]),
        network("N4", [probe("E6", out1)], label="END"),
    ]
    slots = [
        slot("IN1", BOOL, initial=True),
        slot("IN2", BOOL),
        slot("OUT1", BOOL),
        slot("SKIP", BOOL),
        slot("N", INT),
        slot("__E2", BOOL, hidden=True),
    ]
    return prog(pou("MAIN", slots, blocks))


def test_the_fast_variant_has_no_probe_or_pause_code_and_the_monitor_variant_no_pause_code():
    for program in (_st_program(), _ld_program()):
        fast, monitor, debug = (emit_python(program, variant) for variant in ("fast", "monitor", "debug"))
        assert not any(word in fast for word in ("ll_halt", "ll_pr", "yield", "ll_px", "E1"))
        assert not any(word in monitor for word in ("ll_halt", "yield"))
        assert "if ll_halt[0]: yield (0, self)" in debug
    assert "(yield from f_DOUBLE(self.v_A))" in emit_python(_st_program(), "debug")
    for variant in ("monitor", "debug"):  # probe 0 of the group 0 that network N1 starts
        lines = [line.strip() for line in emit_python(_ld_program(), variant).splitlines()]
        assert lines[lines.index("ll_px[0] = ll_k") + 1] == "ll_pr[0] = self.v_IN1  # 'E1'"


def test_the_fast_variant_drops_an_if_that_only_guards_probes_but_keeps_one_whose_test_can_fault():
    """A box's EN-guarded probes leave nothing to run in the fast variant; an index in the test may fault, so it stays."""
    en, i = v("EN", BOOL), v("I", INT)
    main = pou(
        "MAIN",
        [slot("EN", BOOL), slot("ARR", array(BOOL, (1, 2))), slot("I", INT), slot("N", INT)],
        [network("N1", [if_((en, [probe("B1.OUT", v("N", INT))])), if_((v("ARR", BOOL, ix(i)), [probe("B2", en)]))])],
    )
    fast = emit_python(prog(main), "fast")
    execute = fast[fast.index("def ll_x_MAIN") : fast.index("P_MAIN.execute =")]
    assert "if self.v_EN" not in execute
    assert execute.count("if ") == 1 and "v_ARR" in execute
    assert "ll_pr[0] = self.v_N  # 'B1.OUT'" in emit_python(prog(main), "monitor")


def test_probes_record_values_and_which_elements_ran_this_scan():
    sim = Simulation(_ld_program(), variant="debug")
    sim.cycle()
    view = sim.probes("main")
    assert view.values == {"E1": True, "E2": True, "E3": True, "E4": False, "E5": True, "E5.OUT": 1, "E6": True}
    assert view.executed == set(view.values)
    sim.write("MAIN.SKIP", True)
    sim.write("MAIN.IN2", True)
    sim.cycle()
    view = sim.probes("MAIN")
    assert view.executed == {"E1", "E2", "E3", "E4", "E6"}  # N3 was jumped over
    assert view.values == {"E1": True, "E2": False, "E3": False, "E4": True, "E5": True, "E5.OUT": 1, "E6": False}


def test_probes_of_fb_instances_and_functions():
    q = v("Q", BOOL)
    user = pou(
        "BLINK",
        [slot("Q", BOOL, "VAR_OUTPUT")],
        [network("N1", [assign(q, not_(q)), probe("C1", q)])],
        kind="function_block",
    )
    neg = function(
        "ISNEG",
        BOOL,
        [slot("X", INT, "VAR_INPUT")],
        [
            network(
                "N1",
                [
                    assign(v("ISNEG", BOOL), call("LT", v("X", INT), c(0, INT), type=BOOL)),
                    probe("LT1", v("ISNEG", BOOL)),
                ],
            )
        ],
    )
    main = pou(
        "MAIN",
        [slot("F1", fb("BLINK")), slot("F2", fb("BLINK")), slot("R", BOOL)],
        [
            fbcall(v("F1", fb("BLINK"))),
            fbcall(v("F2", fb("BLINK"))),
            fbcall(v("F2", fb("BLINK"))),
            assign(v("R", BOOL), call("ISNEG", c(-3, INT), type=BOOL, user=True)),
        ],
    )
    sim = Simulation(prog(main, user, neg), variant="debug")
    sim.cycle()
    assert sim.probes("MAIN.F1").values == {"C1": True} and sim.probes("MAIN.F2").values == {"C1": False}
    assert sim.probes("isneg").values == {"LT1": True} and sim.probes("MAIN").values == {}
    with pytest.raises(KeyError, match=re.escape("no POU instance 'MAIN.F3' - did you mean 'MAIN.F2'")):
        sim.probes("MAIN.F3")


def test_breakpoint_on_an_st_line_halts_before_the_statement_and_allows_reading_and_writing():
    sim = Simulation(_st_program(), variant="debug")
    assert sim.set_breakpoint("MAIN", line=3) == [3]
    assert sim.cycle(5) == 0
    halt = sim.halted
    assert (halt.reason, halt.point.kind, halt.origin.pou, halt.origin.line, halt.instance) == (
        "breakpoint",
        "statement",
        "MAIN",
        3,
        "MAIN",
    )
    assert (sim.read("MAIN.A"), sim.read("MAIN.B"), sim.read("MAIN.X")) == (1, 2, 0)
    sim.write("MAIN.X", 10)  # at once while halted
    assert sim.read("MAIN.X") == 10
    with pytest.raises(RuntimeError, match="halted"):
        sim.cycle()
    assert sim.resume() is None and sim.halted is None and sim.read("MAIN.X") == 11 and sim.scan_count == 1
    assert sim.cycle() == 0 and sim.halted.origin.line == 3 and sim.time_ms == 20
    sim.clear_breakpoints()
    assert sim.resume() is None and sim.cycle(2) == 2 and sim.read("MAIN.A") == 4


def test_step_statement_goes_into_called_functions():
    sim = Simulation(_st_program(), variant="debug")
    sim.set_breakpoint("MAIN", line=2)
    sim.cycle()
    where = []
    halt = sim.halted
    while halt is not None:
        where.append((halt.origin.pou, halt.origin.line, halt.reason))
        halt = sim.step("statement")
    assert where == [("MAIN", 2, "breakpoint"), ("DOUBLE", 1, "step"), ("DOUBLE", 2, "step"), ("MAIN", 3, "step")]
    assert sim.scan_count == 1 and sim.read("MAIN.B") == 2


def _nested_program():
    """MAIN: 1 A := A + 1; 2 C1(); 3 X := X + 1.  CNT (FB): 1 N := N + 1; 2 M := DOUBLE(N); 3 N := N + 0.
    DOUBLE (function): 1 T := N + N; 2 DOUBLE := T."""
    n, mm = v("N", INT), v("M", INT)
    double = function(
        "DOUBLE",
        INT,
        [slot("N", INT, "VAR_INPUT"), slot("T", INT)],
        [assign(v("T", INT), add(n, n)), assign(v("DOUBLE", INT), v("T", INT))],
    )
    cnt = pou(
        "CNT",
        [slot("N", INT), slot("M", INT)],
        [
            assign(n, add(n, c(1, INT))),
            assign(mm, call("DOUBLE", n, type=INT, user=True)),
            assign(n, add(n, c(0, INT))),
        ],
        kind="function_block",
    )
    main = pou(
        "MAIN",
        [slot("A", INT), slot("X", INT), slot("C1", fb("CNT"))],
        [assign(A, add(A, c(1, INT))), fbcall(v("C1", fb("CNT"))), assign(X, add(X, c(1, INT)))],
    )
    return prog(main, cnt, double)


def _steps(sim, granularity: str) -> list[tuple[str, int, str]]:
    """Where each step of ``granularity`` halts until the scan ends: (POU, line, reason)."""
    where, halt = [], sim.halted
    while halt is not None:
        where.append((halt.origin.pou, halt.origin.line, halt.reason))
        halt = sim.step(granularity)
    return where


@pytest.mark.parametrize(
    ("pou", "line", "granularity", "expected"),
    [
        # Step over (F10) passes over the call of C1 and of DOUBLE; stays in the POU, then its caller.
        ("MAIN", 2, "over", [("MAIN", 2, "breakpoint"), ("MAIN", 3, "step")]),
        ("CNT", 1, "over", [("CNT", 1, "breakpoint"), ("CNT", 2, "step"), ("CNT", 3, "step"), ("MAIN", 3, "step")]),
        # Step into (F11) goes into every call.
        (
            "MAIN",
            2,
            "statement",
            [
                ("MAIN", 2, "breakpoint"),
                ("CNT", 1, "step"),
                ("CNT", 2, "step"),
                ("DOUBLE", 1, "step"),
                ("DOUBLE", 2, "step"),
                ("CNT", 3, "step"),
                ("MAIN", 3, "step"),
            ],
        ),
        # Step out (Shift+F11) runs until the caller goes on.
        ("DOUBLE", 1, "out", [("DOUBLE", 1, "breakpoint"), ("CNT", 3, "step"), ("MAIN", 3, "step")]),
        ("CNT", 2, "out", [("CNT", 2, "breakpoint"), ("MAIN", 3, "step")]),
        ("MAIN", 1, "out", [("MAIN", 1, "breakpoint")]),  # out of the program: the rest of the scan
    ],
)
def test_step_over_into_and_out_of_calls(pou, line, granularity, expected):
    """Issue 17 (CODESYS F10 / F11 / Shift+F11): what each step passes over, from a breakpoint."""
    sim = Simulation(_nested_program(), variant="debug")
    sim.set_breakpoint(pou, line=line)
    sim.cycle()
    sim.clear_breakpoints()
    assert _steps(sim, granularity) == expected
    assert sim.scan_count == 1 and (sim.read("MAIN.X"), sim.read("MAIN.C1.M")) == (1, 2)


def test_a_breakpoint_inside_a_call_halts_a_step_over_it():
    sim = Simulation(_nested_program(), variant="debug")
    sim.set_breakpoint("MAIN", line=2)
    sim.set_breakpoint("DOUBLE", line=2)
    sim.cycle()
    halt = sim.step("over")
    assert (halt.origin.pou, halt.origin.line, halt.reason) == ("DOUBLE", 2, "breakpoint")
    assert (sim.step("out").origin.pou, sim.halted.origin.line) == ("CNT", 3)


def test_step_over_the_last_network_of_a_call_returns_to_the_caller_not_into_a_sibling_call():
    """MAIN (a diagram) calls C1 and C2 in network N1: stepping over C1's last network goes on in MAIN."""
    n = v("N", INT)
    cnt = pou(
        "CNT",
        [slot("N", INT)],
        [network("K1", [assign(n, add(n, c(1, INT)))]), network("K2", [assign(n, add(n, c(1, INT)))])],
        kind="function_block",
    )
    main = pou(
        "MAIN",
        [slot("X", INT), slot("C1", fb("CNT")), slot("C2", fb("CNT"))],
        [
            network("N1", [fbcall(v("C1", fb("CNT"))), fbcall(v("C2", fb("CNT")))]),
            network("N2", [assign(X, add(X, c(1, INT)))]),
        ],
    )
    sim = Simulation(prog(main, cnt), variant="debug")
    sim.set_breakpoint("CNT", network="K2")
    sim.cycle()
    sim.clear_breakpoints()
    assert sim.halted.instance == "MAIN.C1"
    halt = sim.step("over")
    assert (halt.origin.pou, halt.origin.network, sim.read("MAIN.C2.N")) == ("MAIN", "N2", 2)
    assert sim.step("over") is None


def test_step_over_counts_calls_not_the_chunks_of_a_long_body():
    """A POU body split into chunk functions is still one call: step over goes network by network."""
    from .test_chunks import chunk_size

    n = v("N", INT)
    cnt = pou("CNT", [slot("N", INT)], [network("K1", [assign(n, add(n, c(1, INT)))])], kind="function_block")
    main = pou(
        "MAIN",
        [slot("A", INT), slot("X", INT), slot("C1", fb("CNT"))],
        [
            network("N1", [assign(A, add(A, c(1, INT)))]),
            network("N2", [fbcall(v("C1", fb("CNT")))]),
            network("N3", [assign(X, add(X, c(1, INT)))]),
        ],
    )
    with chunk_size(1):
        sim = Simulation(prog(main, cnt), variant="debug")
    assert "def ll_k2_MAIN" in sim.compiled.source  # every network its own chunk
    sim.set_breakpoint("MAIN", network="N1")
    sim.cycle()
    sim.clear_breakpoints()
    where, halt = [], sim.halted
    while halt is not None:
        where.append(halt.origin.network)
        halt = sim.step("over")
    assert where == ["N1", "N2", "N3"] and sim.read("MAIN.C1.N") == 1


def test_step_when_not_halted_starts_a_scan_and_step_cycle_finishes_it():
    sim = Simulation(_st_program(), variant="debug")
    halt = sim.step("statement")
    assert (halt.origin.pou, halt.origin.line, sim.read("MAIN.A")) == ("MAIN", 1, 0)
    assert sim.step("cycle") is None and sim.scan_count == 1 and sim.read("MAIN.X") == 1
    assert sim.step("cycle") is None and sim.scan_count == 2  # ON-05: a single cycle from the stopped state


def test_probes_of_a_halted_scan_show_its_values_for_what_already_ran():
    """Issue 9: the diagram of a halted scan shows the values at the halt point."""
    sim = Simulation(_ld_program(), variant="debug")
    sim.cycle()
    sim.write("MAIN.IN2", True)
    sim.set_breakpoint("MAIN", network="N3")
    sim.cycle()
    view = sim.probes("MAIN")
    assert view.executed == {"E1", "E2", "E3", "E4"}  # N1, N2 ran in this scan, N3 and N4 not yet
    assert view.values == {
        "E1": True,
        "E2": False,
        "E3": False,
        "E4": False,  # this scan: IN2 now TRUE
        "E5": True,
        "E5.OUT": 1,
        "E6": True,
    }  # the last scan's, not run yet
    sim.clear_breakpoints()
    sim.resume()
    assert sim.probes("MAIN").values == {
        "E1": True,
        "E2": False,
        "E3": False,
        "E4": False,
        "E5": True,
        "E5.OUT": 2,
        "E6": False,
    }


def test_step_network_in_a_diagram_and_breakpoints_on_networks_and_elements():
    sim = Simulation(_ld_program(), variant="debug")
    sim.set_breakpoint("MAIN", network="N2")
    sim.cycle()
    assert (sim.halted.point.kind, sim.halted.origin.network) == ("network", "N2")
    assert sim.step("network").origin.network == "N3"
    assert sim.step("network").origin.network == "N4"
    assert sim.step("network") is None
    sim.clear_breakpoint("MAIN", network="N2")
    sim.set_breakpoint("MAIN", element="E5.OUT")
    sim.cycle()
    assert (sim.halted.point.kind, sim.halted.point.element) == ("element", "E5.OUT")
    assert sim.probes("MAIN").executed >= {"E1", "E5", "E5.OUT"} and "E6" not in sim.probes("MAIN").executed


def test_halts_name_the_fb_instance():
    n = v("N", INT)
    user = pou("CNT", [slot("N", INT)], [assign(n, add(n, c(1, INT)))], kind="function_block")
    main = pou(
        "MAIN", [slot("C1", fb("CNT")), slot("C2", fb("CNT"))], [fbcall(v("C1", fb("CNT"))), fbcall(v("C2", fb("CNT")))]
    )
    sim = Simulation(prog(main, user), variant="debug")
    sim.set_breakpoint("CNT", line=1)
    sim.cycle()
    assert sim.halted.instance == "MAIN.C1"
    assert sim.resume().instance == "MAIN.C2" and sim.read("MAIN.C1.N") == 1 and sim.read("MAIN.C2.N") == 0


@pytest.mark.parametrize(
    ("where", "message"),
    [
        ({"line": 9}, "MAIN has no statement at line 9 (possible: 1, 2, 3)"),
        ({"network": "N1"}, "MAIN has no network 'N1' (possible: none)"),
        ({"line": 1, "network": "N1"}, "give exactly one of line, network, element"),
    ],
)
def test_breakpoint_errors(where, message):
    sim = Simulation(_st_program(), variant="debug")
    with pytest.raises(ValueError) as raised:
        sim.set_breakpoint("MAIN", **where)
    assert str(raised.value) == message


def test_debugging_needs_the_debug_variant_and_a_halt():
    fast = Simulation(_st_program())
    with pytest.raises(RuntimeError, match="variant='debug'"):
        fast.set_breakpoint("MAIN", line=1)
    debug = Simulation(_st_program(), variant="debug")
    with pytest.raises(RuntimeError, match="not halted"):
        debug.resume()


def test_reset_ends_a_halted_scan():
    sim = Simulation(_st_program(), variant="debug")
    sim.set_breakpoint("MAIN", line=2)
    sim.cycle()
    sim.reset(cold=True)
    assert sim.halted is None and sim.read("MAIN.A") == 0
    assert sim.cycle() == 0 and sim.read("MAIN.A") == 1  # the breakpoint stays


class _Clock:
    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        self.now += 0.0001
        return self.now


def test_halted_time_does_not_count_against_the_watchdog_and_faults_work_in_debug():
    i = v("I", INT)
    main = pou(
        "MAIN",
        [slot("I", INT), slot("Z", INT), slot("Q", INT)],
        [
            assign(i, c(0, INT)),
            while_(call("LT", i, c(5000, INT), type=BOOL), [assign(i, add(i, c(1, INT)))]),
            assign(v("Q", INT), div(i, v("Z", INT))),
        ],
    )
    clock = _Clock()
    sim = Simulation(prog(main), variant="debug", watchdog_s=0.5, watchdog_clock=clock)
    sim.set_breakpoint("MAIN", line=2)
    sim.cycle()
    clock.now += 3600.0  # an hour at the breakpoint
    assert sim.resume() is None
    assert (sim.fault.code, sim.fault.origin.line, sim.fault.values) == (
        "division_by_zero",
        4,
        {"Q": 0, "I": 5000, "Z": 0},
    )


def test_the_monitor_variant_reads_probes_of_variables_nothing_writes_later_after_the_scan():
    """codegen/deferred.py: IN1 and the TON's Q are read when asked; OUT1 is written after its first probe."""
    in1, out1, t1 = v("IN1", BOOL), v("OUT1", BOOL), v("T1", fb("TON"))
    main = pou(
        "MAIN",
        [slot("IN1", BOOL), slot("OUT1", BOOL), slot("T1", fb("TON"))],
        [
            network(
                "N1",
                [
                    probe("E1", in1),
                    probe("E2", out1),
                    assign(out1, in1),
                    fbcall(t1, {"IN": in1, "PT": c(20, TIME)}),
                    probe("E3", v("T1", BOOL, m("Q"))),
                ],
            )
        ],
    )
    monitor, debug = Simulation(prog(main), variant="monitor"), Simulation(prog(main), variant="debug")
    lines = [line.strip() for line in monitor.compiled.source.splitlines()]
    assert "# ll_pr[0] is read after the scan  # 'E1'" in lines and "ll_pr[1] = self.v_OUT1  # 'E2'" in lines
    assert "# ll_pr[2] is read after the scan  # 'E3'" in lines
    assert monitor.probes("MAIN") == debug.probes("MAIN") == (ProbeView({}, frozenset()))  # nothing ran yet
    for value in (True, True, True, False):
        for sim in (monitor, debug):
            sim.write("MAIN.IN1", value)
            sim.cycle()
        assert monitor.probes("MAIN") == debug.probes("MAIN")
    assert debug.probes("MAIN").values == {"E1": False, "E2": True, "E3": False}
