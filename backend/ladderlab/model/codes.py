"""Every diagnostic code, declared once: its usual severity and a one-line summary.

docs/diagnostics.md explains each code with an example that triggers it and how to fix it; ``make schema``
joins both into ``shared_schema/diagnostics.json``, from which the browser shows a diagnostic's summary and
entry. The test suite fails when a code is used in the sources but missing here, or listed here but produced
by no test (tests/foundation/test_diagnostic_codes.py, tests/diagnostic_codes.py). A code keeps its meaning
for good: clients and users' notes refer to it.

Codes are ``AREA-WORDS`` in capitals; the LD and FBD lowerings share their checks and report them as
``LD-...`` or ``FBD-...`` (``DIAGRAM``). Runtime faults of a running program are all ``ENGINE-RUNTIME``; the
fault's own kind (division_by_zero ...) is in its message (docs/runtime.md).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Literal

Severity = Literal["error", "warning", "info"]

#: The code of every runtime fault of a running program (engine.codegen.faults; the server reports a lost one).
RUNTIME_FAULT = "ENGINE-RUNTIME"


@dataclass(frozen=True)
class Code:
    code: str
    severity: Severity
    summary: str
    area: str


#: The diagram languages whose lowerings report the shared diagram checks under their own prefix.
DIAGRAM_LANGUAGES = ("LD", "FBD")

_AREAS = {
    "project": "Project model",
    "files": "Project files and storage",
    "requests": "Requests to the server",
    "st": "Structured Text",
    "diagram": "LD and FBD",
    "ld": "Ladder diagram",
    "fbd": "Function block diagram and CFC",
    "build": "Building and running",
    "tests": "Unit tests of PLC programs",
    "il": "Instruction List",
    "sfc": "Sequential function charts",
    "export": "ST export",
    "plcopen": "PLCopen XML",
}

_TABLE: list[tuple[str, str, Severity, str]] = [
    # project model (model/validate.py)
    ("project", "BAD-NAME", "error", "A POU or test file name is not a valid name."),
    ("project", "DUPLICATE-POU", "error", "Two POUs have the same name (names ignore case)."),
    ("project", "DUPLICATE-TASK", "error", "Two tasks have the same name."),
    ("project", "DUPLICATE-INSTANCE", "error", "One program instance is run by two tasks."),
    ("project", "TASKS-AND-CONFIGURATION", "error", "A project has both a task list and a configuration."),
    ("project", "DUPLICATE-TEST-FILE", "error", "Two test files have the same name."),
    ("project", "UNEXPECTED-RETURN-TYPE", "error", "A PROGRAM or FUNCTION_BLOCK has a return type."),
    ("project", "BAD-INTERVAL", "error", "A task's interval is not a TIME literal."),
    ("project", "UNKNOWN-PROGRAM", "error", "A task runs a program the project does not have."),
    ("project", "NOT-A-PROGRAM", "error", "A task runs a function or function block instead of a program."),
    ("project", "RESERVED-TASK", "error", "A task is named like the plant task (PLANTS), which is reserved."),
    # project files and storage
    ("files", "BAD-FILE", "error", "A project file does not hold what LadderLab expects there."),
    ("files", "BAD-JSON", "error", "A JSON file or request body is not valid JSON."),
    ("files", "BAD-PATH", "error", "The path given for a project is not a project folder or file."),
    ("files", "NOT-FOUND", "error", "No project or POU of that name exists."),
    ("files", "EXISTS", "error", "A project of that name exists already."),
    ("files", "CONFLICT", "error", "The project changed since it was opened; the save was refused."),
    ("files", "DISK-FULL", "error", "The disk is full: nothing was saved."),
    ("files", "BAD-ENCODING", "error", "A text file is not in the encoding it is read in (UTF-8 unless told)."),
    ("files", "BAD-OPTION", "error", "A command-line option has a value the command cannot use."),
    # requests to the server
    ("requests", "BAD-REQUEST", "error", "A request to the server does not have the expected shape."),
    # structured text (st/)
    ("st", "ST-PARSE", "error", "The text is not valid Structured Text at this place."),
    ("st", "ST-TOO-DEEP", "error", "Expressions or statements are nested deeper than the limit."),
    ("st", "ST-NAME", "error", "A name is not a valid IEC identifier."),
    ("st", "ST-DUPLICATE", "error", "A name is declared twice in the same scope."),
    ("st", "ST-DECL", "error", "A declaration breaks a rule of its VAR block."),
    ("st", "ST-INIT", "error", "An initial value does not fit the declared variable."),
    ("st", "ST-EXTERNAL", "error", "A VAR_EXTERNAL does not match a global variable."),
    ("st", "ST-RECURSION", "error", "A POU calls itself, or a type is defined in terms of itself."),
    ("st", "ST-UNKNOWN-VAR", "error", "A name is used that is not declared."),
    ("st", "ST-UNKNOWN-TYPE", "error", "A type name is not an elementary, standard or declared type."),
    ("st", "ST-UNKNOWN-POU", "error", "A call names a function that does not exist."),
    ("st", "ST-ADDRESS", "error", "A direct address (%IX0.0, %QW4) is malformed or does not fit its variable."),
    ("st", "ST-REF", "error", "A reference (REF, ADR) to a variable that may not be referred to."),
    ("st", "ST-CONFIG", "error", "A CONFIGURATION text does not describe a valid configuration."),
    ("st", "ST-UNKNOWN-MEMBER", "error", "A structure, function block or value has no member of that name."),
    ("st", "ST-NOT-ACCESSIBLE", "error", "A function block's internal variable is used from outside it."),
    ("st", "ST-NOT-CALLABLE", "error", "Something that cannot be called is called."),
    (
        "st",
        "ST-PLANT",
        "error",
        "Control code calls a plant or its method or property (plants run in the plant task, never called).",
    ),
    ("st", "ST-CALL-ARGS", "error", "The arguments of a call do not match its parameters."),
    (
        "st",
        "ST-AMBIGUOUS",
        "error",
        "A name is a value of several enumerations or a variable of several global variable lists.",
    ),
    (
        "st",
        "ST-QUALIFIED-ONLY",
        "error",
        "A variable of a qualified_only global variable list is used without the list's name.",
    ),
    ("st", "ST-TYPE-MISMATCH", "error", "A value of one type is used where another type is needed."),
    ("st", "ST-IMPLICIT-CONV", "warning", "A value is widened to a larger type without an explicit conversion."),
    ("st", "ST-IMPLICIT-NARROW", "warning", "CODESYS typing: a value is narrowed to a smaller type implicitly."),
    ("st", "ST-CODESYS-REGISTER", "error", "CODESYS typing: a value would depend on the width of the PLC's registers."),
    ("st", "ST-RANGE", "error", "A constant lies outside the range of its type."),
    ("st", "ST-INDEX", "error", "An array index or range is wrong."),
    ("st", "ST-CONST-EXPR", "error", "A constant expression is needed here."),
    ("st", "ST-CONST-WRITE", "error", "A CONSTANT is assigned."),
    ("st", "ST-READONLY", "error", "An output of a function block instance is assigned from outside it."),
    ("st", "ST-NOT-LVALUE", "error", "Something that is not a variable is assigned."),
    ("st", "ST-INPUT-WRITE", "warning", "An input of the POU is assigned inside it."),
    ("st", "ST-LOOP-VAR", "error", "A FOR loop's variable or step is not allowed."),
    ("st", "ST-EXIT-OUTSIDE-LOOP", "error", "EXIT or CONTINUE is used outside a loop."),
    ("st", "ST-CASE-OVERLAP", "warning", "Two CASE labels overlap: only the first branch ever runs."),
    ("st", "ST-NO-EFFECT", "error", "A statement computes a value and does nothing with it."),
    ("st", "ST-NO-RESULT", "warning", "A function never assigns its result."),
    ("st", "ST-PRAGMA", "warning", "A pragma stands where it has no effect (call_after_init: an error)."),
    # both diagram languages (ir/diagram_*.py), as LD-... and FBD-...
    ("diagram", "MISSING-OPERAND", "error", "An element has no operand."),
    ("diagram", "NOT-BOOL", "error", "An element that carries power or a BOOL value is given another type."),
    ("diagram", "INPUT-WRITE", "error", "A coil or output writes an input of the POU."),
    ("diagram", "UNKNOWN-CALL", "error", "A box calls a function or function block that does not exist."),
    ("diagram", "PLANT", "error", "A box calls a plant (plants run in the plant task, never called)."),
    ("diagram", "NOT-CALLABLE", "error", "A box in a function or function block calls a program."),
    ("diagram", "NO-INSTANCE", "error", "A function block box has no instance."),
    ("diagram", "INSTANCE", "error", "A function box has an instance."),
    ("diagram", "INSTANCE-TYPE", "error", "A box's instance is not an instance of the function block it calls."),
    ("diagram", "MISSING-PIN", "error", "An input of a box is not connected."),
    ("diagram", "IN-OUT", "error", "An in-out pin of a box is fed a computed value instead of a variable."),
    (
        "diagram",
        "BAD-LABEL",
        "error",
        "A network or CFC label is not an identifier or an unsigned integer, or FBD has a label element.",
    ),
    ("diagram", "DUPLICATE-LABEL", "error", "Two networks of a POU (two labels of a CFC chart) have the same label."),
    ("diagram", "UNKNOWN-LABEL", "error", "A jump names a label no network of the POU (no label of the chart) has."),
    ("diagram", "DUPLICATE-ID", "error", "Two networks or elements of a POU have the same id."),
    # ladder diagram (ir/lower_ld.py)
    ("ld", "LD-PARALLEL", "error", "A parallel branch has fewer than two branches."),
    ("ld", "LD-CONTROL-POSITION", "error", "A jump or return is not at the end of a branch that ends the rung."),
    ("ld", "LD-UNKNOWN-PIN", "error", "A box pin is connected that the box does not have."),
    ("ld", "LD-BOX-POWER", "error", "A box without EN/ENO cannot pass the rung's power flow."),
    # function block diagram (ir/lower_fbd.py, ir/fbd_order.py)
    ("fbd", "FBD-BAD-WIRE", "error", "A wire ends at a node or pin that cannot take it."),
    ("fbd", "FBD-WIRED-OR", "error", "Several wires lead into one input."),
    ("fbd", "FBD-DANGLING", "error", "An output or connector has no input wire."),
    ("fbd", "FBD-CONNECTOR", "error", "A connector or continuation has no partner, or a name that is taken."),
    ("fbd", "FBD-ORDER", "error", "The network's stored execution order names a node it does not have."),
    (
        "fbd",
        "FBD-FEEDBACK",
        "error",
        "A loop carries a generic function's result whose type nothing outside the loop gives.",
    ),
    ("fbd", "FBD-UNKNOWN-PIN", "error", "A wire or flag uses a pin the block does not have."),
    ("fbd", "FBD-PIN-FLAG", "error", "An output pin has an edge flag."),
    ("fbd", "CFC-JUMP-CONDITION", "error", "A jump on a CFC chart has no condition wired into its input."),
    # building and running
    ("build", "IR-UNSUPPORTED", "error", "The program uses something LadderLab cannot run yet."),
    ("build", "IR-EN-CALL", "error", "A call with EN/ENO stands where its statement cannot be lifted out."),
    ("build", "IR-INIT", "error", "An initial value cannot be stored in its variable."),
    ("build", "PANEL-BINDING", "error", "A panel widget is bound to a variable the program does not have."),
    ("build", "IR-INTERNAL", "error", "LadderLab failed on something it should handle: please report it."),
    ("build", "LIMIT-SIZE", "error", "The project is larger than a documented limit allows."),
    ("build", "BUILD-LIMIT", "error", "A check or build ran out of its time or memory."),
    ("build", "ENGINE-COMPILE", "error", "The generated program could not be compiled."),
    ("build", "ENGINE-TASKS", "error", "The task configuration cannot be run."),
    ("build", "ENGINE-RUNTIME", "error", "The running program stopped with a runtime fault."),
    # unit tests of PLC programs (st/testfile.py, testing/)
    ("tests", "TEST-DECL", "error", "A test declares something other than VAR blocks."),
    ("tests", "TEST-DUPLICATE", "error", "Two tests of a file have the same name."),
    ("tests", "TEST-VERB", "error", "A test verb is used with the wrong arguments."),
    ("tests", "TEST-FORCE", "error", "FORCE or RELEASE names something that cannot be forced."),
    ("tests", "TEST-MOCK", "error", "MOCK or MOCK_FUNCTION names something that cannot be mocked."),
    ("tests", "TEST-MEMORY", "error", "A test file needed more memory than its process may use."),
    ("tests", "TEST-WORKER", "error", "The process running a test file stopped."),
    # instruction list (st/il_parser.py, st/il_check.py)
    ("il", "IL-PARSE", "error", "The text is not a valid IL instruction at this place."),
    ("il", "IL-UNKNOWN-OPERATOR", "error", "An IL line starts with a word that is no operator or function."),
    ("il", "IL-OPERAND", "error", "An IL operator has the wrong number or kind of operands."),
    ("il", "IL-TYPE", "error", "The accumulator's type does not fit the operator or the operand."),
    ("il", "IL-NO-CR", "error", "An instruction reads the accumulator before anything was loaded."),
    ("il", "IL-CR-TYPE", "error", "The accumulator cannot hold this type, or its type differs by path."),
    ("il", "IL-LABEL", "error", "A jump names an unknown label, or a label is defined twice."),
    ("il", "IL-PAREN", "error", "A deferred operation's '(' and ')' do not match."),
    # ST export (interchange/st/)
    ("export", "EXPORT-UNKNOWN-POU", "error", "The POU to export does not exist."),
    ("export", "EXPORT-INVALID", "error", "A POU with errors cannot be exported as ST."),
    ("export", "EXPORT-IL-JUMP", "error", "An IL jump that ST cannot write (backwards or out of a jump)."),
    ("export", "EXPORT-UNSUPPORTED", "error", "An SFC POU holds what its ST or textual SFC export cannot say."),
    ("export", "EXPORT-INTERNAL", "error", "The exported ST does not check: please report it."),
    # PLCopen XML (interchange/plcopen/)
    ("plcopen", "XML-TOO-LARGE", "error", "The XML document is larger than the import accepts."),
    ("plcopen", "XML-TOO-DEEP", "error", "The XML document is nested deeper than the import accepts."),
    ("plcopen", "XML-SYNTAX", "error", "The XML document is not well-formed."),
    ("plcopen", "XML-ENCODING", "error", "The XML document's encoding cannot be read."),
    ("plcopen", "XML-ENTITY", "error", "The XML document declares entities, which are refused."),
    ("plcopen", "XML-EXTERNAL", "error", "The XML document refers to an external DTD or entity."),
    ("plcopen", "PLCOPEN-NOT-PLCOPEN", "error", "The XML document is not a PLCopen TC6 project."),
    ("plcopen", "PLCOPEN-VERSION", "warning", "The document uses another PLCopen version; it is read as TC6 v2.01."),
    ("plcopen", "PLCOPEN-POU", "error", "A POU of the document cannot be imported as it is."),
    ("plcopen", "PLCOPEN-DECL", "error", "A variable declaration of the document cannot be imported as it is."),
    ("plcopen", "PLCOPEN-GRAPH", "error", "The graphical layout of a network is inconsistent."),
    ("plcopen", "PLCOPEN-LD", "error", "A ladder network cannot be imported as it is."),
    ("plcopen", "PLCOPEN-LD-BRIDGE", "error", "A ladder network's wiring has no series/parallel form."),
    ("plcopen", "PLCOPEN-FBD", "error", "A function block network cannot be imported as it is."),
    ("plcopen", "PLCOPEN-CONFIG", "warning", "The configuration is imported with changes."),
    ("plcopen", "PLCOPEN-UNSUPPORTED", "warning", "A part of the document uses what LadderLab does not support."),
    ("plcopen", "PLCOPEN-SFC", "error", "An SFC chart in the document cannot be imported as it is drawn."),
    # sequential function charts (docs/sfc.md)
    ("sfc", "SFC-EMPTY", "error", "An SFC chart has no initial step."),
    ("sfc", "SFC-CONDITION", "error", "A transition condition assigns, writes an output or calls an FB (spec SFC-03)."),
    ("sfc", "SFC-ORDER", "error", "Two steps or two transitions follow each other in a chart."),
    ("sfc", "SFC-DANGLING", "error", "A transition leads to no step."),
    ("sfc", "SFC-UNREACHABLE", "error", "Part of a chart can never become active."),
    ("sfc", "SFC-UNSAFE", "error", "A simultaneous branch is left or entered by a jump."),
    ("sfc", "SFC-BRANCHES", "error", "A divergence has fewer than two branches."),
    ("sfc", "SFC-BRANCH-END", "error", "A branch does not end as its kind of divergence needs."),
    ("sfc", "SFC-JUMP", "error", "A jump names no step of the chart."),
    ("sfc", "SFC-DUPLICATE", "error", "Two steps, actions or elements share a name or an id."),
    ("sfc", "SFC-KIND", "error", "A function is written in SFC (it keeps no steps between calls)."),
    ("sfc", "SFC-ACTION", "error", "An association or entry/exit action names no action or BOOL variable."),
    ("sfc", "SFC-TIME", "error", "A qualifier's time is missing, not a TIME, or given where none is taken."),
    ("sfc", "SFC-FLAG", "error", "An SFC flag is declared with the wrong type."),
    ("sfc", "SFC-UNUSED", "warning", "An action of an SFC POU is used by no step."),
    ("sfc", "ST-SFC", "error", "Textual SFC in a .st file describes a chart that cannot be read."),
    ("plcopen", "PLCOPEN-ADDDATA", "warning", "Another tool's data in the document was dropped."),
    ("plcopen", "PLCOPEN-EXPORT", "error", "The project cannot be written as PLCopen XML as it is."),
]


def _codes() -> dict[str, Code]:
    codes: dict[str, Code] = {}
    for area, code, severity, summary in _TABLE:
        names = [f"{lang}-{code}" for lang in DIAGRAM_LANGUAGES] if area == "diagram" else [code]
        for name in names:
            assert name not in codes, f"{name} is catalogued twice"
            codes[name] = Code(name, severity, summary, area)
    return codes


#: Every code by name.
CODES: dict[str, Code] = _codes()
#: Area -> its title in docs/diagnostics.md, in the order of the page.
AREAS = _AREAS

#: Set by the test suite: the file each process appends the codes it produces to (one per line, once each).
RECORD_ENV = "LADDERLAB_RECORD_CODES"
_recorded: set[str] = set()


def record(code: str) -> None:
    """Note that ``code`` was produced, when the test suite asks (``RECORD_ENV``): workers append to the same file."""
    path = os.environ.get(RECORD_ENV)
    if path and code not in _recorded:
        _recorded.add(code)
        with open(path, "a", encoding="utf-8") as out:
            out.write(code + "\n")
