"""Named global variable lists (CODESYS's GVLs): ``GVL_IO.bStart`` in ST, IL, LD/FBD operands and SFC conditions,
``{attribute 'qualified_only'}``, a name in a list and the project's globals, online paths; scan by scan.

Expected behaviour from CODESYS's online help: "Operator: Namespace for Global Variable Lists" (``globlist1.varx``
names the list's variable; using a name declared in several lists without its list is an error), "Attribute:
qualified_only" (``GVL.iVar := 5`` only; ``iVar := 5`` is an error) and "Rules" of identifiers (a local variable
with a global's name has priority in its POU)."""

from __future__ import annotations

from functools import partial

import pytest

from ladderlab.engine.paths import UnknownPath
from ladderlab.model import GlobalVariableList, Pou, Project, Task
from ladderlab.simulation.build import build_project
from ladderlab.simulation.xref import cross_reference
from tests.engine.gvl_support import gvl_errors, gvl_project, gvl_simulation, st
from tests.ir.diagram_support import coil, contact, fbd_pou, inp, ld_pou, net, out, rung
from tests.sfc.support import jump, sfc_pou, step, tr

IO = GlobalVariableList(
    name="GVL_IO",
    qualified_only=True,
    text="VAR_GLOBAL\n    bStart : BOOL;\n    nCount : INT;\n    tOn : TON;\nEND_VAR",
)
PLAIN = GlobalVariableList(name="GVL", text="VAR_GLOBAL\n    counter : INT;\n    bLamp : BOOL;\nEND_VAR")


project = partial(gvl_project, gvls=(IO, PLAIN))
simulation = partial(gvl_simulation, gvls=(IO, PLAIN))
errors = partial(gvl_errors, gvls=(IO, PLAIN))


def test_qualified_names_read_and_write_the_lists_variables_in_st():
    sim = simulation(
        st(
            "GVL.counter := GVL.counter + 1;\n"
            "IF GVL_IO.bStart THEN GVL_IO.nCount := GVL_IO.nCount + counter; END_IF;\n"
            "GVL_IO.tOn(IN := GVL_IO.bStart, PT := T#20ms);\n"
            "GVL.bLamp := GVL_IO.tOn.Q;"
        )
    )
    seen = []
    for scan in range(5):
        if scan == 2:
            sim.write("GVL_IO.bStart", True)
        sim.cycle(1)
        seen.append((sim.read("GVL.counter"), sim.read("GVL_IO.nCount"), sim.read("GVL.bLamp")))
    # scan 3 adds counter 3, scan 4 adds 4 (T#20ms after the rising edge at 30 ms: Q at 50 ms, the 5th scan)
    assert seen == [(1, 0, False), (2, 0, False), (3, 3, False), (4, 7, False), (5, 12, True)]


def test_a_bare_name_of_a_plain_list_is_its_variable_too():
    sim = simulation(st("counter := counter + 2;"))
    sim.cycle(2)
    assert (sim.read("GVL.counter"), sim.read("counter")) == (4, 4)


def test_an_unqualified_use_of_a_qualified_only_list_is_a_located_error_naming_the_list():
    assert errors(st("IF bStart THEN\n    nCount := 1;\nEND_IF;")) == [
        "Main/body:1:4, POU Main: error ST-QUALIFIED-ONLY: 'bStart' belongs to the global variable list GVL_IO, "
        "which is qualified_only: write GVL_IO.bStart",
        "Main/body:2:5, POU Main: error ST-QUALIFIED-ONLY: 'nCount' belongs to the global variable list GVL_IO, "
        "which is qualified_only: write GVL_IO.nCount",
    ]


def test_a_local_variable_named_like_a_list_comes_first():
    built = build_project(
        Project(
            name="gvl",
            types="TYPE Box : STRUCT counter : INT; END_STRUCT; END_TYPE",
            gvls=[PLAIN],
            pous=[st("GVL.counter := GVL.counter + 5;", "VAR\n    GVL : Box;\nEND_VAR")],
            tasks=[Task(name="T", programs=["Main"])],
        )
    )
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    run = built.simulation()
    run.cycle(2)
    assert (run.read("Main.GVL.counter"), run.read("GVL.counter")) == (10, 0)


def test_a_list_without_the_variable_is_a_located_error_with_a_suggestion():
    assert errors(st("GVL_IO.bStrat := TRUE;")) == [
        "Main/body:1:1, POU Main: error ST-UNKNOWN-VAR: the global variable list GVL_IO has no variable 'bStrat' "
        "- did you mean 'bStart'?"
    ]


def test_a_name_of_the_project_globals_in_a_list_too_is_an_error_at_the_second_declaration():
    """The project's global variables have no list name (CODESYS has no such list): a list's ``counter`` and theirs
    could not be told apart, so the second is refused (names shared by lists: test_gvl_shared_names.py)."""
    other = GlobalVariableList(name="GVL_B", text="VAR_GLOBAL\n    x : INT;\n    counter : INT;\nEND_VAR")
    assert errors(st(""), gvls=(other,), globals="VAR_GLOBAL\n    counter : INT;\nEND_VAR") == [
        "gvls/GVL_B:3:5: error ST-DUPLICATE: 'counter' is declared twice (first in the global variables; the global "
        "variables have no list name to tell the two apart by: rename one)"
    ]


def test_a_list_named_like_a_pou_is_an_error():
    clash = GlobalVariableList(name="Main", text="VAR_GLOBAL\n    y : INT;\nEND_VAR")
    assert errors(st(""), gvls=(clash,)) == [
        "gvls/Main: error ST-DUPLICATE: the global variable list Main has the name of the program Main: rename one"
    ]


def test_ld_and_fbd_operands_name_the_lists_variables():
    ld = ld_pou("Rungs", "", rung("n1", contact("c1", "GVL_IO.bStart"), coil("q1", "GVL.bLamp")))
    fbd = fbd_pou(
        "Nodes",
        "",
        net("n1", [inp("i1", "GVL.counter"), out("o1", "GVL_IO.nCount")], [("i1.OUT", "o1.IN")]),
    )
    sim = simulation(ld, fbd, st("GVL.counter := GVL.counter + 1;"))
    sim.cycle(1)
    assert (sim.read("GVL.bLamp"), sim.read("GVL_IO.nCount")) == (False, 0)  # Rungs and Nodes run before Main
    sim.write("GVL_IO.bStart", True)
    sim.cycle(1)
    assert (sim.read("GVL.bLamp"), sim.read("GVL_IO.nCount")) == (True, 1)


def test_an_ld_contact_on_a_bare_qualified_only_name_is_the_same_error():
    ld = ld_pou("Rungs", "", rung("n1", contact("c1", "bStart"), coil("q1", "GVL.bLamp")))
    assert errors(ld) == [
        "POU Rungs, network 1, contact bStart: error ST-QUALIFIED-ONLY: 'bStart' belongs to the global variable "
        "list GVL_IO, which is qualified_only: write GVL_IO.bStart"
    ]


def test_il_operands_name_the_lists_variables():
    il = Pou(name="Main", kind="program", language="il", body="LD GVL.counter\nADD 3\nST GVL.counter\nST GVL_IO.nCount")
    sim = simulation(il)
    sim.cycle(2)
    assert (sim.read("GVL.counter"), sim.read("GVL_IO.nCount")) == (6, 6)


def test_an_sfc_transition_condition_names_a_lists_variable():
    chart = [step("S0"), tr("GVL_IO.bStart"), step("S1"), tr("NOT GVL_IO.bStart"), jump("S0")]
    sim = simulation(sfc_pou("Main", "", chart))
    sim.cycle(1)
    assert sim.read("Main.S1.X") is False
    sim.write("GVL_IO.bStart", True)
    sim.cycle(1)
    assert sim.read("Main.S1.X") is True


@pytest.mark.parametrize(
    "path, message",
    [
        ("GVL_IO.counter", "the global variable list GVL_IO has no variable 'counter'"),
        ("GVL_IO", "unknown variable or program 'GVL_IO'"),
    ],
)
def test_an_online_path_into_a_list_without_the_variable_is_refused(path, message):
    sim = simulation(st(""))
    with pytest.raises(UnknownPath) as refused:
        sim.read(path)
    assert message in str(refused.value)


def test_the_lists_texts_count_in_the_source_size_limit(monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setenv("LADDERLAB_MAX_SOURCE_CHARACTERS", "100")
    big = GlobalVariableList(name="GVL_Big", text="VAR_GLOBAL\n" + "    a0123456789 : INT;\n" * 5 + "END_VAR")
    assert len(big.text) == 11 + 5 * 23 + 7  # 133 characters; the POU has none
    assert errors(st(""), gvls=(big,)) == [
        "POU Main: error LIMIT-SIZE: the project's ST text has 133 characters (the largest POU, Main, has 0), more than the limit of 100 characters for the "
        "ST text of one project (the setting LADDERLAB_MAX_SOURCE_CHARACTERS raises it)"
    ]


def test_the_cross_reference_list_names_a_globals_list_and_its_qualified_uses():
    listed = {
        e.name: [(a.kind, a.gvl, a.pou, a.line) for a in e.accesses]
        for e in cross_reference(project(st("GVL_IO.nCount := counter;\nGVL.counter := GVL_IO.nCount;"))).entries
        if e.pou is None
    }
    assert listed["nCount"] == [("declared", "GVL_IO", None, 3), ("write", None, "Main", 1), ("read", None, "Main", 2)]
    assert listed["counter"] == [("declared", "GVL", None, 2), ("read", None, "Main", 1), ("write", None, "Main", 2)]
