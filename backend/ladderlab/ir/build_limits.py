"""The size limits of a build: the ST text of a project and the values its program holds (docs/security.md).

Checked before the expensive parts run: the text before anything is parsed (a build needs ~800 MB
and ~30 s per MB of ST), the values once the types are known and before the engine allocates them.
Each excess is a located diagnostic naming the limit and its setting (``ladderlab.limits``).
"""

from __future__ import annotations

from .. import limits
from ..model.diagnostics import Diagnostic
from ..model.project import Pou, Project
from ..model.sfc import SfcBody
from .nodes import Program, Slot
from .types import Array, Elementary, FbInstance, IrType, Struct


def source_too_large(project: Project) -> Diagnostic | None:
    """The refusal of a project whose ST text (types, globals and global variable lists, declarations, ST bodies)
    exceeds the limit."""
    # stripped: a POU read from a .st file keeps its lines by leading blank lines, which cost nothing to parse
    sizes = {pou.name: len(pou.declarations.strip()) + _body_text(pou) for pou in project.pous}
    texts = [project.types, project.globals, *(gvl.text for gvl in project.gvls)]
    total = sum(sizes.values()) + sum(len(text.strip()) for text in texts)
    if total <= limits.SOURCE_BYTES.value:
        return None
    largest = max(sizes, key=sizes.__getitem__, default=None)
    where = f" (the largest POU, {largest}, has {sizes[largest]:,})" if largest else ""
    return Diagnostic(
        code="LIMIT-SIZE",
        pou=largest,
        message=limits.SOURCE_BYTES.message(f"the project's ST text has {total:,} characters{where}"),
    )


def _body_text(pou: Pou) -> int:
    """The ST characters of a POU's body: its text, or an SFC POU's ST actions and named transitions."""
    if isinstance(pou.body, str):
        return len(pou.body.strip())
    if isinstance(pou.body, SfcBody):
        parts = (*pou.body.actions, *pou.body.transitions)
        return sum(len(part.body.strip()) for part in parts if isinstance(part.body, str))
    return 0


def data_too_large(program: Program) -> Diagnostic | None:
    """The refusal of a program whose globals and program instances hold more values than the limit."""
    counter = _Counter(program)
    pous = {name.upper(): pou for name, pou in program.pous.items()}
    owners = [("global", program.globals)] + [  # each program instance holds its own values (two: twice)
        (pous[instance.pou.upper()].name, pous[instance.pou.upper()].slots)
        for instance in program.program_instances()
        if instance.pou.upper() in pous
    ]
    total = sum(counter.slot(slot) for _, slots in owners for slot in slots)  # (200,000 slots: no tuple each)
    if total <= limits.DATA_ELEMENTS.value:
        return None
    parts = [(owner, slot.name, counter.slot(slot)) for owner, slots in owners for slot in slots]
    owner, name, count = max(parts, key=lambda part: part[2])
    return Diagnostic(
        code="LIMIT-SIZE",
        pou=None if owner == "global" else owner,
        message=limits.DATA_ELEMENTS.message(
            f"the variables of this program hold {total:,} values (the largest, "
            f"{name if owner == 'global' else f'{owner}.{name}'}, {count:,})"
        ),
    )


class _Counter:
    """Values per slot, with function block instances counted through their POU's slots (once per type)."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self.instances: dict[str, int] = {}

    def slot(self, slot: Slot) -> int:
        if slot.var_class in ("VAR_EXTERNAL", "VAR_IN_OUT"):
            return 0
        return 1 if type(slot.type) is Elementary else self.of(slot.type)  # (most slots: no isinstance chain)

    def of(self, type: IrType) -> int:
        if isinstance(type, Array):
            return _cells(type) * self.of(type.element)
        if isinstance(type, Struct):
            return sum(self.of(f.type) for f in type.fields)
        if isinstance(type, FbInstance):
            return self.instance(type.fb)
        return 1

    def instance(self, fb: str) -> int:
        key = fb.upper()
        if key not in self.instances:
            self.instances[key] = 0  # a recursive instance (refused by the checker) counts nothing more
            pou = self.program.pous.get(key)
            # a standard FB (TON, CTU...) holds a handful of values: 8 is more than any has
            self.instances[key] = 1 + (sum(self.slot(slot) for slot in pou.slots) if pou is not None else 8)
        return self.instances[key]


def _cells(array: Array) -> int:
    cells = 1
    for low, high in array.dims:
        cells *= high - low + 1
    return cells
