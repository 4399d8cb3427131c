"""Hypothesis strategies for random but valid project models."""

from __future__ import annotations

from hypothesis import strategies as st

from ladderlab.model import (
    Block,
    Box,
    Coil,
    Compare,
    Contact,
    FbdBody,
    FbdNetwork,
    GlobalVariableList,
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

identifiers = st.from_regex(r"[A-Z][a-z0-9]{0,6}(_[a-z0-9]{1,4})?", fullmatch=True)
texts = st.text(st.characters(codec="utf-8", exclude_categories=["Cs"]), max_size=30)
operands = st.one_of(identifiers, st.sampled_from(["T#5s", "16#FF", "TRUE", "%IX0.1", "arr[i]", "T1.Q"]))


def _ids():
    counter = iter(range(10**9))
    return st.builds(lambda: f"e{next(counter)}")


def ld_series(depth: int = 2):
    ids = _ids()
    leaf = st.one_of(
        st.builds(Contact, id=ids, var=operands, mode=st.sampled_from(["no", "nc", "p", "n"])),
        st.builds(
            Compare, id=ids, op=st.sampled_from(["GT", "GE", "EQ", "LE", "LT", "NE"]), left=operands, right=operands
        ),
        st.builds(Coil, id=ids, var=identifiers, mode=st.sampled_from(["normal", "negated", "set", "reset", "p", "n"])),
        st.builds(
            Box,
            id=ids,
            call=st.sampled_from(["TON", "ADD", "CTU"]),
            instance=st.none() | identifiers,
            inputs=st.dictionaries(identifiers, operands, max_size=3),
            outputs=st.dictionaries(identifiers, identifiers, max_size=2),
            en=st.booleans(),
        ),
    )
    if depth == 0:
        return st.lists(leaf, max_size=4)
    inner = ld_series(depth - 1)
    element = st.one_of(
        leaf,
        st.builds(Parallel, id=ids, branches=st.lists(inner, min_size=2, max_size=3)),
        st.builds(
            Box,
            id=ids,
            call=st.just("TON"),
            instance=identifiers,
            inputs=st.fixed_dictionaries({"IN": inner, "PT": operands}),
        ),
    )
    tail = st.lists(st.one_of(st.builds(Jump, id=ids, target=identifiers), st.builds(Return, id=ids)), max_size=1)
    return st.tuples(st.lists(element, max_size=4), tail).map(lambda t: t[0] + t[1])


ld_bodies = st.builds(
    LdBody,
    networks=st.lists(
        st.builds(
            LdNetwork, id=identifiers, label=st.none() | identifiers, comment=st.none() | texts, elements=ld_series()
        ),
        max_size=3,
    ),
)

_positions = st.none() | st.builds(Position, x=st.integers(-500, 500).map(float), y=st.integers(0, 900).map(float))
fbd_nodes = st.lists(
    st.one_of(
        st.builds(
            Block,
            id=identifiers,
            call=st.sampled_from(["ADD", "TON", "AND"]),
            instance=st.none() | identifiers,
            en=st.booleans(),
            pos=_positions,
            pins=st.none()
            | st.dictionaries(
                identifiers,
                st.builds(PinFlags, negated=st.booleans(), edge=st.sampled_from([None, "rising", "falling"])),
                max_size=2,
            ),
        ),
        st.builds(InputNode, id=identifiers, expr=operands, pos=_positions),
        st.builds(OutputNode, id=identifiers, var=identifiers, mode=st.sampled_from(["normal", "set", "reset"])),
    ),
    max_size=5,
)
fbd_bodies = st.builds(
    FbdBody,
    networks=st.lists(
        st.builds(
            FbdNetwork,
            id=identifiers,
            label=st.none() | identifiers,
            nodes=fbd_nodes,
            wires=st.lists(
                st.builds(
                    Wire,
                    from_=st.builds(PinRef, node=identifiers, pin=identifiers),
                    to=st.builds(PinRef, node=identifiers, pin=identifiers),
                ),
                max_size=3,
            ),
            order=st.none() | st.lists(identifiers, max_size=3),
        ),
        max_size=2,
    ),
)

declarations = st.sampled_from(
    [
        "",
        "VAR\n    x : INT;\nEND_VAR",
        "(* inputs *)\nVAR_INPUT a, b : BOOL; END_VAR\nVAR_OUTPUT q : BOOL; END_VAR",
        "VAR\n    s : STRING := 'END_VAR';  // tricky\nEND_VAR  (* trailing *)",
    ]
)
st_bodies = st.sampled_from(
    [
        "",
        "x := x + 1;",
        "  (* indented *)\n  IF a THEN q := b; END_IF;",
        "s := 'END_PROGRAM';\n\n\nx := 2;",
        "// only a comment",
    ]
)


il_bodies = st.sampled_from(
    [
        "",
        "LD x\nADD 1\nST x",
        "start: LD a  (* comment *)\n  JMPC start\n\nend:",
        "  CAL t1(IN := a)\n  LD 'END_PROGRAM'",
        "x := 1;",  # an IL POU whose text is not IL yet (being typed): still stored as .il
    ]
)


@st.composite
def pous(draw):
    language = draw(st.sampled_from(["st", "ld", "fbd", "il"]))
    kind = draw(st.sampled_from(["program", "function_block", "function"]))
    body = {"st": st_bodies, "ld": ld_bodies, "fbd": fbd_bodies, "il": il_bodies}[language]
    return Pou(
        name=draw(identifiers),
        kind=kind,
        language=language,
        return_type="INT" if kind == "function" else None,
        declarations=draw(declarations | texts),
        body=draw(body) if language not in ("st", "il") else draw(body | texts),
    )


@st.composite
def projects(draw):
    pou_list = draw(st.lists(pous(), max_size=4, unique_by=lambda p: p.name.upper()))
    return Project(
        name=draw(st.from_regex(r"[a-z][a-z0-9_-]{0,10}", fullmatch=True)),
        types=draw(st.sampled_from(["", "TYPE Color : (Red, Green); END_TYPE"])),
        globals=draw(st.sampled_from(["", "VAR_GLOBAL\n    g : INT;\nEND_VAR"])),
        gvls=draw(
            st.lists(
                st.builds(
                    GlobalVariableList,
                    name=identifiers,
                    qualified_only=st.booleans(),
                    # any text, a pragma-like first line and trailing newlines included: the file keeps it exactly
                    text=st.one_of(
                        texts,
                        st.sampled_from(["", "VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR", "{attribute 'x'}\nVAR_GLOBAL"]),
                    ),
                ),
                max_size=3,
                unique_by=lambda g: g.name.upper(),
            )
        ),
        pous=pou_list,
        tasks=draw(
            st.lists(
                st.builds(
                    Task,
                    name=identifiers,
                    interval=st.sampled_from(["T#10ms", "T#1s"]),
                    priority=st.integers(0, 10),
                    programs=st.lists(identifiers, max_size=2),
                    watchdog_ms=st.none() | st.integers(1, 60_000),
                ),
                max_size=2,
            )
        ),
    )
