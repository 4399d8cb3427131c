"""Two OpenPLC Editor examples (../shared/external/openplc-examples), hand-translated until PLCopen import exists.

The translations keep the original names, wiring and (for FBD) positions; expected traces are derived
from the IEC timer semantics in the docstrings, not recorded from a run. The XML is read to check the
translation still matches the file (skipped when ../shared/external is absent).
"""

from __future__ import annotations

import re

from tests.ir.diagram_support import blk, box, coil, contact, fbd_pou, inp, ld_pou, net, out, rung, simulate
from tests.support import external


def test_openplc_blink_ld():
    """Blink: ``--|/ blink_led|-- TON0(PT 500 ms) -- TOF0(PT 500 ms) --( blink_led )``, task T#20ms.

    The original draws EN from the rail and ENO to the right rail; both boxes always run, so power
    through IN/Q is the same rung. With scans at 20, 40, ... ms: TON0 starts at 20 ms and its Q rises at
    520 ms; blink_led then holds TOF0's Q, which falls 500 ms after its IN fell (540 ms): at 1040 ms.
    The next TON0 run starts at 1060 ms: the square wave is on for [520, 1040) and [1560, 2080) ms.
    """
    xml = external("openplc-examples", "examples", "Blink", "plc.xml").read_text()
    assert re.findall(r'typeName="(\w+)" instanceName="(\w+)"', xml) == [("TON", "TON0"), ("TOF", "TOF0")]
    assert xml.count("<expression>T#500ms</expression>") == 2 and 'negated="true"' in xml
    blink = ld_pou(
        "Blink",
        "VAR blink_led : BOOL; TON0 : TON; TOF0 : TOF; END_VAR",
        rung(
            "n",
            contact("5", "blink_led", "nc"),
            box("3", "TON", "TON0", PT="T#500ms"),
            box("4", "TOF", "TOF0", PT="T#500ms"),
            coil("6", "blink_led"),
        ),
    )
    sim = simulate(blink, interval="T#20ms")
    on = []
    for _ in range(110):
        sim.cycle(1)
        if sim.read("Blink.blink_led"):
            on.append(round(sim.time_ms))
    assert on == list(range(520, 1040, 20)) + list(range(1560, 2080, 20))


def test_openplc_traffic_light_fbd():
    """Trafic_light: three TOFs chained through F_TRIGs - red 6 s, then green 6 s, then orange 4 s.

    First_cycle (initially TRUE) starts red via the OR and is cleared in the first scan. A TOF holds Q
    for PT after its IN fell in the following scan. F_TRIG2 (drawn low) runs after red's output node, so
    it sees red fall in the same scan; F_TRIG1 and F_TRIG0 are drawn above the TOFs driving green and
    orange, so they run first and see those lamps fall one scan later. With 100 ms scans:
    red [100, 6200), green [6200, 12300), orange [12400, 16500), red again from 16600.
    """
    xml = external("openplc-examples", "examples", "Traffic_Light_FBD", "plc.xml").read_text()
    assert sorted(re.findall(r'typeName="(\w+)" instanceName="(\w+)"', xml)) == [
        ("F_TRIG", "F_TRIG0"),
        ("F_TRIG", "F_TRIG1"),
        ("F_TRIG", "F_TRIG2"),
        ("TOF", "TOF0"),
        ("TOF", "TOF1"),
        ("TOF", "TOF2"),
    ]
    declarations = (
        "VAR TOF0, TOF1, TOF2 : TOF; END_VAR VAR O_LEDRed, O_LEDOrange, O_LEDGreen : BOOL; "
        "First_cycle : BOOL := TRUE; END_VAR VAR F_TRIG0, F_TRIG1, F_TRIG2 : F_TRIG; END_VAR"
    )
    nodes = [
        blk("2", "TOF", "TOF0", x=590, y=320),
        inp("4", "T#6s", 510, 410),
        out("6", "O_LEDRed", x=970, y=340),
        blk("1", "TOF", "TOF1", x=550, y=530),
        inp("3", "T#4s", 410, 630),
        out("5", "O_LEDOrange", x=870, y=540),
        blk("7", "TOF", "TOF2", x=380, y=770),
        inp("8", "T#6s", 270, 840),
        out("9", "O_LEDGreen", x=880, y=780),
        inp("17", "O_LEDGreen", 70, 550),
        inp("20", "O_LEDRed", 50, 790),
        inp("23", "O_LEDOrange", 80, 340),
        inp("55", "First_cycle", 260, 390),
        out("56", "First_cycle", x=460, y=960),
        inp("57", "FALSE", 250, 960),
        blk("67", "OR", x=450, y=320),
        blk("68", "F_TRIG", "F_TRIG0", x=290, y=320),
        blk("10", "F_TRIG", "F_TRIG1", x=280, y=530),
        blk("11", "F_TRIG", "F_TRIG2", x=240, y=770),
    ]
    wires = [
        ("67.OUT", "2.IN"),
        ("4.OUT", "2.PT"),
        ("2.Q", "6.IN"),
        ("10.Q", "1.IN"),
        ("3.OUT", "1.PT"),
        ("1.Q", "5.IN"),
        ("11.Q", "7.IN"),
        ("8.OUT", "7.PT"),
        ("7.Q", "9.IN"),
        ("57.OUT", "56.IN"),
        ("68.Q", "67.IN1"),
        ("55.OUT", "67.IN2"),
        ("23.OUT", "68.CLK"),
        ("17.OUT", "10.CLK"),
        ("20.OUT", "11.CLK"),
    ]
    light = fbd_pou("Trafic_light", declarations, net("main", nodes, wires))
    sim = simulate(light, interval="T#100ms")
    lamps = {"O_LEDRed": [], "O_LEDGreen": [], "O_LEDOrange": []}
    for _ in range(200):
        sim.cycle(1)
        for name, times in lamps.items():
            if sim.read(f"Trafic_light.{name}"):
                times.append(round(sim.time_ms))
    assert lamps == {
        "O_LEDRed": list(range(100, 6200, 100)) + list(range(16600, 20100, 100)),
        "O_LEDGreen": list(range(6200, 12300, 100)),
        "O_LEDOrange": list(range(12400, 16500, 100)),
    }
