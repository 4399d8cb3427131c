"""Constant inputs stored once (issue 27; engine/codegen/constant_inputs.py, engine/stored_once.py).

A standard FB input that every call of its instance gives the same constant (``PT := T#50ms``) is stored when the
instance is made, not by each inlined call of the fast and monitor variants; an online write, force or release of
such a pin makes the next scan put the constant back before the program runs, as IEC's next call would store it
(a force still wins, as forces of any variable do). The debug variant calls ``execute`` and stores every input: it
is the reference the other two must match, scan by scan, under random online writes, forces and injected faults
of the pins.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.inputs import InputEvent
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.engine.test_fast_equals_debug import BOOLS, ld_programs
from tests.support import fuzz_settings

VARIANTS = ("fast", "monitor", "debug")

#: FB input pins of the random programs' instances, and values an online write or force may give them
_PINS = st.sampled_from(["T1.PT", "T2.PT", "K1.PV", "T1.IN", "K1.R", "K1.CU"])
_VALUES = {"PT": st.sampled_from(["T#0ms", "T#3ms", "T#25ms", "T#1s"]), "PV": st.integers(-2, 6)}
_ACTIONS = st.one_of(
    st.tuples(st.sampled_from(["write", "force", "stuck", "noisy"]), _PINS, st.integers(-2, 40)),
    st.tuples(st.sampled_from(["release", "clear_fault"]), _PINS, st.none()),
    st.tuples(st.just("input"), st.sampled_from(BOOLS), st.booleans()),
)


def _value(pin: str, number: int | None) -> object:
    if pin.endswith(".PT"):
        return f"T#{number}ms" if number is not None and number >= 0 else "T#0ms"
    if pin.endswith(".PV"):
        return number
    return bool(number and number % 2)


def _act(sim, action: tuple) -> None:
    kind, name, number = action
    if kind == "input":
        sim.write(f"Main.{name}", number)
    elif kind == "write":
        sim.write(f"Main.{name}", _value(name, number))
    elif kind == "force":
        sim.force(f"Main.{name}", _value(name, number))
    elif kind == "release":
        sim.unforce(f"Main.{name}")
    elif kind == "clear_fault":
        sim.submit(InputEvent("clear_fault", f"Main.{name}"))
    elif name.endswith(".PV"):  # injected faults (inputs.py) act on BOOLs and numbers (not TIME): held, or noise
        value = _value(name, number) if kind == "stuck" else None
        sim.submit(InputEvent("fault", f"Main.{name}", value, mode=kind, amplitude=3.0, seed=number))


@fuzz_settings(fast=40)
@given(project=ld_programs(), scans=st.lists(st.lists(_ACTIONS, max_size=3), min_size=1, max_size=10))
def test_online_writes_and_forces_of_fb_inputs_act_as_the_debug_variants_stores(project, scans):
    builds = [build_project(project, variant) for variant in VARIANTS]
    assert all(build.compiled is not None for build in builds), [d.message for d in builds[0].diagnostics]
    fast, monitor, debug = (build.simulation() for build in builds)
    assert fast.snapshot() == monitor.snapshot() == debug.snapshot()
    for scan, actions in enumerate(scans):
        for action in actions:
            for sim in (fast, monitor, debug):
                _act(sim, action)
        assert fast.cycle(1) == monitor.cycle(1) == debug.cycle(1) == 1
        assert fast.snapshot() == debug.snapshot() == monitor.snapshot(), f"scan {scan}"
        assert monitor.probes("Main") == debug.probes("Main"), f"scan {scan}"


TIMER = """
PROGRAM Main
VAR go, done : BOOL; T1 : TON; K1 : CTU; n : INT; END_VAR
T1(IN := go, PT := T#50ms);
K1(CU := T1.Q, PV := 2);
done := K1.Q;
n := K1.CV;
END_PROGRAM
"""


COUNTER = """
PROGRAM Main
VAR go, done : BOOL; K1 : CTU; END_VAR
K1(CU := go, PV := 2);
done := K1.Q;
END_PROGRAM
"""


def _simulations(text: str) -> list:
    project, diagnostics = source_to_project(text, "p")
    assert project is not None and diagnostics == []
    builds = [build_project(project, variant) for variant in VARIANTS]
    assert all(build.compiled is not None for build in builds), [d.message for d in builds[0].diagnostics]
    return builds


def test_a_constant_input_is_stored_when_the_instance_is_made_not_by_each_call():
    """The fast source makes T1 with PT and K1 with PV in them and its calls store IN and CU only; the debug
    variant's calls still store PT and PV. Every variant's pins read the constants, before the first scan too."""
    fast, _, debug = _simulations(TIMER)
    source = fast.compiled.source
    assert "ll_pins(self, 'v_T1', 'PT', 50)" in source and "ll_pins(self, 'v_K1', 'PV', 2)" in source
    assert "ll_fb.IN = self.v_GO" in source and "ll_fb.PT =" not in source and "ll_fb.PV =" not in source
    assert "ll_fb.PT = 50" in debug.compiled.source
    for build in (fast, debug):
        sim = build.simulation()
        assert (sim.read("Main.T1.PT"), sim.read("Main.K1.PV")) == (50, 2)


@pytest.mark.parametrize("variant", VARIANTS)
def test_an_online_write_of_a_constant_input_is_overwritten_by_the_next_call(variant):
    """IEC: ``T1(IN := go, PT := T#50ms)`` stores PT on every call, so a value written online lasts until the next
    call: the timer still times 50 ms (TON, SFB-18: Q after ET reaches PT), and PT reads T#50ms after the scan."""
    sim = _simulations(TIMER)[VARIANTS.index(variant)].simulation()
    sim.write("Main.go", True)
    sim.write("Main.T1.PT", "T#10ms")
    seen = []
    for _ in range(7):  # scans at 0, 10, ... 60 ms: ET 0, 10, ... capped at 50
        sim.cycle(1)
        seen.append((sim.read("Main.T1.PT"), sim.read("Main.T1.ET"), sim.read("Main.T1.Q")))
    assert (
        seen
        == [(50, 0, False), (50, 10, False), (50, 20, False), (50, 30, False), (50, 40, False)] + [(50, 50, True)] * 2
    )


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_forced_constant_input_reads_forced_and_the_constant_again_after_the_release(variant):
    """A force holds the pin at its value before and after every scan (the call's own store of PV acts between:
    the counter compares with PV 2, as today); released, the next call stores PV 2 again."""
    sim = _simulations(COUNTER)[VARIANTS.index(variant)].simulation()
    sim.force("Main.K1.PV", 7)
    for go in (True, False, True, False):  # two rising edges of CU (SFB-13: CV 2, Q := CV >= PV)
        sim.write("Main.go", go)
        sim.cycle(1)
    assert (sim.read("Main.K1.PV"), sim.read("Main.K1.CV"), sim.read("Main.done")) == (7, 2, True)
    sim.unforce("Main.K1.PV")
    assert sim.read("Main.K1.PV") == 7  # until the next call
    sim.cycle(1)
    assert sim.read("Main.K1.PV") == 2


def test_a_restored_state_gets_its_constant_inputs_back_at_the_next_scan():
    """A state captured with a force on PV (the pin holding the forced value) restored into another simulation and
    released there: its next scan stores PV 2 again, in the fast variant as the debug variant's call does."""
    for build in _simulations(COUNTER):
        sim = build.simulation()
        sim.force("Main.K1.PV", 7)
        sim.cycle(1)
        other = build.simulation()
        other.restore(sim.state())
        other.unforce("Main.K1.PV")
        other.cycle(1)
        assert other.read("Main.K1.PV") == 2, build.compiled.variant


@pytest.mark.parametrize(
    "text",
    [
        "T1(IN := go, PT := T#50ms); x := T1.PT;",  # read outside the call
        "T1(IN := go, PT := T#50ms); T1.PT := T#5ms;",  # written outside the call
        "T1(IN := go, PT := T#50ms); T1(IN := go, PT := T#40ms);",  # two constants
        "T1(IN := go, PT := T#50ms); T1(IN := go);",  # a call without it
        "IF go THEN T1(IN := go, PT := T#50ms); END_IF;",  # not on every run of the body
        "p := ADR(T1); T1(IN := go, PT := T#50ms);",  # reachable through a pointer
        "IF go THEN RETURN; END_IF; T1(IN := go, PT := T#50ms);",  # a call a RETURN may skip
    ],
)
def test_a_pin_something_else_may_touch_is_stored_by_every_call(text):
    program = f"PROGRAM Main\nVAR go : BOOL; T1 : TON; x : TIME; p : POINTER TO TON; END_VAR\n{text}\nEND_PROGRAM\n"
    fast = _simulations(program)[0]
    assert "ll_pins(" not in fast.compiled.source
    assert "ll_fb.PT = 50" in fast.compiled.source


BLINK = """
PROGRAM Blink
VAR go : BOOL; T1 : TON; END_VAR
T1(IN := go, PT := T#50ms);
END_PROGRAM
CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK fast (INTERVAL := T#10ms, PRIORITY := 1);
        TASK slow (INTERVAL := T#20ms, PRIORITY := 2);
        PROGRAM a WITH fast : Blink;
        PROGRAM b WITH slow : Blink;
    END_RESOURCE
END_CONFIGURATION
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_written_constant_input_lasts_until_the_task_of_its_program_runs(variant):
    """Two instances of one program in a 10 ms and a 20 ms task (the first scan runs the fast one only, the second
    both, tests/engine/test_configurations.py): a value written into both pins lasts until each instance's next
    call, so after the first scan a's pin reads T#50ms again and b's still T#5ms, after the second both T#50ms."""
    sim = _simulations(BLINK)[VARIANTS.index(variant)].simulation()
    assert "ll_pins(self, 'v_T1', 'PT', 50)" in sim.compiled.source
    for name in ("a", "b"):
        sim.write(f"{name}.T1.PT", "T#5ms")
    seen = []
    for _ in range(2):
        sim.cycle(1)
        seen.append((sim.read("a.T1.PT"), sim.read("b.T1.PT")))
    assert seen == [(50, 5), (50, 50)]


@pytest.mark.parametrize(
    "configuration",
    [
        "VAR_ACCESS seen : Cpu.a.T1.PT : TIME READ_ONLY; END_VAR",  # an access path shows it from the first scan
        "VAR_CONFIG a.T1.PT : TIME := T#7ms; END_VAR",  # its initial value until the first call
    ],
)
def test_a_pin_the_configuration_names_is_stored_by_every_call(configuration):
    text = BLINK.replace("END_CONFIGURATION", f"    {configuration}\nEND_CONFIGURATION")
    fast = _simulations(text)[0]
    assert "ll_fb.PT = 50" in fast.compiled.source and "ll_pins(" not in fast.compiled.source


def test_a_program_another_program_calls_keeps_its_stores():
    """A PROGRAM called from another POU besides its task may run twice in a scan: its calls keep their stores."""
    text = (
        "PROGRAM Main\nVAR go : BOOL; T1 : TON; END_VAR\nT1(IN := go, PT := T#50ms);\nEND_PROGRAM\n"
        "PROGRAM Other\nMain();\nEND_PROGRAM\n"
    )
    fast = _simulations(text)[0]
    assert "ll_fb.PT = 50" in fast.compiled.source and "ll_pins(" not in fast.compiled.source
