"""Exports with plants (issue 21): ``with_plants`` keeps them as programs of a task PLANTS at priority 0 and the
shortest cyclic control interval, in a project's own tasks or in its IEC configuration's first resource."""

from __future__ import annotations

from ladderlab.interchange.plants import for_export
from ladderlab.interchange.st.project import export_project_st
from ladderlab.model import Configuration, ProgramInstance, Resource, Task

from ..engine.plant_support import TANK_CONTROL, TANK_GLOBALS, TANK_PLANT, project


def _configured():
    tasks = [
        Task(name="Cyclic", interval="T#20ms", programs=[ProgramInstance(name="Ctl", type="Main")]),
        Task(name="OnDemand", interval=None, single="Trig", priority=3),  # SINGLE only: no interval to take
    ]
    bench = project(TANK_PLANT, TANK_CONTROL, globals=TANK_GLOBALS + "\nVAR_GLOBAL\n    Trig : BOOL;\nEND_VAR")
    resource = Resource(name="Cpu", tasks=tasks)
    return bench.model_copy(update={"configuration": Configuration(name="Cell", resources=[resource])})


def test_a_configured_project_exports_its_plants_in_the_first_resource():
    exported = for_export(_configured(), with_plants=True)
    text = export_project_st(exported).text
    assert "TASK PLANTS(INTERVAL := T#20ms, PRIORITY := 0);" in text
    assert "PROGRAM Tank WITH PLANTS : Tank;" in text and exported.tasks == []
    # the plant task comes first among the resource's tasks; the configuration's own instance keeps its task
    assert text.index("TASK PLANTS(") < text.index("TASK Cyclic(") and "PROGRAM Ctl WITH Cyclic : Main;" in text


def test_without_plants_the_configuration_is_exported_as_it_is():
    configured = _configured()
    exported = for_export(configured)
    assert [p.name for p in exported.pous] == ["Main"] and exported.configuration == configured.configuration
