"""Operator panels (HMI): widgets on a canvas, each bound to variables of the running program.

A panel is stored as ``hmi/<name>.json`` in the project folder (sorted keys, defaults left out).
Widgets are placed in pixels (``x``, ``y``, ``w``, ``h``) on a canvas of ``width`` x ``height``;
``grid`` is the snap of the editor (0: free placement). A binding is a variable path as the watch
list takes it (``Start``, ``Main.Level``, ``Tank.Valve.Q``) or a direct address (``%IX0.0``: the
variable declared AT it); a binding the program lacks is an error of the build (simulation/build.py).
Input widgets send their actions as panel input events (applied at the start of the next scan,
docs/architecture.md "Inputs"); every widget can be shown only while a BOOL is TRUE (``visible``) and
moved by a number (``move_x``, ``move_y``), which animates plants: boxes on a conveyor, a door, a
cylinder. docs/hmi.md describes every widget.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import ConfigDict, Field, field_validator, model_validator

from .base import Model

#: A colour as ``#rrggbb``: all a widget's SVG needs, and nothing a browser could misread.
Colour = Annotated[str, Field(pattern=r"^#[0-9a-fA-F]{6}$", description="A colour, #rrggbb.")]
#: A variable path or direct address; at most one line of text.
Binding = Annotated[str, Field(min_length=1, max_length=200, pattern=r"^[^\n\r]+$")]
#: A value a widget writes or compares with: a JSON scalar or IEC literal text.
Literal_ = bool | int | float | str

_ID = r"^[A-Za-z_][A-Za-z0-9_-]{0,63}$"
#: The fields of a widget that hold one variable path (the rename refactoring rewrites them too, st/refactor.py);
#: a motion's path is in ``MOTION_FIELDS``' ``path``, a trend's in its list ``paths``.
PATH_FIELDS = ("bind", "fault", "visible")
MOTION_FIELDS = ("move_x", "move_y")
MAX_CANVAS = 4000
MAX_WIDGETS = 500


class Motion(Model):
    """A move by a variable's value: ``min`` leaves the widget where it is placed, ``max`` moves it by ``distance``
    pixels (negative: left or up), values in between in proportion, values outside held at the ends."""

    model_config = ConfigDict(extra="forbid")

    path: Binding
    min: float = 0.0
    max: float = 100.0
    distance: int = Field(ge=-MAX_CANVAS, le=MAX_CANVAS)

    @model_validator(mode="after")
    def _range(self) -> Motion:
        if not self.max > self.min:
            raise ValueError(f"max ({self.max}) must be greater than min ({self.min})")
        return self


class _Widget(Model):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(pattern=_ID, description="Unique within the panel: the widget's name in the log and in tests.")
    x: int = Field(ge=0, le=MAX_CANVAS)
    y: int = Field(ge=0, le=MAX_CANVAS)
    w: int = Field(ge=4, le=MAX_CANVAS)
    h: int = Field(ge=4, le=MAX_CANVAS)
    label: str = Field(default="", max_length=200, description="The caption shown with the widget.")
    visible: Binding | None = Field(default=None, description="A BOOL: the widget is shown only while it is TRUE.")
    move_x: Motion | None = None
    move_y: Motion | None = None

    def bindings(self) -> list[tuple[str, str]]:
        """Every variable path the widget reads or writes, with the field that holds it (``bind``,
        ``paths[1]``, ``move_x.path``), in field order."""
        found: list[tuple[str, str]] = []
        for field in PATH_FIELDS:
            path = getattr(self, field, None)
            if path:
                found.append((field, path))
        for field in MOTION_FIELDS:
            motion = getattr(self, field)
            if motion is not None:
                found.append((f"{field}.path", motion.path))
        found += [(f"paths[{i}]", path) for i, path in enumerate(getattr(self, "paths", None) or [])]
        return found


class PushButton(_Widget):
    """Momentary: the variable is TRUE while the button is held (FALSE while held when ``nc``)."""

    type: Literal["push_button"]
    bind: Binding
    nc: bool = Field(default=False, description="Normally closed: TRUE while not pressed.")
    color: Colour = "#2e7d32"


class ToggleSwitch(_Widget):
    """Two positions that stay: each click writes the other BOOL value."""

    type: Literal["toggle_switch"]
    bind: Binding


class SwitchPosition(Model):
    model_config = ConfigDict(extra="forbid")

    label: str = Field(max_length=40)
    value: Literal_


class SelectorSwitch(_Widget):
    """A rotary selector of two or three positions; turning it writes the position's value."""

    type: Literal["selector_switch"]
    bind: Binding
    positions: list[SwitchPosition] = Field(min_length=2, max_length=3)


class EmergencyStop(_Widget):
    """A latching mushroom button: pressed it stays pressed until released by a second click (a turn to release).
    Normally closed by default, as safety circuits are: the variable is TRUE while the button is not pressed."""

    type: Literal["emergency_stop"]
    bind: Binding
    nc: bool = True


class Lamp(_Widget):
    """An indicator: ``on_color`` while the BOOL is TRUE (blinking when ``blink``), ``off_color`` while FALSE."""

    type: Literal["lamp"]
    bind: Binding
    on_color: Colour = "#43a047"
    off_color: Colour = "#5f6368"
    blink: bool = False
    blink_ms: int = Field(default=500, ge=100, le=5000, description="Half a blink period.")


class IndicatorState(Model):
    model_config = ConfigDict(extra="forbid")

    value: Literal_
    text: str = Field(max_length=60)
    color: Colour = "#5f6368"


class Multistate(_Widget):
    """A value shown as the text and colour of the first state whose value it equals (else ``default_text``)."""

    type: Literal["multistate"]
    bind: Binding
    states: list[IndicatorState] = Field(min_length=1, max_length=32)
    default_text: str = Field(default="?", max_length=60)


class NumericDisplay(_Widget):
    """A value as text: numbers with ``decimals`` (None: as they come) and ``unit``; TIME and dates as IEC
    literals (T#1s500ms), enumerations by name."""

    type: Literal["numeric_display"]
    bind: Binding
    decimals: int | None = Field(default=None, ge=0, le=6)
    unit: str = Field(default="", max_length=20)


class NumericInput(_Widget):
    """A field that writes the number (or IEC literal: T#2s) typed into it, on Enter."""

    type: Literal["numeric_input"]
    bind: Binding
    min: float | None = None
    max: float | None = None


class Slider(_Widget):
    """Writes its value while dragged (each change a panel input event)."""

    type: Literal["slider"]
    bind: Binding
    min: float = 0.0
    max: float = 100.0
    step: float = Field(default=1.0, gt=0)
    vertical: bool = False


class Bar(_Widget):
    """A level between ``min`` and ``max``, as a bar or a tank; red past an alarm limit."""

    type: Literal["bar"]
    bind: Binding
    min: float = 0.0
    max: float = 100.0
    low_alarm: float | None = None
    high_alarm: float | None = None
    tank: bool = Field(default=False, description="Drawn as a tank with liquid, else as a bar.")
    vertical: bool = True
    color: Colour = "#1e88e5"


class SevenSegment(_Widget):
    """An integer on ``digits`` seven-segment digits (a minus sign takes one)."""

    type: Literal["seven_segment"]
    bind: Binding
    digits: int = Field(default=4, ge=1, le=10)
    color: Colour = "#e53935"


class Label(_Widget):
    """Text on the panel."""

    type: Literal["label"]
    text: str = Field(max_length=400)
    size: int = Field(default=14, ge=6, le=96)
    color: Colour = "#202124"
    bold: bool = False


class Trend(_Widget):
    """The last ``span_s`` seconds of up to four BOOL or numeric variables, one line each."""

    type: Literal["trend"]
    paths: list[Binding] = Field(min_length=1, max_length=4)
    span_s: float = Field(default=10.0, gt=0, le=600)
    min: float | None = None
    max: float | None = None


SymbolShape = Literal[
    "motor", "pump", "fan", "valve", "heater", "conveyor", "cylinder", "box", "siren", "person", "car", "door", "wall"
]


class PlantSymbol(_Widget):
    """A plant symbol whose look shows the bound variable: a BOOL runs or stops it (a motor, pump or fan turns, a
    valve opens, a heater glows, a conveyor's belt moves, a siren sounds); a number sets a cylinder's stroke or a
    door's opening from ``min`` (retracted, closed) to ``max``. ``box``, ``person``, ``car`` and ``wall`` are drawn
    as they are (animate them with ``visible`` and ``move_x``/``move_y``). ``fault``: a BOOL that draws it red."""

    type: Literal["symbol"]
    shape: SymbolShape
    bind: Binding | None = None
    min: float = 0.0
    max: float = 100.0
    fault: Binding | None = None
    color: Colour = "#546e7a"


Widget = Annotated[
    PushButton
    | ToggleSwitch
    | SelectorSwitch
    | EmergencyStop
    | Lamp
    | Multistate
    | NumericDisplay
    | NumericInput
    | Slider
    | Bar
    | SevenSegment
    | Label
    | Trend
    | PlantSymbol,
    Field(discriminator="type"),
]

#: The widgets that send panel input events (the others only show values).
INPUT_WIDGETS = ("push_button", "toggle_switch", "selector_switch", "emergency_stop", "numeric_input", "slider")


class Panel(Model):
    """One operator panel: ``hmi/<name>.json``."""

    model_config = ConfigDict(extra="forbid")

    name: str = Field(pattern=r"^[A-Za-z_][A-Za-z0-9_]{0,63}$", description="The file name (hmi/<name>.json).")
    title: str = Field(default="", max_length=200)
    width: int = Field(default=800, ge=40, le=MAX_CANVAS)
    height: int = Field(default=480, ge=40, le=MAX_CANVAS)
    grid: int = Field(default=10, ge=0, le=200, description="The editor's snap in pixels; 0 places freely.")
    background: Colour = "#eceff1"
    widgets: list[Widget] = Field(default_factory=list, max_length=MAX_WIDGETS)

    @field_validator("widgets")
    @classmethod
    def _unique_ids(cls, widgets: list[_Widget]) -> list[_Widget]:
        seen: set[str] = set()
        for widget in widgets:
            if widget.id in seen:
                raise ValueError(f"two widgets are called {widget.id!r}: widget ids must be unique in a panel")
            seen.add(widget.id)
        return widgets
