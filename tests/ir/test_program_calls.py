"""A program called from another program, in ST (seed 003 §2, example of a program call; IL-08's ST column).

CODESYS semantics: a program has one instance (named like it); a call runs it now, with the inputs given and
the outputs copied out; its variables keep their values between calls, whoever calls it. A program that a task
runs and another program calls runs twice in that task's scan. Expected values are counted by hand.
"""

from __future__ import annotations

from ladderlab.engine.simulation import Simulation
from tests.ir.helpers import errors, lower_ok, lower_with_tasks

PRG = """
PROGRAM PRGexample2
VAR_INPUT in_var : INT; END_VAR
VAR_OUTPUT out_var : INT; END_VAR
out_var := in_var + 1;
END_PROGRAM
"""
COUNTER = "PROGRAM Counter\nVAR_OUTPUT n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n"


def test_the_seeds_three_st_forms_il08():
    """``PRGexample2;`` / ``Erg := PRGexample2.out_var;`` and ``PRGexample2(in_var:=33, out_var=>erg);``."""
    body = (
        "PRGexample2.in_var := 4;\nPRGexample2;\nErg := PRGexample2.out_var;\nPRGexample2(in_var:=33, out_var=>erg2);"
    )
    sim = Simulation(
        lower_with_tasks(f"PROGRAM P\nVAR Erg, erg2 : INT; END_VAR\n{body}\nEND_PROGRAM\n{PRG}", {"T": ["P"]})
    )
    sim.cycle()
    assert sim.fault is None
    assert (sim.read("P.Erg"), sim.read("P.erg2"), sim.read("PRGexample2.in_var")) == (5, 34, 33)


def test_a_program_run_by_a_task_and_called_by_another_runs_twice_per_scan():
    """Without tasks every program runs (DEFAULT task) and P calls Counter as well: n grows by 2 per scan; P
    reads n between the two runs. With a task that runs P only, n grows by 1 per scan."""
    source = f"PROGRAM P\nVAR seen : INT; END_VAR\nCounter();\nseen := Counter.n;\nEND_PROGRAM\n{COUNTER}"
    twice = Simulation(lower_ok(source))
    once = Simulation(lower_with_tasks(source, {"T": ["P"]}))
    for k in range(1, 4):
        twice.cycle()
        once.cycle()
        assert (twice.read("P.seen"), twice.read("Counter.n")) == (2 * k - 1, 2 * k)
        assert (once.read("P.seen"), once.read("Counter.n")) == (k, k)


def test_a_local_variable_named_like_a_program_is_not_a_call():
    """``Counter;`` calls the program only when no variable of that name hides it (ST-NO-EFFECT otherwise)."""
    found = errors(f"PROGRAM P\nVAR Counter : INT; END_VAR\nCounter;\nEND_PROGRAM\n{COUNTER}")
    assert found == [
        "P/body:3:1, POU P: error ST-NO-EFFECT: this statement does nothing: expected an assignment ':=' or a call "
        "'(...)'"
    ]


def test_only_a_programs_inputs_may_be_set_from_outside():
    """Inputs are set before a call like an FB instance's (IL-08 ``ST inst1.in1``); outputs stay read-only."""
    found = errors(f"PROGRAM P\nPRGexample2.out_var := 1;\nPRGexample2.in_var := 1;\nEND_PROGRAM\n{PRG}")
    assert found == [
        "P/body:2:1, POU P: error ST-READONLY: 'out_var' is an output of PRGexample2: it can be read but not "
        "assigned from outside"
    ]


def test_function_blocks_and_functions_cannot_call_programs_pou32():
    """POU-32 (seed 000): functions and FBs cannot call programs; seed 003 says it of functions."""
    found = errors(
        f"FUNCTION_BLOCK B\nCounter();\nEND_FUNCTION_BLOCK\nFUNCTION F : INT\nCounter();\nEND_FUNCTION\n{COUNTER}"
    )
    assert found == [
        "B/body:2:1, POU B: error ST-NOT-CALLABLE: a function block cannot call the program Counter",
        "F/body:5:1, POU F: error ST-NOT-CALLABLE: a function cannot call the program Counter",
    ]


def test_a_configuration_that_names_the_instance_otherwise_gets_a_located_error():
    config = (
        "CONFIGURATION C RESOURCE R ON PLC TASK T(INTERVAL := T#10ms, PRIORITY := 0);\n"
        "PROGRAM Main WITH T : P; PROGRAM other : Counter; END_RESOURCE END_CONFIGURATION\n"
    )
    found = errors(f"{config}PROGRAM P\nCounter();\nEND_PROGRAM\n{COUNTER}")
    assert found == [
        "P/body:4:1, POU P: error IR-UNSUPPORTED: the program Counter runs as its instance other: other POUs call "
        "the instance named like the program (PROGRAM Counter : Counter in the configuration)"
    ]
