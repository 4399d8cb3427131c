"""Pydantic project model: the single source of truth for what a user edits.

The JSON Schema in shared_schema/ is generated from these classes.
"""

from .diagnostics import Diagnostic, Severity, has_errors
from .fbd import (
    Block,
    Connector,
    Continuation,
    FbdBody,
    FbdComment,
    FbdJump,
    FbdLabel,
    FbdNetwork,
    FbdNode,
    FbdReturn,
    InputNode,
    OutputNode,
    PinFlags,
    PinRef,
    Position,
    Wire,
)
from .hmi import Panel
from .ld import Box, Coil, Compare, Contact, Jump, LdBody, LdElement, LdNetwork, Parallel, Return
from .project import (
    PROJECT_FORMAT,
    Configuration,
    GlobalVariableList,
    Pou,
    ProgramInstance,
    Project,
    Resource,
    Task,
    TestFile,
)

__all__ = [
    "PROJECT_FORMAT",
    "Block",
    "Box",
    "Coil",
    "Compare",
    "Configuration",
    "Connector",
    "Contact",
    "Continuation",
    "Diagnostic",
    "FbdBody",
    "FbdComment",
    "FbdJump",
    "FbdLabel",
    "FbdNetwork",
    "FbdNode",
    "FbdReturn",
    "GlobalVariableList",
    "InputNode",
    "Jump",
    "LdBody",
    "LdElement",
    "LdNetwork",
    "OutputNode",
    "Panel",
    "Parallel",
    "PinFlags",
    "PinRef",
    "Position",
    "Pou",
    "ProgramInstance",
    "Project",
    "Resource",
    "Return",
    "Severity",
    "Task",
    "TestFile",
    "Wire",
    "has_errors",
]
