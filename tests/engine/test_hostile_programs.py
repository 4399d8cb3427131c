"""Programs that broke the build path (issue 18): each builds and runs, or is refused with a located error.

Every test builds through ``simulation.build_project`` (what the server and the CLI use) in all three
variants and runs scans; expected values are worked out by hand from the program text.
"""

from __future__ import annotations

import threading

import pytest

from ladderlab.model import Pou, Project, Task
from ladderlab.simulation.build import build_project

VARIANTS = ("fast", "monitor", "debug")


def st(name: str, declarations: str, body: str, kind: str = "program", return_type: str | None = None) -> Pou:
    return Pou(name=name, kind=kind, language="st", declarations=declarations, body=body, return_type=return_type)


def run(project: Project, variant: str, scans: int, *paths: str) -> list[object]:
    build = build_project(project, variant)
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    assert [d for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    assert sim.cycle(scans) == scans
    assert sim.fault is None
    return [sim.read(path) for path in paths]


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_type_named_like_a_generated_struct_class_builds(variant: str) -> None:
    """Issue 18: TYPE STRUCT_2 plus two anonymous STRUCT variables gave two generated classes one name and
    the code generator looped forever (40 such requests stopped the server)."""
    project = Project(
        name="p",
        types="TYPE STRUCT_2 : STRUCT p : INT; q : INT; END_STRUCT; END_TYPE",
        pous=[
            st(
                "Main",
                "VAR c : STRUCT_2; a : STRUCT x : INT; END_STRUCT; b : STRUCT y : INT; END_STRUCT; "
                "STRUCT_1 : STRUCT z : INT; END_STRUCT; END_VAR",
                "a.x := a.x + 1; b.y := a.x * 10; c.q := b.y + 1; STRUCT_1.z := c.q + 1;",
            )
        ],
    )
    result: list[object] = []
    worker = threading.Thread(target=lambda: result.append(run(project, variant, 3, *PATHS)), daemon=True)
    worker.start()
    worker.join(60)
    assert not worker.is_alive(), "the build hangs"
    assert result == [[3, 30, 31, 32]]


PATHS = ("Main.a.x", "Main.b.y", "Main.c.q", "Main.STRUCT_1.z")


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_an_empty_diagram_pou_builds_and_runs(variant: str, language: str) -> None:
    """Issue 18: an empty LD/FBD POU (what a new diagram starts as) crashed the code generator, even unused."""
    project = Project(
        name="p",
        pous=[
            st("Main", "VAR n : INT; f : EmptyFb; END_VAR", "f(); n := n + 1 + EmptyFn(1);"),
            Pou(name="EmptyFb", kind="function_block", language=language, body={"networks": []}),
            Pou(
                name="EmptyFn",
                kind="function",
                language=language,
                return_type="INT",
                body={"networks": []},
                declarations="VAR_INPUT x : INT; END_VAR",
            ),
            Pou(name="EmptyProgram", kind="program", language=language, body={"networks": []}),
        ],
        tasks=[Task(name="T", programs=["Main", "EmptyProgram"])],
    )
    # an empty FUNCTION returns its result's initial value, 0: n counts one per scan
    assert run(project, variant, 4, "Main.n") == [4]
