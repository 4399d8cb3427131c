"""The monitor variant records the same power flow as the debug variant, scan by scan (issue 5, ON-09).

Programs come from the LD/FBD equivalence strategies (test_diagram_equivalence.py). Each is lowered once
and run in the monitor variant, in the debug variant (no breakpoints) and in a simulation that switches
between the two every few scans (``Simulation.use_variant``, what the server does around breakpoints):
probe values, the executed set and the variables must be identical after every scan; every element
outside an EN box must have executed (these programs have no jumps), and a box exactly when it counted.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.model import fbd, ld
from ladderlab.model.project import Task
from tests.ir.diagram_support import check_diagram_program, project
from tests.ir.test_diagram_equivalence import COUNTERS, INPUTS, OUTPUTS, fbd_program, ld_program, rungs

SCANS = 40


def _program(pou):
    lowered = project(pou)
    lowered.tasks = [Task(name="main", interval="T#10ms", programs=["Main"])]
    result = lower_project(lowered)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    check_diagram_program(result.program)
    return result.program


def _boxes(pou) -> dict[str, str]:
    """Element id that runs exactly when an ADD box counts -> its counter (LD: the box, FBD: the result node)."""
    if isinstance(pou.body, ld.LdBody):
        return {e.id: e.inputs["IN1"] for n in pou.body.networks for e in n.elements if isinstance(e, ld.Box)}
    return {
        node.id: node.var
        for n in pou.body.networks
        for node in n.nodes
        if isinstance(node, fbd.OutputNode) and node.id.startswith("res")
    }


def _unguarded(pou) -> set[str]:
    """Element ids that run in every scan: all but the ADD box (EN) and what it feeds, in LD and FBD."""
    if isinstance(pou.body, ld.LdBody):
        found: set[str] = set()

        def visit(elements: list) -> None:
            for element in elements:
                if isinstance(element, ld.Parallel):
                    found.add(element.id)
                    for branch in element.branches:
                        visit(branch)
                elif not isinstance(element, ld.Box):
                    found.add(element.id)

        for network in pou.body.networks:
            visit(network.elements)
        return found
    assert isinstance(pou.body, fbd.FbdBody)
    found = set()
    for network in pou.body.networks:
        for node in network.nodes:
            if isinstance(node, fbd.InputNode):
                found.add(node.id)
            elif isinstance(node, fbd.Block) and not node.en:
                found.add(f"{node.id}.OUT")
            elif isinstance(node, fbd.OutputNode) and not node.id.startswith("res"):
                found.add(node.id)
    return found


@settings(max_examples=25)
@given(
    st.lists(rungs, min_size=1, max_size=4),
    st.lists(st.integers(0, 2 ** len(INPUTS) - 1), min_size=SCANS, max_size=SCANS),
    st.sampled_from(["ld", "fbd"]),
    st.integers(1, 4),
)
def test_property_monitor_and_debug_variants_record_the_same_power_flow(program, masks, language, every):
    pou = (ld_program if language == "ld" else fbd_program)(program)
    lowered = _program(pou)
    monitor, debug, switching = (Simulation(lowered, variant=v) for v in ("monitor", "debug", "monitor"))
    always, boxes = _unguarded(pou), _boxes(pou)
    view = monitor.probes("Main")
    for scan, mask in enumerate(masks):
        counted = {c: monitor.read(f"Main.{c}") for c in COUNTERS}
        if scan % every == 0:
            switching.use_variant("debug" if switching.variant == "monitor" else "monitor")
            # the last scan's power flow, as the other variant reads it (a coil's probe: ProbeTable.aliases)
            assert switching.probes("Main") == view, f"before scan {scan}: switching lost probes"
        for sim in (monitor, debug, switching):
            for bit, name in enumerate(INPUTS):
                sim.write(f"Main.{name}", bool(mask >> bit & 1))
            sim.cycle(1)
            assert sim.fault is None, sim.fault
        view = monitor.probes("Main")
        assert debug.probes("Main") == view, f"scan {scan}: debug differs from monitor"
        assert switching.probes("Main") == view, f"scan {scan}: switching to {switching.variant} lost probes"
        assert always <= view.executed <= set(view.values), scan
        for counter, before in counted.items():  # each box that ran added one
            ran = sum(1 for box, c in boxes.items() if c == counter and box in view.executed)
            assert monitor.read(f"Main.{counter}") == before + ran, (scan, counter)
        outputs = [f"Main.{name}" for name in OUTPUTS + COUNTERS]
        assert (
            [debug.read(p) for p in outputs]
            == [monitor.read(p) for p in outputs]
            == [switching.read(p) for p in outputs]
        )
