"""Whole projects -> ir.Program: globals, POUs, tasks, the body-lowering table, diagnostics (docs/ir.md)."""

from __future__ import annotations

from ladderlab.ir import nodes as ir
from ladderlab.ir.context import PouContext
from ladderlab.ir.lower_configuration import DEFAULT_TASK
from ladderlab.ir.lower_project import LOWER_BODY, lower_project
from ladderlab.ir.types import Elementary
from ladderlab.model import Pou, Project, Task
from ladderlab.st.checker import check_project
from tests.ir.helpers import BOOL, INT, REAL, lower_ok, lower_source


def test_globals_are_slots_with_flags_and_addresses():
    program = lower_ok("""VAR_GLOBAL
    Start AT %IX0.0 : BOOL;
    Count : INT := 5;
END_VAR
VAR_GLOBAL RETAIN Total : DINT; END_VAR
VAR_GLOBAL CONSTANT Gain : REAL := 1.5; END_VAR""")
    assert program.globals == [
        ir.Slot("GAIN", "VAR_GLOBAL", REAL, 1.5, constant=True),  # constants are declared first (TYPE bounds)
        ir.Slot("START", "VAR_GLOBAL", BOOL, None, address="%IX0.0"),  # located: the process image holds it
        ir.Slot("COUNT", "VAR_GLOBAL", INT, 5),
        ir.Slot("TOTAL", "VAR_GLOBAL", Elementary("DINT"), 0, retain=True),
    ]


def test_pous_by_upper_case_name_with_kind_language_and_return_type():
    program = lower_ok(
        "FUNCTION_BLOCK MyFb\n;\nEND_FUNCTION_BLOCK\nFUNCTION Get : INT\nGet := 1;\nEND_FUNCTION\n"
        "PROGRAM Main\nEND_PROGRAM\n"
    )
    assert {n: (p.kind, p.language, p.return_type) for n, p in program.pous.items()} == {
        "MYFB": ("function_block", "st", None),
        "GET": ("function", "st", INT),
        "MAIN": ("program", "st", None),
    }
    assert program.pous["MAIN"].blocks == [ir.Block([], ir.Origin("MAIN"))]  # an empty body is an empty block


def _project(pous: list[Pou], tasks: list[Task] | None = None, **texts) -> Project:
    return Project(name="p", pous=pous, tasks=tasks or [], **texts)


def test_tasks_from_the_project_with_intervals_in_ms():
    project = _project(
        [Pou(name="Fast", kind="program", language="st"), Pou(name="Slow", kind="program", language="st")],
        [
            Task(name="t_fast", interval="T#5ms", priority=1, programs=["fast"]),
            Task(name="T_slow", interval="T#1s200ms", priority=2, programs=["Slow"]),
        ],
    )
    result = lower_project(project)
    assert result.diagnostics == []
    assert [(t.name, t.interval_ms, t.priority, t.programs, t.single) for t in result.program.tasks] == [
        ("T_FAST", 5, 1, ["FAST"], None),  # the instance named after its program
        ("T_SLOW", 1200, 2, ["SLOW"], None),
    ]
    assert [(i.name, i.pou) for i in result.program.instances] == [("FAST", "FAST"), ("SLOW", "SLOW")]


def test_without_tasks_every_program_runs_in_the_default_10ms_task():
    project = _project(
        [
            Pou(name="B", kind="program", language="st"),
            Pou(name="Fb", kind="function_block", language="st"),
            Pou(name="A", kind="program", language="st"),
        ]
    )
    (task,) = lower_project(project).program.tasks
    assert (task.name, task.interval_ms, task.priority, task.programs) == (DEFAULT_TASK, 10, 0, ["B", "A"])
    assert lower_project(_project([Pou(name="Fb", kind="function_block", language="st")])).program.tasks == []


def test_a_task_naming_an_unknown_program_makes_no_program():
    project = _project(
        [Pou(name="Main", kind="program", language="st")], [Task(name="T", interval="T#10ms", programs=["Nope"])]
    )
    result = lower_project(project)
    assert result.program is None
    assert [d.code for d in result.diagnostics] == ["UNKNOWN-PROGRAM"]


def test_checker_errors_give_no_program_but_all_diagnostics():
    result = lower_source("PROGRAM P\nVAR i : INT; END_VAR\ni := undefined;\ni := ADR(i);\nEND_PROGRAM\n")
    assert result.program is None
    assert [d.format() for d in result.diagnostics] == [
        "P/body:3:6, POU P: error ST-UNKNOWN-VAR: unknown variable 'undefined'",
        "P/body:4:6, POU P: error ST-TYPE-MISMATCH: cannot assign REF_TO INT to INT",
    ]


def test_unnamed_direct_variables_are_located_slots_named_by_their_address():
    """VAR-74: ``AT %QX0.1 : BOOL`` declares a variable read and written by its address; an address used without a
    declaration is a located global of its size's default type (ST-13)."""
    text = (
        "VAR_GLOBAL AT %QX0.1 : BOOL; END_VAR\nPROGRAM P\nVAR AT %IX1.0 : BOOL; x : INT; END_VAR\n"
        "%QX0.1 := %IX1.0; x := %IW4;\nEND_PROGRAM\n"
    )
    program = lower_ok(text)
    assert [(s.name, s.type, s.address) for s in program.globals] == [
        ("%QX0.1", BOOL, "%QX0.1"),
        ("%IW4", INT, "%IW4"),  # used without a declaration: INT, the default of W
    ]
    assert [(s.name, s.address) for s in program.pous["P"].slots] == [("%IX1.0", "%IX1.0"), ("X", None)]


def test_body_lowering_is_chosen_by_language_through_lower_body(monkeypatch):
    """The contract for the LD/FBD lowerings: a (model.Pou, PouContext) -> blocks entry; hidden slots land in the POU."""
    seen = []

    def lower_ld(pou: Pou, ctx: PouContext) -> list[ir.Block]:
        seen.append((pou.name, ctx.name, sorted(ctx.info.symbols)))
        flag = ctx.hidden("n1 power", BOOL)
        x = ctx.var_for(ctx.info.symbols["X"])
        origin = ir.Origin(ctx.name, network="n1")
        return [ir.Block([ir.Assign(flag, x, origin)], origin, label="N1")]

    monkeypatch.setitem(LOWER_BODY, "ld", lower_ld)
    project = _project([Pou(name="Ladder", kind="program", language="ld", declarations="VAR x : BOOL; END_VAR")])
    result = lower_project(project, check_project(project))
    assert result.diagnostics == [] and seen == [("Ladder", "LADDER", ["X"])]
    pou = result.program.pous["LADDER"]
    assert pou.language == "ld"
    assert pou.slots == [ir.Slot("X", "VAR", BOOL, False), ir.Slot("__N1_POWER", "VAR", BOOL, False, hidden=True)]
    assert pou.blocks[0].label == "N1"


def test_edge_preamble_of_a_diagram_pou_is_a_block_of_its_own(monkeypatch):
    monkeypatch.setitem(LOWER_BODY, "fbd", lambda pou, ctx: [ir.Block([], ir.Origin(ctx.name, network="n1"), "N1")])
    project = _project(
        [Pou(name="Fb", kind="function_block", language="fbd", declarations="VAR_INPUT go : BOOL R_EDGE; END_VAR")]
    )
    blocks = lower_project(project).program.pous["FB"].blocks
    assert [(b.label, len(b.statements), b.origin) for b in blocks] == [
        (None, 2, ir.Origin("FB")),
        ("N1", 0, ir.Origin("FB", network="n1")),
    ]


def test_a_language_without_lowering_is_reported(monkeypatch):
    monkeypatch.delitem(LOWER_BODY, "ld", raising=False)
    result = lower_project(_project([Pou(name="Ladder", kind="program", language="ld")]))
    assert result.program is None
    assert [d.format() for d in result.diagnostics] == ["POU Ladder: error IR-UNSUPPORTED: LD POUs cannot be run yet"]


def test_the_model_rules_are_reported_with_the_project_and_stop_the_build():
    """A program with a return type, two tasks and two test files of one name (names ignore case)."""
    from ladderlab.model import TestFile

    project = _project(
        [Pou(name="Main", kind="program", language="st", return_type="INT")],
        [Task(name="Fast", interval="T#10ms", programs=["Main"]), Task(name="fast", interval="T#20ms")],
        tests=[TestFile(name="motor"), TestFile(name="Motor")],
    )
    result = lower_project(project)
    assert result.program is None
    assert [d.format() for d in result.diagnostics] == [
        "POU Main: error UNEXPECTED-RETURN-TYPE: only functions have a return type; Main is a program",
        "$.tasks[1]: error DUPLICATE-TASK: task 'fast' is declared twice",
        "tests/Motor.st: error DUPLICATE-TEST-FILE: test file 'Motor' is there twice",
    ]


def test_a_function_without_a_return_type_is_reported_with_its_name():
    """FUNCTION needs a result type (IEC 2.5.1); a model written by hand or by a tool can lack it.
    Said once, at its declarations."""
    project = _project([Pou(name="Twice", kind="function", language="st", body="Twice := 2;")], [])
    result = lower_project(project)
    assert result.program is None
    assert [d.format() for d in result.diagnostics] == [
        "Twice/declarations, POU Twice: error ST-DECL: the function Twice needs a return type"
    ]


def test_a_lowering_failure_nothing_explains_is_reported_never_dropped():
    """IR-INTERNAL: a statement the lowering gave up on without a message, while the checker found nothing wrong."""
    from ladderlab.ir.lower_types import LoweringError
    from ladderlab.st import ast

    project = _project(
        [Pou(name="Main", kind="program", language="st", body="x := 1;", declarations="VAR x : INT; END_VAR")]
    )
    checked = check_project(project)
    ctx = PouContext(checked, checked.pou("Main"), [])
    ctx.report_error(LoweringError(None), ast.Name("x", ast.Span(1, 1, 1, 2)))
    assert [d.format() for d in ctx.diagnostics] == [
        "Main/body:1:1, POU Main: error IR-INTERNAL: this could not be lowered (an internal error of LadderLab: "
        "please report it)"
    ]


def test_a_task_interval_that_is_not_a_time_literal_stops_the_build():
    """BAD-INTERVAL (docs/diagnostics.md): ``10ms`` lacks the ``T#`` of a TIME literal."""
    project = _project([Pou(name="Main", kind="program", language="st")], [Task(name="Main", interval="10ms")])
    result = lower_project(project)
    assert result.program is None
    assert [d.format() for d in result.diagnostics] == [
        "$.tasks[0].interval: error BAD-INTERVAL: task Main: interval '10ms' is not a TIME literal such as T#10ms"
    ]


def test_one_program_instance_in_two_tasks_stops_the_build():
    """DUPLICATE-INSTANCE (docs/diagnostics.md, CFG-06): an instance runs in one task only."""
    project = _project(
        [Pou(name="Main", kind="program", language="st")],
        [
            Task(name="Fast", interval="T#10ms", programs=["Main"]),
            Task(name="Slow", interval="T#100ms", programs=["Main"]),
        ],
    )
    result = lower_project(project)
    assert result.program is None
    assert [d.format() for d in result.diagnostics] == [
        "$.tasks[1].programs[0]: error DUPLICATE-INSTANCE: the program instance Main is run twice (task Fast and "
        "task Slow): an instance runs in one task only; declare a second instance to run the program twice"
    ]


def test_a_project_with_a_configuration_keeps_no_task_list():
    """TASKS-AND-CONFIGURATION (docs/diagnostics.md): the tasks belong in the configuration's resources."""
    from ladderlab.model.project import Configuration

    project = _project([Pou(name="Main", kind="program", language="st")], [Task(name="Main", interval="T#10ms")])
    project = project.model_copy(update={"configuration": Configuration(name="Plant")})
    assert [d.format() for d in lower_project(project).diagnostics][:1] == [
        "$.tasks: error TASKS-AND-CONFIGURATION: a project with a configuration keeps its tasks in the "
        "configuration's resources, not in tasks"
    ]
