"""Imports that look like their originals (issue 28). Free comment boxes of OpenPLC and Beremiz drawings: in FBD
each becomes a comment node where it was and as large as it was, in LD a comment network of its own where it
stands; none is merged into a network comment, and they come back the same through LadderLab's PLCopen export.
LD rungs keep the original's left-to-right order. Expected texts, places, sizes and orders are those in the
fixtures' XML (../shared/external), read by hand."""

from __future__ import annotations

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model.fbd import FbdComment
from ladderlab.model.project import Project
from tests.interchange.plcopen_helpers import ld_project
from tests.support import external

TRAFFIC = ("openplc-examples", "examples", "Traffic_Light_FBD", "plc.xml")
BLINK = ("openplc-examples", "examples", "Blink", "plc.xml")
FIRST_STEPS = ("beremiz-examples", "exemples", "first_steps", "plc.xml")
#: The comment boxes of Traffic_Light_FBD/plc.xml as its XML draws them: first line, x, y, width, height.
TRAFFIC_COMMENTS = [
    ("PLC program to control a traffic light with an Arduino Uno as stand alone device.", 50, 50, 1050, 150),
    ("Activation of the Red lamp", 50, 230, 1040, 40),
    ("Activation of the orange lamp", 50, 460, 1020, 40),
    ("Activation of the green lamp", 50, 670, 1010, 40),
    ("Turn off first_cycle", 50, 890, 1010, 40),
]


def imported(*parts: str) -> Project:
    path = external(*parts)
    if not path.is_file():
        pytest.skip(f"{path} is not there (../shared/external)")
    result = import_plcopen(path.read_bytes(), file=path.name)
    assert result.project is not None
    return result.project


def comments(project: Project, pou: str) -> list[tuple[str, float, float, float | None, float | None]]:
    body = project.pou(pou).body
    return [
        (node.text.splitlines()[0], node.pos.x, node.pos.y, node.width, node.height)
        for network in body.networks
        for node in network.nodes
        if isinstance(node, FbdComment)
    ]


def round_trip(project: Project) -> Project:
    result = import_plcopen(export_plcopen(project))
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.project


def test_openplc_fbd_comment_boxes_keep_their_text_place_and_size():
    project = imported(*TRAFFIC)
    pou = next(p.name for p in project.pous if p.language == "fbd")
    expected = TRAFFIC_COMMENTS
    assert comments(project, pou) == expected
    assert all(network.comment is None for network in project.pou(pou).body.networks)
    assert comments(round_trip(project), pou) == expected


def test_beremiz_fbd_comment_box_and_its_lines():
    project = imported(*FIRST_STEPS)
    found = [
        node
        for pou in project.pous
        if pou.language == "fbd"
        for network in pou.body.networks
        for node in network.nodes
        if isinstance(node, FbdComment)
    ]
    assert [(n.pos.x, n.pos.y, n.width, n.height) for n in found] == [(620, 130, 569, 365)]
    assert found[0].text.splitlines()[:3] == [
        "In this example function block with the same functionality ",  # as typed, trailing blank and all
        "is created using all five IEC 61131-3 programing languages:",
        "- IL;",
    ]


def test_openplc_ld_comment_box_is_a_comment_network_above_the_rung():
    project = imported(*BLINK)
    networks = next(p for p in project.pous if p.language == "ld").body.networks
    assert [(bool(n.elements), (n.comment or "")[:40]) for n in networks] == [
        (False, "This example cascades two timers (TON an"),
        (True, ""),
    ]
    again = next(p for p in round_trip(project).pous if p.language == "ld").body.networks
    assert [(n.elements == [], n.comment) for n in again] == [(n.elements == [], n.comment) for n in networks]


def test_two_comment_boxes_between_rungs_are_two_comment_networks_in_drawing_order():
    """Issue 28: nothing merged - each box keeps its own place between the rungs."""
    data = ld_project(
        '<leftPowerRail localId="1" height="200" width="10"><position x="0" y="0"/>'
        '<connectionPointOut formalParameter=""><relPosition x="10" y="10"/></connectionPointOut></leftPowerRail>'
        '<comment localId="7" height="20" width="100"><position x="0" y="50"/>'
        "<content><xhtml:p>first note</xhtml:p></content></comment>"
        '<comment localId="8" height="20" width="100"><position x="300" y="60"/>'
        "<content><xhtml:p>second note</xhtml:p></content></comment>"
        + _rung(2, "a", "q1", 10)
        + _rung(4, "b", "q2", 100)
    )
    result = import_plcopen(data)
    networks = result.project.pous[0].body.networks
    assert [(n.comment, [e.type for e in n.elements]) for n in networks] == [
        (None, ["contact", "coil"]),
        ("first note", []),
        ("second note", []),
        (None, ["contact", "coil"]),
    ]


def _rung(local: int, contact: str, coil: str, y: int) -> str:
    return (
        f'<contact localId="{local}" height="20" width="20" negated="false"><position x="50" y="{y}"/>'
        f'<connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="1"/></connectionPointIn>'
        f'<connectionPointOut><relPosition x="20" y="10"/></connectionPointOut><variable>{contact}</variable></contact>'
        f'<coil localId="{local + 1}" height="20" width="20" negated="false"><position x="150" y="{y}"/>'
        f'<connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="{local}"/></connectionPointIn>'
        f'<connectionPointOut><relPosition x="20" y="10"/></connectionPointOut><variable>{coil}</variable></coil>'
    )


def test_openplc_ld_rungs_read_left_to_right_as_drawn():
    """Blink draws contact (x 180) -> TON (350) -> TOF (640) -> coil (820) on an EN chain from the left rail;
    Arduino_7_Segments the same and then contact -> CTU -> coil."""
    for parts, rungs in (
        (BLINK, [["contact blink_led", "box TON", "box TOF", "coil blink_led"]]),
        (
            ("openplc-examples", "examples", "Arduino_7_Segments", "plc.xml"),
            [
                ["contact square_wave", "box TON", "box TOF", "coil square_wave"],
                ["contact square_wave", "box CTU", "coil ctu_reset"],
            ],
        ),
    ):
        project = imported(*parts)
        networks = next(p for p in project.pous if p.language == "ld").body.networks
        drawn = [
            [f"{e.type} {getattr(e, 'var', None) or getattr(e, 'call', '')}" for e in n.elements]
            for n in networks
            if n.elements
        ]
        assert drawn == rungs
