"""CODESYS's FB_init and FB_exit (issue 25): run by the system, not by the program.

What is expected comes from CODESYS's online help, "Methods FB_Init, FB_Reinit, FB_Exit" (FB_Init "is always
available implicitly and it is used primarily for initialization"; on a first download ``bInCopyCode`` is FALSE and
``bInitRetains`` TRUE; additional inputs of FB_init are set in the instance's declaration, ``fb : F(n := 1)``; FB_Exit
"is called before the controller removes the code of the function block instance"; CODESYS's pragma page: "The
GlobalExit takes place before a new download or a reset. Function blocks provided with an FB_Exit method are
affected") and from Beckhoff's pages for the same CODESYS methods ("FB_init with derived function blocks": the base's
FB_init runs first and the derived one must take the base's inputs first; "FB_exit with derived function blocks":
the derived one's first, then the base's; "the function block instance is already fully initialized via the implicit
initialization code" when the explicit FB_init code runs; compiler error C0119: an FB_init needs the inputs
bInitRetains and bInCopyCode of type BOOL). The values are worked out by hand from the program texts.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.testing.run import prepare
from tests.support import fuzz_settings
from tests.testing.helpers import FILE, outcomes
from tests.testing.helpers import project as unit_project
from tests.testing.helpers import run as run_unit

from .oo_support import build, run

MOTOR = """
VAR_GLOBAL RETAIN
    exits : STRING(40);
END_VAR
FUNCTION_BLOCK FB_Motor
VAR_OUTPUT
    axis : INT := 7;
    before : INT;
    retains : BOOL;
    copy : BOOL := TRUE;
    calls : INT;
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
    bInitRetains : BOOL;
    bInCopyCode : BOOL;
    nAxis : INT;
END_VAR
before := axis;
axis := nAxis;
retains := bInitRetains;
copy := bInCopyCode;
calls := calls + 1;
END_METHOD
axis := axis + 1;
END_FUNCTION_BLOCK
"""


def test_fb_init_runs_once_per_instance_after_the_initial_values_with_the_declarations_arguments():
    sim = run(
        MOTOR
        + """PROGRAM Main
VAR
    fb : FB_Motor(nAxis := 3);
    arr : ARRAY [0..2] OF FB_Motor[(nAxis := 10), (nAxis := 20), (nAxis := 30)];
END_VAR
fb();
arr[1]();
END_PROGRAM
"""
    )
    # before the first scan: FB_init ran once, after axis got its initial value 7, with bInitRetains TRUE (a cold
    # start: the first download) and bInCopyCode FALSE
    assert [sim.read(f"Main.fb.{v}") for v in ("axis", "before", "retains", "copy", "calls")] == [3, 7, True, False, 1]
    assert [sim.read(f"Main.arr[{i}].axis") for i in range(3)] == [10, 20, 30]
    for scan in range(1, 4):  # scan by scan: only the bodies run, FB_init never again
        sim.cycle(1)
        assert (sim.read("Main.fb.axis"), sim.read("Main.fb.calls")) == (3 + scan, 1), scan
        assert [sim.read(f"Main.arr[{i}].axis") for i in range(3)] == [10, 20 + scan, 30], scan


def test_a_warm_restart_runs_fb_init_again_with_bInitRetains_false_and_a_cold_one_with_true():
    sim = run(MOTOR + "PROGRAM Main\nVAR fb : FB_Motor(nAxis := 3); END_VAR\nfb();\nEND_PROGRAM\n")
    sim.cycle(2)
    assert sim.read("Main.fb.axis") == 5
    sim.reset(cold=False)
    assert [sim.read(f"Main.fb.{v}") for v in ("axis", "before", "retains", "calls")] == [3, 7, False, 1]
    sim.cycle(1)
    assert sim.read("Main.fb.axis") == 4
    sim.reset(cold=True)
    assert [sim.read(f"Main.fb.{v}") for v in ("axis", "retains", "calls")] == [3, True, 1]


def test_globals_and_instances_in_function_blocks_get_their_arguments():
    sim = run(
        MOTOR
        + """VAR_GLOBAL
    g : FB_Motor(nAxis := 40);
END_VAR
FUNCTION_BLOCK Machine
VAR_OUTPUT
    drive : FB_Motor(nAxis := 50);
    pair : ARRAY [1..2, 0..1] OF FB_Motor[(nAxis := 1), (nAxis := 2), (nAxis := 3), (nAxis := 4)];
END_VAR
drive();
END_FUNCTION_BLOCK
PROGRAM Main
VAR m : Machine; END_VAR
m();
END_PROGRAM
"""
    )
    assert sim.read("g.axis") == 40
    assert sim.read("Main.m.drive.axis") == 50
    # row-major order, as an array initialiser fills them
    assert [sim.read(f"Main.m.pair[{i}, {j}].axis") for i in (1, 2) for j in (0, 1)] == [1, 2, 3, 4]
    sim.cycle(1)
    assert (sim.read("Main.m.drive.axis"), sim.read("Main.m.drive.calls")) == (51, 1)


ORDER = """
FUNCTION_BLOCK FB_Base
VAR_OUTPUT log : STRING(80); END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; sPath : STRING; END_VAR
log := CONCAT(log, CONCAT('B:', sPath));
END_METHOD
METHOD FB_exit : BOOL
VAR_INPUT bInCopyCode : BOOL; END_VAR
exits := CONCAT(exits, 'b');
END_METHOD
METHOD Describe : STRING
Describe := log;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Sub EXTENDS FB_Base
VAR inner : FB_Base(sPath := 'in'); END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; sPath : STRING; fSpeed : REAL; END_VAR
log := CONCAT(log, CONCAT(' S:', CONCAT(REAL_TO_STRING(fSpeed), CONCAT(' inner=', inner.Describe()))));
END_METHOD
METHOD FB_exit : BOOL
VAR_INPUT bInCopyCode : BOOL; END_VAR
exits := CONCAT(exits, 's');
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR fb : FB_Sub(sPath := 'p', fSpeed := 2.5); END_VAR
END_PROGRAM
"""


def test_the_base_fb_init_runs_first_and_an_instances_own_instances_before_it():
    # FB_Sub's FB_init reads inner's log through a method: inner was initialised before fb's own FB_init ran
    sim = run(MOTOR + ORDER)
    assert sim.read("Main.fb.log") == "B:p S:2.5 inner=B:in"
    assert sim.read("Main.fb.inner.log") == "B:in"


def test_fb_exit_runs_before_a_restart_derived_first_then_base_then_the_instances_inside():
    sim = run(MOTOR + ORDER)
    sim.cycle(1)
    assert sim.read("exits") == ""  # scans do not run it
    sim.reset(cold=False)  # exits is RETAIN: a warm restart keeps what FB_exit wrote
    assert sim.read("exits") == "sbb"  # fb: FB_Sub's, FB_Base's; then fb.inner: FB_Base's
    assert sim.read("Main.fb.log") == "B:p S:2.5 inner=B:in"  # and FB_init ran on the new instances
    sim.reset(cold=False)
    assert sim.read("exits") == "sbbsbb"


def test_fb_init_may_call_methods_and_write_the_instance():
    sim = run(
        """FUNCTION_BLOCK Scale
VAR_OUTPUT gain : REAL; offset : REAL := 1.0; ready : BOOL; END_VAR
METHOD PRIVATE Setup
VAR_INPUT g : REAL; END_VAR
gain := g * 2.0;
ready := TRUE;
END_METHOD
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; g : REAL := 0.5; END_VAR
Setup(g := g);
offset := offset + gain;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Scale(g := 1.5); b : Scale; END_VAR
END_PROGRAM
"""
    )
    assert (sim.read("Main.a.gain"), sim.read("Main.a.offset"), sim.read("Main.a.ready")) == (3.0, 4.0, True)
    # b gives no argument: g keeps its initial value 0.5
    assert (sim.read("Main.b.gain"), sim.read("Main.b.offset")) == (1.0, 2.0)


def test_a_runtime_error_in_fb_init_is_located_in_its_body_and_stops_the_program():
    sim = run(
        """FUNCTION_BLOCK F
VAR_OUTPUT x : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; d : INT; END_VAR
x := 10;
x := x / d;
END_METHOD
x := x + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : F(d := 0); END_VAR
f();
END_PROGRAM
"""
    )
    fault = sim.fault
    assert (fault.code, fault.pou, fault.task) == ("division_by_zero", "F.FB_INIT", "(initialisation)")
    assert (fault.origin.line, fault.origin.column) == (6, 1)
    assert fault.values == {"THIS.X": 10, "D": 0}
    sim.cycle(2)
    assert sim.read("Main.f.x") == 10  # no task ran: the body never added 1


FB = """FUNCTION_BLOCK F
VAR_OUTPUT x : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT; s : STRING := 'd'; END_VAR
x := n;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK G
VAR_OUTPUT x : INT; END_VAR
END_FUNCTION_BLOCK
"""


@pytest.mark.parametrize(
    ("decl", "expected"),
    [
        ("f : F;", [("ST-CALL-ARGS", 1, "the FB_init of F needs n: declare it as F(n := ...)")]),
        (
            "f : ARRAY [0..1] OF F;",
            [("ST-CALL-ARGS", 1, "the FB_init of F needs n: declare it as ARRAY [...] OF F[(n := ...), ...]")],
        ),
        ("f : F(s := 'x');", [("ST-CALL-ARGS", 5, "the FB_init of F needs n: declare it as F(n := ...)")]),
        (
            "f : F(m := 1);",
            [
                ("ST-CALL-ARGS", 7, "the FB_init of F has no input 'm'"),
                ("ST-CALL-ARGS", 5, "the FB_init of F needs n: declare it as F(n := ...)"),
            ],
        ),
        (
            "f : F(n := TRUE);",
            [
                (
                    "ST-TYPE-MISMATCH",
                    12,
                    "FB_init input n: expected INT, got BOOL without a conversion such as BOOL_TO_INT",
                )
            ],
        ),
        ("f : F(n := 100000);", [("ST-RANGE", 12, "100000 is out of range for INT (-32768..32767)")]),
        ("f : F(n := 1, n := 2);", [("ST-CALL-ARGS", 15, "the FB_init input n is given twice")]),
        ("f, f, g : F(n := 1);", [("ST-DUPLICATE", 4, "'f' is declared twice")]),  # g still gets its argument
        ("v, v, w : INT;", [("ST-DUPLICATE", 4, "'v' is declared twice")]),  # w: no FB_init arguments
        (
            "f : F(bInitRetains := TRUE, n := 1);",
            [("ST-CALL-ARGS", 7, "bInitRetains is the system's to set when the instance is initialised")],
        ),
        ("g : G(n := 1);", [("ST-CALL-ARGS", 5, "G has no FB_init method: its instances take no arguments")]),
        ("t : TON(n := 1);", [("ST-CALL-ARGS", 5, "TON has no FB_init method: its instances take no arguments")]),
        (
            "v : INT; f : F(n := v);",
            [
                (
                    "ST-CONST-EXPR",
                    21,
                    "the FB_init input n needs a constant here: LadderLab passes it when the instance is made",
                )
            ],
        ),
        (
            "a : ARRAY [0..2] OF F[(n := 1), (n := 2)];",
            [("ST-INIT", 5, "2 FB_init argument lists for 3 instances of F: give one per element")],
        ),
    ],
)
def test_fb_init_arguments_are_checked_at_the_declaration(decl, expected):
    text = FB + "PROGRAM Main\nVAR\n" + decl + "\nEND_VAR\nEND_PROGRAM\n"
    found = [(d.code, d.file, d.line, d.column, d.message) for d in build(text).diagnostics if d.severity == "error"]
    assert found == [(code, "Main/declarations", 13, column, message) for code, column, message in expected]


def test_positional_and_constant_arguments_are_accepted():
    sim = run(
        FB
        + "PROGRAM Main\nVAR CONSTANT k : INT := 4; END_VAR\nVAR a : F(5); b : F(n := k * 2 + 1); END_VAR\nEND_PROGRAM\n"
    )
    assert (sim.read("Main.a.x"), sim.read("Main.b.x")) == (5, 9)


def test_fb_init_and_fb_exit_declarations_are_checked():
    text = """FUNCTION_BLOCK A
METHOD FB_init : BOOL
VAR_INPUT bInCopyCode : BOOL; END_VAR
END_METHOD
METHOD FB_exit : BOOL
VAR_INPUT bInCopyCode : BOOL; END_VAR
VAR_OUTPUT o : INT; END_VAR
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK B
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; p : INT; END_VAR
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK C EXTENDS B
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; q : INT; END_VAR
END_METHOD
END_FUNCTION_BLOCK
"""
    found = [(d.code, d.file, d.message) for d in build(text).diagnostics if d.severity == "error"]
    assert found == [
        (
            "ST-DECL",
            "A.FB_init/declarations",
            "an FB_init method needs the inputs bInitRetains and bInCopyCode of type BOOL first",
        ),
        (
            "ST-DECL",
            "A.FB_exit/declarations",
            "A.FB_exit takes inputs only: nothing calls it to pass in-outs or outputs",
        ),
        (
            "ST-DECL",
            "C.FB_init/declarations",
            "C.FB_init must take the inputs of B.FB_init first, in their order (bInitRetains, bInCopyCode, p)",
        ),
    ]


def test_arguments_on_an_in_out_are_refused():
    text = FB + "FUNCTION_BLOCK H\nVAR_IN_OUT r : F(n := 1); END_VAR\nEND_FUNCTION_BLOCK\n"
    found = [(d.code, d.line, d.column, d.message) for d in build(text).diagnostics if d.severity == "error"]
    assert found == [
        (
            "ST-DECL",
            12,
            16,
            "FB_init arguments belong where an instance is made (a variable of a program or function block, or a "
            "global), not on a VAR_IN_OUT",
        )
    ]


def test_a_breakpoint_in_fb_init_does_not_halt_the_initialisation_but_halts_an_explicit_call():
    # Beckhoff, "FB_init": setting breakpoints "cannot have the desired effect"; LadderLab passes over them while it
    # initialises (docs/st.md), and halts at them when the program itself calls FB_init
    text = MOTOR + "PROGRAM Main\nVAR fb : FB_Motor(nAxis := 3); END_VAR\nfb.FB_init(FALSE, FALSE, 9);\nEND_PROGRAM\n"
    sim = build_project(source_to_project(text, "oo")[0], "monitor").simulation()  # as the server runs it
    sim.use_variant("debug")
    assert sim.set_breakpoint("FB_Motor.FB_init", line=19)  # before := axis;
    sim.reset(cold=True)
    assert sim.halted is None
    assert (sim.read("Main.fb.axis"), sim.read("Main.fb.calls")) == (3, 1)
    assert sim.cycle(1) == 0  # the program's own call halts there
    assert (sim.halted.point.origin.pou, sim.halted.point.origin.line) == ("FB_MOTOR.FB_INIT", 19)


@fuzz_settings(fast=10)
@given(
    rows=st.lists(st.lists(st.integers(-32768, 32767), min_size=1, max_size=3), min_size=1, max_size=3),
    depth=st.integers(1, 3),
)
def test_every_element_gets_its_own_arguments_and_every_level_of_a_lineage_runs_once_base_first(rows, depth):
    """An ARRAY [1..r, 0..c-1] of a FB derived ``depth`` - 1 times: each element's x is its own argument (row-major
    order) and its trace lists the lineage's FB_init calls base first, each once."""
    width = max(len(row) for row in rows)
    args = [row[i] if i < len(row) else 0 for row in rows for i in range(width)]
    blocks = []
    for level in range(depth):
        extends = f" EXTENDS L{level - 1}" if level else ""
        own = "VAR_OUTPUT x : INT; trace : STRING(40); END_VAR\n" if not level else ""
        blocks.append(
            f"FUNCTION_BLOCK L{level}{extends}\n{own}METHOD FB_init : BOOL\n"
            "VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT; END_VAR\n"
            f"x := n; trace := CONCAT(trace, '{level}');\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        )
    lists = ", ".join(f"(n := {value})" for value in args)
    declaration = f"a : ARRAY [1..{len(rows)}, 0..{width - 1}] OF L{depth - 1}[{lists}];"
    sim = run("".join(blocks) + f"PROGRAM Main\nVAR {declaration} END_VAR\nEND_PROGRAM\n")
    cells = [(r, c) for r in range(1, len(rows) + 1) for c in range(width)]
    assert [sim.read(f"Main.a[{r}, {c}].x") for r, c in cells] == args
    assert {sim.read(f"Main.a[{r}, {c}].trace") for r, c in cells} == {"".join(map(str, range(depth)))}


UNIT = """FUNCTION_BLOCK F
VAR_OUTPUT x : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT := 4; END_VAR
x := n;
END_METHOD
x := x + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : F(n := 7); END_VAR
f();
END_PROGRAM
"""


def test_unit_tests_see_the_program_instances_initialised_by_fb_init_and_a_warm_start_runs_it_again():
    tests = """TEST 'initialised'
ASSERT_EQ(Main.f.x, 7);
RUN_SCANS(1);
ASSERT_EQ(Main.f.x, 8);
WARM_START;
ASSERT_EQ(Main.f.x, 7);
END_TEST
TEST 'each test starts initialised'
ASSERT_EQ(Main.f.x, 7);
END_TEST
"""
    assert outcomes(run_unit(UNIT, tests)) == {"initialised": None, "each test starts initialised": None}


def test_a_tests_own_instance_is_made_without_fb_init_and_says_so():
    prepared = prepare(unit_project(UNIT), FILE, "TEST 'own'\nVAR g : F; END_VAR\nASSERT_EQ(g.x, 0);\nEND_TEST\n")
    assert [d.format() for d in prepared.diagnostics] == [
        "tests/unit.st:2:5: warning ST-DECL: F's FB_init does not run for a test's variables: the instances keep "
        "their declared values"
    ]
    given = prepare(unit_project(UNIT), FILE, "TEST 'own'\nVAR g : F(n := 1); END_VAR\nEND_TEST\n")
    assert [d.format() for d in given.diagnostics] == [
        "tests/unit.st:2:9: error ST-DECL: FB_init arguments belong where an instance is made (a variable of a "
        "program or function block, or a global), not on a test's variable"
    ]


def test_instances_in_a_structure_run_their_fb_init_and_one_needing_inputs_is_refused_there():
    sim = run(
        """TYPE Axis : STRUCT drive : F; spare : ARRAY [1..2] OF F; id : INT; END_STRUCT END_TYPE
FUNCTION_BLOCK F
VAR_OUTPUT x : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT := 5; END_VAR
x := n;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Axis; END_VAR
END_PROGRAM
"""
    )
    assert [sim.read(p) for p in ("Main.a.drive.x", "Main.a.spare[1].x", "Main.a.spare[2].x")] == [5, 5, 5]
    text = "TYPE Axis : STRUCT drive : F; END_STRUCT END_TYPE\n" + FB
    found = [(d.code, d.file, d.line, d.column, d.message) for d in build(text).diagnostics if d.severity == "error"]
    assert found == [
        (
            "ST-CALL-ARGS",
            "types",
            1,
            20,
            "the FB_init of F needs n, which a STRUCT's member cannot be given: give the inputs initial values, or "
            "declare the instance as a variable",
        )
    ]


def test_an_fb_init_input_the_system_cannot_pass_is_refused():
    text = """TYPE Pair : STRUCT a, b : INT; END_STRUCT END_TYPE
FUNCTION_BLOCK A
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; p : Pair; END_VAR
END_METHOD
END_FUNCTION_BLOCK
"""
    found = [(d.code, d.file, d.message) for d in build(text).diagnostics if d.severity == "error"]
    assert found == [
        (
            "ST-DECL",
            "A.FB_init/declarations",
            "A.FB_init's input p is an array, structure or instance, which LadderLab cannot pass when it calls the "
            "method by itself: pass a reference (REFERENCE TO, POINTER TO) or the values",
        )
    ]


def test_a_tests_instance_holding_one_with_fb_init_says_so_too():
    source = UNIT + "FUNCTION_BLOCK Machine\nVAR_OUTPUT drive : F(n := 2); END_VAR\nEND_FUNCTION_BLOCK\n"
    prepared = prepare(unit_project(source), FILE, "TEST 'own'\nVAR m : Machine; END_VAR\nEND_TEST\n")
    assert [d.format() for d in prepared.diagnostics] == [
        "tests/unit.st:2:5: warning ST-DECL: F's FB_init does not run for a test's variables: the instances keep "
        "their declared values"
    ]


# The instance declaration's own initialisation after FB_init (issue 25b). CODESYS's "Attribute: call_after_init"
# page lists how ``fbDoIt : FB_DoIt := (in1 := 99);`` is processed: ``fbDoIt.FB_Init(); fbDoIt.in1 := 99;`` (then
# the call_after_init method); Beckhoff's FB_init page ("Observe the order of initialization"): the values the
# declaration assigns to the FB's inputs are assigned after FB_init. So FB_init sees the FB's own initial values (in1 is
# 5 in FB_DoIt), what it writes to a variable the declaration initialises is overwritten, and what it writes to the
# others stays.
DO_IT = """FUNCTION_BLOCK FB_DoIt
VAR_INPUT in1 : INT := 5; END_VAR
VAR_OUTPUT seen : INT := -1; other : INT; fromN : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT := 1; END_VAR
seen := in1;
in1 := in1 + 100;
other := 42;
fromN := n;
END_METHOD
in1 := in1 + 1;
END_FUNCTION_BLOCK
"""


def _do_it(sim, path: str) -> list:
    return [sim.read(f"{path}.{v}") for v in ("in1", "seen", "other", "fromN")]


def test_the_declarations_initialisation_is_assigned_after_fb_init_as_codesys_lists_it():
    sim = run(
        DO_IT
        + """TYPE Holder : STRUCT f : FB_DoIt := (in1 := 7); END_STRUCT END_TYPE
PROGRAM Main
VAR
    fbDoIt : FB_DoIt := (in1 := 99);
    withArgs : FB_DoIt(n := 3) := (in1 := 98);
    plain : FB_DoIt;
    arr : ARRAY [0..1] OF FB_DoIt := [(in1 := 1), (in1 := 2)];
    h : Holder;
    h2 : Holder := (f := (in1 := 8));
END_VAR
fbDoIt();
withArgs();
END_PROGRAM
"""
    )
    # FB_init saw in1 = 5 (FB_DoIt's own), then the declaration's value replaced its 105; other stays 42
    assert _do_it(sim, "Main.fbDoIt") == [99, 5, 42, 1]
    assert _do_it(sim, "Main.withArgs") == [98, 5, 42, 3]
    assert _do_it(sim, "Main.plain") == [105, 5, 42, 1]  # no initialisation of its own: FB_init's value stays
    assert _do_it(sim, "Main.arr[0]") == [1, 5, 42, 1]
    assert _do_it(sim, "Main.arr[1]") == [2, 5, 42, 1]
    assert _do_it(sim, "Main.h.f") == [7, 5, 42, 1]  # the STRUCT's declaration of its member
    assert _do_it(sim, "Main.h2.f") == [8, 5, 42, 1]  # the variable's, which replaces the STRUCT's
    for scan in range(1, 3):  # scan by scan only the bodies run
        sim.cycle(1)
        assert _do_it(sim, "Main.fbDoIt") == [99 + scan, 5, 42, 1], scan
        assert _do_it(sim, "Main.withArgs") == [98 + scan, 5, 42, 3], scan
        assert sim.read("Main.arr[0].in1") == 1, scan


def test_a_warm_or_cold_restart_initialises_in_the_same_order_and_retain_variables_keep_their_values():
    sim = run(
        """FUNCTION_BLOCK Counter
VAR_INPUT start : INT := 5; END_VAR
VAR_OUTPUT seen : INT; seenKept : INT; END_VAR
VAR RETAIN kept : INT := 1; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR
seen := start;
seenKept := kept;
start := 0;
kept := kept + 1000;
END_METHOD
start := start + 1;
kept := kept + 1;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Plain
VAR_INPUT x : INT := 5; END_VAR
x := x + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR c : Counter := (start := 20, kept := 50); p : Plain := (x := 2); END_VAR
c();
p();
END_PROGRAM
"""
    )
    # cold start: FB_init saw the FB's own values (5 and 1), the declaration's came after it
    assert [sim.read(f"Main.c.{v}") for v in ("start", "kept", "seen", "seenKept")] == [20, 50, 5, 1]
    sim.cycle(2)
    assert [sim.read(v) for v in ("Main.c.start", "Main.c.kept", "Main.p.x")] == [22, 52, 4]
    # warm restart: the same order for start; kept is RETAIN and keeps 52 (FB_init sees it and adds 1000, and the
    # declaration's 50 is not assigned again); p (no FB_init) gets its declaration's 2 again, not Plain's 5
    sim.reset(cold=False)
    assert [sim.read(f"Main.c.{v}") for v in ("start", "kept", "seen", "seenKept")] == [20, 1052, 5, 52]
    assert sim.read("Main.p.x") == 2
    sim.cycle(1)
    assert [sim.read(v) for v in ("Main.c.start", "Main.c.kept", "Main.p.x")] == [21, 1053, 3]
    sim.reset(cold=True)  # a cold restart as the first start
    assert [sim.read(f"Main.c.{v}") for v in ("start", "kept", "seen", "seenKept")] == [20, 50, 5, 1]
    assert sim.read("Main.p.x") == 2


def test_an_instance_inside_is_initialised_with_its_declaration_before_the_outer_fb_init_and_the_outer_one_after():
    # CODESYS makes an instance's own instances completely (FB_init, then their declaration's values) before its
    # FB_init runs; the outer declaration's values for them come after it, and only the variables it names
    sim = run(
        """FUNCTION_BLOCK G
VAR_INPUT a : INT := 5; b : INT := 6; END_VAR
VAR_OUTPUT seenA : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR
seenA := a;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK F
VAR_INPUT inner : G := (a := 7); END_VAR
VAR_OUTPUT seenA : INT; seenB : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR
seenA := inner.a;
seenB := inner.b;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR fb : F := (inner := (b := 2)); END_VAR
END_PROGRAM
"""
    )
    # G's FB_init saw its own a (5); F's saw inner as F declares it (a 7, b 6); then Main's b := 2, a stays 7
    assert [sim.read(f"Main.fb.inner.{v}") for v in ("a", "b", "seenA")] == [7, 2, 5]
    assert [sim.read(f"Main.fb.{v}") for v in ("seenA", "seenB")] == [7, 6]


@fuzz_settings(fast=10)
@given(own=st.integers(-1000, 1000), declared=st.integers(-1000, 1000), added=st.integers(-1000, 1000))
def test_fb_init_sees_the_fbs_own_value_and_the_declarations_value_wins(own, declared, added):
    """Whatever the FB's own initial value, the declaration's and what FB_init adds: FB_init sees the FB's own value,
    the variable ends with the declaration's, and the variable FB_init writes alone keeps what FB_init wrote."""
    sim = run(
        f"""FUNCTION_BLOCK F
VAR_INPUT v : INT := {own}; END_VAR
VAR_OUTPUT seen : INT; w : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR
seen := v;
v := v + {added};
w := v;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : F := (v := {declared}); END_VAR
END_PROGRAM
"""
    )
    assert [sim.read(f"Main.f.{n}") for n in ("v", "seen", "w")] == [declared, own, own + added]


def test_structured_values_of_the_declaration_come_after_fb_init_too():
    # a standard FB's input, a STRING, an array's element and a STRUCT's member set by the declaration: FB_init sees
    # F's own values (PT T#0s as TON declares it, 'own', 3, y 2), then the declaration's are assigned
    sim = run(
        """TYPE Pt : STRUCT x : REAL := 1.5; y : INT := 2; END_STRUCT END_TYPE
FUNCTION_BLOCK F
VAR_INPUT t : TON; s : STRING := 'own'; arr : ARRAY [0..2] OF INT := [1, 2, 3]; p : Pt; END_VAR
VAR_OUTPUT seenPT : TIME; seenS : STRING; seenArr : INT; seenY : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR
seenPT := t.PT; seenS := s; seenArr := arr[2]; seenY := p.y;
s := 'init';
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR fb : F := (t := (PT := T#1s), s := 'decl', arr := [9], p := (y := 5)); END_VAR
END_PROGRAM
"""
    )
    assert [sim.read(f"Main.fb.{v}") for v in ("seenPT", "seenS", "seenArr", "seenY")] == [0, "own", 3, 2]
    assert [sim.read(f"Main.fb.{v}") for v in ("t.PT", "s", "arr[0]", "p.x", "p.y")] == [1000, "decl", 9, 1.5, 5]
