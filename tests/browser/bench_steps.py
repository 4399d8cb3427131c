"""What the lab bench scenarios do in the browser: open an example from the project picker, go online,
operate a panel's widgets with the mouse, and read what its widgets show (their data-* attributes)."""

from __future__ import annotations

import json
import re
import urllib.request

from playwright.sync_api import expect


def watch_errors(page) -> list[str]:
    """Every page error and console error from now on (a scenario ends by asserting there was none)."""
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(f"page error: {error}"))
    page.on("console", lambda message: errors.append(message.text) if message.type == "error" else None)
    return errors


def new_from_example(page, server: str, example: str, name: str, start: str = "solution") -> None:
    """Creates project ``name`` from the shipped ``example`` through "New from example"; it opens."""
    page.goto(server)
    page.get_by_role("button", name="New from example").click()
    form = page.get_by_role("form", name="New from example")
    form.get_by_label("Example", exact=True).select_option(example)
    form.get_by_label("Start from").select_option(start)
    form.get_by_label("New project name").fill(name)
    form.get_by_role("button", name="Create").click()
    page.get_by_role("heading", name=name, exact=True).wait_for()


def open_panel(page, name: str) -> None:
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile(f"^{name}")).filter(
        has_text="HMI"
    ).click()
    page.locator(f'svg.hmi-canvas[data-panel="{name}"]').wait_for()


def go_online(page, run: bool = True) -> None:
    bar = page.get_by_role("toolbar", name="Simulation")
    bar.get_by_role("button", name="Compile & simulate").click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    if run:
        bar.get_by_role("button", name="Run", exact=True).click()
        page.get_by_role("status", name="Online state").filter(has_text="Online · running").wait_for()


def widget(page, widget_id: str):
    return page.locator(f'[data-widget="{widget_id}"]')


def press(page, widget_id: str, hold_ms: int = 80) -> None:
    """A real mouse press and release on a push button."""
    button = widget(page, widget_id).get_by_role("button")
    button.hover()
    page.mouse.down()
    page.wait_for_timeout(hold_ms)
    page.mouse.up()


def lamp(page, widget_id: str):
    """The element whose data-on says whether a lamp (or switch, or symbol) is on."""
    return widget(page, widget_id).locator("[data-on]").first


def expect_on(page, widget_id: str, on: bool = True, timeout: int = 20_000) -> None:
    expect(lamp(page, widget_id)).to_have_attribute("data-on", "true" if on else "false", timeout=timeout)


def expect_text(page, widget_id: str, text: str, timeout: int = 20_000) -> None:
    expect(widget(page, widget_id).locator("[data-text]").first).to_have_attribute("data-text", text, timeout=timeout)


def text_of(page, widget_id: str) -> str:
    return widget(page, widget_id).locator("[data-text]").first.get_attribute("data-text") or ""


def place_of(page, widget_id: str) -> str:
    """The widget's transform: where its motion put it."""
    return widget(page, widget_id).get_attribute("transform") or ""


def set_speed(page, panel: str, scale: str) -> None:
    page.get_by_role("toolbar", name=f"Panel {panel} controls").get_by_label("Time scale").select_option(scale)


def run_until(page, panel: str, what: str) -> None:
    bar = page.get_by_role("toolbar", name=f"Panel {panel} controls")
    bar.get_by_label("Run until").fill(what)
    bar.get_by_role("button", name="Run until").click()


def simulation_of(server: str, project: str) -> dict:
    with urllib.request.urlopen(f"{server}/api/simulations", timeout=10) as response:
        return next(s for s in json.load(response) if s["project"] == project)


def open_example_online(page, server: str, example: str, name: str, panel: str, start: str = "solution") -> list[str]:
    """New from example, its panel, online and running; returns the page's errors from then on."""
    errors = watch_errors(page)
    new_from_example(page, server, example, name, start)
    open_panel(page, panel)
    go_online(page)
    return errors
