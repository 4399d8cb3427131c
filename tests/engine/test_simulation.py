"""The Simulation API: paths, read/write/force (ON-06, ON-07), reset (VAR-82..85), snapshot, statistics."""

from __future__ import annotations

import pytest

from ladderlab.engine.compile import CompileError, compile_program
from ladderlab.engine.paths import UnknownPath
from ladderlab.engine.simulation import Simulation
from ladderlab.ir import types as t

from .irbuild import (
    BOOL,
    DINT,
    INT,
    REAL,
    STRING,
    TIME,
    add,
    array,
    assign,
    c,
    fb,
    fbcall,
    g,
    pou,
    prog,
    slot,
    string,
    struct,
    trace,
    v,
)

POINT = struct("POINT", ("X", INT), ("NAME", string(8), "p"))
COLOR = t.Enum("COLOR", (("RED", 0), ("GREEN", 1), ("BLUE", 5)))
PCT = t.Subrange(INT, 0, 100)


def _program():
    """MAIN counts up, copies IN to OUT every scan and runs a TON; globals: a RETAIN and a plain counter."""
    cnt, out, inp = v("COUNT", INT), v("OUT", INT), v("IN", INT)
    main = pou(
        "MAIN",
        [
            slot("COUNT", INT),
            slot("IN", INT),
            slot("OUT", INT),
            slot("T1", fb("TON")),
            slot("ARR", array(INT, (1, 3)), initial=(1, 2, 3)),
            slot("GRID", array(BOOL, (0, 1), (0, 1))),
            slot("P", POINT),
            slot("COLOR", COLOR),
            slot("PCT", PCT),
            slot("R", REAL),
            slot("D", TIME),
            slot("S", STRING),
            slot("HIDDEN", INT, hidden=True),
        ],
        [
            assign(cnt, add(cnt, c(1, INT))),
            assign(out, inp),
            fbcall(v("T1", fb("TON")), {"IN": c(True, BOOL), "PT": c(25, TIME)}),
            assign(g("WARM", DINT), add(g("WARM", DINT), c(1, DINT))),
            assign(g("COLD", DINT), add(g("COLD", DINT), c(1, DINT))),
        ],
    )
    return prog(
        main,
        globals=[
            slot("WARM", DINT, "VAR_GLOBAL", initial=100, retain=True),
            slot("COLD", DINT, "VAR_GLOBAL", initial=100),
        ],
    )


@pytest.fixture
def sim():
    return Simulation(_program())


def test_paths_are_case_insensitive_and_reach_members_elements_and_globals(sim):
    sim.cycle(2)
    assert sim.read("main.count") == sim.read("MAIN.COUNT") == 2
    assert sim.read("Main.T1.ET") == 10 and sim.read("MAIN.t1.q") is False
    assert sim.read("MAIN.ARR[2]") == 2 and sim.read("MAIN.ARR") == [1, 2, 3]
    assert sim.read("MAIN.GRID[1, 0]") is False and sim.read("MAIN.GRID[1]") == [False, False]
    assert sim.read("MAIN.P.NAME") == "p" and sim.read("MAIN.P") == {"X": 0, "NAME": "p"}
    assert sim.read("warm") == sim.read("GVL.WARM") == 102
    assert sim.read("MAIN.T1")["PT"] == 25


@pytest.mark.parametrize(
    ("path", "error", "message"),
    [
        ("MAIN.CONUT", UnknownPath, "MAIN has no variable 'CONUT' - did you mean 'COUNT'?"),
        ("MIAN.COUNT", UnknownPath, "unknown variable or program 'MIAN' - did you mean 'MAIN'?"),
        ("GVL.WRAM", UnknownPath, "unknown global variable 'WRAM' - did you mean 'WARM'?"),
        ("MAIN.T1.QQ", UnknownPath, "MAIN.T1 (TON) has no pin 'QQ' - did you mean 'Q'?"),
        ("MAIN.P.Y", UnknownPath, "MAIN.P (POINT) has no field 'Y'"),
        ("MAIN.ARR[4]", ValueError, "index 4 of MAIN.ARR is outside 1..3"),
        ("MAIN.ARR[1, 1]", ValueError, "MAIN.ARR has 1 dimension(s), not 2"),
        ("MAIN.COUNT.X", ValueError, "MAIN.COUNT is an INT: it has no member 'X'"),
        ("MAIN.COUNT[1]", ValueError, "MAIN.COUNT is an INT: it cannot be indexed"),
        ("MAIN.ARR[x]", ValueError, "'MAIN.ARR[x]': array indices must be integers"),
        ("MAIN..COUNT", ValueError, "'MAIN..COUNT': expected '.name' after MAIN"),
        ("MAIN.COUNT;", ValueError, "'MAIN.COUNT;' is not a variable path (unexpected ';')"),
    ],
)
def test_bad_paths_are_refused_with_a_message(sim, path, error, message):
    with pytest.raises(error) as raised:
        sim.read(path)
    assert str(raised.value) == message


def test_write_is_applied_once_before_the_next_scan_on06(sim):
    sim.write("MAIN.COUNT", 1000)
    assert sim.read("MAIN.COUNT") == 0  # pending until the next scan
    assert trace(sim, ["MAIN.COUNT"], 2) == [(1001,), (1002,)]


def test_force_holds_the_value_even_against_the_program_on07(sim):
    """A forced variable the program assigns is back at the forced value after every scan."""
    sim.force("MAIN.COUNT", 7)
    sim.force("MAIN.IN", "16#10")
    assert sim.read("MAIN.COUNT") == 7 and sim.forced == {"MAIN.COUNT": 7, "MAIN.IN": 16}
    assert trace(sim, ["MAIN.COUNT", "MAIN.OUT"], 2) == [(7, 16), (7, 16)]
    sim.unforce("main.count")
    assert trace(sim, ["MAIN.COUNT", "MAIN.OUT"], 1) == [(8, 16)]
    sim.unforce_all()
    sim.write("MAIN.IN", 3)
    assert trace(sim, ["MAIN.OUT"], 1) == [(3,)] and sim.forced == {}


@pytest.mark.parametrize(
    ("path", "value", "stored"),
    [
        ("MAIN.R", "1.5", 1.5),
        ("MAIN.R", 2, 2.0),
        ("MAIN.D", "T#1m30s", 90_000),
        ("MAIN.S", "hello", "hello"),
        ("MAIN.COLOR", "BLUE", 5),
        ("MAIN.COLOR", "color#green", 1),
        ("MAIN.COLOR", 5, 5),
        ("MAIN.PCT", 100, 100),
        ("MAIN.T1.PT", "T#2s", 2000),
        ("MAIN.GRID[0, 1]", "TRUE", True),
        ("MAIN.P.X", -3, -3),
    ],
)
def test_forces_and_writes_accept_python_values_and_iec_literals(sim, path, value, stored):
    sim.force(path, value)  # applied at once as well
    assert sim.read(path) == stored
    sim.unforce(path)
    sim.write(path, value)


@pytest.mark.parametrize(
    ("path", "value", "message"),
    [
        ("MAIN.COUNT", 40000, "MAIN.COUNT: 40000 is out of range for INT (-32768..32767)"),
        ("MAIN.COUNT", "abc", "MAIN.COUNT: 'abc' is not an INT"),
        ("MAIN.PCT", 101, "MAIN.PCT: 101 is outside the subrange 0..100"),
        ("MAIN.COLOR", "PINK", "MAIN.COLOR: 'PINK' is not a value of COLOR (RED, GREEN, BLUE)"),
        ("MAIN.COLOR", 2, "MAIN.COLOR: 2 is not a value of COLOR (RED, GREEN, BLUE)"),
        ("MAIN.ARR", [1, 2, 3], "MAIN.ARR is an ARRAY [1..3] OF INT: write its elements one by one"),
        ("MAIN.T1", 1, "MAIN.T1 is a TON: write its elements one by one"),
    ],
)
def test_bad_values_are_refused_naming_the_path(sim, path, value, message):
    with pytest.raises(ValueError) as raised:
        sim.write(path, value)
    assert str(raised.value) == message
    with pytest.raises(ValueError):
        sim.force(path, value)


def test_warm_reset_keeps_retain_cold_reset_reinitialises_var82(sim):
    sim.cycle(3)
    assert (sim.read("WARM"), sim.read("COLD"), sim.read("MAIN.COUNT")) == (103, 103, 3)
    sim.reset()
    assert (sim.read("WARM"), sim.read("COLD"), sim.read("MAIN.COUNT"), sim.read("MAIN.T1.ET")) == (103, 100, 0, 0)
    sim.cycle()
    sim.reset(cold=True)
    assert (sim.read("WARM"), sim.read("COLD"), sim.read("MAIN.ARR")) == (100, 100, [1, 2, 3])


def test_retain_survives_warm_reset_inside_user_fb_instances():
    keep, lose = v("KEEP", INT), v("LOSE", INT)
    user = pou(
        "KEEPER",
        [slot("KEEP", INT, retain=True), slot("LOSE", INT)],
        [assign(keep, add(keep, c(1, INT))), assign(lose, add(lose, c(1, INT)))],
        kind="function_block",
    )
    main = pou("MAIN", [slot("K", fb("KEEPER"))], [fbcall(v("K", fb("KEEPER")))])
    sim = Simulation(prog(main, user))
    sim.cycle(4)
    sim.reset()
    assert (sim.read("MAIN.K.KEEP"), sim.read("MAIN.K.LOSE")) == (4, 0)
    sim.reset(cold=True)
    assert (sim.read("MAIN.K.KEEP"), sim.read("MAIN.K.LOSE")) == (0, 0)


def test_snapshot_lists_every_elementary_variable(sim):
    sim.cycle()
    snap = sim.snapshot()
    assert snap["MAIN.COUNT"] == 1 and snap["MAIN.ARR[3]"] == 3 and snap["MAIN.GRID[1, 1]"] is False
    assert snap["MAIN.P.NAME"] == "p" and snap["MAIN.T1.ET"] == 0 and snap["WARM"] == 101
    assert "MAIN.HIDDEN" not in snap and sim.read("MAIN.HIDDEN") == 0
    assert sorted(snap) == sorted(
        [
            "MAIN.COUNT",
            "MAIN.IN",
            "MAIN.OUT",
            "MAIN.T1.IN",
            "MAIN.T1.PT",
            "MAIN.T1.Q",
            "MAIN.T1.ET",
            "MAIN.ARR[1]",
            "MAIN.ARR[2]",
            "MAIN.ARR[3]",
            "MAIN.GRID[0, 0]",
            "MAIN.GRID[0, 1]",
            "MAIN.GRID[1, 0]",
            "MAIN.GRID[1, 1]",
            "MAIN.P.X",
            "MAIN.P.NAME",
            "MAIN.COLOR",
            "MAIN.PCT",
            "MAIN.R",
            "MAIN.D",
            "MAIN.S",
            "WARM",
            "COLD",
        ]
    )


def test_time_and_scan_statistics(sim):
    assert sim.time_ms == 0 and sim.stats.count == 0
    sim.cycle(3)
    assert sim.time_ms == 30 and sim.scan_count == 3
    assert sim.stats.count == 3 and 0 < sim.stats.min_ms <= sim.stats.avg_ms <= sim.stats.max_ms
    assert sim.run_for(25) == 2 and sim.time_ms == 50
    assert sim.scan_at(52.5) and sim.time_ms == 52.5 and sim.read("MAIN.T1.ET") == 25
    assert sim.next_scan_time() == 60
    with pytest.raises(ValueError, match="before the current time"):
        sim.scan_at(50)


def test_simulations_of_one_compiled_program_share_nothing():
    compiled = compile_program(_program())
    first, second = Simulation(compiled), Simulation(compiled)
    first.cycle(5)
    assert (first.read("MAIN.COUNT"), second.read("MAIN.COUNT"), second.read("WARM")) == (5, 0, 100)


def test_compile_errors_are_located_diagnostics():
    bad = pou(
        "MAIN",
        [slot("X", INT)],
        [assign(v("X", INT), v("NOPE", INT)), fbcall(v("X", INT)), assign(v("X", INT), c(1, INT))],
    )
    with pytest.raises(CompileError) as raised:
        Simulation(prog(bad))
    messages = [(d.line, d.message) for d in raised.value.diagnostics]
    assert messages == [(1, "unknown variable NOPE in MAIN"), (2, "X is not an FB instance")]
    assert "POU MAIN line 1 column 1: unknown variable NOPE in MAIN" in str(raised.value)
