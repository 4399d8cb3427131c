"""A PROGRAM's slots start with their declared initial value, or their type's default (TYP-05, the seed's table
"Default initial values": 0, FALSE, 0.0, T#0s, the empty string, an FB's inputs and outputs at theirs), whichever
slots share a type, a type object or a page of slots, after a cold and a warm start (RETAIN slots keep theirs).

The code generator finds the initialiser of a slot with a scalar initial value (the lowering gives the type's default
to one declared without) once per type object and value, and the object holding a page once per page (codegen/pou.py,
``_plain_inits``); the values expected here are the table's and the texts'.
"""

from __future__ import annotations

from hypothesis import example, given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen.layout import PAGE_SIZE

from .oo_support import run

#: (type, initial value text or None, the value a read shows: the declared one, else the type's default; a statement
#: changing slot ``{x}``, and the value it leaves; FB inputs from variables: a constant one is stored once, at the
#: instance's initialisation, codegen/constant_inputs.py)
DECLARATIONS = [
    ("BOOL", None, False, "{x} := NOT {x};", True),
    ("BOOL", "TRUE", True, "{x} := NOT {x};", False),
    ("INT", None, 0, "{x} := {x} + 1;", 1),
    ("INT", "-3", -3, "{x} := {x} + 1;", -2),
    ("DINT", "70000", 70000, "{x} := {x} * 2;", 140000),
    ("BYTE", "16#FF", 255, "{x} := {x} AND 16#0F;", 15),
    ("REAL", None, 0.0, "{x} := {x} + 0.5;", 0.5),
    ("LREAL", "2.5", 2.5, "{x} := {x} * 2.0;", 5.0),
    ("TIME", None, 0, "{x} := {x} + T#2ms;", 2),
    ("TIME", "T#1s", 1000, "{x} := {x} + T#2ms;", 1002),
    ("STRING", None, "", "{x} := CONCAT({x}, 'z');", "z"),
    ("STRING", "'ab'", "ab", "{x} := CONCAT({x}, 'z');", "abz"),
    ("STRING", "'abcd'", "abcd", "{x} := CONCAT('z', {x});", "zabcd"),
    ("STRING(2)", "'abcd'", "ab", "{x} := CONCAT('z', {x});", "za"),  # (TYP-04: cut to its length)
    ("REAL", "-0.0", -0.0, "{x} := {x} * 2.0;", -0.0),
    ("REAL", "0.0", 0.0, "{x} := {x} - 1.0;", -1.0),
    ("ARRAY[0..2] OF INT", None, [0, 0, 0], "{x}[1] := 5;", [0, 5, 0]),
    (
        "TON",
        None,
        {"IN": False, "PT": 0, "Q": False, "ET": 0},
        "{x}(IN := on, PT := three);",
        {"IN": True, "PT": 3, "Q": False, "ET": 0},
    ),
    (
        "CTU",
        None,
        {"CU": False, "R": False, "PV": 0, "Q": False, "CV": 0},
        "{x}(CU := on, PV := pv);",
        {"CU": True, "R": False, "PV": 3, "Q": False, "CV": 1},
    ),
]


def _program(slots: list[tuple[int, bool]], filler: int) -> str:
    """Main with the slots (a declaration's index, RETAIN or not) ``x0``, ``x1``..., ``filler`` BOOLs between the
    first half and the rest (``PAGE_SIZE``: those on the next page of slots), and a body changing each slot."""
    half = len(slots) // 2
    lines, body = ["VAR on : BOOL := TRUE; three : TIME := T#3ms; pv : INT := 3; END_VAR"], []  # (the FBs' inputs)
    for i, (index, retain) in enumerate(slots):
        ty, initial, _, change, _ = DECLARATIONS[index]
        if i == half and filler:
            lines.append(f"VAR {', '.join(f'f{k}' for k in range(filler))} : BOOL; END_VAR")
        lines.append(f"VAR{' RETAIN' if retain else ''} x{i} : {ty}{f' := {initial}' if initial else ''}; END_VAR")
        body.append(change.format(x=f"x{i}"))
    return "PROGRAM Main\n" + "\n".join(lines + body) + "\nEND_PROGRAM\n"


@settings(max_examples=20, deadline=None)
@given(
    slots=st.lists(st.tuples(st.integers(0, len(DECLARATIONS) - 1), st.booleans()), min_size=1, max_size=24),
    filler=st.sampled_from([0, 3, PAGE_SIZE]),
)
@example(slots=[(i, i % 3 == 0) for i in range(len(DECLARATIONS))] * 2, filler=PAGE_SIZE)  # (each kind beside each)
def test_each_slot_starts_with_its_declared_value_or_its_types_default(
    slots: list[tuple[int, bool]], filler: int
) -> None:
    sim = run(_program(slots, filler))
    read = lambda: [repr(sim.read(f"Main.x{i}")) for i in range(len(slots))]  # noqa: E731  # (FALSE is not 0)
    assert read() == [repr(DECLARATIONS[index][2]) for index, _ in slots]
    sim.cycle(1)
    assert read() == [repr(DECLARATIONS[index][4]) for index, _ in slots]
    sim.reset(cold=False)  # warm: the RETAIN slots keep what the scan left
    assert read() == [repr(DECLARATIONS[index][4 if retain else 2]) for index, retain in slots]
    sim.reset(cold=True)
    assert read() == [repr(DECLARATIONS[index][2]) for index, _ in slots]
