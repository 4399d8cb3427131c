"""A fault in the middle of an LD/FBD network stops the elements after it (docs/runtime.md, "Probes").

A probe group stores the scan's stamp before its first probe, so without ``engine/stopped.py`` the elements after
the faulting one counted as run in the monitor and debug variants and showed the values an earlier scan left (a lit
coil beside the fault message). Scan by scan: the elements before the fault show this scan's values, those after
it (in the faulted instance and, for a fault in a called FB, in the caller's network from the call box on) show
not run; after a reset and a good scan every element is exact again. Expected values worked out by hand from the
diagrams (IEC 61131-3 DIV, ADD, MOVE; a task stops at its fault).
"""

from __future__ import annotations

import pytest

from ladderlab.model import fbd
from ladderlab.model.project import Pou, Project
from ladderlab.simulation.build import build_project
from ladderlab.simulation.history import History
from tests.ir.diagram_support import blk, box, coil, contact, inp, ld_pou, net, out, rung

VARIANTS = ["monitor", "debug"]


def _sim(variant: str, *pous: Pou):
    build = build_project(Project(name="p", pous=list(pous)), variant)
    assert build.compiled is not None, [d.message for d in build.diagnostics]
    return build.simulation()


def _shown(sim, instance: str, pou: str = "MAIN") -> dict[str, object]:
    """What a frame shows of each element of ``pou``: its value when it ran in the last scan, else None (not run)."""
    view = sim.probes(instance)
    elements = sim.compiled.generated.context.probes_of(pou).elements
    return {e: (view.values.get(e) if e in view.executed else None) for e in elements}


def _ld_main() -> Pou:
    """n0 runs before the fault; in n1 ADD runs, DIV faults when Y = 0, the coil after it does not run; n2 after."""
    return ld_pou(
        "Main",
        "VAR START : BOOL := TRUE; Q, Q2, R : BOOL; X : INT := 7; Y : INT := 1; W, Z : INT; END_VAR",
        rung("n0", contact("r0", "START"), coil("c0", "R")),
        rung(
            "n1",
            contact("s", "START"),
            box("a", "ADD", en=True, outputs={"OUT": "W"}, IN1="X", IN2="1"),
            box("d", "DIV", en=True, outputs={"OUT": "Z"}, IN1="W", IN2="Y"),
            coil("o", "Q"),
        ),
        rung("n2", contact("s2", "START"), coil("o2", "Q2")),
    )


@pytest.mark.parametrize("variant", VARIANTS)
def test_ld_div_by_zero_in_the_middle_of_a_rung(variant):
    sim = _sim(variant, _ld_main())
    sim.cycle(1)
    ran = {"r0": True, "c0": True, "s": True, "a": True, "a.OUT": 8, "d": True, "d.OUT": 8, "o": True}
    assert _shown(sim, "MAIN") == {**ran, "s2": True, "o2": True}
    sim.write("Main.X", 9)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "division_by_zero"
    assert (sim.fault.origin.network, sim.fault.origin.element) == ("n1", "d")
    # before the fault: this scan's values (ADD gives 10 now); from the DIV on and the next network: not run
    expected = {"r0": True, "c0": True, "s": True, "a": True, "a.OUT": 10}
    assert _shown(sim, "MAIN") == {**expected, "d": None, "d.OUT": None, "o": None, "s2": None, "o2": None}
    sim.reset()
    sim.write("Main.X", 9)
    sim.cycle(1)  # Y is 1 again (its initial value)
    assert sim.fault is None
    assert _shown(sim, "MAIN") == {**expected, "d": True, "d.OUT": 10, "o": True, "s2": True, "o2": True}


@pytest.mark.parametrize("variant", VARIANTS)
def test_ld_array_index_out_of_range_in_a_move_operand(variant):
    main = ld_pou(
        "Main",
        "VAR START : BOOL := TRUE; Q : BOOL; I : INT; K : INT := 3; ARR : ARRAY[0..3] OF INT := [5, 6, 7, 8];"
        " W, Z : INT; END_VAR",
        rung(
            "n1",
            contact("s", "START"),
            box("k", "MOVE", en=True, outputs={"OUT": "W"}, IN="K"),
            box("m", "MOVE", en=True, outputs={"OUT": "Z"}, IN="ARR[I]"),
            coil("o", "Q"),
        ),
    )
    sim = _sim(variant, main)
    sim.cycle(1)
    assert _shown(sim, "MAIN") == {"s": True, "k": True, "k.OUT": 3, "m": True, "m.OUT": 5, "o": True}
    sim.write("Main.K", 4)
    sim.write("Main.I", 4)
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "index_out_of_range"
    assert _shown(sim, "MAIN") == {"s": True, "k": True, "k.OUT": 4, "m": None, "m.OUT": None, "o": None}
    sim.reset()
    sim.write("Main.I", 2)
    sim.cycle(1)
    assert sim.fault is None
    assert _shown(sim, "MAIN") == {"s": True, "k": True, "k.OUT": 3, "m": True, "m.OUT": 7, "o": True}


@pytest.mark.parametrize("variant", VARIANTS)
def test_fbd_div_by_zero_in_the_middle_of_a_network(variant):
    network = net(
        "n1",
        [inp("x", "X"), inp("y", "Y"), blk("a", "ADD"), blk("d", "DIV"), out("w", "W"), out("z", "Z")],
        [("x.OUT", "a.IN1"), ("x.OUT", "a.IN2"), ("a.OUT", "w.IN"), ("a.OUT", "d.IN1"), ("y.OUT", "d.IN2")]
        + [("d.OUT", "z.IN")],
        order=["a", "w", "d", "z"],
    )
    main = Pou(
        name="Main",
        kind="program",
        language="fbd",
        declarations="VAR X : INT := 3; Y : INT := 2; W, Z : INT; END_VAR",
        body=fbd.FbdBody(networks=[network]),
    )
    sim = _sim(variant, main)
    sim.cycle(1)
    first = _shown(sim, "MAIN")
    assert {e: first[e] for e in ("a.OUT", "d.OUT")} == {"a.OUT": 6, "d.OUT": 3}
    assert all(value is not None for value in first.values()), first
    sim.write("Main.X", 5)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "division_by_zero"
    shown = _shown(sim, "MAIN")
    stopped = {e for e, value in shown.items() if value is None}
    assert stopped == {e for e in shown if e.split(".")[0] in ("d", "z")}, shown
    assert shown["a.OUT"] == 10 and stopped
    sim.reset()
    sim.write("Main.X", 5)
    sim.cycle(1)
    assert sim.fault is None
    shown = _shown(sim, "MAIN")
    assert all(value is not None for value in shown.values()), shown
    assert (shown["a.OUT"], shown["d.OUT"]) == (10, 5)


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_fault_inside_an_fb_called_from_an_ld_box_stops_both_networks(variant):
    divider = ld_pou(
        "Divider",
        "VAR_INPUT A, B : INT; END_VAR VAR_OUTPUT P, Q : INT; DONE : BOOL; END_VAR",
        rung(
            "m1",
            box("p", "ADD", en=True, outputs={"OUT": "P"}, IN1="A", IN2="1"),
            box("q", "DIV", en=True, outputs={"OUT": "Q"}, IN1="A", IN2="B"),
            coil("e", "DONE"),
        ),
        kind="function_block",
    )
    main = ld_pou(
        "Main",
        "VAR START : BOOL := TRUE; OK : BOOL; X : INT := 6; Y : INT := 3; P, Z : INT; F1 : Divider; END_VAR",
        rung(
            "n1",
            contact("s", "START"),
            box("f", "Divider", instance="F1", en=True, outputs={"P": "P", "Q": "Z"}, A="X", B="Y"),
            coil("o", "OK"),
        ),
    )
    sim = _sim(variant, divider, main)
    sim.cycle(1)
    caller = _shown(sim, "MAIN")
    assert (caller["s"], caller["o"]) == (True, True) and None not in caller.values(), caller
    assert _shown(sim, "MAIN.F1", "DIVIDER") == {"p": True, "p.OUT": 7, "q": True, "q.OUT": 2, "e": True}
    sim.write("Main.X", 8)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "division_by_zero"
    assert (sim.fault.pou, sim.fault.instance) == ("DIVIDER", "MAIN.F1")
    assert _shown(sim, "MAIN.F1", "DIVIDER") == {"p": True, "p.OUT": 9, "q": None, "q.OUT": None, "e": None}
    caller = _shown(sim, "MAIN")
    assert caller["s"] is True
    assert {e for e, value in caller.items() if value is None} == {e for e in caller if e != "s"}, caller
    sim.reset()
    sim.write("Main.X", 8)
    sim.write("Main.Y", 4)
    sim.cycle(1)
    assert sim.fault is None
    assert _shown(sim, "MAIN.F1", "DIVIDER") == {"p": True, "p.OUT": 9, "q": True, "q.OUT": 2, "e": True}
    assert None not in _shown(sim, "MAIN").values()


def test_a_restored_state_of_a_faulted_scan_shows_what_the_fault_stopped():
    """A scan history restores the state a faulted scan left (it cannot redo that scan: History.seek)."""
    sim = _sim("monitor", _ld_main())
    sim.cycle(1)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    state = sim.state()
    other = _sim("monitor", _ld_main())
    other.restore(state)
    assert _shown(other, "MAIN") == _shown(sim, "MAIN")
    assert (_shown(other, "MAIN")["o"], _shown(other, "MAIN")["a.OUT"]) == (None, 8)
    other.reset()  # (the restored task stays stopped by its fault until a reset)
    other.cycle(1)
    assert other.fault is None and _shown(other, "MAIN")["o"] is True


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_fault_in_an_st_fb_stops_the_callers_network_from_the_call_box_on(variant):
    """An ST body has no elements: where its fault stands is a line, so the caller's rung stops at the call box."""
    divider = Pou(
        name="Divider",
        kind="function_block",
        language="st",
        declarations="VAR_INPUT A, B : INT; END_VAR VAR_OUTPUT Q : INT; END_VAR",
        body="Q := A / B;",
    )
    main = ld_pou(
        "Main",
        "VAR START : BOOL := TRUE; OK : BOOL; X : INT := 6; Y : INT := 3; W, Z : INT; F1 : Divider; END_VAR",
        rung(
            "n1",
            contact("s", "START"),
            box("a", "ADD", en=True, outputs={"OUT": "W"}, IN1="X", IN2="1"),
            box("f", "Divider", instance="F1", en=True, outputs={"Q": "Z"}, A="W", B="Y"),
            coil("o", "OK"),
        ),
    )
    sim = _sim(variant, divider, main)
    sim.cycle(1)
    assert None not in _shown(sim, "MAIN").values()
    sim.write("Main.X", 9)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    assert sim.fault is not None and (sim.fault.code, sim.fault.origin.line) == ("division_by_zero", 1)
    shown = _shown(sim, "MAIN")
    assert {e: shown[e] for e in ("s", "a", "a.OUT")} == {"s": True, "a": True, "a.OUT": 10}
    assert {e for e, value in shown.items() if value is None} == set(shown) - {"s", "a", "a.OUT"}
    assert {"f", "o"} <= set(shown)


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_fault_inside_an_ld_function_stops_its_network_and_the_callers(variant):
    quotient = ld_pou(
        "Quot",
        "VAR_INPUT A, B : INT; END_VAR VAR T : INT; END_VAR",
        rung(
            "m1",
            box("p", "ADD", en=True, outputs={"OUT": "T"}, IN1="A", IN2="1"),
            box("q", "DIV", en=True, outputs={"OUT": "Quot"}, IN1="T", IN2="B"),
        ),
        kind="function",
    )
    quotient.return_type = "INT"
    main = ld_pou(
        "Main",
        "VAR START : BOOL := TRUE; OK : BOOL; X : INT := 6; Y : INT := 3; Z : INT; END_VAR",
        rung(
            "n1", contact("s", "START"), box("f", "Quot", en=True, outputs={"OUT": "Z"}, A="X", B="Y"), coil("o", "OK")
        ),
    )
    sim = _sim(variant, quotient, main)
    sim.cycle(1)
    assert _shown(sim, "Quot", "QUOT") == {"p": True, "p.OUT": 7, "q": True, "q.OUT": 2}
    assert _shown(sim, "MAIN") == {"s": True, "f": True, "f.OUT": 2, "o": True}
    sim.write("Main.X", 8)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    assert sim.fault is not None and (sim.fault.code, sim.fault.pou) == ("division_by_zero", "QUOT")
    assert _shown(sim, "Quot", "QUOT") == {"p": True, "p.OUT": 9, "q": None, "q.OUT": None}
    assert _shown(sim, "MAIN") == {"s": True, "f": None, "f.OUT": None, "o": None}


def test_a_history_seek_to_the_faulted_scan_shows_what_the_fault_stopped():
    """The history cannot redo a faulted scan: a seek to it restores the checkpoint after it (History.seek)."""
    sim = _sim("monitor", _ld_main())
    history = History(sim, min_interval=4)
    sim.cycle(3)
    sim.write("Main.Y", 0)
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.scan == 3
    live = _shown(sim, "MAIN")
    assert (live["a.OUT"], live["o"]) == (8, None)
    assert _shown(history.seek(1), "MAIN")["o"] is True
    assert _shown(history.seek(3), "MAIN") == live
