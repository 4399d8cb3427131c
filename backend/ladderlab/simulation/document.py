"""The data of a printed project document (issue 28), shared by ``GET /api/projects/{name}/document`` and
``ladderlab doc``: the project, its revision and the date for the title page, the POUs to print, each POU's
declarations as the checker resolved them, the block catalogue the diagrams draw pins from, and the
cross-reference list. Drawing is the browser's (frontend/src/print): one renderer for the editor and the page.
"""

from __future__ import annotations

from datetime import UTC, datetime

from ..model import Project
from ..model.api import PrintDocument, SymbolInfo
from ..st.checker import check_project
from ..st.printer import print_initializer, print_type
from ..st.symbols import GvlInfo, Symbol
from ..storage.project_folder import revision_of
from .library import standard_entries, user_entries
from .xref import cross_reference


class UnknownPou(LookupError):
    """A POU asked for by name that the project does not have."""


def symbol_info(symbol: Symbol, gvl: GvlInfo | None = None) -> SymbolInfo:
    """One symbol with its type and initial value as ST text (as declared, not the resolved internals); ``gvl``: the
    global variable list declaring it."""
    return SymbolInfo(
        name=symbol.name,
        var_class=symbol.var_class,
        type=print_type(symbol.type_spec),
        initial=print_initializer(symbol.init) if symbol.init is not None else None,
        address=symbol.address,
        comment=symbol.comment,
        retain=symbol.retain,
        constant=symbol.constant,
        gvl=gvl.name if gvl is not None else None,
    )


def print_document(project: Project, pous: list[str] | None = None, now: datetime | None = None) -> PrintDocument:
    """The document of ``pous`` (names, any case; None: every POU) of ``project``."""
    chosen = [p.name for p in project.pous]
    if pous:
        wanted = {name.upper(): name for name in pous}
        missing = [name for key, name in wanted.items() if project.pou(key) is None]
        if missing:
            raise UnknownPou(f"the project has no POU {', '.join(repr(m) for m in missing)}")
        chosen = [name for name in chosen if name.upper() in wanted]
    checked = check_project(project)
    called = {call for name in chosen for call in _calls(project, name)}
    library = [entry for entry in [*standard_entries(), *user_entries(project)] if entry.name.upper() in called]
    symbols = {}
    for name in chosen:
        info = checked.pou(name)
        symbols[name] = [symbol_info(s) for s in info.symbols.values()] if info is not None else []
    return PrintDocument(
        project=project,
        revision=revision_of(project),
        date=(now or datetime.now(UTC)).replace(microsecond=0).isoformat(),
        pous=chosen,
        library=library,
        symbols=symbols,
        globals=[symbol_info(s, checked.listed.get(key)) for key, s in checked.globals.items()],
        xref=cross_reference(project),
    )


def _calls(project: Project, name: str) -> set[str]:
    """The blocks a diagram POU draws (upper case); none for ST."""
    pou = project.pou(name)
    body = pou.body if pou is not None else None
    return body.calls() if body is not None and hasattr(body, "calls") else set()
