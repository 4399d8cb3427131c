"""The call stack of a halted scan (ON-03: halted, the values stay inspectable; issue 25 item 6): each POU call the
scan stands in, outermost first, with a FUNCTION's and a METHOD's own variables read from the suspended call.
Every expected value is worked out by hand from the program text: a call's variables start at their declared
initial values (IEC 61131-3: a function's variables are initialised at each call), inputs are the arguments.
"""

from __future__ import annotations

import pytest

from ladderlab.engine.call_stack import call_stack
from ladderlab.engine.paths import UnknownPath
from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.st.project_text import source_to_project

TEXT = """
FUNCTION Clamp : INT
VAR_INPUT v : INT; lo : INT; hi : INT; END_VAR
VAR tmp : INT := 7; t : TIME := T#1s; s : STRING := 'x'; END_VAR
VAR_TEMP w : REAL; END_VAR
tmp := v;
IF tmp < lo THEN tmp := lo; END_IF;
IF tmp > hi THEN tmp := hi; END_IF;
w := INT_TO_REAL(tmp) / 4.0;
Clamp := tmp;
END_FUNCTION
FUNCTION Inc : INT
VAR_IN_OUT c : INT; END_VAR
c := c + 1;
Inc := c;
END_FUNCTION
FUNCTION Twice : INT
VAR_INPUT a : INT; END_VAR
VAR k : INT; END_VAR
k := a;
Inc(k);
Inc(k);
Twice := k;
END_FUNCTION
FUNCTION_BLOCK Motor
VAR count : INT; END_VAR
METHOD PUBLIC Start : INT
VAR_INPUT n : INT; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR tmp : INT; arr : ARRAY[1..3] OF INT := [1, 2, 3]; END_VAR
tmp := n * 2;
count := count + Clamp(tmp, 0, 10);
q := TRUE;
Start := count;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR m : Motor; r : INT; b : BOOL; x : INT := 7; y : INT; END_VAR
r := m.Start(n := x, q => b);
y := Twice(x);
x := x + 1;
END_PROGRAM
"""


def line(text: str) -> int:
    """The line of TEXT that is exactly ``text`` (the lines breakpoints and halts name)."""
    return TEXT.splitlines().index(text) + 1


def simulation() -> Simulation:
    project, diagnostics = source_to_project(TEXT, "stack")
    assert project is not None and diagnostics == []
    return Simulation(lower_project(project).program, variant="debug")


def calls(sim: Simulation) -> list[tuple[str, str, str | None, int | None]]:
    """The halted scan's calls as (POU, kind, instance, line), outermost first."""
    return [(f.pou, f.kind, f.instance, f.origin.line) for f in sim.call_stack()]


def variables(sim: Simulation, depth: int = -1) -> dict[str, tuple[str, object]]:
    """A call's variables (the innermost's by default): name -> (kind, value)."""
    frame = sim.call_stack()[depth]
    assert all(v.reason is None for v in frame.variables)
    return {v.name: (v.kind, v.value) for v in frame.variables}


MAIN_CALL = ("MAIN", "program", "MAIN", line("r := m.Start(n := x, q => b);"))
START_CALL = ("MOTOR.START", "method", "MAIN.M", line("count := count + Clamp(tmp, 0, 10);"))


def test_a_function_halted_inside_a_method_shows_the_stack_and_both_calls_variables():
    sim = simulation()
    sim.set_breakpoint("Clamp", line=line("IF tmp > hi THEN tmp := hi; END_IF;"))
    sim.cycle(1)
    assert calls(sim) == [
        MAIN_CALL,
        START_CALL,
        ("CLAMP", "function", None, line("IF tmp > hi THEN tmp := hi; END_IF;")),
    ]
    # Clamp(tmp := 7 * 2, 0, 10): tmp := v ran, the clamp to hi not yet; w and the result still initial
    assert variables(sim) == {
        "V": ("input", 14),
        "LO": ("input", 0),
        "HI": ("input", 10),
        "TMP": ("var", 14),
        "T": ("var", 1000),  # TIME in ms, as every online value (the type says TIME)
        "S": ("var", "x"),
        "W": ("temp", 0.0),
        "CLAMP": ("result", 0),
    }
    # the method stands in its call of Clamp: tmp := n * 2 ran; q and the result are still initial
    assert variables(sim, 1) == {
        "N": ("input", 7),
        "Q": ("output", False),
        "TMP": ("var", 14),
        "ARR": ("var", [1, 2, 3]),
        "START": ("result", 0),
    }
    assert [v.type.name for v in sim.call_stack()[-1].variables] == [
        *("INT",) * 4,
        "TIME",
        "STRING",
        "REAL",
        "INT",
    ]


def test_stepping_changes_the_stack_and_the_values_of_the_halted_call():
    sim = simulation()
    sim.set_breakpoint("Clamp", line=line("Clamp := tmp;"))
    sim.cycle(1)
    assert variables(sim)["TMP"] == ("var", 10) and variables(sim)["W"] == ("temp", 2.5)  # 10 / 4.0
    sim.clear_breakpoints()
    sim.step("statement")  # Clamp returns: the method's next statement
    assert calls(sim) == [MAIN_CALL, ("MOTOR.START", "method", "MAIN.M", line("q := TRUE;"))]
    assert variables(sim)["Q"] == ("output", False)
    sim.step("over")
    assert variables(sim)["Q"] == ("output", True)
    assert variables(sim)["START"] == ("result", 0)
    sim.step("over")  # Start := count ran (count = 0 + 10); the method returns to Main
    assert calls(sim) == [("MAIN", "program", "MAIN", line("y := Twice(x);"))]
    assert sim.read("Main.r") == 10 and sim.read("Main.b") is True
    assert sim.call_stack()[0].variables == ()  # a program's variables have paths: the watch shows them
    sim.step("statement")  # into Twice, at its first statement: every variable still initial but the input
    assert calls(sim)[-1] == ("TWICE", "function", None, line("k := a;"))
    assert variables(sim) == {"A": ("input", 7), "K": ("var", 0), "TWICE": ("result", 0)}


def test_step_into_over_and_out_of_a_call_grow_and_shrink_the_stack():
    sim = simulation()
    sim.set_breakpoint("Motor.Start", line=line("count := count + Clamp(tmp, 0, 10);"))
    sim.cycle(1)
    assert calls(sim) == [MAIN_CALL, START_CALL]
    sim.clear_breakpoints()
    sim.step("statement")
    assert [c[0] for c in calls(sim)] == ["MAIN", "MOTOR.START", "CLAMP"]
    sim.step("out")
    assert calls(sim) == [MAIN_CALL, ("MOTOR.START", "method", "MAIN.M", line("q := TRUE;"))]
    sim.reset()
    sim.set_breakpoint("Motor.Start", line=line("count := count + Clamp(tmp, 0, 10);"))
    sim.cycle(1)
    sim.clear_breakpoints()
    sim.step("over")  # over the call of Clamp: never halted inside it
    assert calls(sim) == [MAIN_CALL, ("MOTOR.START", "method", "MAIN.M", line("q := TRUE;"))]


def test_an_in_out_shows_the_variable_it_refers_to_and_a_boxed_local_its_value_nested_calls():
    sim = simulation()
    sim.set_breakpoint("Inc", line=line("Inc := c;"))
    sim.cycle(1)
    twice_first = ("TWICE", "function", None, line("Inc(k);"))
    assert calls(sim) == [
        ("MAIN", "program", "MAIN", line("y := Twice(x);")),
        twice_first,
        ("INC", "function", None, line("Inc := c;")),
    ]
    assert variables(sim) == {"C": ("in_out", 8), "INC": ("result", 0)}  # k = 7, c := c + 1 ran on it
    assert variables(sim, 1) == {"A": ("input", 7), "K": ("var", 8), "TWICE": ("result", 0)}
    sim.resume()  # the second Inc(k): the same line of Twice's text, a new call
    assert calls(sim)[1][3] == line("Inc(k);") + 1  # Twice's second line "Inc(k);"
    assert variables(sim) == {"C": ("in_out", 9), "INC": ("result", 0)}
    assert variables(sim, 1)["K"] == ("var", 9)


def test_every_call_starts_from_the_initial_values_and_nothing_is_shown_when_not_halted():
    sim = simulation()
    assert sim.call_stack() == ()
    sim.set_breakpoint("Motor.Start", line=line("tmp := n * 2;"))
    sim.cycle(1)
    assert variables(sim) == {
        "N": ("input", 7),
        "Q": ("output", False),
        "TMP": ("var", 0),
        "ARR": ("var", [1, 2, 3]),
        "START": ("result", 0),
    }
    sim.resume()
    assert sim.halted is None and sim.call_stack() == ()
    sim.cycle(1)  # the next scan: x = 8; the method's variables are fresh again (TMP was 14 when its call ended)
    assert variables(sim)["N"] == ("input", 8) and variables(sim)["TMP"] == ("var", 0)


def test_a_path_into_a_method_or_function_is_refused_and_says_where_its_variables_are_shown():
    """As CODESYS: a call's variables exist only in the call, so the watch list cannot name them."""
    sim = simulation()
    sim.set_breakpoint("Clamp", line=line("Clamp := tmp;"))
    sim.cycle(1)  # refused while halted in the call too: a path names a variable of every scan, not of one call
    one_call = (
        "its variables live for one call only, so no path names them; they are shown while a scan is halted in it"
    )
    with pytest.raises(UnknownPath, match=f"MAIN.M.Start is a METHOD of MOTOR: {one_call}"):
        sim.location("Main.m.Start.tmp")
    with pytest.raises(UnknownPath, match=f"Clamp is a FUNCTION: {one_call}"):
        sim.location("Clamp.tmp")


def test_a_variable_the_call_does_not_hold_is_listed_without_a_value_and_with_the_reason():
    """Never a stale or made-up value: a call whose frame lacks a variable (here a stand-in generator of Clamp's name
    with no locals at all) lists each one with why it shows none."""
    sim = simulation()
    sim.set_breakpoint("Clamp", line=line("Clamp := tmp;"))
    sim.cycle(1)
    namespace: dict[str, object] = {}
    exec("def f_CLAMP():\n    yield", namespace)  # the generated function's name (names.function("CLAMP"))
    function = namespace["f_CLAMP"]
    assert callable(function)
    stand_in = function()
    next(stand_in)
    (frame,) = call_stack([stand_in], sim.halted, sim.compiled.generated, lambda obj: None)
    assert (frame.pou, frame.kind) == ("CLAMP", "function")
    assert [(v.name, v.value, v.reason) for v in frame.variables][:2] == [
        ("V", None, "not held in the call's frame ('v_V')"),
        ("LO", None, "not held in the call's frame ('v_LO')"),
    ]
    assert all(v.value is None and v.reason for v in frame.variables)
