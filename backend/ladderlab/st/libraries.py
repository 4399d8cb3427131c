"""Vendor compatibility libraries (``Project.libraries``): ST source shipped in ``library_sources/``.

A TwinCAT project adds Tc2_Math or Tc2_Utilities in its library manager; code brought from it calls their
functions. A LadderLab project lists the libraries it uses, and checking and lowering see the library's POUs
beside the project's own: a POU of the project with the same name shadows a library one (as a project's POU
hides a library's in TwinCAT). The project the user edits never contains them.
"""

from __future__ import annotations

import functools
import re
from importlib import resources
from typing import Any, get_args

from ..model import Pou, Project
from ..model.project import LibraryName
from .project_text import source_to_project


def _source(name: str) -> str:
    return resources.files(__package__).joinpath("library_sources", f"{name}.st").read_text(encoding="utf-8")


@functools.cache
def library_pous(name: str) -> tuple[Pou, ...]:
    """The POUs of library ``name``, parsed once per process (the sources are tested to parse without a problem)."""
    text = _source(name)
    project, diagnostics = source_to_project(text, name)
    if project is None or diagnostics:
        raise RuntimeError(f"the {name} library's source has problems: {[d.format() for d in diagnostics]}")
    return tuple(project.pous)


def with_libraries(project: Project) -> Project:
    """``project`` with the POUs of the libraries it uses that none of its own POUs shadows (itself when it uses
    none); applying it twice adds nothing more."""
    if not project.libraries:
        return project
    taken = {pou.name.upper() for pou in project.pous}
    added = [pou for name in project.libraries for pou in library_pous(name) if pou.name.upper() not in taken]
    return project.model_copy(update={"pous": [*project.pous, *added]}) if added else project


def library_of(name: str) -> str | None:
    """The library that has a POU called ``name`` (for the hint of an unknown function), if any."""
    upper = name.upper()
    return next((lib for lib in get_args(LibraryName) if any(p.name.upper() == upper for p in library_pous(lib))), None)


#: A library function's head in its source: ``FUNCTION NAME : TYPE`` and the comment on the next line.
_HEAD = re.compile(r"^FUNCTION (\w+) : (\w+)\n\(\* (.*?) \*\)", re.MULTILINE | re.DOTALL)
_INPUTS = re.compile(r"VAR_INPUT(.*?)END_VAR", re.DOTALL)
_INPUT = re.compile(r"(\w+) : (\w+);")


def library_catalogue() -> list[dict[str, Any]]:
    """Every library with its functions' signatures and descriptions, for the browser's library view (the
    vocabulary, ``make schema``): read from the sources, so the two cannot disagree."""
    catalogue = []
    for name in get_args(LibraryName):
        descriptions = {m[1]: (m[2], " ".join(m[3].split())) for m in _HEAD.finditer(_source(name))}
        functions = []
        for pou in library_pous(name):
            result, description = descriptions[pou.name]
            inputs = [f"{n} : {t}" for block in _INPUTS.findall(pou.declarations) for n, t in _INPUT.findall(block)]
            functions.append(
                {
                    "name": pou.name,
                    "signature": f"{pou.name}({', '.join(inputs)}) : {result}",
                    "description": description,
                }
            )
        catalogue.append({"name": name, "functions": functions})
    return catalogue
