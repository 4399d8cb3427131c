"""Hypothesis strategies for projects that survive a PLCopen round trip exactly.

LD rungs are random series/parallel trees of contacts, compares, coils and boxes
(TON/CTU/ADD with text inputs, contact chains on inputs and outputs to
variables), with jumps and returns at branch ends, in the canonical form the
importer rebuilds (see docs/plcopen.md): no empty branch, no branch that is a
lone parallel, and a parallel with a branch that ends in a jump/return is the
last element of its series list. FBD networks are random wired node sets.
"""

from __future__ import annotations

from hypothesis import strategies as st

from ladderlab.model import (
    Block,
    Box,
    Coil,
    Compare,
    Connector,
    Contact,
    Continuation,
    FbdBody,
    FbdComment,
    FbdJump,
    FbdNetwork,
    FbdReturn,
    InputNode,
    Jump,
    LdBody,
    LdNetwork,
    OutputNode,
    Parallel,
    PinFlags,
    PinRef,
    Position,
    Pou,
    Project,
    Return,
    Task,
    Wire,
)

names = st.sampled_from(["Start", "Stop", "Motor", "Lamp", "A1", "b_2", "x", "Y", "Run", "Fault"])
operands = st.one_of(names, st.sampled_from(["T#5s", "16#FF", "TRUE", "%IX0.1", "T1.Q", "x + 1"]))
comments = st.none() | st.text(st.characters(codec="utf-8", exclude_categories=["Cs", "Cc"]), max_size=20)
labels = st.none() | st.sampled_from(["L1", "Again", "10"])


class Ids:
    """Unique element ids within one drawn project (ids must be unique per POU)."""

    def __init__(self) -> None:
        self.n = 0

    def __call__(self) -> str:
        self.n += 1
        return f"e{self.n}"


def _ends_dead(series: list) -> bool:
    """Does every path through the series end in a jump or return?"""
    if not series:
        return False
    last = series[-1]
    if isinstance(last, (Jump, Return)):
        return True
    return isinstance(last, Parallel) and all(_ends_dead(b) for b in last.branches)


def _has_dead_branch(item) -> bool:
    return isinstance(item, Parallel) and any(_ends_dead(b) for b in item.branches)


@st.composite
def ld_leaf(draw, ids: Ids, depth: int):
    kind = draw(st.sampled_from(["contact", "contact", "coil", "compare", "box"]))
    if kind == "contact":
        return Contact(id=ids(), var=draw(names), mode=draw(st.sampled_from(["no", "nc", "p", "n"])))
    if kind == "coil":
        return Coil(
            id=ids(), var=draw(names), mode=draw(st.sampled_from(["normal", "negated", "set", "reset", "p", "n"]))
        )
    if kind == "compare":
        return Compare(
            id=ids(),
            op=draw(st.sampled_from(["GT", "GE", "EQ", "LE", "LT", "NE"])),
            left=draw(operands),
            right=draw(operands),
        )
    call = draw(st.sampled_from(["TON", "CTU", "ADD"]))
    if call == "ADD":  # no BOOL input: power always enters EN
        return Box(
            id=ids(),
            call="ADD",
            en=True,
            inputs={"IN1": draw(operands), "IN2": draw(operands)},
            outputs=draw(st.sampled_from([{}, {"OUT": "x"}])),
        )
    en = draw(st.booleans())
    side = draw(ld_series(ids, depth - 1, dead=False)) if depth > 0 and draw(st.booleans()) else None
    if call == "TON":
        inputs: dict = {"PT": draw(operands)}
        if en:
            inputs["IN"] = side if side is not None else draw(operands)
        outputs = draw(st.sampled_from([{}, {"ET": "Elapsed"}, {"Q": "Done", "ET": "t"}]))
    else:
        inputs = {"PV": draw(operands)}
        if side is not None:
            inputs["R"] = side
        outputs = draw(st.sampled_from([{}, {"CV": "Count"}]))
    return Box(id=ids(), call=call, instance=draw(names), en=en, inputs=inputs, outputs=outputs)


@st.composite
def ld_series(draw, ids: Ids, depth: int, dead: bool = True, min_size: int = 0):
    """A canonical series list; ``dead`` allows a jump/return at its end."""
    items = []
    for _ in range(draw(st.integers(min_size, 4))):
        if depth > 0 and draw(st.integers(0, 3)) == 0:
            branches = draw(st.lists(ld_series(ids, depth - 1, dead=dead, min_size=1), min_size=2, max_size=3))
            branches = [b for b in branches if not (len(b) == 1 and isinstance(b[0], Parallel))]
            if len(branches) < 2:
                continue
            items.append(Parallel(id=ids(), branches=branches))
            if _has_dead_branch(items[-1]):
                return items
        else:
            items.append(draw(ld_leaf(ids, depth)))
    if dead and draw(st.integers(0, 4)) == 0:
        items.append(
            Jump(id=ids(), target=draw(st.sampled_from(["L1", "Again"]))) if draw(st.booleans()) else Return(id=ids())
        )
    return items


@st.composite
def ld_bodies(draw, ids: Ids | None = None):
    ids = ids or Ids()
    networks = []
    for _ in range(draw(st.integers(0, 3))):
        networks.append(
            LdNetwork(id=ids(), label=draw(labels), comment=draw(comments), elements=draw(ld_series(ids, 2)))
        )
    return LdBody(networks=networks)


_coordinates = st.integers(-400, 900).map(float) | st.sampled_from([0.5, 12.25, 100.1, 33.3])


@st.composite
def fbd_bodies(draw, ids: Ids | None = None):
    ids = ids or Ids()
    networks = []
    for _ in range(draw(st.integers(0, 2))):
        nodes = []
        for _ in range(draw(st.integers(0, 5))):
            pos = draw(st.none() | st.builds(Position, x=_coordinates, y=_coordinates))
            kind = draw(
                st.sampled_from(["block", "block", "input", "output", "jump", "return", "conn", "cont", "comment"])
            )
            if kind == "block":
                flags = st.builds(PinFlags, negated=st.booleans(), edge=st.sampled_from([None, "rising", "falling"]))
                nodes.append(
                    Block(
                        id=ids(),
                        pos=pos,
                        call=draw(st.sampled_from(["ADD", "TON", "AND", "Vendor"])),
                        instance=draw(st.none() | names),
                        en=draw(st.booleans()),
                        pins=draw(
                            st.none() | st.dictionaries(st.sampled_from(["IN1", "IN", "Q", "PT"]), flags, max_size=2)
                        ),
                    )
                )
            elif kind == "input":
                nodes.append(InputNode(id=ids(), pos=pos, expr=draw(operands)))
            elif kind == "output":
                nodes.append(
                    OutputNode(
                        id=ids(),
                        pos=pos,
                        var=draw(names),
                        mode=draw(st.sampled_from(["normal", "negated", "set", "reset", "p", "n"])),
                    )
                )
            elif kind == "jump":
                nodes.append(FbdJump(id=ids(), pos=pos, target="L1"))
            elif kind == "return":
                nodes.append(FbdReturn(id=ids(), pos=pos))
            elif kind == "comment":  # issue 28: free comment boxes keep their text, place and size
                size = draw(st.none() | st.integers(10, 400).map(float))
                nodes.append(
                    FbdComment(
                        id=ids(), pos=pos, text=(draw(comments) or "").strip(), width=size, height=size and size / 2
                    )
                )
            else:
                cls = Connector if kind == "conn" else Continuation
                nodes.append(cls(id=ids(), pos=pos, name=draw(st.sampled_from(["c1", "c2"]))))
        sources = [n for n in nodes if isinstance(n, (Block, InputNode, Continuation))]
        sinks = [n for n in nodes if not isinstance(n, (InputNode, Continuation, FbdComment))]
        wires = []
        if sources and sinks:
            for _ in range(draw(st.integers(0, 4))):
                source, sink = draw(st.sampled_from(sources)), draw(st.sampled_from(sinks))
                from_pin = (
                    draw(st.sampled_from(["OUT", "Q", *(["ENO"] if getattr(source, "en", False) else [])]))
                    if isinstance(source, Block)
                    else "OUT"
                )
                to_pin = (
                    draw(st.sampled_from(["IN1", "IN2", "IN", *(["EN"] if getattr(sink, "en", False) else [])]))
                    if isinstance(sink, Block)
                    else "IN"
                )
                wire = Wire(from_=PinRef(node=source.id, pin=from_pin), to=PinRef(node=sink.id, pin=to_pin))
                if wire not in wires:
                    wires.append(wire)
        order = draw(st.none() | st.permutations([n.id for n in nodes]).map(lambda ids_: ids_[:3] or None))
        networks.append(
            FbdNetwork(id=ids(), label=draw(labels), comment=draw(comments), nodes=nodes, wires=wires, order=order)
        )
    return FbdBody(networks=networks)


DECLARATIONS = [
    "",
    "VAR\n    x : INT;\nEND_VAR",
    "VAR_INPUT\n    a, b : BOOL;  (* two inputs *)\nEND_VAR\nVAR_OUTPUT\n    q : BOOL := TRUE;\nEND_VAR",
    "VAR CONSTANT\n    Limit : INT := 10;\nEND_VAR\nVAR RETAIN\n    Count : DINT;\nEND_VAR",
    "VAR\n    arr : ARRAY [1..3] OF INT := [1, 2, 3];\n    s : STRING[20] := 'hi';\n    t : TIME := T#1s;\n"
    "    p : Point := (x := 1, y := 2);\n    r : INT (0..100);\nEND_VAR",
    "VAR_INPUT\n    clk : BOOL R_EDGE;\nEND_VAR\nVAR_IN_OUT\n    io : INT;\nEND_VAR\n"
    "VAR_TEMP\n    tmp : REAL;\nEND_VAR",
    "VAR_EXTERNAL\n    g : INT;\nEND_VAR\nVAR\n    t1 AT %QX0.1 : BOOL;\n    c : (Red, Green := 5);\nEND_VAR",
]
TYPES = [
    "",
    "TYPE\n    Color : (Red, Green, Blue) := Green;\nEND_TYPE",
    "TYPE\n    Point : STRUCT\n        x : INT;\n        y : INT := 2;\n    END_STRUCT;\n    Small : INT (0..9);"
    "\n    Row : ARRAY [0..7] OF BYTE;\nEND_TYPE",
]
GLOBALS = [
    "",
    "VAR_GLOBAL\n    g : INT;\nEND_VAR",
    "VAR_GLOBAL CONSTANT\n    Max : INT := 5;\nEND_VAR\nVAR_GLOBAL\n    Start AT %IX0.0 : BOOL;  (* button *)\nEND_VAR",
]
ST_BODIES = ["", "x := x + 1;", "\n\n  IF a THEN\r\n    q := b;\r\n  END_IF;", "s := 'END_PROGRAM <&>';\n\nx := 2;"]


@st.composite
def pous(draw, name: str):
    language = draw(st.sampled_from(["st", "ld", "fbd"]))
    kind = draw(st.sampled_from(["program", "function_block", "function"]))
    body = {"st": st.sampled_from(ST_BODIES), "ld": ld_bodies(), "fbd": fbd_bodies()}[language]
    return Pou(
        name=name,
        kind=kind,
        language=language,
        return_type=draw(st.sampled_from(["INT", "BOOL", "STRING[10]", "TIME_OF_DAY"])) if kind == "function" else None,
        declarations=draw(st.sampled_from(DECLARATIONS)),
        body=draw(body),
    )


@st.composite
def projects(draw):
    pou_names = draw(st.lists(st.sampled_from(["Main", "Helper", "Fb1", "Calc"]), unique=True, max_size=3))
    pou_list = [draw(pous(name)) for name in pou_names]
    programs = [p.name for p in pou_list if p.kind == "program"]
    tasks = [
        Task(
            name=f"T{i}",
            interval=draw(st.sampled_from(["T#10ms", "T#1s", "T#100ms"])),
            priority=draw(st.integers(0, 10)),
            programs=draw(st.lists(st.sampled_from(programs), max_size=2, unique=True)) if programs else [],
        )
        for i in range(draw(st.integers(0, 2)))
    ]
    return Project(
        name=draw(st.sampled_from(["demo", "plant 1", "x"])),
        types=draw(st.sampled_from(TYPES)),
        globals=draw(st.sampled_from(GLOBALS)),
        pous=pou_list,
        tasks=tasks,
    )
