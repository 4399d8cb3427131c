"""The resolved declarations of one POU, for the variable table and operand autocomplete.

They come from the ST checker, which resolves every POU's declarations before (and
independently of) its body, so the table is complete while the body has errors.
"""

from __future__ import annotations

from fastapi import APIRouter

from ..model import Project
from ..model.api import SymbolTable
from ..simulation.document import symbol_info
from ..st.checker import check_project as check_st
from ..storage import NotFoundError
from .context import WorkspaceDep
from .errors import responses

router = APIRouter(prefix="/api/projects", tags=["symbols"])

#: Diagnostic ``file`` values of the texts every POU's symbols depend on.
_SHARED_TEXTS = {"types", "globals"}


def symbol_table(project: Project, pou_name: str) -> SymbolTable:
    """The POU's symbols in declaration order, the globals, and the diagnostics that concern them."""
    pou = project.pou(pou_name)
    if pou is None:
        raise NotFoundError("POU", pou_name)
    result = check_st(project)
    key = pou.name.upper()
    info = result.pous[key]  # the checker registers every POU (the first one, like project.pou, on duplicates)
    diagnostics = [
        d for d in result.diagnostics if (d.pou is not None and d.pou.upper() == key) or d.file in _SHARED_TEXTS
    ]
    return SymbolTable(
        pou=pou.name,
        symbols=[symbol_info(s) for s in info.symbols.values()],
        globals=[symbol_info(s) for s in result.globals.values()],
        diagnostics=diagnostics,
    )


@router.get("/{name}/pous/{pou}/symbols", response_model=SymbolTable, responses=responses(404, 422))
def get_symbols(name: str, pou: str, workspace: WorkspaceDep) -> SymbolTable:
    return symbol_table(workspace.load(name).project, pou)
