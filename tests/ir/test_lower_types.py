"""Checker types -> IR types and declared initial values -> slot initial values (TYP-05, TYP-11, docs/ir.md)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.iec.elementary import ELEMENTARY
from ladderlab.iec.values import f32
from ladderlab.ir import types as ir
from ladderlab.ir.lower_types import LoweringError, TypeLowering, ir_type
from ladderlab.ir.types import Array, Elementary, Enum, FbInstance, Struct, StructField, Subrange
from ladderlab.st import types as t
from ladderlab.st.checker import check_project
from ladderlab.st.project_text import source_to_project
from tests.engine.helpers import date_ms, ms
from tests.ir.helpers import BOOL, DINT, INT, REAL, STRING, TIME, errors, lower_ok


def slots(declarations: str, extra: str = "") -> dict:
    program = lower_ok(f"PROGRAM P\nVAR\n{declarations}\nEND_VAR\nEND_PROGRAM\n{extra}")
    return {s.name: s for s in program.pous["P"].slots}


def initial(declaration: str, extra: str = "") -> object:
    return slots(f"x : {declaration};", extra)["X"].initial


# ---------------------------------------------------------------- types


def test_ir_type_of_elementary_and_string_types():
    assert ir_type(t.Elementary("TIME_OF_DAY")) == Elementary("TIME_OF_DAY")
    assert ir_type(t.StringType(False, 20)) == Elementary("STRING", 20)
    assert ir_type(t.StringType(True)) == Elementary("STRING", wide=True)  # WSTRING: a Python str too, 2 bytes a char
    assert ir_type(t.UntypedInt(70000)) == DINT and ir_type(t.UntypedReal()) == Elementary("LREAL")


def test_ir_type_of_references_and_refusal_of_open_arrays_and_errors():
    assert ir_type(t.PointerType(t.INT)) == ir.Reference(ir.Elementary("INT"))
    with pytest.raises(LoweringError, match=r"ARRAY \[\*\]"):
        ir_type(t.ArrayType((None,), t.INT))
    with pytest.raises(LoweringError) as error:
        ir_type(t.ERROR)
    assert error.value.message is None  # already reported by the checker


def test_slot_types_of_every_kind():
    declared = slots(
        """
        a : ARRAY [1..2, 0..3] OF INT;
        e : TColor;
        s : TPoint;
        r : TPercent;
        q : INT (-5..5);
        f : TON;
        c : CTU_DINT;
        w : STRING[12];
    """,
        """TYPE TColor : (red, green := 5, blue); TPercent : INT (0..100);
    TPoint : STRUCT x : REAL := 1.5; p : TPercent := 7; END_STRUCT; END_TYPE""",
    )
    assert declared["A"].type == Array(INT, ((1, 2), (0, 3)))
    assert declared["E"].type == Enum("TCOLOR", (("red", 0), ("green", 5), ("blue", 6)))  # the values as declared
    percent = Subrange(INT, 0, 100)
    assert declared["S"].type == Struct("TPOINT", (StructField("X", REAL, 1.5), StructField("P", percent, 7)))
    assert declared["R"].type == percent
    assert declared["Q"].type == Subrange(INT, -5, 5)
    assert declared["F"].type == FbInstance("TON") and declared["C"].type == FbInstance("CTU_DINT")
    assert declared["W"].type == Elementary("STRING", 12)


_SHORTCUT_TYPES = """TYPE TTimer : TON; TMotor : Motor; TPercent : INT (0..100); TCount : DINT; TInt : INT; END_TYPE
FUNCTION_BLOCK Motor
VAR_INPUT on : BOOL; END_VAR
END_FUNCTION_BLOCK
"""


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.sampled_from(["INT", "bool", "TON", "ctu_dint", "Motor", "TTimer", "TMotor", "TPercent", "TCount", "TInt"])
        | st.sampled_from(sorted(ELEMENTARY)),
        min_size=1,
        max_size=6,
    )
)
def test_the_type_shortcuts_give_the_general_ways_types_and_slots(declared):
    """``TypeLowering.type_of``'s shortcuts (an elementary type without a TYPE, an FB instance: issue 27) and the
    elementary slots' shared types and defaults give what ``_type_of`` and the general slot give."""
    text = (
        "PROGRAM P\nVAR\n" + "".join(f"v{i} : {name};\n" for i, name in enumerate(declared)) + "END_VAR\nEND_PROGRAM\n"
    )
    project, diagnostics = source_to_project(text + _SHORTCUT_TYPES, "test")
    assert project is not None and not diagnostics
    checked = check_project(project)
    types = TypeLowering(checked, checked.pou("P"))
    for symbol in checked.pou("P").symbols.values():
        assert types.type_of(symbol.type, symbol.type_spec) == types._type_of(symbol.type, symbol.type_spec)
        slot = types.slot(symbol)
        assert (slot.type, slot.initial) == (
            types._type_of(symbol.type, symbol.type_spec),
            types.initial(symbol.type, symbol.type_spec, symbol.init),
        )
        assert type(slot.initial) is type(types.initial(symbol.type, symbol.type_spec, symbol.init))


# ---------------------------------------------------------------- initial values (TYP-05 defaults)


@pytest.mark.parametrize("name", sorted(ELEMENTARY))
def test_elementary_defaults_typ05(name):
    assert initial(name) == ELEMENTARY[name].default
    assert type(initial(name)) is type(ELEMENTARY[name].default)


def test_defaults_of_enum_subrange_array_struct_fb():
    extra = "TYPE TColor : (red := 3, green); TPoint : STRUCT x : INT; b : BOOL; END_STRUCT; END_TYPE"
    assert initial("TColor", extra) == 3  # the first value, whatever its number
    assert initial("INT (-5..5)") == 0 and initial("INT (10..20)") == 10  # lower limit when 0 is outside
    assert initial("ARRAY [1..2, 1..3] OF BOOL") == ((False,) * 3, (False,) * 3)
    assert initial("TPoint", extra) == (0, False)
    assert initial("TON") is None


# ---------------------------------------------------------------- declared initial values


@pytest.mark.parametrize(
    "declaration, expected",
    [
        ("INT := -32768", -32768),
        ("SINT := -5", -5),
        ("BYTE := 16#FF", 255),
        ("WORD := 2#1010", 10),
        ("DINT := INT#-9", -9),
        ("BOOL := 1", True),
        ("BOOL := BOOL#0", False),
        ("REAL := 0.1", f32(0.1)),
        ("REAL := 3", 3.0),
        ("LREAL := -1.5E3", -1500.0),
        ("TIME := T#1h30m", ms(h=1, m=30)),
        ("TIME := T#-250ms", -250),
        ("TIME := T#1.5ms", 2),  # milliseconds are whole: rounded, ties to even
        ("TOD := TOD#12:30:15.5", ms(h=12, m=30, s=15.5)),
        ("DATE := D#2003-06-21", date_ms("2003-06-21")),
        ("DT := DT#2003-06-21-11:38:52.35", date_ms("2003-06-21 11:38:52.350")),
        ("STRING[3] := 'abcdef'", "abc"),
        ("STRING := 'it$'s $N'", "it's \n"),
    ],
)
def test_elementary_initial_values_are_engine_values(declaration, expected):
    value = initial(declaration)
    assert value == expected and type(value) is type(expected)


def test_array_initialisers_with_repeats_and_missing_elements():
    assert initial("ARRAY [1..6] OF INT := [1, 2(7), 3]") == (1, 7, 7, 3, 0, 0)
    assert initial("ARRAY [0..4] OF INT := [2(), 3(-1)]") == (0, 0, -1, -1, -1)
    assert initial("ARRAY [1..2, 1..3] OF INT := [1, 2, 3, 4]") == ((1, 2, 3), (4, 0, 0))  # row-major
    assert initial("ARRAY [1..3] OF REAL := [1, 0.5]") == (1.0, 0.5, 0.0)


def test_struct_initialisers_override_field_initials():
    extra = """TYPE TInner : STRUCT a : INT := 1; b : INT := 2; END_STRUCT;
    TOuter : STRUCT i : TInner; s : STRING[4] := 'ab'; t : TIME; END_STRUCT; END_TYPE"""
    assert initial("TOuter", extra) == ((1, 2), "ab", 0)
    assert initial("TOuter := (i := (b := 5), t := T#2s)", extra) == ((1, 5), "ab", 2000)
    assert initial("ARRAY [1..2] OF TInner := [(a := 9)]", extra) == ((9, 2), (1, 2))


def test_alias_initial_values_are_inherited_typ11():
    extra = "TYPE TRoomTemp : REAL := 20.0; THomeTemp : TRoomTemp; TMyInt : INT; END_TYPE"
    assert initial("THomeTemp", extra) == 20.0
    assert initial("TMyInt", extra) == 0
    assert initial("ARRAY [1..2] OF THomeTemp", extra) == (20.0, 20.0)
    assert initial("ARRAY [1..3] OF THomeTemp := [1.0]", extra) == (1.0, 20.0, 20.0)


def test_enum_initial_values_by_name_and_typed_literal():
    extra = "TYPE TColor : (red, green := 5, blue) := blue; END_TYPE"
    assert initial("TColor", extra) == 6
    assert initial("TColor := green", extra) == 5
    assert initial("TColor := TColor#red", extra) == 0


def test_fb_instance_initial_values_are_pin_overrides():
    assert initial("TON := (PT := T#2s)") == (("PT", 2000),)
    program = lower_ok(
        "FUNCTION_BLOCK Fb\nVAR_INPUT period : TIME := T#1s; n : INT; END_VAR\n;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM P\nVAR x : Fb := (n := 4, Period := T#5s); END_VAR\nEND_PROGRAM\n"
    )
    assert program.pous["P"].slots[0].initial == (("N", 4), ("PERIOD", 5000))


def test_constants_in_initial_values():
    declared = slots(
        "n : INT := LIMIT_VALUE * 2; m : INT := -LIMIT_VALUE; a : ARRAY [1..2] OF INT := [2(LIMIT_VALUE)];",
        "VAR_GLOBAL CONSTANT LIMIT_VALUE : INT := 21; END_VAR",
    )
    assert (declared["N"].initial, declared["M"].initial, declared["A"].initial) == (42, -21, (21, 21))


def test_slot_flags_and_classes():
    program = lower_ok("""FUNCTION_BLOCK Fb
VAR_INPUT i : INT; END_VAR
VAR_OUTPUT o : BOOL; END_VAR
VAR_IN_OUT io : DINT; END_VAR
VAR RETAIN r : INT := 3; END_VAR
VAR CONSTANT c : INT := 4; END_VAR
VAR_TEMP tmp : INT; END_VAR
VAR_EXTERNAL g : INT; END_VAR
VAR led AT %QX0.1 : BOOL; END_VAR
;
END_FUNCTION_BLOCK
VAR_GLOBAL g : INT; END_VAR""")
    found = [(s.name, s.var_class, s.initial, s.retain, s.constant, s.address) for s in program.pous["FB"].slots]
    assert found == [
        ("I", "VAR_INPUT", 0, False, False, None),
        ("O", "VAR_OUTPUT", False, False, False, None),
        ("IO", "VAR_IN_OUT", None, False, False, None),
        ("R", "VAR", 3, True, False, None),
        ("C", "VAR", 4, False, True, None),
        ("TMP", "VAR_TEMP", 0, False, False, None),
        ("LED", "VAR", None, False, False, "%QX0.1"),  # located: the process image holds its value
    ]


def test_non_constant_initial_value_is_a_located_error():
    text = "PROGRAM P\nVAR\n  a : INT;\n  b : INT := a;\nEND_VAR\nEND_PROGRAM\n"
    assert errors(text) == [
        "P/declarations:4:14, POU P: error IR-INIT: an initial value must be a constant "
        "(a literal, a CONSTANT or an enumeration value)"
    ]


def test_references_start_as_null_or_as_ref_of_a_whole_variable_or_an_array_element():
    """An element with literal indices (seed 000 TYP-46: ``ADR(arrayINT[0])``) is accepted; a field is not yet."""
    text = (
        "TYPE Pair : STRUCT f : INT; END_STRUCT; END_TYPE\n"
        "PROGRAM P\nVAR\n  x : INT;\n  a : ARRAY [1..2] OF INT;\n  p : POINTER TO INT;\n  q : REF_TO INT := NULL;\n"
        "  r : REF_TO INT := REF(x);\n  s : REF_TO INT := REF(a[1]);\n  pr : Pair;\n  t : REF_TO INT := REF(pr.f);\n"
        "END_VAR\nEND_PROGRAM\n"
    )
    assert errors(text) == [
        "P/declarations:11:21, POU P: error IR-INIT: a reference starts as NULL or as REF(x) of a whole variable x "
        "or of an array element x[3] (assign REF(a[i]) or REF(s.f) in the body)"
    ]


@given(st.integers(-32768, 32767), st.integers(1, 5), st.integers(0, 3))
def test_repeat_initialisers_expand_in_order(value, count, spare):
    """``[count(value), 1]`` in an ARRAY with ``spare`` more elements: repeats, then 1, then defaults."""
    declared = f"ARRAY [1..{count + 1 + spare}] OF INT := [{count}({value}), 1]"
    expected = [value] * count + [1] + [0] * spare
    assert initial(declared) == tuple(expected)


def test_bool_time_string_declarations_types():
    declared = slots("b : BOOL; t : TIME; s : STRING;")
    assert (declared["B"].type, declared["T"].type, declared["S"].type) == (BOOL, TIME, STRING)
