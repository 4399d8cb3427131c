"""Networks the LD lowering filled in from a template (``ir.Block.filled``, issue 27) give the very code, line
origins and origins when the code generator takes their shape from that template (codegen/templates.py, ``_Filled``)
and their liveness from the template's first network (codegen/liveness.py, ``_Known``) as when it computes both for
each network.

The diagrams repeat random shapes whose variables rotate in their pools at each repetition, over a page boundary
of the slots (``ll_p1.v_X``: the same template, other pages), with INT compares, ADD boxes writing their input,
TON instances and their outputs (``T0.Q``), set/reset and edge coils, globals, and a compare's text naming another
variable (``I1 + 1``), which a later network of the shape has as its own variable; the reference is the same IR
with every block's ``filled`` cleared.
"""

from __future__ import annotations

import os

import pytest
from benchmarks.diagrams import project as benchmark_project
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen import chunks, generate
from ladderlab.engine.codegen.layout import PAGE_SIZE
from ladderlab.ir import nodes as ir
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Project
from tests.engine.test_block_templates import _project  # (the same program of LD networks)
from tests.support import ld_shapes_project

#: the pools the variables rotate in: the last BOOLs live on the second page of slots
BOOLS = ["B0", "B1", "B2", "P0", "P1"]
INTS = ["I0", "I1"]
TIMERS = ["T0", "T1"]

element = st.one_of(
    st.tuples(st.just("contact"), st.sampled_from([*BOOLS, "G1", "T0.Q"]), st.sampled_from(["no", "nc", "p"])),
    st.tuples(st.just("coil"), st.sampled_from([*BOOLS, "G1"]), st.sampled_from(["normal", "set", "reset", "n"])),
    st.tuples(st.just("compare"), st.sampled_from(INTS), st.sampled_from(["I0", "I1", "7", "I1 + 1"])),
    st.tuples(st.just("ton"), st.sampled_from(TIMERS), st.sampled_from(["T#5ms", "T#1s"])),
    st.tuples(st.just("add"), st.sampled_from(INTS), st.sampled_from(["I0", "I1", "1"])),
)


def _rotated(spec: tuple[str, str, str], turn: int) -> tuple[str, str, str]:
    """The variables named plainly moved ``turn`` places along their pools (texts such as ``I1 + 1`` kept)."""

    def rotate(text: str) -> str:
        root, dot, member = text.partition(".")
        for pool in (BOOLS, INTS, TIMERS):
            if root in pool:
                return pool[(pool.index(root) + turn) % len(pool)] + dot + member
        return text

    kind, a, b = spec
    return kind, rotate(a), b if kind in ("contact", "coil") else rotate(b)


def _same_without_filled(project: Project, variants: tuple[str, ...] = ("fast", "monitor")) -> list[ir.Block]:
    """The code of ``project`` with and without the blocks' ``filled``: the same; the blocks that had it."""
    lowered = lower_project(project)
    assert lowered.program is not None, [d.format() for d in lowered.diagnostics]
    blocks = [block for pou in lowered.program.pous.values() for block in pou.blocks]
    filled = [(block, block.filled) for block in blocks if block.filled is not None]
    for variant in variants:
        ours = generate(lowered.program, variant)
        for block, _ in filled:
            block.filled = None
        theirs = generate(lowered.program, variant)
        for block, was in filled:
            block.filled = was
        assert ours.source == theirs.source
        assert ours.line_origins == theirs.line_origins
        assert ours.origins == theirs.origins
        assert [id(s) for s in ours.origin_statements] == [id(s) for s in theirs.origin_statements]
        assert [d.format() for d in ours.diagnostics] == [d.format() for d in theirs.diagnostics]
    return [block for block, _ in filled]


@settings(max_examples=int(os.environ.get("TEMPLATE_EXAMPLES", "25")), deadline=None)
@given(
    shapes=st.lists(st.lists(element, min_size=1, max_size=4), min_size=1, max_size=4),
    repeats=st.integers(2, 10),
    chunk=st.sampled_from([4, 15, chunks.CHUNK_STATEMENTS]),
)
def test_networks_filled_from_a_template_give_the_code_of_their_own_shape(
    shapes: list[list[tuple[str, str, str]]], repeats: int, chunk: int
) -> None:
    """(Small chunks: networks whose temporaries the next chunk takes over, chunks that load no second page.)"""
    networks = [
        [_rotated(spec, i // len(shapes)) for spec in shapes[i % len(shapes)]] for i in range(repeats * len(shapes))
    ]
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(chunks, "CHUNK_STATEMENTS", chunk)
        _same_without_filled(_project(networks))


#: BOOLs on three pages of slots: a network's variables on one page or on several, its template's first on others
PAGED = ["B0", "B1", "P0", "P1", "Q0", "Q1"]


def _paged_project(networks: list[list[tuple[str, str, str]]]) -> Project:
    fillers = [" ".join(f"{page}{i}," for i in range(PAGE_SIZE)) for page in ("F", "H")]
    declarations = (
        f"VAR\n  B0, B1 : BOOL; I0, I1 : INT; T0, T1 : TON;\n  {fillers[0]} P0, P1 : BOOL;\n  {fillers[1]} Q0, Q1 : BOOL;\n"
        "END_VAR\nVAR_EXTERNAL G1 : BOOL; END_VAR"
    )
    return ld_shapes_project(declarations, networks)  # type: ignore[return-value]


@settings(max_examples=int(os.environ.get("TEMPLATE_EXAMPLES", "25")), deadline=None)
@given(
    shape=st.lists(
        st.one_of(
            st.tuples(st.just("contact"), st.sampled_from(range(len(PAGED))), st.sampled_from(["no", "nc", "p"])),
            st.tuples(st.just("coil"), st.sampled_from(range(len(PAGED))), st.sampled_from(["normal", "set", "n"])),
            st.tuples(st.just("ton"), st.sampled_from(["T0", "T1"]), st.sampled_from(["T#5ms", "T#1s"])),
        ),
        min_size=1,
        max_size=4,
    ),
    turns=st.lists(st.integers(0, len(PAGED) - 1), min_size=2, max_size=12),
    chunk=st.sampled_from([4, 15, chunks.CHUNK_STATEMENTS]),
)
def test_the_networks_of_a_template_share_its_code_whatever_pages_their_variables_live_on(
    shape: list[tuple[str, object, str]], turns: list[int], chunk: int
) -> None:
    """A filled network's code is its template's first network's with its own variables' codes (``ll_p2.v_Q0`` for
    ``self.v_B0``) and it loads the pages those name (codegen/templates.py, ``_Twin``): each network here moves the
    shape's BOOLs ``turn`` places along variables of three pages."""
    networks = [
        [
            (kind, PAGED[(a + turn) % len(PAGED)] if isinstance(a, int) else a, b)  # type: ignore[operator]
            for kind, a, b in shape
        ]
        for turn in turns
    ]
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(chunks, "CHUNK_STATEMENTS", chunk)
        _same_without_filled(_paged_project(networks))


@pytest.mark.parametrize("timed", [1, 4])
def test_the_benchmark_diagram_gives_the_same_code(timed: int) -> None:
    filled = _same_without_filled(benchmark_project("ld", 300, timed))
    assert len(filled) >= 300 - 3  # every network but the first of each shape (and of the temporaries' growth)


def test_a_network_whose_variable_another_text_of_its_shape_names_is_not_marked_filled() -> None:
    """``I1 + 1`` reads I1 in every network of the shape; where I1 is also the network's own variable (n2) its code
    names one slot twice where the template's network (n1, after n0 made the temporaries) named two: the generator
    must compute its shape."""
    networks = [[("contact", "B0", "no"), ("compare", "I0", "I1 + 1"), ("coil", "B1", "normal")]] * 2
    networks.append([("contact", "B1", "no"), ("compare", "I1", "I1 + 1"), ("coil", "B2", "normal")])
    networks.append([("contact", "B2", "no"), ("compare", "I0", "I1 + 1"), ("coil", "P0", "normal")])
    filled = _same_without_filled(_project(networks))
    assert [block.origin.network for block in filled] == ["n3"]
    (block,) = filled
    assert [var.name for var in block.filled.variables(block.statements)] == ["B2", "I0", "P0"]  # type: ignore[union-attr]
