"""A name declared in two named global variable lists (issue 25): two variables, each used as ``LIST.x``; a bare
``x`` is a located error naming the lists; scan by scan in ST, IL, LD, FBD and SFC, and online paths.

Expected behaviour from CODESYS's online help: "Operator: Namespace for Global Variable Lists" (``globlist1.varx :=
globlist2.varx`` copies one list's ``varx`` to the other's; "If you reference a variable that is declared in several
global variable lists without referencing the prepended list name, then an error message is printed"), "Compiler
Error C0136" ("ambiguous use of name": qualify the variable with the desired GVL) and "Rules" (a variable of a GVL
may have the name of one in another GVL; a local variable with a global's name has priority in its POU)."""

from __future__ import annotations

from functools import partial

import pytest

from ladderlab.engine.paths import UnknownPath
from ladderlab.model import GlobalVariableList, Pou
from ladderlab.simulation.xref import cross_reference
from tests.engine.gvl_support import gvl_errors, gvl_project, gvl_simulation, st
from tests.ir.diagram_support import coil, contact, fbd_pou, inp, ld_pou, net, out, rung
from tests.sfc.support import jump, sfc_pou, step, tr

A = GlobalVariableList(name="GVL_A", text="VAR_GLOBAL\n    x : INT := 5;\n    b : BOOL;\n    t : TON;\nEND_VAR")
B = GlobalVariableList(name="GVL_B", qualified_only=True, text="VAR_GLOBAL\n    x : INT;\n    b : BOOL;\nEND_VAR")
C = GlobalVariableList(name="GVL_C", text="VAR_GLOBAL\n    x : INT := 3;\nEND_VAR")


project = partial(gvl_project, gvls=(A, B))
simulation = partial(gvl_simulation, gvls=(A, B))
errors = partial(gvl_errors, gvls=(A, B))


def test_each_list_keeps_its_own_variable_and_initial_value_in_st():
    sim = simulation(st("GVL_B.x := GVL_B.x + GVL_A.x;\nGVL_A.t(IN := GVL_A.b, PT := T#20ms);\nGVL_B.b := GVL_A.t.Q;"))
    seen = []
    for scan in range(5):
        if scan == 1:
            sim.write("GVL_A.b", True)
        sim.cycle(1)
        seen.append((sim.read("GVL_A.x"), sim.read("GVL_B.x"), sim.read("GVL_A.b"), sim.read("GVL_B.b")))
    # GVL_A.x stays 5 and GVL_B.x (0 at start) adds it every scan; the TON started at 10 ms is done at 30 ms
    assert seen == [(5, 5, False, False), (5, 10, True, False), (5, 15, True, False), (5, 20, True, True)] + [
        (5, 25, True, True)
    ]


def test_codesys_example_copies_one_lists_variable_to_the_other():
    sim = simulation(st("GVL_A.x := GVL_C.x;"), gvls=(A, B, C))
    assert (sim.read("GVL_A.x"), sim.read("GVL_C.x")) == (5, 3)
    sim.cycle(1)
    assert (sim.read("GVL_A.x"), sim.read("GVL_B.x"), sim.read("GVL_C.x")) == (3, 0, 3)


def test_a_bare_use_is_a_located_error_naming_every_list():
    assert errors(st("x := 1;\nIF b THEN\n    t(IN := TRUE, PT := T#1s);\nEND_IF;"), gvls=(A, B, C)) == [
        "Main/body:1:1, POU Main: error ST-AMBIGUOUS: 'x' is declared in the global variable lists GVL_A, GVL_B "
        "and GVL_C: write GVL_A.x or GVL_B.x or GVL_C.x",
        "Main/body:2:4, POU Main: error ST-AMBIGUOUS: 'b' is declared in the global variable lists GVL_A and GVL_B: "
        "write GVL_A.b or GVL_B.b",
    ]


def test_a_bare_call_of_a_shared_instance_name_is_the_same_error():
    other = GlobalVariableList(name="GVL_T", text="VAR_GLOBAL\n    t : TON;\nEND_VAR")
    assert errors(st("t(IN := TRUE, PT := T#1s);"), gvls=(A, other)) == [
        "Main/body:1:1, POU Main: error ST-AMBIGUOUS: 't' is declared in the global variable lists GVL_A and GVL_T: "
        "write GVL_A.t or GVL_T.t"
    ]


def test_a_var_external_of_a_shared_name_is_the_same_error():
    assert errors(st("", "VAR_EXTERNAL\n    x : INT;\nEND_VAR")) == [
        "Main/declarations:2:5, POU Main: error ST-AMBIGUOUS: 'x' is declared in the global variable lists GVL_A "
        "and GVL_B: write GVL_A.x or GVL_B.x"
    ]


def test_a_local_variable_of_the_name_comes_first():
    sim = simulation(st("x := x + 1;\nGVL_B.x := x;", "VAR\n    x : INT := 10;\nEND_VAR"))
    sim.cycle(2)
    assert (sim.read("Main.x"), sim.read("GVL_A.x"), sim.read("GVL_B.x")) == (12, 5, 12)


def test_a_name_of_the_project_globals_and_two_lists_is_refused_at_the_lists():
    """The project's own global variables have no list name to qualify them with: a list may not share a name with
    them (test_global_variable_lists.py), whether one list or several declare it."""
    assert errors(st(""), globals="VAR_GLOBAL\n    x : INT;\nEND_VAR") == [
        "gvls/GVL_A:2:5: error ST-DUPLICATE: 'x' is declared twice (first in the global variables; the global "
        "variables have no list name to tell the two apart by: rename one)",
        "gvls/GVL_B:2:5: error ST-DUPLICATE: 'x' is declared twice (first in the global variables; the global "
        "variables have no list name to tell the two apart by: rename one)",
    ]


def test_a_name_twice_in_one_list_is_a_plain_duplicate():
    twice = GlobalVariableList(name="GVL_D", text="VAR_GLOBAL\n    x : INT;\n    x : BOOL;\nEND_VAR")
    assert errors(st(""), gvls=(A, twice)) == ["gvls/GVL_D:3:5: error ST-DUPLICATE: 'x' is declared twice"]


def test_ld_and_fbd_operands_name_each_lists_variable():
    ld = ld_pou("Rungs", "", rung("n1", contact("c1", "GVL_A.b"), coil("q1", "GVL_B.b")))
    fbd = fbd_pou("Nodes", "", net("n1", [inp("i1", "GVL_A.x"), out("o1", "GVL_B.x")], [("i1.OUT", "o1.IN")]))
    sim = simulation(ld, fbd)
    sim.cycle(1)
    assert (sim.read("GVL_A.b"), sim.read("GVL_B.b"), sim.read("GVL_B.x")) == (False, False, 5)
    sim.write("GVL_A.b", True)
    sim.cycle(1)
    assert (sim.read("GVL_B.b"), sim.read("GVL_A.x")) == (True, 5)


def test_a_bare_ld_operand_is_the_located_error():
    ld = ld_pou("Rungs", "", rung("n1", contact("c1", "b"), coil("q1", "GVL_B.b")))
    assert errors(ld) == [
        "POU Rungs, network 1, contact b: error ST-AMBIGUOUS: 'b' is declared in the global variable lists GVL_A and "
        "GVL_B: write GVL_A.b or GVL_B.b"
    ]


def test_il_operands_name_each_lists_variable():
    il = Pou(name="Main", kind="program", language="il", body="LD GVL_A.x\nADD GVL_B.x\nADD 1\nST GVL_B.x")
    sim = simulation(il)
    sim.cycle(3)
    assert (sim.read("GVL_A.x"), sim.read("GVL_B.x")) == (5, 18)  # 0 -> 6 -> 12 -> 18


def test_an_sfc_transition_condition_names_one_lists_variable():
    chart = [step("S0"), tr("GVL_B.b"), step("S1"), tr("NOT GVL_B.b"), jump("S0")]
    sim = simulation(sfc_pou("Main", "", chart))
    sim.write("GVL_A.b", True)  # the other list's b: no step
    sim.cycle(1)
    assert sim.read("Main.S1.X") is False
    sim.write("GVL_B.b", True)
    sim.cycle(1)
    assert sim.read("Main.S1.X") is True


def test_online_paths_write_and_force_each_lists_variable_and_refuse_the_bare_name():
    sim = simulation(st("GVL_A.x := GVL_A.x + 1;"))
    sim.write("gvl_b.X", 40)
    sim.force("GVL_A.x", "7")
    sim.cycle(2)
    assert (sim.read("GVL_A.x"), sim.read("GVL_B.x")) == (7, 40)
    with pytest.raises(UnknownPath) as refused:
        sim.read("x")
    assert str(refused.value) == "x is declared in several global variable lists: write GVL_A.X or GVL_B.X"


def test_the_cross_reference_list_names_each_lists_variable_apart():
    listed = {
        e.name: [(a.kind, a.gvl, a.pou, a.line) for a in e.accesses]
        for e in cross_reference(project(st("GVL_B.x := GVL_A.x;"))).entries
        if e.pou is None
    }
    assert listed["GVL_A.x"] == [("declared", "GVL_A", None, 2), ("read", None, "Main", 1)]
    assert listed["GVL_B.x"] == [("declared", "GVL_B", None, 2), ("write", None, "Main", 1)]
    assert listed["t"] == [("declared", "GVL_A", None, 4)]  # in one list only: its own name


def test_a_list_called_gvl_sharing_a_name_is_read_by_its_own_name_online():
    """``GVL.x`` is any global for an online path, unless a list is called GVL: then it is that list's."""
    gvl = GlobalVariableList(name="GVL", text="VAR_GLOBAL\n    x : INT := 7;\nEND_VAR")
    sim = simulation(st("GVL_A.x := GVL.x + 1;"), gvls=(A, gvl))
    sim.cycle(1)
    assert (sim.read("GVL.x"), sim.read("GVL_A.x")) == (7, 8)
