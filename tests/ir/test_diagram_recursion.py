"""POU-02 across languages: a call cycle through LD boxes or FBD blocks is a check error, not a runtime crash."""

from __future__ import annotations

from ladderlab.ir.lower_project import lower_project
from ladderlab.model import fbd, ld
from ladderlab.model.project import Pou, Project

MAIN = Pou(name="Main", kind="program", language="st", declarations="VAR y : INT; END_VAR", body="y := F(1);")


def errors(*pous: Pou) -> list[str]:
    result = lower_project(Project(name="p", pous=[*pous, MAIN]))
    assert result.program is None
    return [d.format() for d in result.diagnostics if d.severity == "error"]


def ld_function(name: str, calls: str) -> Pou:
    inputs = {"IN1": "x", "IN2": "1"} if calls == "ADD" else {"x": "x"}
    box = ld.Box(id="b1", call=calls, en=True, inputs=inputs, outputs={"OUT": name})
    return Pou(
        name=name,
        kind="function",
        language="ld",
        return_type="INT",
        declarations="VAR_INPUT x : INT; END_VAR",
        body=ld.LdBody(networks=[ld.LdNetwork(id="n1", elements=[box])]),
    )


def test_an_ld_function_calling_itself_from_a_box_is_reported():
    assert errors(ld_function("F", "F")) == [
        "F/body, POU F: error ST-RECURSION: recursive call F -> F: POUs must not call themselves"
    ]


def test_a_cycle_through_an_fbd_block_and_an_st_function_is_reported_once():
    wire = fbd.Wire.model_validate({"from": {"node": "i", "pin": "OUT"}, "to": {"node": "g", "pin": "x"}})
    back = fbd.Wire.model_validate({"from": {"node": "g", "pin": "OUT"}, "to": {"node": "o", "pin": "IN"}})
    f = Pou(
        name="F",
        kind="function",
        language="fbd",
        return_type="INT",
        declarations="VAR_INPUT x : INT; END_VAR",
        body=fbd.FbdBody(
            networks=[
                fbd.FbdNetwork(
                    id="n1",
                    nodes=[
                        fbd.InputNode(id="i", expr="x"),
                        fbd.Block(id="g", call="G"),
                        fbd.OutputNode(id="o", var="F"),
                    ],
                    wires=[wire, back],
                )
            ]
        ),
    )
    g = Pou(
        name="G",
        kind="function",
        language="st",
        return_type="INT",
        declarations="VAR_INPUT x : INT; END_VAR",
        body="G := F(x);",
    )
    assert errors(f, g) == [
        "F/body, POU F: error ST-RECURSION: recursive call F -> G -> F: POUs must not call themselves"
    ]


def test_calling_standard_functions_and_other_pous_is_no_cycle():
    result = lower_project(Project(name="p", pous=[ld_function("F", "ADD"), MAIN]))
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
