"""What the object orientation tests share (test_methods, test_inheritance, test_interfaces, test_properties): build
a ``.st`` text as a project, run it, list its errors."""

from __future__ import annotations

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project


def build(text: str):
    """The build of the project the text imports as (the import itself must be clean)."""
    project, diagnostics = source_to_project(text, "oo")
    assert project is not None and [d.format() for d in diagnostics] == []
    return build_project(project)


def run(text: str):
    """A simulation of the text, which must build without errors."""
    result = build(text)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def errors(text: str) -> list[tuple[str, str | None, str]]:
    """The build's errors as (code, file, message)."""
    return [(d.code, d.file, d.message) for d in build(text).diagnostics if d.severity == "error"]
