"""The panel's widgets online in a real browser (issue 21, items 1 and 2), those the shipped exercises do
not already operate: a numeric input (a number within its limits, an IEC TIME literal), a slider (mouse and
keys), a three-position selector, a normally closed push button, a blinking lamp, a multistate indicator,
a seven-segment display, a TIME display and a trend. Then a breakpoint: at the halt the panel shows the
halt's values and a press waits for the next scan. Each scenario fails on any page or console error."""

from __future__ import annotations

import json
import re
import urllib.request

import pytest
from playwright.sync_api import expect

from .bench_steps import (
    expect_on,
    expect_text,
    go_online,
    new_from_example,
    open_panel,
    simulation_of,
    watch_errors,
    widget,
)
from .steps import new_pou, store_project

pytestmark = pytest.mark.browser

MAIN = {
    "name": "Main",
    "kind": "program",
    "language": "st",
    "declarations": (
        "VAR\n    Setpoint : INT;\n    Doubled : INT;\n    Wait : TIME;\n    Dial : REAL;\n    Mode : INT;\n"
        "    Stop : BOOL := TRUE;\n    Running : BOOL;\nEND_VAR"
    ),
    "body": "Doubled := Setpoint * 2;\nRunning := Stop AND Mode = 2;",
}


def _w(kind: str, wid: str, x: int, y: int, w: int, h: int, **more) -> dict:
    return {"type": kind, "id": wid, "x": x, "y": y, "w": w, "h": h, "label": wid, **more}


DESK = {
    "name": "Desk",
    "width": 800,
    "height": 420,
    "widgets": [
        _w("numeric_input", "setpoint", 20, 20, 100, 30, bind="Main.Setpoint", min=0, max=100),
        _w("seven_segment", "doubled", 160, 20, 120, 50, bind="Main.Doubled", digits=4),
        _w("numeric_input", "wait_in", 20, 100, 120, 30, bind="Main.Wait"),
        _w("numeric_display", "wait", 160, 100, 140, 30, bind="Main.Wait"),
        _w("slider", "dial", 20, 180, 200, 40, bind="Main.Dial", min=0, max=10, step=0.5),
        _w("numeric_display", "dial_shown", 260, 180, 100, 30, bind="Main.Dial", decimals=1),
        _w("trend", "trend", 400, 20, 300, 150, paths=["Main.Dial"], span_s=10, min=0, max=10),
        _w(
            "selector_switch",
            "mode",
            20,
            260,
            120,
            90,
            bind="Main.Mode",
            positions=[{"label": "Off", "value": 0}, {"label": "Hand", "value": 1}, {"label": "Auto", "value": 2}],
        ),
        _w(
            "multistate",
            "mode_shown",
            160,
            260,
            120,
            30,
            bind="Main.Mode",
            states=[{"value": 0, "text": "off"}, {"value": 1, "text": "by hand"}, {"value": 2, "text": "automatic"}],
        ),
        _w("push_button", "stop", 320, 260, 90, 44, bind="Main.Stop", nc=True, color="#c62828"),
        _w("lamp", "running", 440, 260, 30, 30, bind="Main.Running", blink=True, blink_ms=300),
    ],
}


def _type_into(page, widget_id: str, text: str) -> None:
    field = widget(page, widget_id).locator("input")
    field.click()
    field.fill(text)
    field.press("Enter")


def test_inputs_displays_and_the_trend_online(page, server):
    errors = watch_errors(page)
    store_project(server, {"name": "desk", "pous": [MAIN], "panels": [DESK]})
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^desk")).click()
    page.get_by_role("heading", name="desk").wait_for()
    open_panel(page, "Desk")
    go_online(page)

    # a numeric input writes on Enter; the program doubles it onto the seven-segment display
    _type_into(page, "setpoint", "42")
    expect_text(page, "doubled", "84")
    expect_text(page, "setpoint", "42")
    _type_into(page, "setpoint", "500")  # past its max (100): not sent
    page.wait_for_timeout(300)
    expect_text(page, "setpoint", "42")
    expect_text(page, "doubled", "84")
    # an IEC TIME literal typed in, shown back as one
    _type_into(page, "wait_in", "T#2s500ms")
    expect_text(page, "wait", "T#2s500ms")

    # the slider: a click three quarters along is 7.5 (on its 0.5 steps), a key one step more
    slider = widget(page, "dial").get_by_role("slider")
    box = slider.bounding_box()
    page.mouse.click(box["x"] + box["width"] * 0.75, box["y"] + box["height"] / 2)
    expect_text(page, "dial_shown", "7.5")
    slider.focus()
    page.keyboard.press("ArrowRight")
    expect_text(page, "dial_shown", "8.0")
    expect(slider).to_have_attribute("aria-valuenow", "8")
    # the trend samples the dial as the scans go by, drawn by uPlot on its canvas
    trend = widget(page, "trend").locator(".hmi-trend")
    expect(trend.locator("canvas")).to_have_count(1)
    expect(trend).to_have_attribute("data-samples", re.compile(r"^(?:[3-9]|\d{2,})$"))

    # a three-position selector, its position shown by the multistate indicator
    selector = widget(page, "mode").get_by_role("radiogroup")
    for position, value, text in (("Hand", "1", "by hand"), ("Auto", "2", "automatic"), ("Off", "0", "off")):
        selector.get_by_role("radio", name=position).click()
        expect(selector).to_have_attribute("data-value", value)
        expect(selector.get_by_role("radio", name=position)).to_have_attribute("aria-checked", "true")
        expect_text(page, "mode_shown", text)
    selector.get_by_role("radio", name="Auto").click()

    # the normally closed stop button: TRUE until held; the blinking lamp goes out while it is held
    expect_on(page, "stop")
    expect_on(page, "running")
    expect(widget(page, "running").locator(".hmi-blink")).to_have_count(1)
    widget(page, "stop").get_by_role("button").hover()
    page.mouse.down()
    expect_on(page, "stop", False)
    expect_on(page, "running", False)
    expect(widget(page, "running").locator(".hmi-blink")).to_have_count(0)
    page.mouse.up()
    expect_on(page, "running")

    # every action above is an input event of the session, with the panel and widget it came from
    sim = simulation_of(server, "desk")["id"]
    with urllib.request.urlopen(f"{server}/api/simulations/{sim}/inputs", timeout=10) as answer:
        events = [json.loads(line) for line in answer.read().decode().splitlines()]
    assert [(e["path"], e["value"]) for e in events if e["source"] == "panel Desk/setpoint"] == [("Main.Setpoint", 42)]
    assert [e["value"] for e in events if e["source"] == "panel Desk/wait_in"] == ["T#2s500ms"]
    assert [e["value"] for e in events if e["source"] == "panel Desk/stop"] == [False, True]
    assert [e["value"] for e in events if e["source"] == "panel Desk/mode"] == [1, 2, 0, 2]
    assert [e["value"] for e in events if e["source"] == "panel Desk/dial"][-2:] == [7.5, 8]
    assert errors == []


def _continue_to_the_next_halt(page, server: str, scan_count: int) -> None:
    """Continue; the next scan halts at the breakpoint (its diagram comes forward): back to the panel."""
    page.get_by_role("region", name="Debugging").get_by_role("button", name="Continue").click()
    for _ in range(100):
        if simulation_of(server, "halt")["scan_count"] == scan_count:
            break
        page.wait_for_timeout(100)
    else:
        raise AssertionError(f"no halt in scan {scan_count} after 10 s")
    page.get_by_role("status", name="Online state").filter(has_text="Online · halted").wait_for()
    page.get_by_role("tab", name="Tank (panel)").click()


def test_a_press_at_a_breakpoint_waits_for_the_next_scan(page, server):
    """Halted before the tank's only network: the panel shows the halt's values and says so; Auto turned
    there is pending, applied at the start of the next scan (the selector shows it at the next halt), and
    the pump starts in the scan after that, when the network runs with it."""
    errors = watch_errors(page)
    new_from_example(page, server, "tank_filling", "halt")
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile("^Filling")).click()
    page.get_by_role("button", name="Toggle breakpoint on network 1").click()
    open_panel(page, "Tank")
    go_online(page, run=False)
    page.get_by_role("toolbar", name="Simulation").get_by_role("button", name="Run", exact=True).click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · halted").wait_for()
    page.get_by_role("tab", name="Tank (panel)").click()
    expect(page.locator(".hmi-run")).to_contain_text("Halted: the panel shows the values at the halt")
    halted_at = simulation_of(server, "halt")["scan_count"]
    selector = widget(page, "mode").get_by_role("radiogroup")
    selector.get_by_role("radio", name="Auto").click()
    page.wait_for_timeout(300)
    expect(selector).to_have_attribute("data-value", "false")  # still the halt's value
    assert simulation_of(server, "halt")["pending_inputs"] == 1

    _continue_to_the_next_halt(page, server, halted_at + 1)
    expect(selector).to_have_attribute("data-value", "true")  # applied at the start of the next scan
    expect_on(page, "pump", False)  # halted before the network that starts it
    assert simulation_of(server, "halt")["pending_inputs"] == 0
    _continue_to_the_next_halt(page, server, halted_at + 2)
    expect_on(page, "pump")
    sim = simulation_of(server, "halt")["id"]
    with urllib.request.urlopen(f"{server}/api/simulations/{sim}/inputs", timeout=10) as answer:
        events = [json.loads(line) for line in answer.read().decode().splitlines()]
    assert events == [
        {"scan": halted_at + 1, "kind": "panel", "path": "Auto", "value": True, "source": "panel Tank/mode"}
    ]
    assert errors == []


OVEN_GLOBALS = "VAR_GLOBAL\n    Start : BOOL;\n    Heater : BOOL;\n    Hot : BOOL;\n    Done : BOOL;\nEND_VAR"
CONTROL = {
    "name": "Control",
    "kind": "program",
    "language": "st",
    "declarations": "VAR\nEND_VAR",
    "body": "Heater := (Start OR Heater) AND NOT Hot;\nDone := Done OR Hot;",
}
OVEN_PANEL = {
    "name": "Oven",
    "widgets": [
        _w("push_button", "start", 20, 20, 90, 44, bind="Start"),
        _w("symbol", "heater", 140, 20, 60, 50, bind="Heater", shape="heater"),
        _w("lamp", "hot", 230, 20, 30, 30, bind="Hot"),
        _w("lamp", "done", 290, 20, 30, 30, bind="Done"),
        _w("numeric_display", "temp", 20, 100, 120, 30, bind="Oven.Temp", decimals=1),
    ],
}


def test_a_teacher_writes_a_plant_in_the_browser(page, server):
    """Item 3, "teachers write their own plants": a new POU of kind plant, written in ST in the browser, is
    listed under Plants, runs before the program in every scan and closes the loop through the panel: the
    heater warms the oven 1 degree a scan up to 50 (Hot), the program switches it off and latches Done, the
    oven cools down 0.5 a scan to 0."""
    errors = watch_errors(page)
    store_project(server, {"name": "oven", "globals": OVEN_GLOBALS, "pous": [CONTROL], "panels": [OVEN_PANEL]})
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^oven")).click()
    page.get_by_role("heading", name="oven").wait_for()
    new_pou(page, "Oven", language="st", kind="plant")
    page.get_by_label("Oven body").wait_for()
    for label, text in (
        ("Oven declarations", "VAR\n    Temp : REAL;\nEND_VAR"),
        (
            "Oven body",
            "IF Heater THEN\n    Temp := Temp + 1.0;\nELSIF Temp > 0.0 THEN\n    Temp := Temp - 0.5;\nEND_IF;\nHot := Temp >= 50.0;",
        ),
    ):
        page.get_by_label(label).click()
        page.keyboard.press("Control+a")
        page.keyboard.insert_text(text)
    page.keyboard.press("Control+s")
    page.get_by_role("status").filter(has_text="All changes saved").wait_for()
    plants = (
        page.get_by_role("navigation", name="Project tree")
        .locator("section")
        .filter(has=page.get_by_role("heading", name="Plants", exact=True))
    )
    expect(plants.get_by_role("button", name=re.compile("^Oven"))).to_be_visible()
    with urllib.request.urlopen(f"{server}/api/projects/oven", timeout=10) as answer:
        stored = {p["name"]: p for p in json.load(answer)["project"]["pous"]}
    assert (stored["Oven"]["kind"], stored["Oven"]["language"]) == ("plant", "st")

    open_panel(page, "Oven")
    go_online(page)
    widget(page, "start").get_by_role("button").click()
    expect_on(page, "done")  # the plant's heating made Hot TRUE for one scan: the program latched it
    expect_on(page, "heater", False)
    expect_text(page, "temp", "0.0")  # cooled down again, the heater off for good
    assert widget(page, "hot").locator("[data-on]").first.get_attribute("data-on") == "false"
    assert errors == []
