"""What a large build allocates (issue 27). The lowering leaves no reference cycles behind: what it allocates and does
not keep is freed by reference counts as it goes, so the collection that ends its collector pause
(ladderlab/collector.py) traverses only what survives. And what survives (the IR) shares its immutable parts.

Issue 27: a few closures calling themselves, a checker reporting through its own bound method and the diagram
operands owning call templates that pointed back at them held the whole check (AST spans, symbols, types) of a
50,000-network program until that collection: ~1.3 million objects, ~1 s of its ~1.8 s."""

from __future__ import annotations

import gc
from collections import Counter

import pytest
from benchmarks.diagrams import project as diagram_project

from ladderlab.engine.codegen.mentions import expression_nodes, own_expressions, walk
from ladderlab.examples import example_names, example_project
from ladderlab.ir.lower_project import lower_project
from ladderlab.ir.nodes import Member, Var
from ladderlab.ir.types import FbInstance
from ladderlab.model import Project


def _cyclic_garbage(project: Project) -> Counter[str]:
    """Types of the objects the lowering of ``project`` left in reference cycles (the pause's collection saves
    them in ``gc.garbage`` instead of freeing them)."""
    gc.collect()
    gc.garbage.clear()
    gc.set_debug(gc.DEBUG_SAVEALL)
    try:
        lowered = lower_project(project)
    finally:
        gc.set_debug(0)
    assert lowered.program is not None, [d.format() for d in lowered.diagnostics[:3]]
    found = Counter(type(o).__qualname__ for o in gc.garbage)
    gc.garbage.clear()
    return found


@pytest.mark.parametrize("name", example_names())
def test_lowering_an_example_leaves_no_cycles(name: str) -> None:
    """The examples hold ST, LD (contacts, coils, TON/CTU boxes), FBD (chained blocks), SFC and a configuration."""
    assert _cyclic_garbage(example_project(name, name)) == Counter()


@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_lowering_a_diagram_with_box_templates_leaves_no_cycles(language: str) -> None:
    """benchmarks/diagrams.py's networks: every fourth with a TON, a CTU and an ADD box (call templates)."""
    assert _cyclic_garbage(diagram_project(language, 40)) == Counter()


def test_the_ir_shares_one_object_per_fb_type_and_per_output_pin_name() -> None:
    """40 networks, 10 with a TON and a CTU: 20 instances and 30 reads of their outputs (``T0.Q``, ``K0.Q``,
    ``K0.CV``...), yet one ``FbInstance`` per FB type and one ``Member`` per pin name."""
    lowered = lower_project(diagram_project("ld", 40))
    assert lowered.program is not None
    main = lowered.program.pous["MAIN"]
    instances = [s.type for s in main.slots if isinstance(s.type, FbInstance)]
    assert len(instances) == 20
    assert len({id(ty) for ty in instances}) == 2
    members = [
        selector
        for block in main.blocks
        for statement in walk(block.statements)
        for expression in own_expressions(statement)
        for node in expression_nodes(expression)
        if isinstance(node, Var)
        for selector in node.path
        if isinstance(selector, Member)
    ]
    assert len(members) >= 20
    assert len({id(m) for m in members}) == len({m.name for m in members})


def test_a_slot_and_every_access_of_it_share_the_declared_name() -> None:
    """The declarations spell the names in upper case (``A0``, ``T0``): the slot, every ``Var`` reading or writing
    it and the checker's symbol hold the one string of the declaration, not a copy each (~10 MB per copy at
    50,000 networks)."""
    lowered = lower_project(diagram_project("ld", 40))
    assert lowered.program is not None
    main = lowered.program.pous["MAIN"]
    declared = {s.name: s.name for s in main.slots if not s.hidden}
    accesses = [
        node
        for block in main.blocks
        for statement in walk(block.statements)
        for expression in own_expressions(statement)
        for node in expression_nodes(expression)
        if isinstance(node, Var) and node.name in declared
    ]
    assert len(accesses) >= 120  # A, B and C of each network at least
    assert all(var.name is declared[var.name] for var in accesses)
