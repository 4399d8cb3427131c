"""METHODs of function blocks (issue 25, item 5; IEC 61131-3 ed. 3, 6.6.5; CODESYS): inputs, in-outs, local
variables, a result in expressions and as a statement, ``THIS^``, the access specifiers checked at compile time,
ABSTRACT; run scan by scan. Expected values are worked out by hand from the program text and the standard's rules:
a method's VAR is fresh in every call (it has no memory of its own, like a function), the instance's variables keep
their values between calls and scans, and each instance has its own.
"""

from __future__ import annotations

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.workspace import Workspace

from .oo_support import build, errors, run

COUNTER = """
FUNCTION_BLOCK Counter
VAR_INPUT step : INT := 1; END_VAR
VAR count : INT; END_VAR
METHOD PUBLIC Add : INT
VAR_INPUT n : INT; END_VAR
VAR tmp : INT; END_VAR
tmp := tmp + n;
count := count + tmp * step;
Add := count;
END_METHOD
METHOD Twice : INT
Add(1);
Twice := THIS^.Add(n := 1);
END_METHOD
METHOD PRIVATE Clear
count := 0;
END_METHOD
METHOD ClearAbove
VAR_INPUT limit : INT; END_VAR
IF count > limit THEN
    Clear();
END_IF;
END_METHOD
END_FUNCTION_BLOCK
"""


def located_errors(text: str) -> list[tuple[str, str | None, int | None, int | None, str]]:
    return [(d.code, d.file, d.line, d.column, d.message) for d in build(text).diagnostics if d.severity == "error"]


def test_a_method_call_in_an_expression_and_as_a_statement_scan_by_scan():
    sim = run(
        COUNTER
        + "PROGRAM Main\nVAR c : Counter; r : INT; q : INT; END_VAR\n"
        + "r := c.Add(n := 5);\nq := c.Twice();\nc.Add(2);\nEND_PROGRAM\n"
    )
    count = 0
    for _ in range(3):
        sim.cycle(1)
        count += 5  # tmp starts at 0 in every call: Add(n) adds n * step
        r = count
        count += 1 + 1  # Twice: Add(1) then THIS^.Add(1)
        q = count
        count += 2
        assert (sim.read("Main.r"), sim.read("Main.q"), sim.read("Main.c.count")) == (r, q, count)


def test_each_instance_has_its_own_variables_and_the_method_sees_the_instance_inputs():
    sim = run(
        COUNTER
        + "PROGRAM Main\nVAR a : Counter; b : Counter := (step := 10); END_VAR\n"
        + "a.Add(1);\nb.Add(1);\nb.Add(n := 2);\nEND_PROGRAM\n"
    )
    sim.cycle(2)
    assert (sim.read("Main.a.count"), sim.read("Main.b.count")) == (2 * 1, 2 * (10 + 20))


def test_a_private_method_is_called_by_a_sibling_method():
    sim = run(
        COUNTER + "PROGRAM Main\nVAR c : Counter; END_VAR\n" + "c.Add(4);\nc.ClearAbove(limit := 10);\nEND_PROGRAM\n"
    )
    expected = []
    count = 0
    for _ in range(4):
        count += 4
        if count > 10:
            count = 0
        expected.append(count)
    assert [(sim.cycle(1), sim.read("Main.c.count"))[1] for _ in range(4)] == expected == [4, 8, 0, 4]


def test_a_method_with_in_outs_works_on_the_callers_variables_and_is_called_through_an_in_out_instance():
    sim = run(
        """
FUNCTION_BLOCK Swapper
VAR swaps : INT; END_VAR
METHOD Swap : BOOL
VAR_IN_OUT a, b : INT; END_VAR
VAR t : INT; END_VAR
t := a; a := b; b := t;
swaps := swaps + 1;
Swap := swaps MOD 2 = 0;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK SwapWith
VAR_IN_OUT s : Swapper; x, y : INT; END_VAR
VAR_OUTPUT even : BOOL; END_VAR
even := s.Swap(a := x, b := y);
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Swapper; w : SwapWith; x : INT := 1; y : INT := 2; even : BOOL; END_VAR
w(s := s, x := x, y := y, even => even);
END_PROGRAM
"""
    )
    sim.cycle(1)
    assert (sim.read("Main.x"), sim.read("Main.y"), sim.read("Main.even"), sim.read("Main.s.swaps")) == (2, 1, False, 1)
    sim.cycle(1)
    assert (sim.read("Main.x"), sim.read("Main.y"), sim.read("Main.even"), sim.read("Main.s.swaps")) == (1, 2, True, 2)


def test_access_specifiers_are_checked_at_compile_time_with_located_errors():
    text = COUNTER.replace("METHOD PRIVATE Clear", "METHOD PROTECTED Guarded\nEND_METHOD\nMETHOD PRIVATE Clear")
    text += "PROGRAM Main\nVAR c : Counter; END_VAR\nc.Clear();\n   c.Guarded();\nc.ClearAbove(1);\nEND_PROGRAM\n"
    first = text.splitlines().index("c.Clear();") + 1  # the body's lines are the file's
    assert located_errors(text) == [
        (
            "ST-NOT-ACCESSIBLE",
            "Main/body",
            first,
            1,
            "the method Counter.Clear is PRIVATE: only its own function block may call it",
        ),
        (
            "ST-NOT-ACCESSIBLE",
            "Main/body",
            first + 1,
            4,
            "the method Counter.Guarded is PROTECTED: only its function block and those derived from it may call it",
        ),
    ]


def test_internal_and_public_methods_are_called_from_anywhere_in_the_project():
    sim = run(
        "FUNCTION_BLOCK F\nVAR n : INT; END_VAR\nMETHOD INTERNAL Inc\nn := n + 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR f : F; END_VAR\nf.Inc();\nf.Inc();\nEND_PROGRAM\n"
    )
    sim.cycle(3)
    assert sim.read("Main.f.n") == 6


@pytest.mark.parametrize(
    ("method", "call", "expected"),
    [
        (
            "METHOD ABSTRACT M : INT\nEND_METHOD\n",
            "",
            ("ST-DECL", "F.M/declarations", "F has the ABSTRACT method M, so it must be ABSTRACT too"),
        ),
        (
            "METHOD M : INT\nVAR_GLOBAL g : INT; END_VAR\nEND_METHOD\n",
            "",
            ("ST-DECL", "F.M/declarations", "VAR_GLOBAL is not allowed in a method"),
        ),
        (
            "METHOD M : INT\nVAR_OUTPUT o : INT; END_VAR\nEND_METHOD\n",
            "x := f.M(o => b);",
            (
                "ST-TYPE-MISMATCH",
                "Main/body",
                "output o is INT and cannot be stored in BOOL without a conversion such as INT_TO_BOOL",
            ),
        ),
        (
            "METHOD M : INT\nVAR_OUTPUT o : INT; END_VAR\nEND_METHOD\n",
            "x := f.M(o := x);",
            ("ST-CALL-ARGS", "Main/body", "'o' is an output of f.M: write o => variable"),
        ),
        (
            "METHOD n : INT\nEND_METHOD\n",
            "",
            ("ST-DUPLICATE", "F.n/declarations", "'n' is both a variable and a method or property of F"),
        ),
        (
            "METHOD M : INT\nM := n + undefined;\nEND_METHOD\n",
            "",
            ("ST-UNKNOWN-VAR", "F.M/body", "unknown variable 'undefined'"),
        ),
        (
            "METHOD M : INT\nEND_METHOD\n",
            "x := f.M;",
            ("ST-NOT-CALLABLE", "Main/body", "'M' is a method of F: call it (add the ( ))"),
        ),
        (
            "METHOD M : INT\nVAR_INPUT a : INT; END_VAR\nEND_METHOD\n",
            "x := f.M(b := 1);",
            ("ST-CALL-ARGS", "Main/body", "f.M has no parameter 'b'"),
        ),
    ],
)
def test_method_declaration_and_call_errors(method, call, expected):
    text = (
        f"FUNCTION_BLOCK F\nVAR n : INT; END_VAR\n{method}END_FUNCTION_BLOCK\n"
        f"PROGRAM Main\nVAR f : F; x : INT; b : BOOL; END_VAR\n{call}\nEND_PROGRAM\n"
    )
    assert errors(text) == [expected]


def test_a_function_has_no_methods():
    """A function block and a program have methods (CODESYS; tests/engine/test_program_methods.py), a FUNCTION none."""
    from ladderlab.model.project import Method, Pou, Project

    project = Project(
        name="p",
        pous=[
            Pou(name="F", kind="function", language="st", return_type="INT", body="F := 1;", methods=[Method(name="M")])
        ],
    )
    assert [(d.code, d.file, d.message) for d in build_project(project).diagnostics] == [
        ("ST-DECL", "F.M/declarations", "only a function block or a program has methods, not a function")
    ]


def test_methods_survive_a_project_folder(tmp_path):
    project, _ = source_to_project(COUNTER + "PROGRAM Main\nVAR c : Counter; END_VAR\nc.Add(3);\nEND_PROGRAM\n", "p")
    workspace = Workspace(tmp_path)
    workspace.create(project)
    loaded = workspace.load("p").project
    assert loaded == project
    assert (tmp_path / "p" / "pous" / "Counter.st.json").is_file()
    assert (tmp_path / "p" / "pous" / "Main.st").is_file()  # POUs without methods keep their IEC text files
    sim = build_project(loaded).simulation()
    sim.cycle(2)
    assert sim.read("Main.c.count") == 6


def test_an_ld_box_and_an_fbd_block_call_a_method_of_an_instance():
    """In LD and FBD a method call is a box ``inst.Method`` (CODESYS): EN gates it, OUT is its result."""
    from tests.ir.diagram_support import blk, box, contact, fbd_pou, inp, ld_pou, net, out, rung

    project, _ = source_to_project(COUNTER, "ld")
    adds = box("b1", "c.Add", en=True, n="5", outputs={"OUT": "r"})
    ld_main = ld_pou("Main", "VAR c : Counter; go : BOOL; r : INT; END_VAR", rung("n1", contact("k", "go"), adds))
    network = net(
        "n1",
        [inp("i", "3"), blk("a", "c.Add"), blk("b", "c.Twice"), out("o", "f")],
        [("i.OUT", "a.n"), ("b.OUT", "o.IN")],
        order=["a", "b", "o"],
    )
    project.pous += [ld_main, fbd_pou("Side", "VAR c : Counter; f : INT; END_VAR", network)]
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    assert (sim.read("Main.r"), sim.read("Main.c.count")) == (0, 0)  # EN FALSE: not called
    sim.write("Main.go", True)
    for count in (5, 10):
        sim.cycle(1)
        assert (sim.read("Main.r"), sim.read("Main.c.count")) == (count, count)
    side = 3 * (3 + 2)  # each of the three scans: Add(3), then Twice (Add(1) twice), in the network's order
    assert sim.read("Side.c.count") == side and sim.read("Side.f") == side


def test_methods_that_call_themselves_are_refused_also_through_an_override():
    """POU-02: through a sibling, and through the override a dispatched call may run."""
    direct = (
        "FUNCTION_BLOCK F\nMETHOD M : INT\nM := M2();\nEND_METHOD\nMETHOD M2 : INT\nM2 := M();\nEND_METHOD\n"
        "END_FUNCTION_BLOCK\n"
    )
    assert errors(direct) == [
        ("ST-RECURSION", "F.M/body", "recursive call F.M -> F.M2 -> F.M: methods must not call themselves (POU-02)")
    ]
    dispatched = (
        "FUNCTION_BLOCK A\nMETHOD Area : INT\nEND_METHOD\nMETHOD Show : INT\nShow := Area();\nEND_METHOD\n"
        "END_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK B EXTENDS A\nMETHOD Area : INT\nArea := Show();\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
    )
    assert errors(dispatched) == [
        (
            "ST-RECURSION",
            "A.Show/body",
            "recursive call A.Show -> B.Area -> A.Show: methods must not call themselves (POU-02)",
        )
    ]
