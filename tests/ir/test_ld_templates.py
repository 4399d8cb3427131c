"""LD networks of one shape filled in from a template (ir/ld_templates.py, issue 27) give the very IR, diagnostics and
generated code that lowering every network on its own gives.

The diagrams repeat random shapes whose variables are the same or different, of other types (INT compares, an ADD
box writing its input), FB boxes and their outputs read by contacts (``T0.Q``), parallel branches, box inputs fed by
series lists, edge contacts and coils (their memories are slots of their own), globals, constants, literals and
unknown names (reported); the plain lowering is what ``LdTemplates`` does without its templates.
"""

from __future__ import annotations

import os

import pytest
from benchmarks.diagrams import project as benchmark_project
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen import generate
from ladderlab.examples import example_names, example_project
from ladderlab.ir import ld_templates
from ladderlab.ir.lower_project import LoweringResult, lower_project
from ladderlab.model import ld
from ladderlab.model.project import Pou, Project, Task
from tests.support import ld_shapes_project

BOOLS = ["B0", "B1", "B2", "B3"]


def _plain(self: ld_templates.LdTemplates, network: ld.LdNetwork) -> object:
    return self.rung.lower(network)


def _lowered(project: Project, plain: bool) -> LoweringResult:
    with pytest.MonkeyPatch.context() as patched:
        if plain:
            patched.setattr(ld_templates.LdTemplates, "lower", _plain)
        return lower_project(project)


def _both(project: Project, variants: tuple[str, ...] = ("fast",)) -> LoweringResult:
    """The project lowered with and without templates: the same IR, diagnostics and code (``variants``)."""
    filled, plain = _lowered(project, False), _lowered(project, True)
    assert [d.format() for d in filled.diagnostics] == [d.format() for d in plain.diagnostics]
    assert repr(filled.program) == repr(plain.program)
    if filled.program is not None and plain.program is not None:
        for variant in variants:
            ours, theirs = generate(filled.program, variant), generate(plain.program, variant)
            assert ours.source == theirs.source
            assert ours.line_origins == theirs.line_origins
    return filled


def _filled_networks(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The ids of the networks filled in from a template from now on."""
    filled: list[str] = []
    fill = ld_templates.LdTemplates._filled
    monkeypatch.setattr(
        ld_templates.LdTemplates, "_filled", lambda self, *args: (filled.append(args[1].id), fill(self, *args))[1]
    )
    return filled


series = st.lists(
    st.one_of(
        st.tuples(
            st.just("contact"),
            st.sampled_from([*BOOLS, "G1", "K1", "T0.Q", "T1.Q", "I0"]),
            st.sampled_from(["no", "nc", "p"]),
        ),
        st.tuples(
            st.just("coil"), st.sampled_from([*BOOLS, "G1", "Nope"]), st.sampled_from(["normal", "negated", "set", "n"])
        ),
        st.tuples(
            st.just("compare"), st.sampled_from(["I0", "I1", "5"]), st.sampled_from(["I0", "I1", "K2", "I0 + 1"])
        ),
        st.tuples(st.just("ton"), st.sampled_from(["T0", "T1", "B0"]), st.sampled_from(["T#5ms", "T#1s"])),
        st.tuples(st.just("add"), st.sampled_from(["I0", "I1"]), st.sampled_from(["I0", "I1", "1"])),
        st.tuples(st.just("parallel"), st.sampled_from(BOOLS), st.sampled_from(BOOLS)),
        st.tuples(st.just("fed"), st.sampled_from(["T0", "T1"]), st.sampled_from(BOOLS)),
    ),
    min_size=1,
    max_size=4,
)


def _project(networks: list[list[tuple[str, str, str]]]) -> Project:
    declarations = (
        f"VAR\n  {', '.join(BOOLS)} : BOOL; I0, I1 : INT; T0, T1 : TON;\nEND_VAR\n"
        "VAR CONSTANT K1 : BOOL := TRUE; K2 : INT := 3; END_VAR\nVAR_EXTERNAL G1 : BOOL; END_VAR"
    )
    return ld_shapes_project(declarations, networks)


@settings(max_examples=int(os.environ.get("TEMPLATE_EXAMPLES", "30")), deadline=None)
@given(shapes=st.lists(series, min_size=1, max_size=5), repeats=st.integers(2, 8))
def test_networks_of_repeated_shapes_give_the_plain_lowering(
    shapes: list[list[tuple[str, str, str]]], repeats: int
) -> None:
    networks = [
        [_renamed(spec, i // len(shapes)) for spec in shapes[i % len(shapes)]] for i in range(repeats * len(shapes))
    ]
    _both(_project(networks))


def test_a_member_of_another_instance_is_not_the_networks_own(monkeypatch: pytest.MonkeyPatch) -> None:
    """``--| T0.Q |--[TON T1]--`` after ``--| T0.Q |--[TON T0]--``: the contact reads T0.Q, not the network's own
    instance's Q (a member named by its text was kept as the text, its instance bound as the network's variable)."""
    filled = _filled_networks(monkeypatch)
    networks = [[("contact", "T0.Q", "no"), ("ton", instance, "T#5ms")] for instance in ["T0", "T0", "T1", "T0"]]
    _both(_project(networks))
    assert filled == ["n3"]  # (n2's contact and box name two instances, n1's one: another shape)


def _renamed(spec: tuple[str, str, str], turn: int) -> tuple[str, str, str]:
    """The variables named plainly rotated in their pools each repetition (texts such as ``I0 + 1`` kept): later
    networks of a shape have other variables than its first."""

    def rename(text: str) -> str:
        root, dot, member = text.partition(".")
        pool = BOOLS if root in BOOLS else ["I0", "I1"] if root in ("I0", "I1") else ["T0", "T1"]
        return pool[(pool.index(root) + turn) % len(pool)] + dot + member if root in pool else text

    kind, a, b = spec
    return kind, rename(a), rename(b) if kind != "contact" and kind != "coil" else b


@pytest.mark.parametrize("timed", [1, 4])
def test_the_benchmark_diagram_gives_the_plain_lowering(timed: int, monkeypatch: pytest.MonkeyPatch) -> None:
    filled = _filled_networks(monkeypatch)
    _both(benchmark_project("ld", 300, timed), ("fast", "monitor", "debug"))
    assert len(filled) >= 300 - 3  # every network but the first of each shape (and of the temporaries' growth)


@pytest.mark.parametrize("name", example_names())
@pytest.mark.parametrize("start", ["solution", "exercise"])
def test_every_example_gives_the_plain_lowering(name: str, start: str) -> None:
    _both(example_project(name, name, start), ("fast", "monitor"))


def test_a_variable_of_another_type_class_or_sameness_is_another_shape(monkeypatch: pytest.MonkeyPatch) -> None:
    """Networks alike but for a variable's class (C), its type (a bit of a WORD: no template at all) or which of
    the variables are the same are each lowered on their own; only the last is filled in (from n1: n0 added the
    power-flow temporary's slot)."""
    declarations = "VAR A, B : BOOL; W : WORD; END_VAR\nVAR_OUTPUT C : BOOL; END_VAR"
    pairs = [("A", "B"), ("B", "A"), ("A", "C"), ("W.1", "B"), ("B", "B"), ("A", "B")]
    networks = [
        ld.LdNetwork(id=f"n{n}", elements=[ld.Contact(id=f"a{n}", var=a), ld.Coil(id=f"c{n}", var=c)])
        for n, (a, c) in enumerate(pairs)
    ]
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=networks))
    project = Project(name="kinds", pous=[pou], tasks=[Task(name="t", interval="T#10ms", programs=["Main"])])
    filled = _filled_networks(monkeypatch)
    _both(project)
    assert filled == ["n5"]


@pytest.mark.parametrize(
    ("kind", "declarations", "pairs"),
    [
        # an FB's inputs, outputs and R_EDGE input (read as its detected edge: never filled in)
        (
            "function_block",
            "VAR_INPUT I1, I2 : BOOL; E1 : BOOL R_EDGE; END_VAR VAR_OUTPUT Q1, Q2 : BOOL; END_VAR",
            [("I1", "Q1"), ("I2", "Q2"), ("E1", "Q1"), ("I2", "Q1"), ("E1", "Q2")],
        ),
        # a function's result written by a coil, its temporaries
        (
            "function",
            "VAR_INPUT I1, I2 : BOOL; END_VAR VAR_TEMP T1 : BOOL; END_VAR",
            [("I1", "T1"), ("I2", "T1"), ("T1", "Fn"), ("I1", "Fn"), ("I2", "T1")],
        ),
    ],
)
def test_function_blocks_and_functions_give_the_plain_lowering(
    kind: str, declarations: str, pairs: list[tuple[str, str]], monkeypatch: pytest.MonkeyPatch
) -> None:
    networks = [
        ld.LdNetwork(id=f"n{n}", elements=[ld.Contact(id=f"a{n}", var=a), ld.Coil(id=f"c{n}", var=c)])
        for n, (a, c) in enumerate(pairs * 2)
    ]
    pou = Pou(
        name="Fn",
        kind=kind,
        language="ld",
        declarations=declarations,
        return_type="BOOL" if kind == "function" else None,
        body=ld.LdBody(networks=networks),
    )
    main = Pou(
        name="Main",
        kind="program",
        language="st",
        declarations="VAR f : Fn; x : BOOL; END_VAR" if kind == "function_block" else "VAR x : BOOL; END_VAR",
        body="f(I1 := x);" if kind == "function_block" else "x := Fn(I1 := x, I2 := TRUE);",
    )
    project = Project(name="pous", pous=[main, pou], tasks=[Task(name="t", interval="T#10ms", programs=["Main"])])
    filled = _filled_networks(monkeypatch)
    assert _both(project).program is not None
    assert filled  # (some of the second round of networks)


def test_an_operand_text_naming_a_variable_of_the_network_keeps_it_plain(monkeypatch: pytest.MonkeyPatch) -> None:
    """``I1 + 1`` is kept as its text in the shape: a template whose texts name one of its own variables would bind
    that name in them too (n3 would compare with ``I0 + 1``; n0 added the power flow's slot, n1 names its own I1)."""
    declarations = "VAR I0, I1 : INT; END_VAR"
    specs = [("I0", "I1 + 1"), ("I1", "I1 + 1"), ("I0", "I1 + 1"), ("I0", "I1 + 1")]
    networks = [
        ld.LdNetwork(id=f"n{n}", elements=[ld.Compare(id=f"k{n}", op="LT", left=a, right=b)])
        for n, (a, b) in enumerate(specs)
    ]
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=networks))
    project = Project(name="texts", pous=[pou], tasks=[Task(name="t", interval="T#10ms", programs=["Main"])])
    filled = _filled_networks(monkeypatch)
    _both(project)
    assert filled == []
