"""CODESYS ``TIME()`` (issue 25 item 1: OSCAT BASIC's T_PLC_MS and T_PLC_US read the PLC timer with it, and 94 OSCAT
POUs call those): "the time in milliseconds since the system started", a TIME. Here the system is the simulation:
its virtual clock at the start of the running scan, the same clock the timers (TON ...) run on, in whole
milliseconds. CODESYS's TIME counts 32 bits of milliseconds and wraps after 2^32 ms (49.7 days); LadderLab's TIME is
32-bit signed, so past 2^31 ms TIME() is negative, and ``TIME_TO_DWORD(TIME())`` (what T_PLC_MS returns) is the same
DWORD in both: the milliseconds modulo 2^32.
"""

from __future__ import annotations

from .test_references import build

PLC_MS = "FUNCTION PLC_MS : DWORD\nVAR tx : TIME; END_VAR\ntx := TIME();\nPLC_MS := TIME_TO_DWORD(tx);\nEND_FUNCTION\n"


def _simulation(body: str, declarations: str):
    result = build(f"{PLC_MS}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n")
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def test_time_is_the_clock_of_the_running_scan_in_programs_and_functions():
    sim = _simulation(
        "now := TIME();\nstep := now - before;\nbefore := now;\nms := PLC_MS();\nton(IN := TRUE, PT := T#1h);",
        "now, before, step : TIME; ms : DWORD; ton : TON; started : TIME;",
    )
    sim.cycle(1)
    first = sim.read("Main.now")
    assert first == sim.time_ms and sim.read("Main.ms") == first  # the scan's clock, in a function too
    for scan in range(1, 5):
        sim.cycle(1)
        # one task period (10 ms, the default task) between two scans, as the TON counts it
        assert (sim.read("Main.now"), sim.read("Main.step")) == (first + 10 * scan, 10)
        assert sim.read("Main.ton")["ET"] == 10 * scan
        assert sim.read("Main.ms") == sim.read("Main.now")


def test_past_two_to_the_31_milliseconds_the_dword_keeps_counting_and_wraps_at_2_to_the_32():
    sim = _simulation("now := TIME();\nms := PLC_MS();", "now : TIME; ms : DWORD;")
    sim.advance_clock(2**31 + 5)  # 24.9 days
    sim.cycle(1)
    at = int(sim.time_ms)
    assert (sim.read("Main.ms"), sim.read("Main.now")) == (at, at - 2**32)
    sim.advance_clock(2**31)  # 49.7 days: past 2^32 ms
    sim.cycle(1)
    assert sim.read("Main.ms") == int(sim.time_ms) - 2**32


def test_a_project_may_define_its_own_time_function_and_calls_that():
    """TIME() is CODESYS's, not IEC's: a project's own FUNCTION TIME is no redefinition of a standard function and
    is what ``TIME()`` calls there (IronPLC end_to_end_time_function, allow_time_as_function_name)."""
    result = build(
        "FUNCTION TIME : TIME\nTIME := T#5s;\nEND_FUNCTION\nPROGRAM Main\nVAR t : TIME; END_VAR\n"
        "t := TIME();\nEND_PROGRAM\n"
    )
    assert [d.format() for d in result.diagnostics] == []
    sim = result.simulation()
    sim.cycle(3)
    assert sim.read("Main.t") == 5000
