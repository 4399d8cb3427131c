"""Runs a one-PROGRAM ST text scan by scan for the IEC 3rd edition / CODESYS feature tests (issue 25)."""

from __future__ import annotations

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project


def build(text: str, variant: str = "fast"):
    """The build of ``text`` (a whole .st file) in the code generator's ``variant``; the parse must succeed."""
    project, diagnostics = source_to_project(text, "ed3")
    assert project is not None and not [d for d in diagnostics if d.severity == "error"], diagnostics
    return build_project(project, variant)


def errors(text: str) -> list[str]:
    """The error diagnostics of ``text``, formatted as the user reads them."""
    project, diagnostics = source_to_project(text, "ed3")
    found = diagnostics if project is None else [*diagnostics, *build_project(project).diagnostics]
    return [d.format() for d in found if d.severity == "error"]


def program(declarations: str, body: str, types: str = "") -> str:
    return f"{types}\nPROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n"


def scans(text: str, count: int, *paths: str, variant: str = "fast") -> list[list]:
    """The values of ``Main.<path>`` after each of ``count`` scans (the program must compile and not fault)."""
    result = build(text, variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    seen = []
    for _ in range(count):
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        seen.append([sim.read(f"Main.{p}") for p in paths])
    return seen
