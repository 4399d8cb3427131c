"""Networks of one shape filled in from a template (codegen/templates.py, issue 27) give the very module, line origins
and origins that emitting every network on its own gives, in the fast variant and in the monitor variant's unviewed
twins: the same code, the same fault locations.

The diagrams mix shapes whose variables are the same or different (``A AND A`` folds to ``A``), of other types
(INT compares, an ADD box), FB boxes, set/reset and edge coils, globals, and enough variables that later ones live
on a page of their own (``ll_p1.v_X``); the plain emission is what ``Statements`` does without the templates.
"""

from __future__ import annotations

import dataclasses
import os

import pytest
from benchmarks.diagrams import project as benchmark_project
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen import generate, templates
from ladderlab.engine.codegen.layout import PAGE_SIZE
from ladderlab.ir import nodes as ir
from ladderlab.ir.lower_project import lower_project
from ladderlab.model import ld
from ladderlab.model.project import Pou, Project, Task
from ladderlab.simulation.build import build_project
from tests.support import ld_shapes_project

BOOLS = [f"B{i}" for i in range(4)]


def _plain(self: templates.BlockTemplates, st_: object, block: object, own_group: bool) -> None:
    st_.statements(block.statements, own_group=own_group)  # type: ignore[attr-defined]


def _both(project: Project, variant: str = "fast") -> None:
    lowered = lower_project(project)
    assert lowered.program is not None, [d.format() for d in lowered.diagnostics]
    filled = generate(lowered.program, variant)
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(templates.BlockTemplates, "emit", _plain)
        plain = generate(lowered.program, variant)
    assert filled.source == plain.source
    assert filled.line_origins == plain.line_origins
    assert filled.origins == plain.origins
    assert [id(s) for s in filled.origin_statements] == [id(s) for s in plain.origin_statements]
    assert [d.format() for d in filled.diagnostics] == [d.format() for d in plain.diagnostics]


element = st.one_of(
    st.tuples(st.just("contact"), st.sampled_from(BOOLS + ["G1", "P0", "P1"]), st.sampled_from(["no", "nc", "p"])),
    st.tuples(st.just("coil"), st.sampled_from(BOOLS + ["G1", "P1"]), st.sampled_from(["normal", "set", "reset", "n"])),
    st.tuples(st.just("compare"), st.sampled_from(["I0", "I1", "5"]), st.sampled_from(["I0", "I1", "7"])),
    st.tuples(st.just("ton"), st.sampled_from(["T0", "T1"]), st.sampled_from(["T#5ms", "T#1s"])),
    st.tuples(st.just("add"), st.sampled_from(["I0", "I1"]), st.sampled_from(["I0", "I1", "1"])),
)


def _project(networks: list[list[tuple[str, str, str]]]) -> Project:
    filler = " ".join(f"F{i}," for i in range(PAGE_SIZE))  # P0 and P1 on the second page of slots
    declarations = (
        f"VAR\n  {', '.join(BOOLS)} : BOOL; I0, I1 : INT; T0, T1 : TON;\n  {filler} P0, P1 : BOOL;\nEND_VAR\n"
        "VAR_EXTERNAL G1 : BOOL; END_VAR"
    )
    return ld_shapes_project(declarations, networks)


@settings(max_examples=int(os.environ.get("TEMPLATE_EXAMPLES", "25")), deadline=None)
@given(shapes=st.lists(st.lists(element, min_size=1, max_size=4), min_size=2, max_size=6), repeats=st.integers(2, 12))
def test_networks_of_repeated_shapes_give_the_plain_emission(
    shapes: list[list[tuple[str, str, str]]], repeats: int
) -> None:
    networks = [shapes[i % len(shapes)] for i in range(repeats * len(shapes))]
    _both(_project(networks))
    _both(_project(networks), "monitor")  # (its unviewed twins: the chunks that record no probe)


@pytest.mark.parametrize("language", ["ld", "fbd"])
@pytest.mark.parametrize("timed", [1, 4])
@pytest.mark.parametrize("variant", ["fast", "monitor"])
def test_the_benchmark_diagrams_give_the_plain_emission(language: str, timed: int, variant: str) -> None:
    _both(benchmark_project(language, 400, timed), variant)


def test_only_code_without_probes_is_filled_in(monkeypatch: pytest.MonkeyPatch) -> None:
    """The debug variant has no templates; the monitor variant fills in only its unviewed twins."""
    lowered = lower_project(benchmark_project("ld", 20))
    assert lowered.program is not None
    calls: list[bool] = []
    monkeypatch.setattr(
        templates.BlockTemplates,
        "emit",
        lambda self, st_, block, own: (calls.append(st_.probes is None), _plain(self, st_, block, own)),
    )
    generate(lowered.program, "debug")
    assert calls == []
    generate(lowered.program, "monitor")
    assert calls and all(calls)


def test_the_shape_models_every_field_of_the_statements_it_fills() -> None:
    """templates._Shape lists the fields of these statements one by one: a field added to one of them must be added
    to its shape (or two networks differing in it would share code)."""
    modelled = {
        ir.Assign: ["target", "value", "origin"],
        ir.If: ["branches", "orelse", "origin"],
        ir.FbCall: ["instance", "inputs", "outputs", "origin", "en", "eno", "body"],
        ir.FnCall: ["call", "target", "origin", "en", "eno"],
        ir.Probe: ["element", "value", "origin", "kind"],  # (none recorded in the fast variant)
        ir.Var: ["scope", "name", "type", "path"],  # (scope and name: in the variable's code)
        ir.Binary: ["op", "left", "right", "type"],
        ir.Unary: ["op", "operand", "type"],
        ir.Const: ["value", "type"],
    }
    assert {cls: [f.name for f in dataclasses.fields(cls)] for cls in modelled} == modelled


def test_a_network_passing_its_variable_to_an_in_out_names_its_own() -> None:
    """An LD box calling a FUNCTION with a VAR_IN_OUT passes a reference to its network's own variable (``f_INC((self,
    'v_A1'))``: the attribute outside the variable's code), never the first network of the shape's: each call adds
    1 to its own argument (IEC 61131-3 VAR_IN_OUT: by reference; CODESYS's online help, "VAR_IN_OUT")."""
    networks = [
        ld.LdNetwork(
            id=f"n{n}",
            elements=[
                ld.Contact(id=f"c{n}", var=f"B{n}", mode="no"),
                ld.Box(id=f"b{n}", call="INC", en=True, inputs={"X": f"A{n}"}),
                ld.Coil(id=f"k{n}", var=f"C{n}", mode="normal"),
            ],
        )
        for n in range(3)
    ]
    main = Pou(
        name="Main",
        kind="program",
        language="ld",
        declarations="VAR A0, A1, A2 : INT; B0, B1, B2 : BOOL := TRUE; C0, C1, C2 : BOOL; END_VAR",
        body=ld.LdBody(networks=networks),
    )
    inc = Pou(
        name="INC",
        kind="function",
        language="st",
        return_type="BOOL",
        declarations="VAR_IN_OUT X : INT; END_VAR",
        body="X := X + 1; INC := TRUE;",
    )
    project = Project(name="in_out", pous=[main, inc], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])
    _both(project)
    build = build_project(project, "fast")
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    sim = build.simulation()
    sim.cycle(2)
    assert [sim.read(f"Main.{name}") for name in ("A0", "A1", "A2", "C0", "C1", "C2")] == [2, 2, 2, True, True, True]
    sim.write("Main.B1", False)
    sim.cycle(1)
    assert [sim.read(f"Main.{name}") for name in ("A0", "A1", "A2", "C1")] == [3, 2, 3, False]
