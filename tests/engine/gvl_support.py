"""Projects of ST programs and named global variable lists, for the GVL tests (test_global_variable_lists.py,
test_gvl_shared_names.py): each binds its own lists as the default ``gvls`` with ``functools.partial``."""

from __future__ import annotations

from collections.abc import Sequence

from ladderlab.engine.simulation import Simulation
from ladderlab.model import GlobalVariableList, Pou, Project, Task
from ladderlab.simulation.build import build_project


def gvl_project(*pous: Pou, gvls: Sequence[GlobalVariableList], globals: str = "") -> Project:
    """The POUs with the lists ``gvls`` (and unnamed ``globals``), every program in one task."""
    programs = [p.name for p in pous if p.kind == "program"]
    return Project(
        name="gvl", gvls=list(gvls), globals=globals, pous=list(pous), tasks=[Task(name="T", programs=programs)]
    )


def st(body: str, declarations: str = "") -> Pou:
    return Pou(name="Main", kind="program", language="st", declarations=declarations, body=body)


def gvl_simulation(*pous: Pou, **options) -> Simulation:
    """A simulation of ``gvl_project(*pous, **options)``, which builds without an error."""
    built = build_project(gvl_project(*pous, **options))
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    return built.simulation()


def gvl_errors(*pous: Pou, **options) -> list[str]:
    """The errors of building ``gvl_project(*pous, **options)``, formatted."""
    return [d.format() for d in build_project(gvl_project(*pous, **options)).diagnostics if d.severity == "error"]
