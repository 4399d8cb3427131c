"""Reading the probes of some elements only (issue 17, item 6): an online view watches the networks it shows.

``Simulation.probes(instance, elements)`` must report exactly what the whole read reports for those elements,
in the monitor variant (where probes of variables nothing writes later are read after the scan, one by one
through their paths instead of ``ll_read_probes``) and in the debug variant. The reference is a twin
simulation of the same program, driven alike, read whole.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.simulation import ProbeView, Simulation
from ladderlab.simulation.build import build_project
from ladderlab.storage.load import load_project_path
from tests.support import EXAMPLES

MOTOR = load_project_path(EXAMPLES / "motor")
MONITOR = build_project(MOTOR, "monitor").compiled
DEBUG = build_project(MOTOR, "debug").compiled
ELEMENTS = {
    instance: sorted(MONITOR.generated.context.probes_of(pou).elements)
    for instance, pou in (("MAIN", "MAIN"), ("SCALING", "SCALING"))
}


def restricted(view: ProbeView, elements: list[str]) -> ProbeView:
    return ProbeView(
        {e: v for e, v in view.values.items() if e in elements}, frozenset(e for e in view.executed if e in elements)
    )


@settings(max_examples=40)
@given(
    variant=st.sampled_from(["monitor", "debug"]),
    scans=st.lists(st.tuples(st.booleans(), st.booleans(), st.integers(0, 3)), max_size=6),
    instance=st.sampled_from(sorted(ELEMENTS)),
    data=st.data(),
)
def test_a_subset_reads_what_the_whole_read_says_about_it(variant, scans, instance, data) -> None:
    compiled = MONITOR if variant == "monitor" else DEBUG
    whole, some = Simulation(compiled), Simulation(compiled)
    for start, stop, count in scans:
        for sim in (whole, some):
            sim.write("Start", start)
            sim.write("Stop", stop)
            sim.cycle(count)
    elements = data.draw(st.lists(st.sampled_from(ELEMENTS[instance]), max_size=8))
    assert some.probes(instance, elements + ["no_such_element"]) == restricted(whole.probes(instance), elements)


def test_an_empty_selection_reads_nothing_and_none_reads_everything() -> None:
    sim = Simulation(MONITOR)
    sim.write("Start", True)
    sim.cycle(2)
    assert sim.probes("MAIN", []) == ProbeView({}, frozenset())
    everything = sim.probes("MAIN")
    assert {"start", "motor", "ton.ET"} <= everything.executed and everything.values["motor"] is True
