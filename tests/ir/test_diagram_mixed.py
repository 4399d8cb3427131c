"""Mixed-language calls (issue 5): LD uses an ST FB, ST uses an LD FB, FBD uses an ST function; the motor example."""

from __future__ import annotations

import itertools
from pathlib import Path

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Pou
from ladderlab.storage.load import read_project_folder
from tests.ir.diagram_support import (
    blk,
    box,
    coil,
    contact,
    fbd_pou,
    inp,
    ld_pou,
    net,
    out,
    rung,
    simulate,
    trace,
)
from tests.support import EXAMPLES


def st_pou(name: str, kind: str, declarations: str, body: str, return_type: str | None = None) -> Pou:
    return Pou(name=name, kind=kind, language="st", declarations=declarations, body=body, return_type=return_type)


def test_ld_program_calls_an_st_function_block():
    """An ST toggle FB in an LD box: power enters its first BOOL input, its first BOOL output carries it on."""
    toggle = st_pou(
        "Toggle",
        "function_block",
        "VAR_INPUT clk : BOOL; END_VAR VAR_OUTPUT q : BOOL; END_VAR VAR edge : R_TRIG; END_VAR",
        "edge(CLK := clk);\nIF edge.Q THEN q := NOT q; END_IF;",
    )
    main = ld_pou(
        "Main",
        "VAR button, light : BOOL; t : Toggle; END_VAR",
        rung("n", contact("b", "button"), box("tg", "Toggle", "t"), coil("l", "light")),
    )
    presses = [True, True, False, True, False, False, True]
    assert trace(simulate(toggle, main), "Main", [{"button": p} for p in presses], ["light"]) == [
        (True,),
        (True,),
        (True,),
        (False,),
        (False,),
        (False,),
        (True,),
    ]


def test_st_program_calls_an_ld_function_block_and_each_instance_has_its_own_edge_memory():
    """Invariant 7: the P contact's memory is per instance, so u1 and u2 see only their own input's edges."""
    pulse = ld_pou(
        "Pulse",
        "VAR_INPUT x : BOOL; END_VAR VAR_OUTPUT q : BOOL; END_VAR",
        rung("n", contact("edge", "x", "p"), coil("out", "q")),
        kind="function_block",
    )
    main = st_pou(
        "Main",
        "program",
        "VAR a, b, qa, qb : BOOL; u1, u2 : Pulse; END_VAR",
        "u1(x := a, q => qa);\nu2(x := b, q => qb);",
    )
    scans = [(True, False), (True, True), (False, True), (True, False), (True, True)]
    assert trace(simulate(pulse, main), "Main", [{"a": a, "b": b} for a, b in scans], ["qa", "qb"]) == [
        (True, False),
        (False, True),
        (False, False),
        (True, False),
        (False, True),
    ]


def test_fbd_network_calls_a_user_function_written_in_st():
    clamp = st_pou(
        "Clamp", "function", "VAR_INPUT x, lo, hi : INT; END_VAR", "Clamp := MIN(MAX(x, lo), hi);", return_type="INT"
    )
    main = fbd_pou(
        "Main",
        "VAR raw, level : INT; END_VAR",
        net(
            "n",
            [inp("r", "raw"), inp("lo", "0"), inp("hi", "100"), blk("c", "Clamp"), out("o", "level")],
            [("r.OUT", "c.X"), ("lo.OUT", "c.LO"), ("hi.OUT", "c.HI"), ("c.OUT", "o.IN")],
        ),
    )
    assert trace(simulate(clamp, main), "Main", [{"raw": v} for v in (50, -7, 250, 100)], ["level"]) == [
        (50,),
        (0,),
        (100,),
        (100,),
    ]


def test_ld_function_block_called_from_fbd_with_en():
    """An LD FB as an FBD block with EN: with EN FALSE it is not called, so its outputs and its timer's ET
    keep their values; called again, the TON sees the time since IN rose (SFB-19: one clock per scan)."""
    delay = ld_pou(
        "Delay",
        "VAR_INPUT go : BOOL; END_VAR VAR_OUTPUT done : BOOL; END_VAR VAR t : TON; END_VAR",
        rung("n", contact("g", "go"), box("t", "TON", "t", PT="T#30ms"), coil("d", "done")),
        kind="function_block",
    )
    main = fbd_pou(
        "Main",
        "VAR run, go, done : BOOL; d : Delay; END_VAR",
        net(
            "n",
            [inp("r", "run"), inp("g", "go"), blk("d", "Delay", "d", en=True), out("o", "done")],
            [("r.OUT", "d.EN"), ("g.OUT", "d.GO"), ("d.DONE", "o.IN")],
        ),
    )
    scans = [{"run": True, "go": True}, {}, {"run": False}, {}, {}, {"run": True}, {}]
    assert trace(simulate(delay, main), "Main", scans, ["done", "d.t.ET"]) == [
        (False, 0),
        (False, 10),
        (False, 10),
        (False, 10),
        (False, 10),
        (True, 30),
        (True, 30),
    ]


def test_motor_example_start_stop_seal_in_timer_counter_and_st_blinker():
    """examples/motor: Main (LD) seals Motor in, MotorRunning after 5 s, counts starts, blinks Lamp via the ST
    FB Blinker; Scaling (FBD) computes Speed from StartCount. Blinker toggles when its TON (Period / 2 =
    250 ms) expires and restarts the timer in the next call, so Lamp switches every 26 scans of 10 ms."""
    result = lower_project(read_project_folder(Path(EXAMPLES / "motor")))
    sim = Simulation(result.program)

    def step(**inputs):
        for name, value in inputs.items():
            sim.write(name, value)
        sim.cycle(1)

    step(**{"Start": True})
    assert sim.read("Motor") is True and sim.read("StartCount") == 1 and sim.read("Speed") == 15
    step(**{"Start": False})
    assert sim.read("Motor") is True and sim.read("StartCount") == 1
    sim.run_for(4980)  # up to t = 5000 ms: the TON started at 10 ms
    assert sim.read("Main.MotorRunning") is False
    step()
    assert sim.read("Main.MotorRunning") is True and sim.read("Main.Lamp") is False
    lamp = []
    for _ in range(60):
        step()
        lamp.append(sim.read("Main.Lamp"))
    switches = [i for i in range(1, len(lamp)) if lamp[i] != lamp[i - 1]]
    assert [b - a for a, b in itertools.pairwise(switches)] == [26] * (len(switches) - 1) and len(switches) >= 2
    step(**{"Stop": True})
    assert sim.read("Motor") is False
    step(**{"Stop": False})
    assert sim.read("Main.MotorRunning") is False and sim.read("Main.Lamp") is False
