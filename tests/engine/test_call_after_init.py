"""CODESYS's ``{attribute 'call_after_init'}`` (issue 25): a method each instance calls by itself after its FB_init
and its declaration's initial values, at start and after every restart; every misuse a located error.

Expected behaviour from CODESYS's online help, "Attribute: call_after_init" (the attribute on the function block and
on the method, each "in its own first line above the declaration part"; ``fbDoIt : FB_DoIt := (in1 := 99)`` runs as
``fbDoIt.FB_Init(); fbDoIt.in1 := 99; fbDoIt.FB_AfterInit();``; "VAR_INPUT declarations in functions or methods which
use this attribute lead to compile errors") and Beckhoff's page for the same compiler (the method's name is free
"exceptions: FB_init, FB_reinit and FB_exit"; "a function block that extends another function block, which uses the
attribute 'call_after_init', must also be assigned the attribute"; the override of the method, with the same name,
calls ``SUPER^.MyInit``). The order among instances is the FB_init's (test_fb_init.py): an instance's own instances
first. The values are worked out by hand from the program texts."""

from __future__ import annotations

from ladderlab.model import Pou, Project
from ladderlab.model.project import Accessor, Property
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.st_text import compose_pou_text, parse_pou_text

from .oo_support import run

ATTRIBUTE = "{attribute 'call_after_init'}"

DO_IT = """VAR_GLOBAL order : STRING(120); END_VAR
{attribute 'call_after_init'}
FUNCTION_BLOCK FB_DoIt
VAR_INPUT in1 : INT; END_VAR
VAR_OUTPUT seenInit : INT; seenAfter : INT; calls : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR
seenInit := in1;
order := CONCAT(order, 'init;');
END_METHOD
{attribute 'call_after_init'}
METHOD FB_AfterInit
seenAfter := in1;
calls := calls + 1;
order := CONCAT(order, CONCAT('after', CONCAT(INT_TO_STRING(in1), ';')));
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR fbDoIt : FB_DoIt := (in1 := 99); plain : FB_DoIt; END_VAR
fbDoIt(in1 := fbDoIt.in1 + 1);
END_PROGRAM
"""


def test_the_method_runs_once_per_instance_after_fb_init_and_the_declarations_values():
    sim = run(DO_IT)
    # FB_init saw in1 0 (the FB's own value), the method 99 (the declaration's): CODESYS's example
    assert [sim.read(f"Main.fbDoIt.{v}") for v in ("seenInit", "seenAfter", "calls")] == [0, 99, 1]
    assert [sim.read(f"Main.plain.{v}") for v in ("seenInit", "seenAfter", "calls")] == [0, 0, 1]
    assert sim.read("order") == "init;after99;init;after0;"
    sim.cycle(3)  # the program's calls never run it again
    assert (sim.read("Main.fbDoIt.in1"), sim.read("Main.fbDoIt.calls"), sim.read("Main.plain.calls")) == (102, 1, 1)


def test_a_restart_runs_it_again_warm_and_cold():
    sim = run(DO_IT)
    sim.cycle(2)
    sim.reset(cold=False)
    assert (sim.read("Main.fbDoIt.in1"), sim.read("Main.fbDoIt.seenAfter"), sim.read("Main.fbDoIt.calls")) == (
        99,
        99,
        1,
    )
    assert sim.read("order") == "init;after99;init;after0;"  # a restart starts the globals anew too
    sim.reset(cold=True)
    assert (sim.read("Main.fbDoIt.seenAfter"), sim.read("Main.plain.calls")) == (99, 1)


def test_inner_instances_first_and_an_override_runs_in_the_base_methods_place():
    sim = run(
        """VAR_GLOBAL order : STRING(120); END_VAR
{attribute 'call_after_init'}
FUNCTION_BLOCK FB_Base
VAR_OUTPUT tag : STRING(10) := 'b'; END_VAR
{attribute 'call_after_init'}
METHOD MyInit
order := CONCAT(order, CONCAT('base:', CONCAT(tag, ';')));
END_METHOD
END_FUNCTION_BLOCK
{attribute 'call_after_init'}
FUNCTION_BLOCK FB_Sub EXTENDS FB_Base
VAR inner : FB_Base := (tag := 'in'); END_VAR
{attribute 'call_after_init'}
METHOD MyInit
order := CONCAT(order, CONCAT('sub:', CONCAT(tag, ';')));
SUPER^.MyInit();
END_METHOD
END_FUNCTION_BLOCK
{attribute 'call_after_init'}
FUNCTION_BLOCK FB_Heir EXTENDS FB_Base
END_FUNCTION_BLOCK
PROGRAM Main
VAR fb : FB_Sub := (tag := 's'); heir : FB_Heir := (tag := 'h'); END_VAR
END_PROGRAM
"""
    )
    # inner's own call first; fb's MyInit is FB_Sub's override (once), which calls the base's; heir inherits it
    assert sim.read("order") == "base:in;sub:s;base:s;base:h;"


def test_a_fault_in_the_method_is_located_in_its_body_and_stops_the_program():
    sim = run(
        """{attribute 'call_after_init'}
FUNCTION_BLOCK F
VAR_OUTPUT x : INT; d : INT; END_VAR
{attribute 'call_after_init'}
METHOD Check
x := 10;
x := x / d;
END_METHOD
x := x + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : F; END_VAR
f();
END_PROGRAM
"""
    )
    fault = sim.fault
    assert (fault.code, fault.pou, fault.task) == ("division_by_zero", "F.CHECK", "(initialisation)")
    assert (fault.origin.line, fault.origin.column) == (7, 1)  # x := x / d; (the file's lines)
    sim.cycle(2)
    assert sim.read("Main.f.x") == 10  # no task ran


def _fb(fb_attribute: bool = True, method: str = "METHOD Ready\ndone := TRUE;\nEND_METHOD", extra: str = "") -> str:
    head = f"{ATTRIBUTE}\n" if fb_attribute else ""
    return (
        f"{head}FUNCTION_BLOCK F\nVAR_OUTPUT done : BOOL; END_VAR\n{method}\nEND_FUNCTION_BLOCK\n{extra}"
        "PROGRAM Main\nVAR f : F; END_VAR\nEND_PROGRAM\n"
    )


def _message(why: str) -> str:
    return (
        f"the attribute 'call_after_init' has no effect {why}: CODESYS calls a method after an instance's "
        "initialisation when the attribute stands on the first line of the declarations of both the function block "
        "and the method; move it there or remove it"
    )


def located(text: str) -> list[tuple[str, str | None, int | None, int | None, str]]:
    project, diagnostics = source_to_project(text, "oo")
    found = diagnostics + (build_project(project).diagnostics if project is not None else [])
    return [(d.code, d.file, d.line, d.column, d.message) for d in found if d.severity == "error"]


def test_the_method_without_the_attribute_on_its_function_block_is_an_error_at_the_method():
    found = located(_fb(fb_attribute=False, method=f"{ATTRIBUTE}\nMETHOD Ready\ndone := TRUE;\nEND_METHOD"))
    assert found == [("ST-PRAGMA", "F.Ready/declarations", 1, 1, _message("unless F has it too"))]


def test_a_method_with_inputs_is_an_error_as_codesys_gives():
    method = f"{ATTRIBUTE}\nMETHOD Ready\nVAR_INPUT n : INT; END_VAR\ndone := n > 0;\nEND_METHOD"
    assert located(_fb(method=method)) == [
        (
            "ST-PRAGMA",
            "F.Ready/declarations",
            1,
            1,
            _message(
                "on a method with inputs (n): nothing passes them when the system calls it (CODESYS: a compile error)"
            ),
        )
    ]


def test_fb_init_fb_reinit_and_fb_exit_cannot_carry_it():
    method = f"{ATTRIBUTE}\nMETHOD FB_reinit : BOOL\ndone := TRUE;\nEND_METHOD"
    assert located(_fb(method=method)) == [
        (
            "ST-PRAGMA",
            "F.FB_reinit/declarations",
            1,
            1,
            _message("on FB_reinit, which the system calls by itself (name the method otherwise)"),
        )
    ]


def test_two_methods_of_one_function_block_are_an_error_at_the_second():
    method = f"{ATTRIBUTE}\nMETHOD A\ndone := TRUE;\nEND_METHOD\n{ATTRIBUTE}\nMETHOD B\ndone := FALSE;\nEND_METHOD"
    assert located(_fb(method=method)) == [
        (
            "ST-PRAGMA",
            "F.B/declarations",
            1,
            1,
            _message("twice in F (A has it: the order of the calls would be unknown)"),
        )
    ]


def test_a_derived_function_block_without_it_is_an_error():
    derived = "FUNCTION_BLOCK G EXTENDS F\nEND_FUNCTION_BLOCK\n"
    method = f"{ATTRIBUTE}\nMETHOD Ready\ndone := TRUE;\nEND_METHOD"
    assert located(_fb(method=method, extra=derived)) == [
        (
            "ST-PRAGMA",
            "G/declarations",
            None,
            None,
            "G extends F, which has {attribute 'call_after_init'}: G needs it too, on the first line of its "
            "declarations (CODESYS)",
        )
    ]


def test_on_a_program_a_function_a_property_the_globals_or_in_a_body_it_is_an_error_where_it_stands():
    getter = Accessor(declarations=f"{ATTRIBUTE}\nVAR n : INT; END_VAR", body="P := v;")
    project = Project(
        name="oo",
        globals=f"{ATTRIBUTE}\nVAR_GLOBAL g : INT; END_VAR",
        pous=[
            Pou(
                name="Main",
                kind="program",
                language="st",
                declarations=f"{ATTRIBUTE}\nVAR x : INT; END_VAR",
                body=f"x := 1;\n{ATTRIBUTE}\nx := 2;",
            ),
            Pou(name="Fn", kind="function", language="st", return_type="INT", declarations=ATTRIBUTE, body="Fn := 1;"),
            Pou(
                name="F",
                kind="function_block",
                language="st",
                declarations="VAR_OUTPUT v : INT; END_VAR",
                properties=[Property(name="P", type="INT", get=getter)],
            ),
        ],
    )
    found = [(d.file, d.line, d.column, d.message) for d in build_project(project).diagnostics if d.severity == "error"]
    assert found == [
        ("Main/body", 2, 1, _message("here")),  # (the parser's: a body never holds it)
        ("Main/declarations", 1, 1, _message("on a program")),
        ("Fn/declarations", 1, 1, _message("on a function")),
        ("F.P.GET/declarations", 1, 1, _message("on a property")),
        ("globals", 1, 1, _message("on global variables")),
    ]


def test_above_a_program_in_an_st_file_it_is_an_error_where_it_stands():
    _, diagnostics = source_to_project(f"{ATTRIBUTE}\nPROGRAM Main\nVAR x : INT; END_VAR\nEND_PROGRAM\n", "oo")
    assert [(d.code, d.line, d.column, d.end_column, d.message) for d in diagnostics] == [
        ("ST-PRAGMA", 1, 1, 30, _message("here"))
    ]


def test_above_a_method_of_an_interface_it_is_an_error_where_it_stands_in_the_file_and_in_the_types():
    """An INTERFACE's METHOD is a prototype no instance runs: CODESYS puts the attribute on the function block's
    method. Reported at the attribute in an ST file and, for a project whose types text holds it, by the check."""
    interface = f"INTERFACE I\n{ATTRIBUTE}\nMETHOD Setup\nEND_METHOD\nEND_INTERFACE\n"
    project, diagnostics = source_to_project(f"{interface}PROGRAM Main\nVAR x : INT; END_VAR\nEND_PROGRAM\n", "oo")
    why = _message("on a method of an INTERFACE")
    assert [(d.code, d.line, d.column, d.message) for d in diagnostics] == [("ST-PRAGMA", 2, 1, why)]
    assert project is not None
    checked = build_project(project.model_copy(update={"types": interface}))
    assert [(d.code, d.file, d.line, d.column, d.message) for d in checked.diagnostics] == [
        ("ST-PRAGMA", "types", 2, 1, why)
    ]


def test_on_a_function_block_alone_it_is_a_warning():
    built = build_project(source_to_project(_fb(), "oo")[0])
    assert [(d.severity, d.code, d.file, d.line) for d in built.diagnostics] == [
        ("warning", "ST-PRAGMA", "F/declarations", 1)
    ]
    assert "on F alone: none of its methods has it" in built.diagnostics[0].message


def test_one_between_a_methods_variable_blocks_is_an_error_where_it_stands():
    between = f"METHOD Ready\nVAR x : INT; END_VAR\n{ATTRIBUTE}\nVAR y : INT; END_VAR\ndone := TRUE;\nEND_METHOD"
    assert located(_fb(method=between)) == [  # the file's, and the method's declarations' when the project builds
        ("ST-PRAGMA", None, 6, 1, _message("here")),
        ("ST-PRAGMA", "F.Ready/declarations", 6, 1, _message("here")),
    ]


def test_a_function_block_with_the_attribute_is_stored_as_its_st_file_and_read_back():
    """The project folder's ``pous/G.st``: the attribute above the header, as CODESYS writes it."""
    derived = Pou(
        name="G",
        kind="function_block",
        language="st",
        declarations=f"{ATTRIBUTE}\nVAR x : INT; END_VAR",
        body="x := 1;",
    )
    text = compose_pou_text(derived)
    assert text == f"{ATTRIBUTE}\nFUNCTION_BLOCK G\nVAR x : INT; END_VAR\nx := 1;\nEND_FUNCTION_BLOCK\n"
    assert parse_pou_text(text) == derived
