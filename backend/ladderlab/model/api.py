"""Shapes of the HTTP API's JSON bodies that the browser reads (typed from the generated schema).

Request bodies forbid unknown fields so a typo in a client is a 422 naming the field,
not a silently ignored value.
"""

from __future__ import annotations

from datetime import datetime
from typing import Literal

from pydantic import ConfigDict, Field

from .base import Model
from .diagnostics import Diagnostic
from .monitor import HistoryRange, Value
from .project import Project
from .xref import XrefList


class ProjectSummary(Model):
    """One row of ``GET /api/projects``; a project whose files do not load has no revision and says why in
    ``problems`` (located in its files), so it is listed rather than silently missing."""

    name: str
    revision: str | None
    modified: datetime
    pou_count: int
    problems: list[Diagnostic] = Field(default_factory=list)


class CreateProject(Model):
    """Body of ``POST /api/projects``: an empty project, or a copy of a shipped example."""

    model_config = ConfigDict(extra="forbid")

    name: str
    example: str | None = Field(default=None, description="Name of a shipped example to copy, e.g. 'motor'.")
    start: Literal["solution", "exercise"] = Field(
        default="solution",
        description="An example that is an exercise: 'exercise' starts from the student's files (the control "
        "POUs to write, declarations only); 'solution' copies the reference solution.",
    )


class ExampleInfo(Model):
    """``GET /api/examples``: a shipped example project ("New from example")."""

    name: str
    title: str
    summary: str = ""
    exercise: bool = Field(description="It is an exercise: it can start from the student's files.")
    plants: list[str] = Field(default_factory=list, description="Its plants (the processes it models).")
    panels: list[str] = Field(default_factory=list)


class RenameProject(Model):
    """Body of ``POST /api/projects/{name}/rename``."""

    model_config = ConfigDict(extra="forbid")

    new_name: str


class ProjectDocument(Model):
    """``GET /api/projects/{name}``: the project and the revision a later save must name in ``If-Match``."""

    name: str
    revision: str
    modified: datetime
    project: Project


class SaveResult(Model):
    """Answer to a successful save: the new revision (also sent as the ``ETag`` header)."""

    revision: str
    modified: datetime


class CheckReport(Model):
    """``POST /api/projects/{name}/check``: every diagnostic of the saved project."""

    diagnostics: list[Diagnostic]


class SymbolInfo(Model):
    """One declared variable, for the variable table and operand autocomplete."""

    name: str
    var_class: str = Field(description="VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_EXTERNAL, VAR_TEMP or VAR_GLOBAL.")
    type: str = Field(description="The type as declared, e.g. 'TON' or 'ARRAY[1..10] OF INT'.")
    initial: str | None = Field(
        description="Declared initial value (or the user type's), as ST text; null means the type's default."
    )
    address: str | None = Field(description="Direct address of an AT declaration, e.g. '%IX0.0'.")
    comment: str | None
    retain: bool
    constant: bool
    gvl: str | None = Field(
        default=None, description="A global's global variable list (CODESYS's GVL), whose name qualifies it: GVL.x."
    )


class SymbolTable(Model):
    """``GET /api/projects/{name}/pous/{pou}/symbols``."""

    pou: str
    symbols: list[SymbolInfo] = Field(description="The POU's own declarations, in declaration order.")
    globals: list[SymbolInfo]
    diagnostics: list[Diagnostic] = Field(
        description="Problems of this POU, the global declarations and the user types."
    )


class VariableNode(Model):
    """One variable of the instance tree (ON-10): a POU's variable, an FB's pin or variable, a field, an element."""

    name: str = Field(description="As declared ('RunTimer', 'ET'), or an array element's index ('[3]').")
    path: str = Field(description="The path that reads, writes and forces it: 'MAIN.RunTimer.ET', 'MAIN.arr[3]'.")
    type: str = Field(description="Its type as IEC text: 'TIME', 'TON', 'ARRAY [1..3] OF INT'.")
    var_class: str | None = Field(
        default=None, description="VAR, VAR_INPUT, VAR_OUTPUT... of a variable; null for fields and array elements."
    )
    expandable: bool = Field(
        description="It has members: an FB instance, a structure, an array, or a pointer (its target 'p^', ON-11)."
    )
    pointer: bool = Field(
        default=False,
        description="A REF_TO, POINTER TO or REFERENCE TO: it has a value of its own (the REF()/ADR() it holds) "
        "and expands to what it points to.",
    )


class VariableChildren(Model):
    """``GET /api/projects/{name}/variables?path=``: what one variable of the saved project holds.

    No path: the programs (each its own instance) and the global variables."""

    path: str
    type: str | None = Field(description="The variable's type as IEC text; null for the top (no path).")
    children: list[VariableNode]
    more: int = Field(default=0, description="Array elements left out after the first ones (too many to list).")


class Pin(Model):
    """A parameter of a library function or function block."""

    name: str
    type: str = Field(description="Elementary type, user type, or generic family such as ANY_NUM.")


class LibraryEntry(Model):
    """One function or function block the box picker offers (EN/ENO are implicit on all of them); a program's PUBLIC
    METHOD is a function named ``Prog.M`` (CODESYS: another POU calls it so)."""

    name: str
    kind: Literal["function", "function_block"]
    source: Literal["standard", "user", "library"] = Field(
        description="standard: IEC; user: a POU of the project; library: of a vendor library the project uses."
    )
    inputs: list[Pin]
    outputs: list[Pin]
    in_outs: list[Pin]
    extensible: bool = Field(description="More inputs like the last one may be added (IN3, IN4, ...).")
    return_type: str | None = Field(description="Functions only: the result type (a family for generic ones).")
    comment: str | None
    methods: list[LibraryEntry] = Field(
        default_factory=list,
        description="A user function block's PUBLIC METHODs (own and inherited), each as a function entry: what an "
        "FBD block 'inst.M' draws as its pins.",
    )


class ScanTimes(Model):
    """Wall time of the scans run so far, in milliseconds (halted time excluded)."""

    min: float
    avg: float
    max: float
    last: float


class IoPoint(Model):
    """One direct address the program uses, for the I/O view."""

    area: Literal["I", "Q", "M", "S"] = Field(description="I inputs, Q outputs, M memory, S the Mosaic system area.")
    address: str = Field(description="The address as written, e.g. '%IX0.1'; also its path for watch and write.")
    type: str = Field(description="Its elementary type, e.g. 'BOOL' or 'INT'.")
    names: list[str] = Field(
        default_factory=list,
        description="Paths of the variables declared AT it (e.g. 'MAIN.START'); empty when it is used without a name.",
    )


class SimulationInfo(Model):
    """``GET /api/simulations/{id}``: one live simulation of a saved project."""

    id: str
    project: str
    revision: str = Field(description="The project revision it was compiled from.")
    state: Literal["running", "stopped", "halted", "faulted"]
    scan_count: int
    time_ms: float = Field(description="Virtual time of the last scan.")
    real_time_ms: float = Field(description="Wall time spent running (started and not stopped).")
    scan_ms: ScanTimes
    overruns: int = Field(description="Times the scans fell behind the wall clock and skipped ahead.")
    fault: Diagnostic | None = Field(description="The fault that stopped it, located; null when none.")
    clients: int = Field(description="Websocket clients watching it.")
    created: datetime
    instances: dict[str, list[str]] = Field(
        default_factory=dict,
        description="Instance paths of every program and function block by POU name (upper case), e.g. "
        '{"BLINKER": ["MAIN.BLINK"]}: the instances an online view can show.',
    )
    speed: float = Field(default=1.0, description="The time scale: scans are paced at this times real time.")
    pending_inputs: int = Field(default=0, description="Input events waiting for the start of the next scan.")
    until: str | None = Field(default=None, description="What a run until waits for (a condition or a time).")
    history: HistoryRange | None = Field(default=None, description="The scan history (null: none is kept).")
    io: list[IoPoint] = Field(
        default_factory=list,
        description="The direct addresses the program uses (inputs, outputs, memory), in address order.",
    )


class SeekScan(Model):
    """Body of ``POST /api/simulations/{id}/seek``: the scan to show, numbered as ``scan_count``."""

    model_config = ConfigDict(extra="forbid")

    scan: int = Field(ge=0)


class HistoryStep(Model):
    """Body of ``POST /api/simulations/{id}/history/step``: how far one step through the scan shown goes
    (``statement``: the next network or line, into calls; ``over`` past the calls; ``out`` of the POU; ``back``:
    to the point before the one reached)."""

    model_config = ConfigDict(extra="forbid")

    granularity: Literal["statement", "over", "out", "network", "back"] = "statement"


class HistoryFound(Model):
    """``GET /api/simulations/{id}/history/find``: the scan where the variable changed (null: none kept)."""

    scan: int | None


class HistoryMark(Model):
    """A scan with something from outside (the inputs' kinds: write, force, release, panel, fault, reset...),
    a runtime error (``error``), a breakpoint hit (``breakpoint``: the scan halted there) or a trace's trigger
    (``trigger``: it fired at the end of that scan)."""

    scan: int
    kinds: list[str]


class HistoryDiff(Model):
    """``GET /api/simulations/{id}/history/diff``: the variables that differ between the ends of two scans."""

    model_config = ConfigDict(ser_json_inf_nan="strings")

    first: int
    second: int
    differences: dict[str, list[Value]] = Field(description="Canonical path -> [its value in first, in second].")


class ResetSimulation(Model):
    """Body of ``POST /api/simulations/{id}/reset``: warm (RETAIN kept) or cold restart."""

    model_config = ConfigDict(extra="forbid")

    cold: bool = False


class SourceMapEntry(Model):
    """A line of exported ST (1-based) and the network / element it came from."""

    line: int
    network: str
    element: str | None = None


class StExport(Model):
    """``GET /api/projects/{name}/export/st``: the complete IEC text of a POU or the project, with its source map."""

    text: str
    source_map: list[SourceMapEntry] = Field(default_factory=list)
    diagnostics: list[Diagnostic] = Field(default_factory=list)


class ImportReport(Model):
    """``POST /api/import/plcopen``: the stored project and what the import had to say (warnings)."""

    project: ProjectSummary
    diagnostics: list[Diagnostic] = Field(default_factory=list)


class FbdOrder(Model):
    """``POST /api/fbd/order``: the node ids of one FBD network in the order the scan runs them."""

    order: list[str] = Field(description="Blocks, input, output, jump and return nodes; connectors have no place.")


class LdAsIl(Model):
    """``POST /api/ld/il``: an LD network as IL ("View as IL", read-only), or why it has no IL equivalent."""

    text: str | None = Field(description="The IL text; null when the network has no plain IL equivalent.")
    reason: str | None = Field(default=None, description="Why there is no IL (the element and what it needs).")


class TestCaseInfo(Model):
    name: str
    line: int = Field(description="Line of its TEST keyword in the test file.")


class TestFileInfo(Model):
    """A test file's tests, or the diagnostics that keep it from compiling."""

    file: str = Field(description="tests/<name>.st")
    tests: list[TestCaseInfo] = Field(default_factory=list)
    diagnostics: list[Diagnostic] = Field(default_factory=list)


class TestListing(Model):
    """``POST /api/tests/list``: every test file of the working copy and its tests (parsed, not run)."""

    files: list[TestFileInfo]


class TestFailureInfo(Model):
    message: str
    line: int | None = None
    column: int | None = None
    verb: str | None = None
    actual: str | None = Field(default=None, description="The actual value as an IEC literal (assertions).")
    expected: str | None = Field(default=None, description="The expected value as an IEC literal (assertions).")
    note: str | None = Field(default=None, description="The assertion's own message.")
    kind: str = Field(description="assertion, timeout, budget, fault, watchdog, memory or error")


class TestResultInfo(Model):
    file: str
    name: str
    line: int
    outcome: Literal["passed", "failed"]
    duration_s: float
    scans: int
    failure: TestFailureInfo | None = None


class CoverageInfo(Model):
    """What the tests never executed or energised in one POU (element ids of LD/FBD, body lines of ST)."""

    language: str
    elements: int
    executed: int
    never_executed: list[str] = Field(default_factory=list)
    never_energised: list[str] = Field(default_factory=list)
    never_executed_lines: list[int] = Field(default_factory=list)


class TestSummary(Model):
    passed: int
    failed: int
    skipped: int
    files_with_errors: int
    seconds: float


class TestEvent(Model):
    """One line of the ``POST /api/tests/run`` stream: a file prepared (its tests or its diagnostics), a test's
    result, or the end (summary, and coverage per POU when asked for)."""

    type: Literal["file", "result", "done"]
    file: TestFileInfo | None = None
    result: TestResultInfo | None = None
    summary: TestSummary | None = None
    coverage: dict[str, CoverageInfo] | None = None


class TestRunRequest(Model):
    """Body of ``POST /api/tests/run``: the working copy, and which tests (none: all; a file; one test)."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    file: str | None = Field(default=None, description="tests/<name>.st; None: every test file")
    test: str | None = Field(default=None, description="one test of that file by name; None: all of them")
    coverage: bool = False


class TestOpenRequest(Model):
    """Body of ``POST /api/tests/open``: the failing test whose last state is to be opened online."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    file: str
    test: str


class TestCheckRequest(Model):
    """Body of ``POST /api/tests/check``: the diagnostics of one test file of the working copy (ST editor)."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    file: str


class Reference(Model):
    """One place that uses a project-level name (a POU, type or global), as a rename changes it or a
    delete would break it: the POU and its part, the line of a text or the network and element of a
    diagram, the task, the operator panel and widget, and the text there (the line, the operand, the
    widget's variable path) as it was."""

    pou: str | None = None
    part: Literal[
        "declarations",
        "body",
        "network",
        "transition",
        "step",
        "return type",
        "globals",
        "gvl",
        "types",
        "task",
        "test",
        "extends",
        "implements",
        "panel",
        "method",
    ]
    member: str | None = Field(
        default=None,
        description="A text of the POU's METHOD or PROPERTY: its name (`M`, or `P.GET` / `P.SET` / `P` for the "
        "property's type).",
    )
    line: int | None = None
    network: str | None = None
    network_number: int | None = None
    network_label: str | None = None
    element: str | None = None
    task: str | None = None
    file: str | None = None
    panel: str | None = Field(default=None, description="An operator panel's name (``element``: its widget's id).")
    text: str = ""


class RenameRequest(Model):
    """Body of ``POST /api/refactor/rename``: the (unsaved) project and the name to rename in it."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    old_name: str
    new_name: str


class MemberRenameRequest(Model):
    """Body of ``POST /api/refactor/rename-member``: method or property ``old_name`` of function block ``pou`` renamed
    with every call (issue 25 item 5)."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    pou: str
    old_name: str
    new_name: str


class RenameResult(Model):
    """The renamed project (nothing is stored) and every place that changed, for the preview."""

    project: Project
    changes: list[Reference]


class ReferencesRequest(Model):
    """Body of ``POST /api/refactor/references``: the (unsaved) project and the name whose uses are wanted."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    name: str


class ReferenceList(Model):
    references: list[Reference]


class DuplicateRequest(Model):
    """Body of ``POST /api/refactor/duplicate``: a copy of POU ``name`` called ``new_name``."""

    model_config = ConfigDict(extra="forbid")

    project: Project
    name: str
    new_name: str


class PrintDocument(Model):
    """What a printed project document holds (issue 28): the print view draws it with the editors' own layout
    and SVG drawing; ``GET /api/projects/{name}/document`` and ``ladderlab doc`` make it."""

    project: Project
    revision: str
    date: str = Field(description="When the document was made, ISO 8601 (UTC).")
    pous: list[str] = Field(description="The POUs to print, in project order.")
    library: list[LibraryEntry] = Field(description="Standard and user blocks: the pins the diagrams draw.")
    symbols: dict[str, list[SymbolInfo]] = Field(description="Each printed POU's declarations, by POU name.")
    globals: list[SymbolInfo]
    xref: XrefList
