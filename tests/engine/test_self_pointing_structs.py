"""A STRUCT that points to itself (issue 25 item 2): a linked list's ``next : POINTER TO Node``.

IEC 61131-3 and CODESYS refuse only a STRUCT that contains itself by value (it would have no size); a pointer or a
reference to the STRUCT's own type - or two STRUCTs pointing at each other - is an address, as in C's linked
lists. The list is walked with ``p := p^.next`` until NULL (CODESYS compares a pointer with 0 or NULL), and
dereferencing the NULL at its end is the located NULL fault. SIZEOF counts a pointer member as the 32-bit target's
address (4 bytes, 4-aligned: docs/st.md, as SIZEOF of a pointer; CODESYS's alignment, as in C).
"""

from __future__ import annotations

import pytest

from ladderlab.ir.types import Elementary, Reference, Struct, StructField

from .ed3_support import build, errors, program, scans

NODE = "TYPE Node : STRUCT v : INT; next : POINTER TO Node; END_STRUCT; END_TYPE"

#: three nodes linked a -> b -> c, each scan walks the list from a and adds up the values; c's value grows
WALK = """a.v := 1; b.v := 2; c.v := c.v + 10; a.next := ADR(b); b.next := ADR(c);
p := ADR(a); sum := 0; n := 0;
WHILE p <> NULL DO sum := sum + p^.v; n := n + 1; p := p^.next; END_WHILE;
size := SIZEOF(a); psize := SIZEOF(p);"""


@pytest.mark.parametrize("variant", ["fast", "monitor", "debug"])
def test_walking_a_linked_list_until_null(variant):
    text = program("a, b, c : Node; p : POINTER TO Node; sum, n : INT; size, psize : DINT;", WALK, NODE)
    # c.v is 10, 20, 30: the sums are 1 + 2 + 10k; SIZEOF(Node) = INT at 0, the pointer at 4 (4-aligned), 8 bytes
    expected = [[1 + 2 + 10 * k, 3, 8, 4] for k in (1, 2, 3)]
    assert scans(text, 3, "sum", "n", "size", "psize", variant=variant) == expected


def test_ref_to_and_two_structs_pointing_at_each_other():
    types = (
        "TYPE Owner : STRUCT id : INT; first : REF_TO Item; END_STRUCT; END_TYPE\n"
        "TYPE Item : STRUCT w : REAL; owner : REF_TO Owner; next : REF_TO Item; END_STRUCT; END_TYPE"
    )
    body = """o.id := 7; o.first := REF(i1); i1.w := 1.5; i2.w := 2.25; i1.next := REF(i2);
i1.owner := REF(o); i2.owner := REF(o); total := 0.0; ids := 0;
r := o.first;
WHILE r <> NULL DO total := total + r^.w; ids := ids + r^.owner^.id; r := r^.next; END_WHILE;
size := SIZEOF(o) + SIZEOF(i1);"""
    text = program("o : Owner; i1, i2 : Item; r : REF_TO Item; total : REAL; ids : INT; size : DINT;", body, types)
    # Owner: INT at 0, address at 4 -> 8 bytes; Item: REAL at 0, two addresses at 4 and 8 -> 12 bytes
    assert scans(text, 2, "total", "ids", "size") == [[3.75, 14, 20]] * 2


def test_a_member_by_value_of_a_struct_that_points_back():
    """Tree -> (pointer) Leaf -> (by value) Tree is finite: Leaf holds a Tree, Tree only an address of a Leaf."""
    types = (
        "TYPE Tree : STRUCT n : DINT; leaf : POINTER TO Leaf; END_STRUCT; END_TYPE\n"
        "TYPE Leaf : STRUCT copy : Tree; k : INT; END_STRUCT; END_TYPE"
    )
    body = "t.n := 5; l.k := 3; t.leaf := ADR(l); l.copy := t; x := t.leaf^.copy.n + t.leaf^.copy.leaf^.k;"
    text = program("t : Tree; l : Leaf; x : DINT;", body, types)
    assert scans(text, 1, "x") == [[8]]


def test_reading_past_the_end_of_the_list_is_the_located_null_fault():
    body = """a.next := ADR(b); p := ADR(a); n := n + 1;
IF n = 3 THEN p := p^.next; p := p^.next; sum := p^.v; END_IF;"""
    sim = build(program("a, b : Node; p : POINTER TO Node; sum, n : INT;", body, NODE)).simulation()
    sim.cycle(2)
    assert sim.fault is None
    sim.cycle(1)
    assert sim.fault is not None
    assert sim.fault.text().startswith(
        "P is NULL: it refers to no variable, so '^' has nothing to reach at POU MAIN, line 7 column 43"
    ), sim.fault.text()


@pytest.mark.parametrize(
    "types, message",
    [
        (
            "TYPE Node : STRUCT v : INT; n : Node; END_STRUCT; END_TYPE",
            "types:1:33: error ST-RECURSION: the type 'Node' is defined in terms of itself",
        ),
        (
            "TYPE A : STRUCT b : B; END_STRUCT; END_TYPE\nTYPE B : STRUCT a : A; END_STRUCT; END_TYPE",
            "types:2:21: error ST-RECURSION: the type 'A' is defined in terms of itself",
        ),
        (
            "TYPE A : STRUCT b : ARRAY [1..2] OF B; END_STRUCT; END_TYPE\nTYPE B : STRUCT a : A; END_STRUCT; END_TYPE",
            "types:2:21: error ST-RECURSION: the type 'A' is defined in terms of itself",
        ),
        (
            "TYPE P : POINTER TO P; END_TYPE",
            "types:1:21: error ST-RECURSION: the type 'P' is defined in terms of itself",
        ),
        (
            "TYPE A : B; END_TYPE\nTYPE B : A; END_TYPE",
            "types:2:10: error ST-RECURSION: the type 'A' is defined in terms of itself",
        ),
    ],
)
def test_containing_itself_by_value_stays_refused_once_where_it_is_named(types, message):
    assert errors(program("x : INT;", "x := 1;", types)) == [message]


def _node(value_type: str) -> Struct:
    node = Struct("NODE", ())
    fields = (StructField("V", Elementary(value_type)), StructField("NEXT", Reference(node)))
    object.__setattr__(node, "fields", fields)
    return node


def test_self_pointing_ir_structs_compare_hash_and_print_without_looping():
    """Each POU's lowering builds its own Struct for Node: two of them are one type (the engine's caches key on it)."""
    first, second, other = _node("INT"), _node("INT"), _node("DINT")
    assert first == second and hash(first) == hash(second)
    assert first != other
    assert repr(first) == "Struct('NODE', ['V', 'NEXT'])"
