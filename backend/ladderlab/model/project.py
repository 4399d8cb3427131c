"""The project: what a user edits and saves (POUs, types, globals, tasks)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import ConfigDict, Field, ValidationInfo, field_validator, model_validator

from .base import Model
from .cfc import CfcBody
from .fbd import FbdBody
from .hmi import Panel
from .ld import LdBody
from .names import pou_name_problem
from .sfc import SfcBody

ProjectFormat = Literal["ladderlab/1"]
PROJECT_FORMAT: ProjectFormat = "ladderlab/1"

#: ``plant``: a program that models the process (reads the control program's outputs, writes its inputs); it
#: runs in the plant task before the control tasks of every scan and cannot be called from control code.
PouKind = Literal["program", "function_block", "function", "plant"]
Language = Literal["st", "ld", "fbd", "cfc", "il", "sfc"]
#: The type rules a project's ST is checked by: IEC 61131-3 (strict, the default) or CODESYS V3's (docs/st.md).
Typing = Literal["iec", "codesys"]

#: Vendor compatibility libraries a project may use, as a TwinCAT project adds them in its library manager; their
#: functions are ST source shipped with LadderLab (st/library_sources/, docs/st.md "Vendor libraries").
LibraryName = Literal["Tc2_Math", "Tc2_Utilities"]

#: Languages whose body is text (ST statements, IL instructions).
TEXT_LANGUAGES = frozenset({"st", "il"})
#: The body model of each graphical language (an ST POU's body is its text).
DIAGRAM_BODY: dict[str, type[LdBody] | type[FbdBody] | type[SfcBody]] = {
    "ld": LdBody,
    "fbd": FbdBody,
    "cfc": CfcBody,
    "sfc": SfcBody,
}


def _strip_trailing_whitespace(value: Any) -> Any:
    """ST texts are kept as typed except trailing whitespace, which files and editors disagree on."""
    return value.rstrip() if isinstance(value, str) else value


#: Who may call a method (IEC 61131-3 ed. 3, 6.6.5): PUBLIC anyone, PRIVATE the FB itself, PROTECTED the FB and
#: the FBs derived from it, INTERNAL the same namespace (a LadderLab project is one namespace).
MethodAccess = Literal["PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL"]


class Method(Model):
    """A METHOD of a FUNCTION_BLOCK or a PROGRAM (IEC 61131-3 ed. 3, CODESYS): its own variables and ST body; it
    works on the variables of the instance it is called on (docs/st.md, object orientation)."""

    model_config = ConfigDict(extra="forbid")

    name: str
    access: MethodAccess = Field(default="PUBLIC", description="Who may call it; CODESYS's default is PUBLIC.")
    final: bool = Field(default=False, description="FINAL: an FB derived from this one cannot override it.")
    abstract: bool = Field(default=False, description="ABSTRACT: no body; a derived FB must implement it.")
    return_type: str | None = Field(default=None, description="The result type; None: a method without a value.")
    declarations: str = Field(default="", description="ST text of its VAR...END_VAR blocks, as typed.")
    body: str = Field(default="", description="ST statements.")

    _normalise_texts = field_validator("declarations", "body", mode="before")(_strip_trailing_whitespace)


class Accessor(Model):
    """A PROPERTY's GET or SET: its own variables and ST body (GET assigns the property's name, SET reads it)."""

    model_config = ConfigDict(extra="forbid")

    declarations: str = Field(default="", description="ST text of its VAR...END_VAR blocks, as typed.")
    body: str = Field(default="", description="ST statements.")

    _normalise_texts = field_validator("declarations", "body", mode="before")(_strip_trailing_whitespace)


class Property(Model):
    """A PROPERTY of a FUNCTION_BLOCK (CODESYS, IEC 61131-3 ed. 3 draft): read as ``inst.P`` through its GET,
    written as ``inst.P := v`` through its SET; a missing accessor makes it write-only or read-only."""

    model_config = ConfigDict(extra="forbid")

    name: str
    type: str = Field(description="Its type, as written.")
    access: MethodAccess = Field(default="PUBLIC", description="Who may read and write it.")
    get: Accessor | None = None
    set: Accessor | None = None


class PouAction(Model):
    """An ACTION of a FUNCTION_BLOCK outside SFC (CODESYS; IEC 61131-3 ed. 2's action syntax): statements that run
    on the variables of the instance it is called on - ``inst.Action();`` in ST, ``CAL inst.Action`` in IL,
    ``Action();`` in the FB itself (IL-08). No variables or parameters of its own (docs/st.md, "Actions")."""

    model_config = ConfigDict(extra="forbid")

    name: str
    body: str = Field(default="", description="ST statements.")

    _normalise_texts = field_validator("body", mode="before")(_strip_trailing_whitespace)


class Pou(Model):
    """A program organisation unit. ``body`` is ST or IL text, an ``LdBody``, an ``FbdBody``, a ``CfcBody`` (one
    FBD chart) or an ``SfcBody`` per ``language``."""

    model_config = ConfigDict(extra="forbid")

    name: str
    kind: PouKind
    language: Language
    return_type: str | None = Field(default=None, description="Functions only: the result type.")
    declarations: str = Field(default="", description="ST text of the VAR...END_VAR blocks, as typed.")
    body: str | LdBody | CfcBody | FbdBody | SfcBody = ""
    methods: list[Method] = Field(default_factory=list, description="Function blocks and programs only: their METHODs.")
    properties: list[Property] = Field(
        default_factory=list, description="Function blocks and programs only: their PROPERTYs."
    )
    actions: list[PouAction] = Field(
        default_factory=list, description="Function blocks only: their ACTIONs outside SFC (CODESYS), ST bodies."
    )
    extends: str | None = Field(default=None, description="Function blocks only: the function block it EXTENDS.")
    implements: list[str] = Field(
        default_factory=list, description="Function blocks only: the INTERFACEs (declared in the types) it IMPLEMENTS."
    )
    abstract: bool = Field(default=False, description="Function blocks only: ABSTRACT, it cannot be instantiated.")
    final: bool = Field(default=False, description="Function blocks only: FINAL, no function block extends it.")

    _normalise_texts = field_validator("declarations", "body", mode="before")(_strip_trailing_whitespace)

    @field_validator("body", mode="wrap")
    @classmethod
    def _body_matches_language(cls, value: Any, handler: Any, info: ValidationInfo) -> Any:
        """Validate ``body`` as the type its ``language`` names, so errors point at the right shape."""
        language = info.data.get("language")
        if language in TEXT_LANGUAGES:
            if not isinstance(value, str):
                raise ValueError(f"an {language.upper()} POU's body must be a string of {language.upper()} text")
            return handler(value)
        if not isinstance(language, str) or language not in DIAGRAM_BODY:
            return handler(value)
        expected = DIAGRAM_BODY[language]
        if type(value) is expected:
            return value
        if isinstance(value, FbdBody) and expected in (FbdBody, CfcBody):  # a chart made FBD, or FBD made a chart
            return expected.model_validate(value.model_dump(by_alias=True))
        if not isinstance(value, dict):
            shape = "'chart'" if language == "sfc" else "'networks'"
            raise ValueError(f"an {language.upper()} POU's body must be an object with {shape}")
        return expected.model_validate(value)

    @model_validator(mode="after")
    def _empty_graphical_body(self) -> Pou:
        """A new LD/FBD POU created without a body starts with no networks (an SFC POU with an empty chart)."""
        if self.language not in TEXT_LANGUAGES and isinstance(self.body, str):
            self.body = DIAGRAM_BODY[self.language]()
        return self


class ProgramInstance(Model):
    """A program instance: ``PROGRAM name WITH task : type (inputs, outputs)`` (IEC 61131-3 2.7.1, CFG-06)."""

    model_config = ConfigDict(extra="forbid")

    name: str = Field(description="The instance's name: watch paths start with it (name.var).")
    type: str = Field(description="The PROGRAM it is an instance of; two instances of one program are two states.")
    retain: Literal["RETAIN", "NON_RETAIN"] | None = Field(
        default=None, description="RETAIN: every variable of the instance keeps its value on a warm restart."
    )
    inputs: dict[str, str] = Field(
        default_factory=dict, description="VAR_INPUT name -> ST expression (globals, literals) set before each run."
    )
    outputs: dict[str, str] = Field(
        default_factory=dict, description="VAR_OUTPUT name -> variable (a global) written after each run."
    )


class Task(Model):
    model_config = ConfigDict(extra="forbid")

    name: str
    interval: str | None = Field(
        default="T#10ms", description="IEC TIME literal, e.g. T#10ms: the task runs cyclically; null: only on SINGLE."
    )
    single: str | None = Field(
        default=None, description="A BOOL global or direct address: the task runs once on each of its rising edges."
    )
    priority: int = 0
    programs: list[str | ProgramInstance] = Field(
        default_factory=list,
        description="What the task runs, in list order: a program's name (one instance named after it) or an instance.",
    )
    watchdog_ms: int | None = Field(
        default=None,
        ge=1,
        le=60_000,
        description="The task's time budget per scan in ms (its scan's own running time); longer is a watchdog "
        "fault. Null: the default of 100 ms (CODESYS's).",
    )


class Resource(Model):
    """A RESOURCE of a configuration (``RESOURCE name ON processor``): its globals and its tasks."""

    model_config = ConfigDict(extra="forbid")

    name: str | None = Field(default=None, description="None: the configuration's tasks without a RESOURCE block.")
    on: str | None = Field(default=None, description="The processor type after ON.")
    globals: str = Field(default="", description="ST text of the resource's VAR_GLOBAL blocks.")
    tasks: list[Task] = Field(default_factory=list)
    programs: list[ProgramInstance] = Field(
        default_factory=list, description="Program instances without a task (they run in a cyclic 10 ms task)."
    )

    _normalise_texts = field_validator("globals", mode="before")(_strip_trailing_whitespace)


class Configuration(Model):
    """The IEC configuration a project runs as (CONFIGURATION ... END_CONFIGURATION, CFG-01..08)."""

    model_config = ConfigDict(extra="forbid")

    name: str
    globals: str = Field(default="", description="ST text of the configuration's VAR_GLOBAL blocks.")
    resources: list[Resource] = Field(default_factory=list)
    access: str = Field(default="", description="ST text of VAR_ACCESS blocks: named access paths.")
    config: str = Field(default="", description="ST text of VAR_CONFIG blocks: initial values and addresses.")

    _normalise_texts = field_validator("globals", "access", "config", mode="before")(_strip_trailing_whitespace)

    def tasks(self) -> list[Task]:
        return [task for resource in self.resources for task in resource.tasks]


class TestFile(Model):
    """A file of unit tests, ``tests/<name>.st`` in the project folder (docs/testing.md).

    Tests a teacher hides from students live in ``tests/hidden/`` and are not part of the model: the
    browser never sees them, ``ladderlab test --grade`` runs them."""

    model_config = ConfigDict(extra="forbid")
    name: str = Field(description="File name without the .st suffix (letters, digits, '_' and '-').")
    text: str = Field(default="", description="ST test text: SETUP, TEARDOWN and TEST blocks, as typed.")

    _normalise_texts = field_validator("text", mode="before")(_strip_trailing_whitespace)


#: The pragma that makes a GVL's variables usable only qualified, as CODESYS writes it above its VAR_GLOBAL
QUALIFIED_ONLY = "{attribute 'qualified_only'}"


class GlobalVariableList(Model):
    """A named global variable list (GVL) as CODESYS and TwinCAT keep globals: ``gvls/<name>.st`` in the project
    folder. Code reads its variables as ``Name.x`` or, unless ``qualified_only``, as ``x`` (docs/st.md)."""

    model_config = ConfigDict(extra="forbid")

    name: str = Field(description="The list's name (an IEC identifier): the qualifier of ``Name.x``.")
    qualified_only: bool = Field(
        default=False, description="{attribute 'qualified_only'}: its variables are used only as ``Name.x``."
    )
    text: str = Field(default="", description="ST text of its VAR_GLOBAL ... END_VAR blocks, as typed.")

    _normalise_texts = field_validator("text", mode="before")(_strip_trailing_whitespace)

    @field_validator("name")
    @classmethod
    def _identifier(cls, name: str) -> str:
        problem = pou_name_problem(name)
        if problem is not None:
            raise ValueError(f"{name!r} cannot name a global variable list: {problem}")
        return name

    @model_validator(mode="after")
    def _pragma_line(self) -> GlobalVariableList:
        """The qualified_only pragma typed as the text's first line is the flag (one form, as its file stores it)."""
        first, _, rest = self.text.partition("\n")
        if first.strip() == QUALIFIED_ONLY:
            self.qualified_only, self.text = True, rest
        return self


class Project(Model):
    model_config = ConfigDict(extra="forbid")

    name: str
    format: ProjectFormat = PROJECT_FORMAT
    types: str = Field(default="", description="ST text of TYPE ... END_TYPE blocks.")
    globals: str = Field(default="", description="ST text of VAR_GLOBAL ... END_VAR blocks.")
    gvls: list[GlobalVariableList] = Field(
        default_factory=list, description="Named global variable lists (gvls/<name>.st), in order."
    )
    pous: list[Pou] = Field(default_factory=list)
    tasks: list[Task] = Field(
        default_factory=list, description="The tasks of a project without a configuration (one implicit resource)."
    )
    configuration: Configuration | None = Field(
        default=None, description="The IEC configuration; when given, its resources hold the tasks."
    )
    panels: list[Panel] = Field(default_factory=list, description="Operator panels (hmi/<name>.json), in order.")
    exercise: str = Field(
        default="", description="Markdown: the statement of the exercise this project is (stored as EXERCISE.md)."
    )
    tests: list[TestFile] = Field(default_factory=list, description="Unit test files (tests/<name>.st).")
    libraries: list[LibraryName] = Field(
        default_factory=list,
        description="Vendor compatibility libraries the project uses; a POU of the project shadows a library "
        "function of the same name.",
    )
    typing: Typing = Field(
        default="iec",
        description="Type rules of the ST checker: 'iec' (IEC 61131-3, the default) or 'codesys' (CODESYS V3's "
        'arithmetic on bit strings, shifts on integers, implicit conversions; docs/st.md "CODESYS typing").',
    )

    _normalise_texts = field_validator("types", "globals", "exercise", mode="before")(_strip_trailing_whitespace)

    @field_validator("panels")
    @classmethod
    def _unique_panels(cls, panels: list[Panel]) -> list[Panel]:
        seen: set[str] = set()
        for panel in panels:
            if panel.name.upper() in seen:
                raise ValueError(f"two panels are called {panel.name!r} (names ignore case: they are file names)")
            seen.add(panel.name.upper())
        return panels

    @field_validator("gvls")
    @classmethod
    def _unique_gvls(cls, gvls: list[GlobalVariableList]) -> list[GlobalVariableList]:
        seen: set[str] = set()
        for gvl in gvls:
            if gvl.name.upper() in seen:
                raise ValueError(f"two global variable lists are called {gvl.name!r} (names ignore case)")
            seen.add(gvl.name.upper())
        return gvls

    def gvl(self, name: str) -> GlobalVariableList | None:
        """The global variable list called ``name`` (case-insensitive)."""
        key = name.upper()
        return next((g for g in self.gvls if g.name.upper() == key), None)

    def panel(self, name: str) -> Panel | None:
        key = name.upper()
        return next((p for p in self.panels if p.name.upper() == key), None)

    def pou(self, name: str) -> Pou | None:
        """The POU called ``name`` (IEC names are case-insensitive)."""
        key = name.upper()
        return next((p for p in self.pous if p.name.upper() == key), None)

    def all_tasks(self) -> list[Task]:
        """The tasks the project runs: its own, or its configuration's."""
        return self.configuration.tasks() if self.configuration is not None else list(self.tasks)
