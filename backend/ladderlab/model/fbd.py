"""Function block diagram model: networks as graphs of nodes and wires.

Positions are layout hints only; execution order comes from the wiring (and the
optional ``order`` list where the wiring leaves it open).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import ConfigDict, Field

from .base import Model
from .ld import CoilMode


class Position(Model):
    """Finite coordinates only: NaN/inf would not survive the JSON project files."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    x: float
    y: float


class PinFlags(Model):
    model_config = ConfigDict(extra="forbid")

    negated: bool = False
    edge: Literal["rising", "falling"] | None = None


class _Node(Model):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1)
    pos: Position | None = None


class Block(_Node):
    type: Literal["block"] = "block"
    call: str
    instance: str | None = None
    en: bool = False
    pins: dict[str, PinFlags] | None = None


class InputNode(_Node):
    type: Literal["input"] = "input"
    expr: str = Field(description="A variable or literal in ST operand syntax.")


class OutputNode(_Node):
    type: Literal["output"] = "output"
    var: str
    mode: CoilMode = "normal"


class FbdJump(_Node):
    type: Literal["jump"] = "jump"
    target: str


class FbdReturn(_Node):
    type: Literal["return"] = "return"


class FbdLabel(_Node):
    """A jump target on a CFC chart (CODESYS's CFC label): the chart's jumps to ``name`` go on at its execution
    order number. FBD labels its networks instead (``FbdNetwork.label``), so an FBD network refuses one."""

    type: Literal["label"] = "label"
    name: str


class Connector(_Node):
    type: Literal["connector"] = "connector"
    name: str


class Continuation(_Node):
    type: Literal["continuation"] = "continuation"
    name: str


class FbdComment(_Node):
    """A free comment box (issue 28): text drawn at ``pos`` in a box of ``width`` x ``height`` (None: as the
    text needs); it takes no part in the logic (no pins, no wires, not in the evaluation order)."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    type: Literal["comment"] = "comment"
    text: str = ""
    width: float | None = Field(default=None, gt=0)
    height: float | None = Field(default=None, gt=0)


#: The elements of a CFC chart that have an execution order number (CFC-02; input nodes are read where used): the
#: lowering orders them (ir/fbd_order.py); the editor's copy (frontend/src/fbd/order.ts) is checked by its test.
EXECUTED_ELEMENTS: tuple[str, ...] = ("block", "output", "jump", "label", "return")

FbdNode = Annotated[
    Block | InputNode | OutputNode | FbdJump | FbdReturn | FbdLabel | Connector | Continuation | FbdComment,
    Field(discriminator="type"),
]


class PinRef(Model):
    model_config = ConfigDict(extra="forbid")

    node: str
    pin: str


class Wire(Model):
    """A connection from an output pin to an input pin (``from`` is a Python keyword, hence the alias)."""

    model_config = ConfigDict(extra="forbid", populate_by_name=True, serialize_by_alias=True)

    from_: PinRef = Field(alias="from")
    to: PinRef


class FbdNetwork(Model):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1)
    label: str | None = None
    comment: str | None = None
    nodes: list[FbdNode] = Field(default_factory=list)
    wires: list[Wire] = Field(default_factory=list)
    order: list[str] | None = Field(
        default=None, description="Node ids fixing the execution order where the wiring leaves it open."
    )


class FbdBody(Model):
    model_config = ConfigDict(extra="forbid")

    networks: list[FbdNetwork] = Field(default_factory=list)

    def calls(self) -> set[str]:
        """The names (upper case) of the functions and FB types the blocks call: the body's edges of the call graph."""
        return {node.call.upper() for n in self.networks for node in n.nodes if isinstance(node, Block)}
