"""PLCopen TC6 import and export of SFC POUs: steps, transitions, actions, branches, jumps, qualifiers.

Round trips are property-tested on random charts (strategies.py): LadderLab's own files come back equal; the same
files without LadderLab's addData (as another tool leaves them) come back as the same chart graph (steps,
transitions with their steps and conditions, associations, actions), and run the same scan for scan.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model import Pou, Project, Task
from ladderlab.model.sfc import SfcBody, steps
from ladderlab.model.sfc_graph import chart_graph
from ladderlab.storage import load_project_path
from tests.interchange.plcopen_helpers import strip_ladderlab, xsd_errors
from tests.support import EXAMPLES

from .strategies import sfc_bodies
from .support import build
from .test_graph import loop_back_into_a_branch


def sfc_project(body: dict) -> Project:
    """A program ``Seq`` of ``body`` with the BOOL conditions of its charts (its own and its SFC actions') and the
    counters its actions add to (``n``, ``m``: tests/sfc/strategies.py); a condition that is a named transition is
    not declared, the ``c<n>`` the named transition reads is."""
    charts = [body["chart"], *(a["body"] for a in body.get("actions", []) if a["language"] == "sfc")]
    named = body.get("transitions", [])
    written = {t["condition"] for chart in charts for t in _transitions(chart["elements"])}
    conditions = sorted(written - {t["name"] for t in named} | {t["body"].split()[-1] for t in named})
    counters = "n, m : INT;"
    declarations = (
        f"VAR {', '.join(conditions)} : BOOL; {counters} END_VAR" if conditions else f"VAR {counters} END_VAR"
    )
    pou = Pou(name="Seq", kind="program", language="sfc", declarations=declarations, body=body)
    return Project(name="sfc", pous=[pou], tasks=[Task(name="t", interval="T#10ms", programs=["Seq"])])


def _transitions(elements: list) -> list[dict]:
    out = []
    for e in elements:
        if e["type"] == "transition":
            out.append(e)
        for branch in e.get("branches", []):
            out += _transitions(branch)
    return out


def semantics(body: SfcBody) -> tuple:
    """What a chart means, whatever its drawing: its graph, each step's associations, the actions."""
    graph = chart_graph(body.chart)
    edges = sorted(
        (tuple(sorted(t.sources)), tuple(sorted(t.targets)), t.transition.condition, t.transition.priority)
        for t in graph.transitions
    )
    associations = {s.name: [(a.qualifier, a.action, a.time) for a in s.actions] for s in steps(body.chart.elements)}
    initial = graph.initial.step.name if graph.initial else None
    return edges, associations, initial, sorted((a.name, _without_ids(a.body)) for a in body.actions)


def _without_ids(body: object) -> object:
    """A body to compare across a file without LadderLab's addData, which carries the element ids and which network
    a comment belongs to (without it a network's comment box is read as a comment network of its own)."""
    if isinstance(body, str):
        return body
    data = body.model_dump(mode="json", exclude_none=True)  # type: ignore[attr-defined]  # LD/FBD
    data["networks"] = [n for n in data["networks"] if n.get("elements")]
    return repr(_drop(data))


def _drop(data: object) -> object:
    if isinstance(data, dict):
        return {k: _drop(v) for k, v in data.items() if k not in ("id", "pos", "node", "comment")}
    if isinstance(data, list):
        return [_drop(v) for v in data]
    return data


@given(sfc_bodies())
def test_sfc_pous_come_back_equal(body):
    project = sfc_project(body)
    data = export_plcopen(project)
    result = import_plcopen(data)
    assert [d.format() for d in result.diagnostics] == []
    assert result.project == project


@given(sfc_bodies())
@settings(max_examples=30)
def test_without_ladderlab_data_an_sfc_pou_comes_back_as_the_same_chart(body):
    project = sfc_project(body)
    result = import_plcopen(strip_ladderlab(export_plcopen(project)))
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    assert semantics(result.project.pous[0].body) == semantics(project.pous[0].body)


@given(sfc_bodies(), st.lists(st.integers(0, 2**30), min_size=20, max_size=20))
@settings(max_examples=15)
def test_without_ladderlab_data_an_sfc_pou_runs_the_same(body, seeds):
    project = sfc_project(body)
    again = import_plcopen(strip_ladderlab(export_plcopen(project))).project
    conditions = sorted({t["condition"] for t in _transitions(body["chart"]["elements"])})
    traces = []
    for candidate in (project, again):
        sim = build(candidate)
        trace = []
        for seed in seeds:
            for bit, name in enumerate(conditions):
                sim.write(f"Seq.{name}", bool(seed >> bit & 1))
            sim.cycle(1)
            trace.append(
                (
                    sim.read("Seq.n"),
                    tuple(
                        sim.read(f"Seq.{name}.X")
                        for name in sorted(s.name for s in steps(project.pous[0].body.chart.elements))
                    ),
                )
            )
        traces.append(trace)
    assert traces[0] == traces[1]


def test_a_chart_whose_join_jumps_back_into_an_alternative_branch_imports_without_ladderlab_data():
    """Found by the round trips above: the import refused the file ("a simultaneous divergence activates step S25,
    which is also reached another way") though LadderLab drew it."""
    project = sfc_project({"chart": {"elements": loop_back_into_a_branch()}, "actions": [], "transitions": []})
    result = import_plcopen(strip_ladderlab(export_plcopen(project)))
    assert [d.format() for d in result.diagnostics] == []
    assert semantics(result.project.pous[0].body) == semantics(project.pous[0].body)


@given(sfc_bodies())
@settings(max_examples=10)
def test_exported_sfc_validates_against_the_tc6_schema(body):
    assert xsd_errors(export_plcopen(sfc_project(body))) == []


def test_the_sfc_example_comes_back_equal_and_validates():
    project = load_project_path(EXAMPLES / "car_wash_sfc")
    data = export_plcopen(project)
    assert xsd_errors(data) == []
    result = import_plcopen(data)
    assert [d.format() for d in result.diagnostics] == [] and result.project == project
    stripped = import_plcopen(strip_ladderlab(data))
    wash = stripped.project.pou("Wash")
    assert semantics(wash.body) == semantics(project.pou("Wash").body)


def test_a_foreign_chart_imports_with_inline_actions_named_references_and_a_drawn_condition():
    """A hand-written TC6 chart: an inline ST action, an action by reference with D and a duration, a named
    transition, a condition drawn with a negated contact from the left rail, and a jump."""
    pou = """<pou name="Seq" pouType="program">
      <interface><localVars>
        <variable name="go"><type><BOOL/></type></variable><variable name="n"><type><INT/></type></variable>
      </localVars></interface>
      <actions><action name="Blink"><body><ST><xhtml:p>n := n + 10;</xhtml:p></ST></body></action></actions>
      <transitions><transition name="Ready"><body><ST><xhtml:p>Ready := go AND n > 0;</xhtml:p></ST></body>
      </transition></transitions>
      <body><SFC>
        <step localId="1" name="Init" initialStep="true"><position x="0" y="0"/>
          <connectionPointOut formalParameter=""/><connectionPointOutAction formalParameter=""/></step>
        <actionBlock localId="2"><position x="150" y="0"/>
          <connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <action localId="3" qualifier="N"><relPosition x="0" y="0"/>
            <inline><ST><xhtml:p>n := n + 1;</xhtml:p></ST></inline></action>
          <action localId="4" qualifier="D" duration="T#20ms"><relPosition x="0" y="20"/>
            <reference name="Blink"/></action>
        </actionBlock>
        <transition localId="5"><position x="40" y="50"/>
          <connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <condition><reference name="Ready"/></condition></transition>
        <step localId="6" name="Done"><position x="0" y="100"/>
          <connectionPointIn><connection refLocalId="5"/></connectionPointIn></step>
        <leftPowerRail localId="7"><position x="-100" y="150"/><connectionPointOut formalParameter=""/></leftPowerRail>
        <contact localId="8" negated="true"><position x="-60" y="150"/>
          <connectionPointIn><connection refLocalId="7"/></connectionPointIn><variable>go</variable></contact>
        <transition localId="9"><position x="40" y="150"/>
          <connectionPointIn><connection refLocalId="6"/></connectionPointIn>
          <condition><connectionPointIn><connection refLocalId="8"/></connectionPointIn></condition></transition>
        <jumpStep localId="10" targetName="Init"><position x="40" y="200"/>
          <connectionPointIn><connection refLocalId="9"/></connectionPointIn></jumpStep>
      </SFC></body></pou>"""
    document = (
        '<?xml version="1.0" encoding="utf-8"?><project xmlns="http://www.plcopen.org/xml/tc6_0201" '
        'xmlns:xhtml="http://www.w3.org/1999/xhtml"><fileHeader companyName="x" productName="x" productVersion="1" '
        'creationDateTime="2024-01-01T00:00:00"/><contentHeader name="x"><coordinateInfo><fbd><scaling x="1" y="1"/>'
        '</fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>'
        f"<types><dataTypes/><pous>{pou}</pous></types><instances><configurations/></instances></project>"
    )
    result = import_plcopen(document.encode())
    assert [d.format() for d in result.diagnostics] == []
    body = result.project.pou("Seq").body
    assert [(a.name, a.body) for a in body.actions] == [("Blink", "n := n + 10;"), ("Init_action1", "n := n + 1;")]
    assert [(t.name, t.body) for t in body.transitions] == [("Ready", "go AND n > 0")]
    init, t1, done, t2, back = body.chart.elements
    assert [(a.qualifier, a.action, a.time) for a in init.actions] == [
        ("N", "Init_action1", None),
        ("D", "Blink", "T#20ms"),
    ]
    assert (t1.condition, done.name, t2.condition, back.target) == ("Ready", "Done", "NOT go", "Init")
    project = result.project.model_copy(update={"tasks": [Task(name="t", interval="T#10ms", programs=["Seq"])]})
    sim = build(project)
    sim.cycle(3)  # Init: n + 1 every scan, Blink (D 20 ms) from its third scan: + 10
    assert sim.read("Seq.n") == 13


def test_an_action_written_in_sfc_comes_back_and_runs_the_same_without_ladderlab_data():
    """Issue 24 item 1: an SFC action body is written as the action's <SFC> and read back as a chart."""
    from .test_sfc_actions import chart

    project = chart()
    data = export_plcopen(project)
    assert xsd_errors(data) == []
    assert import_plcopen(data).project == project
    stripped = import_plcopen(strip_ladderlab(data))
    assert [d.format() for d in stripped.diagnostics if d.severity == "error"] == []
    seq = stripped.project.pou("Main").body.action("Seq")
    assert seq is not None and seq.language == "sfc"
    assert semantics(SfcBody(chart=seq.body)) == semantics(SfcBody(chart=project.pou("Main").body.action("Seq").body))
    assert all(e.id.startswith("Seq_") for e in steps(seq.body.elements))  # unique beside the POU chart's ids
    sims = [build(p) for p in (project, stripped.project)]
    for scan in range(8):
        for sim in sims:
            for name, value in (("go", scan == 3), ("next", scan == 1), ("back", scan == 6)):
                sim.write(f"Main.{name}", value)
            sim.cycle(1)
        assert [tuple(sim.read(f"Main.{v}") for v in ("a", "b", "I0.X", "I1.X", "M0.X")) for sim in sims] == [
            tuple(sims[0].read(f"Main.{v}") for v in ("a", "b", "I0.X", "I1.X", "M0.X"))
        ] * 2
