"""METHODs and PROPERTYs of PROGRAMs (issue 25, item 5; CODESYS): called bare ``M(...)`` and ``THIS^.M(...)`` in the
program, ``Prog.M(...)`` from other POUs (the program's one instance: the one named like it), on the program's
variables, which persist, while a method's own VAR are fresh in every call; private and protected ones refused from
outside; every engine variant; breakpoints and the call stack in a program's method (ON-03, ON-04). Expected values
are worked out by hand from the program texts and those rules.
"""

from __future__ import annotations

import pytest

from ladderlab.model.project import Method, Pou, PouAction, Project
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

from .oo_support import errors, run

TALLY = """
PROGRAM Tally
VAR count : INT; last : INT; calls : INT; END_VAR
METHOD Add : INT
VAR_INPUT n : INT; END_VAR
VAR_OUTPUT doubled : INT; END_VAR
VAR fresh : INT; END_VAR
fresh := fresh + n;
count := count + fresh;
calls := calls + 1;
doubled := count * 2;
Add := count;
END_METHOD
METHOD PRIVATE Reset
count := 0;
END_METHOD
PROPERTY Level : INT
GET
Level := count * 10;
END_GET
SET
count := Level / 10;
END_SET
END_PROPERTY
last := Add(1);
last := last + THIS^.Add(n := 2);
IF count > 20 THEN
    Reset();
END_IF;
END_PROGRAM
"""

USER = """
PROGRAM User
VAR r : INT; d : INT; l : INT; END_VAR
r := Tally.Add(n := 4, doubled => d);
l := Tally.Level;
END_PROGRAM
"""

LINES = (TALLY + USER).splitlines()


def line(text: str) -> int:
    """The line of TALLY + USER that is exactly ``text`` (the lines breakpoints and halts name)."""
    return LINES.index(text) + 1


def expected_scans(scans: int) -> list[tuple[int, int, int, int, int, int]]:
    """(Tally.count, Tally.last, Tally.calls, User.r, User.d, User.l) after each scan, by hand: Tally runs first
    (it is first in the project), then User; ``fresh`` starts at 0 in every call, so Add(n) adds exactly n."""
    count = calls = 0
    rows = []
    for _ in range(scans):
        count += 1  # Add(1)
        last = count
        count += 2  # THIS^.Add(n := 2)
        last += count
        calls += 2
        if count > 20:
            count = 0  # Reset()
        count += 4  # User: Tally.Add(n := 4)
        calls += 1
        r, d = count, count * 2
        rows.append((count, last, calls, r, d, count * 10))
    return rows


def test_expected_values_by_hand():
    """The hand-worked rows for four scans, written out."""
    assert expected_scans(4) == [
        (7, 1 + 3, 3, 7, 14, 70),
        (14, 8 + 10, 6, 14, 28, 140),
        (21, 15 + 17, 9, 21, 42, 210),
        (0 + 4, 22 + 24, 12, 4, 8, 40),  # 21 + 3 = 24 > 20: Reset, then User's Add(4)
    ]


@pytest.mark.parametrize("variant", ["fast", "monitor", "debug"])
def test_a_program_calls_its_methods_bare_and_through_this_and_other_programs_through_its_name(variant):
    """The program's variables persist between calls and scans; the method's VAR ``fresh`` is 0 at every call; the
    caller's ``doubled =>`` receives the method's output; ``Tally.Level`` runs the property's GET. Same values in
    every engine variant."""
    project, diagnostics = source_to_project(TALLY + USER, "tally")
    assert project is not None and diagnostics == []
    result = build_project(project, variant)
    assert [d.format() for d in result.diagnostics] == []
    sim = result.simulation()
    seen = []
    for _ in range(4):
        sim.cycle(1)
        names = ("Tally.count", "Tally.last", "Tally.calls", "User.r", "User.d", "User.l")
        seen.append(tuple(sim.read(name) for name in names))
    assert seen == expected_scans(4)


def test_a_function_block_its_method_and_a_function_call_a_program_method():
    """``Prog.M()`` from an FB's body, from one of its methods and from a FUNCTION: the program's one instance."""
    sim = run(
        """
PROGRAM Store
VAR total : INT; END_VAR
METHOD Put : INT
VAR_INPUT n : INT; END_VAR
total := total + n;
Put := total;
END_METHOD
PROPERTY Sum : INT
GET
Sum := total;
END_GET
SET
total := Sum;
END_SET
END_PROPERTY
END_PROGRAM
FUNCTION PutTen : INT
PutTen := Store.Put(10);
END_FUNCTION
FUNCTION_BLOCK Feeder
VAR_OUTPUT a : INT; b : INT; END_VAR
METHOD Feed : INT
Feed := Store.Put(n := 100);
END_METHOD
a := Store.Put(1);
b := Feed();
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : Feeder; c : INT; END_VAR
f();
c := PutTen();
IF c > 200 THEN
    Store.Sum := 0;
END_IF;
END_PROGRAM
"""
    )
    sim.cycle(1)  # Store's own body does nothing; Main: +1, +100, +10
    assert (sim.read("Main.f.a"), sim.read("Main.f.b"), sim.read("Main.c"), sim.read("Store.total")) == (
        1,
        101,
        111,
        111,
    )
    sim.cycle(1)  # 112, 212, 222 > 200: the property's SET writes 0
    assert (sim.read("Main.f.a"), sim.read("Main.f.b"), sim.read("Main.c"), sim.read("Store.total")) == (
        112,
        212,
        222,
        0,
    )


def test_each_instance_of_a_program_runs_its_methods_on_its_own_variables():
    """A configuration with two instances of one PROGRAM (CFG-06): ``Step()`` inside the program works on the
    instance running it, so each counts on its own (``a`` starts at 5 through VAR_CONFIG)."""
    sim = run(
        """
PROGRAM Counter
VAR n : INT; END_VAR
METHOD Step : INT
VAR_INPUT inc : INT; END_VAR
n := n + inc;
Step := n;
END_METHOD
Step(1);
THIS^.Step(inc := 10);
END_PROGRAM
CONFIGURATION C
RESOURCE R ON PLC
TASK T(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM a WITH T : Counter;
PROGRAM b WITH T : Counter;
END_RESOURCE
VAR_CONFIG
a.n : INT := 5;
END_VAR
END_CONFIGURATION
"""
    )
    sim.cycle(2)
    assert (sim.read("a.n"), sim.read("b.n")) == (5 + 2 * 11, 2 * 11)


def test_a_program_method_called_from_outside_needs_the_instance_named_like_the_program():
    """With a configuration whose instances of Counter are ``a`` and ``b``, ``Counter.Step()`` from another program
    names no instance: a located error (as reading ``Counter.n`` is), never a guess."""
    text = """
PROGRAM Counter
VAR n : INT; END_VAR
METHOD Step : INT
n := n + 1;
Step := n;
END_METHOD
END_PROGRAM
PROGRAM User
VAR x : INT; END_VAR
x := Counter.Step();
END_PROGRAM
CONFIGURATION C
RESOURCE R ON PLC
TASK T(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM a WITH T : Counter;
PROGRAM b WITH T : Counter;
PROGRAM User WITH T : User;
END_RESOURCE
END_CONFIGURATION
"""
    project, _ = source_to_project(text, "p")
    found = [
        (d.code, d.file, d.line, d.column, d.message)
        for d in build_project(project).diagnostics
        if d.severity == "error"
    ]
    assert found == [
        (
            "IR-UNSUPPORTED",
            "User/body",
            11,
            6,
            "the program Counter runs as its instances a, b: other POUs call the instance named like the program "
            "(PROGRAM Counter : Counter in the configuration)",
        )
    ]


def test_private_and_protected_methods_of_a_program_are_refused_outside_it():
    """Access specifiers (IEC 61131-3 ed. 3, 6.6.5): nothing derives from a program, so PROTECTED is PRIVATE; the
    program's own body and methods call both."""
    text = """
PROGRAM Main
VAR n : INT; END_VAR
METHOD PRIVATE Hidden : INT
Hidden := n;
END_METHOD
METHOD PROTECTED Guarded
n := n + 1;
END_METHOD
METHOD Both : INT
Guarded();
Both := Hidden();
END_METHOD
Guarded();
n := n + THIS^.Hidden();
END_PROGRAM
PROGRAM Other
VAR x : INT; END_VAR
x := Main.Hidden();
Main.Guarded();
END_PROGRAM
"""
    project, _ = source_to_project(text, "p")
    found = [(d.code, d.file, d.line, d.column, d.message) for d in build_project(project).diagnostics]
    assert found == [
        (
            "ST-NOT-ACCESSIBLE",
            "Other/body",
            19,
            6,
            "the method Main.Hidden is PRIVATE: only its own program may call it",
        ),
        (
            "ST-NOT-ACCESSIBLE",
            "Other/body",
            20,
            1,
            "the method Main.Guarded is PROTECTED: only its own program may call it",
        ),
    ]


@pytest.mark.parametrize(
    ("members", "expected"),
    [
        (
            "METHOD ABSTRACT M\nEND_METHOD\n",
            [("ST-DECL", "Main.M/declarations", "a program's method cannot be ABSTRACT: nothing extends a program")],
        ),
        (
            "METHOD FINAL M\nEND_METHOD\n",
            [("ST-DECL", "Main.M/declarations", "a program's method cannot be FINAL: nothing extends a program")],
        ),
        (
            "METHOD n\nEND_METHOD\n",
            [("ST-DUPLICATE", "Main.n/declarations", "'n' is both a variable and a method or property of Main")],
        ),
        (
            "METHOD A\nB();\nEND_METHOD\nMETHOD B\nTHIS^.A();\nEND_METHOD\n",
            [
                (
                    "ST-RECURSION",
                    "Main.A/body",
                    "recursive call Main.A -> Main.B -> Main.A: methods must not call themselves (POU-02)",
                )
            ],
        ),
    ],
)
def test_program_method_declaration_errors_are_located(members, expected):
    assert errors(f"PROGRAM Main\nVAR n : INT; END_VAR\n{members}END_PROGRAM\n") == expected


def test_a_program_still_has_no_actions_and_no_extends():
    """ACTIONs outside SFC stay a function block's (IL-08); ``EXTENDS`` after a program's name is a parse error."""
    project = Project(
        name="p",
        pous=[
            Pou(
                name="Main",
                kind="program",
                language="st",
                methods=[Method(name="M", body="")],
                actions=[PouAction(name="A", body="")],
            )
        ],
    )
    assert [(d.code, d.file, d.message) for d in build_project(project).diagnostics] == [
        ("ST-DECL", "Main.A/declarations", "only a function block has actions, not a program")
    ]
    _, diagnostics = source_to_project("PROGRAM Main EXTENDS Base\nEND_PROGRAM\n", "p")
    assert [(d.code, d.line, d.column) for d in diagnostics] == [("ST-PARSE", 1, 22)]


def test_a_breakpoint_in_a_program_method_halts_in_each_call_with_the_call_stack():
    """ON-03: a breakpoint on a line of ``Tally.Add`` halts in the debug engine's POU ``TALLY.ADD`` before that
    statement, once for each call: from Tally's own body (``Add(1)``) and from User (``Tally.Add(n := 4)``); the call
    stack shows the caller's program frame, then the method's with its instance and its own variables (``fresh``
    already holds n, the result is still 0). ON-04: a step goes to the method's next statement."""
    project, _ = source_to_project(TALLY + USER, "tally")
    sim = build_project(project, "debug").simulation()
    at = line("count := count + fresh;")
    sim.set_breakpoint("Tally.Add", line=at)
    sim.cycle(1)

    def halted():
        return [
            (f.pou, f.kind, f.instance, f.origin.line, [(v.name, v.kind, v.value) for v in f.variables])
            for f in sim.call_stack()
        ]

    method = ("TALLY.ADD", "method", "TALLY", at)
    assert (sim.halted.reason, sim.halted.origin.pou, sim.halted.origin.line) == ("breakpoint", "TALLY.ADD", at)
    assert halted() == [
        ("TALLY", "program", "TALLY", line("last := Add(1);"), []),
        (*method, [("N", "input", 1), ("DOUBLED", "output", 0), ("FRESH", "var", 1), ("ADD", "result", 0)]),
    ]
    assert sim.read("Tally.count") == 0
    halt = sim.step("statement")
    assert (halt.origin.pou, halt.origin.line) == ("TALLY.ADD", line("calls := calls + 1;"))
    assert sim.read("Tally.count") == 1
    sim.resume()  # THIS^.Add(n := 2): halts again
    assert halted()[0][3] == line("last := last + THIS^.Add(n := 2);")
    sim.resume()  # Tally.Add(n := 4) from User
    assert halted() == [
        ("USER", "program", "USER", line("r := Tally.Add(n := 4, doubled => d);"), []),
        (*method, [("N", "input", 4), ("DOUBLED", "output", 0), ("FRESH", "var", 4), ("ADD", "result", 0)]),
    ]
    assert sim.resume() is None and sim.halted is None
    assert (sim.read("Tally.count"), sim.read("User.r"), sim.read("User.d")) == (7, 7, 14)


def test_a_plants_methods_run_in_the_plant_and_control_code_cannot_call_them():
    """A plant (issue 21) is a PROGRAM that models the process: its own body calls its method (level rises by 1 each
    scan), while control code calling ``Tank.Fill()`` or reading its property is ST-PLANT at the call, as calling the
    plant itself is."""
    from ladderlab.model.project import Accessor, Property

    tank = Pou(
        name="Tank",
        kind="plant",
        language="st",
        declarations="VAR level : INT; END_VAR",
        body="level := level + Fill();",
        methods=[Method(name="Fill", return_type="INT", body="Fill := 1;")],
        properties=[Property(name="Height", type="INT", get=Accessor(body="Height := level;"))],
    )
    main = Pou(name="Main", kind="program", language="st", declarations="VAR x : INT; END_VAR", body="")
    sim = build_project(Project(name="p", pous=[tank, main])).simulation()
    sim.cycle(3)
    assert sim.read("Tank.level") == 3
    calling = main.model_copy(update={"body": "x := Tank.Fill();\nx := Tank.Height;"})
    found = [
        (d.code, d.file, d.line, d.column) for d in build_project(Project(name="p", pous=[tank, calling])).diagnostics
    ]
    assert found == [("ST-PLANT", "Main/body", 1, 6), ("ST-PLANT", "Main/body", 2, 6)]


def test_a_test_file_calls_a_program_method_between_scans():
    """A TEST (docs/testing.md) reaches the program through its link ``Tally``: ``Tally.Add(n := 5)`` runs on the
    program's instance (count 0 -> 5), then one scan of Tally's body adds 1 and 2 (8 <= 20: no Reset); the property
    reads 8 * 10."""
    from tests.testing.helpers import outcomes
    from tests.testing.helpers import run as run_tests

    tests = """
TEST 'a program method from a test'
  ASSERT_EQ(Tally.Add(n := 5), 5);
  ASSERT_EQ(Tally.count, 5);
  RUN_SCANS(1);
  ASSERT_EQ(Tally.count, 8);
  ASSERT_EQ(Tally.Level, 80);
  ASSERT_EQ(Tally.last, 6 + 8);
END_TEST
"""
    assert outcomes(run_tests(TALLY, tests)) == {"a program method from a test": None}
    failing = tests.replace("ASSERT_EQ(Tally.count, 8);", "ASSERT_EQ(Tally.count, 9);")
    assert outcomes(run_tests(TALLY, failing))["a program method from a test"] is not None


def test_a_program_method_does_not_call_a_program():
    """POU-32 (functions and FBs cannot call programs) holds for methods, a program's too: the message names the
    method, not the function it is checked as."""
    text = "PROGRAM Main\nMETHOD M\nO();\nEND_METHOD\nM();\nEND_PROGRAM\nPROGRAM O\nEND_PROGRAM\n"
    assert errors(text) == [("ST-NOT-CALLABLE", "Main.M/body", "a method cannot call the program O")]


def test_an_ld_box_and_an_fbd_block_call_a_program_method():
    """In LD and FBD a method call is a box ``Prog.M`` (CODESYS), as ``inst.M`` is for an FB: the LD box (EN from a
    TRUE contact) puts 5 into Store, then the FBD block puts 3 and reads the output ``was`` (the total before): per
    scan +8 in all, so after scan k: Lad.r = 8k - 3, Side.f = 8k, Side.g = 8k - 3."""
    from tests.ir.diagram_support import blk, box, contact, fbd_pou, inp, ld_pou, net, out, rung

    project, diagnostics = source_to_project(STORE, "boxes")
    assert project is not None and diagnostics == []
    puts = box("b1", "Store.Put", en=True, n="5", outputs={"OUT": "r"})
    network = net(
        "n1",
        [inp("i", "3"), blk("a", "Store.Put"), out("o", "f"), out("w", "g")],
        [("i.OUT", "a.n"), ("a.OUT", "o.IN"), ("a.was", "w.IN")],
        order=["a", "o", "w"],
    )
    project.pous += [
        ld_pou("Lad", "VAR r : INT; END_VAR", rung("n1", contact("k", "TRUE"), puts)),
        fbd_pou("Side", "VAR f : INT; g : INT; END_VAR", network),
    ]
    sim = run_project(project)
    for k in (1, 2, 3):
        sim.cycle(1)
        assert (sim.read("Lad.r"), sim.read("Side.f"), sim.read("Side.g")) == (8 * k - 3, 8 * k, 8 * k - 3)


STORE = """
PROGRAM Store
VAR total : INT; END_VAR
METHOD Put : INT
VAR_INPUT n : INT; END_VAR
VAR_OUTPUT was : INT; END_VAR
was := total;
total := total + n;
Put := total;
END_METHOD
END_PROGRAM
"""


def test_an_fbd_method_blocks_unwired_output_has_a_value_online():
    """ON-09 (a value on every pin, as an FB's unwired outputs have): the FBD block ``Store.Put`` with nothing wired
    to its output ``was`` still probes it, so the editor's pin shows it. By hand, n = 3 each scan: after scan k the
    total is 3k, Put gives 3k and ``was`` (the total before the call) 3k - 3."""
    from tests.ir.diagram_support import blk, fbd_pou, inp, net, out

    project, diagnostics = source_to_project(STORE, "unwired")
    assert project is not None and diagnostics == []
    network = net("n1", [inp("i", "3"), blk("a", "Store.Put"), out("o", "f")], [("i.OUT", "a.n"), ("a.OUT", "o.IN")])
    project.pous.append(fbd_pou("Side", "VAR f : INT; END_VAR", network))
    result = build_project(project, "monitor")  # the variant the editor runs online: probes recorded
    assert [d.format() for d in result.diagnostics] == []
    sim = result.simulation()
    for k in (1, 2, 3):
        sim.cycle(1)
        values = sim.probes("Side").values
        assert (values["a.OUT"], values["a.WAS"], values["o"]) == (3 * k, 3 * k - 3, 3 * k)


def run_project(project):
    result = build_project(project)
    assert [d.format() for d in result.diagnostics] == []
    return result.simulation()
