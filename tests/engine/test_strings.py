"""String functions (spec FUN-80..FUN-83): IEC Table 29 vectors, clamping, truncation."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.errors import INVALID_ARGUMENT, TRUNCATED
from ladderlab.engine.stdlib import make_function

S = "STRING"


def call(name, types, *args, result=S):
    return make_function(name, types, result)(*args)


def checked(name, types, *args, result=S):
    return make_function(name, types, result, checked=True)(*args)


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("LEN", [S], ("ASTRING",), 7),  # FUN-81 (IEC Table 29)
        ("LEN", [S], ("",), 0),
        ("LEFT", [S, "INT"], ("ASTR", 3), "AST"),
        ("RIGHT", [S, "INT"], ("ASTR", 3), "STR"),
        ("MID", [S, "INT", "INT"], ("ASTR", 2, 2), "ST"),
        ("CONCAT", [S, S, S], ("AB", "CD", "E"), "ABCDE"),
        ("INSERT", [S, S, "INT"], ("ABC", "XY", 2), "ABXYC"),  # after the P-th character
        ("DELETE", [S, "INT", "INT"], ("ABXYC", 2, 3), "ABC"),
        ("REPLACE", [S, S, "INT", "INT"], ("ABCDE", "X", 2, 3), "ABXE"),
        ("FIND", [S, S], ("ABCBC", "BC"), 2),
        ("FIND", [S, S], ("ABCBC", "XY"), 0),  # not found
        ("FIND", [S, S], ("ABC", ""), 0),  # nothing to find
        ("LEFT", [S, "INT"], ("AB", 5), "AB"),  # more than there is: all of it, no error
        ("RIGHT", [S, "INT"], ("AB", 5), "AB"),
        ("RIGHT", [S, "INT"], ("AB", 0), ""),
        ("MID", [S, "INT", "INT"], ("ASTR", 9, 3), "TR"),
        ("MID", [S, "INT", "INT"], ("ASTR", 2, 5), ""),  # P = LEN + 1 is valid: empty
        ("INSERT", [S, S, "INT"], ("ABC", "XY", 0), "XYABC"),
        ("INSERT", [S, S, "INT"], ("ABC", "XY", 3), "ABCXY"),
        ("DELETE", [S, "INT", "INT"], ("ABC", 9, 2), "A"),
        ("REPLACE", [S, S, "INT", "INT"], ("ABC", "XY", 0, 4), "ABCXY"),
        ("ADD", [S, S], ("message", " [C]"), "message [C]"),  # FUN-82: + concatenates
    ],
)
def test_string_vectors_FUN_81(name, types, args, expected):
    result = call(name, types, *args)
    assert result == expected and type(result) is type(expected)
    assert checked(name, types, *args) == (expected, None)


@pytest.mark.parametrize(
    "name, types, args, clamped, pin",
    [
        ("LEFT", [S, "INT"], ("ASTR", -1), "", "L = -1"),  # FUN-83: clamp and ENO FALSE
        ("RIGHT", [S, "INT"], ("ASTR", -2), "", "L = -2"),
        ("MID", [S, "INT", "INT"], ("ASTR", 2, 0), "AS", "P = 0"),
        ("MID", [S, "INT", "INT"], ("ASTR", 2, 6), "", "P = 6"),
        ("MID", [S, "INT", "INT"], ("ASTR", -1, 2), "", "L = -1"),
        ("INSERT", [S, S, "INT"], ("ABC", "XY", -1), "XYABC", "P = -1"),
        ("INSERT", [S, S, "INT"], ("ABC", "XY", 4), "ABCXY", "P = 4"),
        ("DELETE", [S, "INT", "INT"], ("ABC", 1, 0), "BC", "P = 0"),
        ("REPLACE", [S, S, "INT", "INT"], ("ABC", "X", -5, 9), "ABCX", "L = -5, P = 9"),
    ],
)
def test_out_of_range_positions_are_clamped_and_reported_FUN_83(name, types, args, clamped, pin):
    assert call(name, types, *args) == clamped
    value, warning = checked(name, types, *args)
    assert value == clamped
    assert warning.code == INVALID_ARGUMENT and pin in warning.message


def test_results_are_cut_to_the_declared_length_TYP_04():
    assert call("CONCAT", [S, S], "abc", "def", result="STRING[4]") == "abcd"
    value, warning = checked("CONCAT", [S, S], "abc", "def", result="STRING[4]")
    assert value == "abcd" and warning.code == TRUNCATED
    assert call("CONCAT", [S, S], "x" * 200, "y" * 200) == "x" * 80  # default STRING length
    assert call("INSERT", [S, S, "INT"], "abc", "XYZ", 1, result="STRING[3]") == "aXY"


def test_concat_template_inlines_the_cut():
    from ladderlab.engine.stdlib import function_template

    assert function_template("CONCAT", [S, S], "STRING[4]") == "(({0}) + ({1}))[:4]"


text = st.text(alphabet="ABCXYZ", max_size=12)


@given(a=text, b=text, data=st.data())
def test_delete_undoes_insert(a, b, data):
    p = data.draw(st.integers(0, len(a)))
    inserted = call("INSERT", [S, S, "INT"], a, b, p, result="STRING[255]")
    assert call("DELETE", [S, "INT", "INT"], inserted, len(b), p + 1, result="STRING[255]") == a


@given(a=text, b=text, data=st.data())
def test_replace_is_left_plus_new_plus_rest(a, b, data):
    p = data.draw(st.integers(1, len(a) + 1))
    n = data.draw(st.integers(0, len(a) + 2))
    expected = call("LEFT", [S, "INT"], a, p - 1) + b + call("RIGHT", [S, "INT"], a, max(len(a) - (p - 1) - n, 0))
    assert call("REPLACE", [S, S, "INT", "INT"], a, b, n, p, result="STRING[255]") == expected


@given(a=text, b=st.text(alphabet="ABC", min_size=1, max_size=3))
def test_find_gives_a_position_where_mid_matches(a, b):
    position = call("FIND", [S, S], a, b)
    if position:
        assert call("MID", [S, "INT", "INT"], a, len(b), position) == b
        assert b not in a[: position - 1 + len(b) - 1]
    else:
        assert b not in a


@pytest.mark.parametrize(
    "name, types", [("LEN", ["INT"]), ("LEFT", [S, "REAL"]), ("CONCAT", [S, "INT"]), ("FIND", [S])]
)
def test_wrong_types_are_rejected(name, types):
    with pytest.raises(TypeError):
        make_function(name, types, S)
