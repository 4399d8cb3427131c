"""The single entry point of inputs (issue 21, item 2; engine/inputs.py): every input applies at a scan start
(or at once, as documented), is reported with its scan, and injected faults act where plant and program meet."""

from __future__ import annotations

import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.inputs import AppliedInput, InputEvent, InputRefused

from .plant_support import TANK_CONTROL, TANK_GLOBALS, TANK_PLANT, simulate, st_pou

COUNTER = st_pou(
    "Main",
    "program",
    "VAR\n    Button : BOOL;\n    Presses : INT;\n    Seen : INT;\n    Edge : R_TRIG;\n    R : REAL;\nEND_VAR",
    "Edge(CLK := Button);\nIF Edge.Q THEN\n    Presses := Presses + 1;\nEND_IF;\nIF Button THEN\n"
    "    Seen := Seen + 1;\nEND_IF;",
)


def _recording(sim) -> list[AppliedInput]:
    applied: list[AppliedInput] = []
    sim.on_input = applied.append
    return applied


def test_a_panel_event_applies_at_the_start_of_the_next_scan_and_is_recorded_with_it():
    sim = simulate(COUNTER)
    applied = _recording(sim)
    sim.cycle(2)
    sim.submit(InputEvent("panel", "Main.Button", True, source="panel P/b1"))
    assert sim.read("Main.Button") is False and applied == []  # queued, not applied
    sim.cycle()
    assert (sim.read("Main.Presses"), sim.read("Main.Seen")) == (1, 1)
    assert [a.to_json() for a in applied] == [
        {"scan": 2, "kind": "panel", "path": "Main.Button", "value": True, "source": "panel P/b1"}
    ]


def test_a_click_shorter_than_a_scan_still_lasts_one_scan():
    """Press and release before the same scan: the release waits a scan, so the program sees the press once."""
    sim = simulate(COUNTER)
    applied = _recording(sim)
    sim.submit(InputEvent("panel", "Main.Button", True))
    sim.submit(InputEvent("write", "Main.R", 1.5))  # another variable: not held back
    sim.submit(InputEvent("panel", "Main.Button", False))
    sim.cycle()
    assert (sim.read("Main.Button"), sim.read("Main.Seen"), sim.read("Main.R")) == (True, 1, 1.5)
    sim.cycle()
    assert (sim.read("Main.Button"), sim.read("Main.Seen"), sim.read("Main.Presses")) == (False, 1, 1)
    assert [(a.scan, a.event.kind, a.event.value) for a in applied] == [
        (0, "panel", True),
        (0, "write", 1.5),
        (1, "panel", False),
    ]


def test_events_after_a_waiting_panel_event_on_the_same_variable_wait_too():
    sim = simulate(COUNTER)
    applied = _recording(sim)
    for value in (True, False, True):
        sim.submit(InputEvent("panel", "Main.Button", value))
    sim.submit(InputEvent("write", "Main.Button", False))
    for _ in range(4):
        sim.cycle()
    assert [(a.scan, a.event.value) for a in applied] == [(0, True), (1, False), (2, True), (2, False)]
    assert sim.read("Main.Presses") == 1  # scan 2 ends with the write (FALSE): one rising edge, at scan 0


def test_forces_releases_and_resets_act_at_once_and_are_recorded_for_the_next_scan():
    sim = simulate(COUNTER)
    applied = _recording(sim)
    sim.cycle(3)
    sim.force("Main.Button", True)
    assert sim.read("Main.Button") is True and sim.forced == {"MAIN.BUTTON": True}
    sim.unforce("Main.Button")
    sim.reset(cold=True)
    assert [(a.scan, a.phase, a.event.kind) for a in applied] == [
        (3, "start", "force"),
        (3, "start", "release"),
        (3, "start", "reset"),
    ]
    assert applied[-1].to_json() == {"scan": 3, "kind": "reset", "cold": True}


def test_a_write_while_halted_acts_on_the_halted_scan_and_records_the_halt():
    sim = simulate(COUNTER, variant="debug")
    applied = _recording(sim)
    sim.cycle(2)
    sim.set_breakpoint("Main", line=5)  # IF Button THEN
    assert not sim.cycle()
    sim.write("Main.Button", True)  # at once: this scan counts Seen, the edge was missed
    sim.submit(InputEvent("panel", "Main.R", 2.5))  # a panel's: waits for the next scan
    sim.resume()
    assert (sim.read("Main.Seen"), sim.read("Main.Presses"), sim.read("Main.R")) == (1, 0, 0.0)
    sim.clear_breakpoints()
    sim.cycle()
    assert sim.read("Main.R") == 2.5
    write, panel = applied
    assert (write.scan, write.phase, write.halts) == (2, "halt", 1) and write.pause is not None
    assert write.to_json()["halt"] == {"pause": write.pause, "count": 1}
    assert (panel.scan, panel.phase) == (3, "start")


def test_a_reset_of_a_halted_scan_gives_the_abandoned_scan_its_number():
    sim = simulate(COUNTER, variant="debug")
    applied = _recording(sim)
    sim.set_breakpoint("Main", line=1)
    assert not sim.cycle() and sim.scan_count == 0
    sim.reset()
    assert sim.halted is None and sim.scan_count == 1
    assert (applied[0].scan, applied[0].phase, applied[0].event.kind) == (0, "halt", "reset")


@pytest.mark.parametrize(
    ("event", "error", "message"),
    [
        (InputEvent("panel", "Main.Nope", True), KeyError, "Nope"),
        (InputEvent("panel", "Main.Presses", "lots"), ValueError, "MAIN.PRESSES"),
        (InputEvent("panel", "Main.Presses"), InputRefused, "a panel event needs a value"),
        (InputEvent("fault", "Main.Presses", mode="melted"), InputRefused, "a fault's mode must be one of"),
        (InputEvent("fault", "Main.Presses", mode="noisy"), InputRefused, "a noisy fault needs a seed"),
        (InputEvent("fault", "Main.Presses", mode="stuck_true"), InputRefused, "stuck_true is for BOOL signals"),
        (InputEvent("fault", "Main.Button", mode="stuck"), InputRefused, "hold a BOOL with stuck_true"),
        (InputEvent("fault", "Main.Edge", mode="open"), InputRefused, "faults act on one BOOL or numeric signal"),
        (InputEvent("fault", "Main.R", mode="noisy", seed=1, rate=2), InputRefused, "a probability from 0 to 1"),
    ],
)
def test_bad_inputs_are_refused_when_submitted_and_nothing_happens(event, error, message):
    sim = simulate(COUNTER)
    with pytest.raises(error) as raised:
        sim.submit(event)
    assert message in str(raised.value)
    assert sim.pending == []


def test_stuck_and_open_faults_hold_what_the_program_reads_from_the_plant():
    """The plant sets High from level 10 on; stuck FALSE the program never sees it and keeps pumping; cleared,
    the program stops the pump in the scan after the plant sets High again."""
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    sim.submit(InputEvent("fault", "High", mode="stuck_false"))
    levels = []
    for _ in range(8):
        sim.cycle()
        levels.append((sim.read("Level"), sim.read("High"), sim.read("Pump")))
    # the pump starts in the first scan; the plant fills from the second: 3 in, 1 out per scan
    assert levels == [(2 * n, False, True) for n in range(8)] and sim.injected == {"HIGH": "stuck_false"}
    sim.submit(InputEvent("clear_fault", "High"))
    sim.cycle()
    assert (sim.read("Level"), sim.read("High"), sim.read("Pump")) == (16, True, False)
    sim.submit(InputEvent("fault", "Level", mode="open"))
    sim.cycle()
    assert sim.read("Level") == 0 and sim.injected == {"LEVEL": "open"}


def test_a_fault_on_an_actuator_is_what_the_plant_reads():
    """Pump stuck FALSE: the program commands the pump, the plant's pump never runs, the level stays 0."""
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    sim.submit(InputEvent("fault", "Pump", mode="stuck_false"))
    sim.cycle(5)
    assert sim.read("Level") == 0


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), rate=st.floats(0, 1))
def test_a_noisy_bool_flips_as_its_seeded_generator_says(seed, rate):
    """Without a plant a signal crosses once per scan: flip when the generator's draw is below the rate."""
    sim = simulate(COUNTER)
    sim.submit(InputEvent("fault", "Main.Button", mode="noisy", seed=seed, rate=rate))
    reference, seen = random.Random(seed), 0
    for _ in range(40):
        sim.cycle()
        expected = reference.random() < rate  # the program never writes Button: the signal is FALSE
        seen += expected
        assert sim.read("Main.Button") is expected
    assert sim.read("Main.Seen") == seen


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), amplitude=st.floats(0, 1000, allow_nan=False))
def test_noisy_numbers_stray_within_the_amplitude_and_their_type(seed, amplitude):
    plant = st_pou("Gauge", "plant", "VAR_EXTERNAL\n    Level : INT;\nEND_VAR", "Level := 32760;")
    sim = simulate(TANK_CONTROL, plant, globals=TANK_GLOBALS)
    sim.submit(InputEvent("fault", "Level", mode="noisy", seed=seed, amplitude=amplitude))
    reference = random.Random(seed)
    for _ in range(10):
        sim.cycle()
        reference.random()  # the first crossing (before the plant) is overwritten by the plant
        noisy = 32760 + (2.0 * reference.random() - 1.0) * amplitude
        assert sim.read("Level") == min(32767, int(noisy + 0.5) if noisy >= 0 else -int(-noisy + 0.5))


def test_the_same_events_give_the_same_scans():
    """Replaying the recorded inputs of one run into a fresh simulation gives every scan's values again."""
    live = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    applied = _recording(live)
    expected = []
    for scan in range(30):
        if scan == 4:
            live.submit(InputEvent("fault", "High", mode="noisy", seed=99, rate=0.5))
        if scan == 12:
            live.force("Main.Starts", 7)
        if scan == 20:
            live.submit(InputEvent("clear_fault"))
            live.unforce_all()
        live.cycle()
        expected.append(live.snapshot())
    replay = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    lines = [a.to_json() for a in applied]
    for scan in range(30):
        for line in lines:
            if line["scan"] == scan:
                replay.submit(InputEvent.from_json(line))
        replay.cycle()
        assert replay.snapshot() == expected[scan], scan


LOCATED = st_pou(
    "Main",
    "program",
    "VAR_EXTERNAL\n    Start : BOOL;\n    Lamp : BOOL;\nEND_VAR\nVAR\n    Level AT %IW2 : INT;\n    Twice : INT;\nEND_VAR",
    "Lamp := Start;\nTwice := Level * 2;",
)
LOCATED_GLOBALS = "VAR_GLOBAL\n    Start AT %IX0.0 : BOOL;\n    Lamp AT %QX0.0 : BOOL;\nEND_VAR"


def test_a_panel_bound_to_a_direct_address_drives_the_variable_declared_at_it():
    """Issue 21 item 1, widgets bound to direct addresses (IEC 61131-3 2.4.1.1): %IX0.0 is the global Start,
    %IW2 the program's Level; values and faults are reported under the address the panel used."""
    sim = simulate(LOCATED, globals=LOCATED_GLOBALS)
    applied = _recording(sim)
    sim.submit(InputEvent("panel", "%ix0.0", True, source="panel P/start"))
    sim.submit(InputEvent("panel", "%IW2", 21))
    sim.cycle()
    assert (sim.read("Lamp"), sim.read("%QX0.0"), sim.read("Main.Twice"), sim.read("%iw2")) == (True, True, 42, 21)
    assert [(a.scan, a.event.path, a.event.value) for a in applied] == [(0, "%ix0.0", True), (0, "%IW2", 21)]
    sim.submit(InputEvent("fault", "%IX0.0", mode="stuck_false"))
    sim.cycle()
    assert (sim.read("Lamp"), sim.read("%QX0.0")) == (False, False)


@pytest.mark.parametrize(
    ("path", "error"),
    [
        ("%IX9.9", "%IX9.9: a byte has bits 0..7, not 9"),
        ("%QW2", "%QW2 is outside the process image: the program uses 1 byte(s) of %Q (%QB0..%QB0)"),
        ("%Q", "'%Q' is not a direct address such as %IX0.1, %QW4 or %MD8"),
        ("%IX0.0.", "'%IX0.0.' is not a direct address"),
    ],
)
def test_an_address_outside_the_image_or_malformed_is_refused_with_the_reason(path, error):
    """An address the program's process image does not hold, or that is no address, is refused with the
    reason (engine/paths.py's wording); one inside the image reads it even with nothing declared at it."""
    sim = simulate(LOCATED, globals=LOCATED_GLOBALS)
    with pytest.raises((KeyError, ValueError)) as refused:
        sim.read(path)
    assert error in str(refused.value)
    assert sim.read("%IX1.0") is False  # in the input image, no variable declared at it


HEAT = st_pou(
    "Heat",
    "plant",
    "VAR_EXTERNAL\n    T : REAL;\nEND_VAR\nVAR\n    Temp : REAL;\nEND_VAR",
    "Temp := Temp + 1.0;\nT := Temp;",
)
SEEN = st_pou("Main", "program", "VAR_EXTERNAL\n    T : REAL;\nEND_VAR\nVAR\n    Seen : REAL;\nEND_VAR", "Seen := T;")
HEAT_GLOBALS = "VAR_GLOBAL\n    T : REAL;\nEND_VAR"


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_noise_on_a_plants_own_variable_never_feeds_back_into_its_physics(seed):
    """The plant integrates Temp by 1 a scan and puts it out on T; noise of 0.5 on Heat.Temp is what is read
    of it after the plant ran (the panel, the program), while the plant goes on from the true value: after n
    scans Heat.Temp reads n within 0.5 and T is exactly n (noise fed back into the plant would wander off)."""
    sim = simulate(HEAT, SEEN, globals=HEAT_GLOBALS)
    sim.submit(InputEvent("fault", "Heat.Temp", mode="noisy", amplitude=0.5, seed=seed))
    for n in range(1, 201):
        sim.cycle()
        assert abs(sim.read("Heat.Temp") - n) <= 0.5 and sim.read("Main.Seen") == n, n


def test_a_stuck_plant_variable_is_what_is_read_while_the_plant_goes_on():
    sim = simulate(HEAT, SEEN, globals=HEAT_GLOBALS)
    sim.submit(InputEvent("fault", "Heat.Temp", mode="stuck", value=30))
    sim.cycle(50)
    assert (sim.read("Heat.Temp"), sim.read("Main.Seen")) == (30.0, 50.0)
    sim.submit(InputEvent("clear_fault", "Heat.Temp"))
    sim.cycle()
    assert sim.read("Heat.Temp") == 51.0  # the plant counted every scan: only the reading was stuck
