"""LD validation (issue 5 "Validation"): every problem is a diagnostic with POU, network, element and pin."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir.lower_project import lower_project
from ladderlab.model import ld
from tests.ir.diagram_support import (
    box,
    coil,
    compare,
    contact,
    errors,
    jump,
    ld_pou,
    parallel,
    project,
    ret,
    rung,
)

DECL = (
    "VAR a, b : BOOL; n : INT; w : WORD; t1 : TON; c1 : CTU; END_VAR VAR CONSTANT kc : BOOL := TRUE; END_VAR "
    "VAR_INPUT inb : BOOL; END_VAR"
)
WHERE = "POU Main, network n1, element"

CASES = {
    "unknown variable": (
        rung("n1", contact("c", "Strat"), coil("q", "a")),
        "POU Main, network 1, contact Strat: error ST-UNKNOWN-VAR: unknown variable 'Strat'",
    ),
    "contact on a non-BOOL variable": (
        rung("n1", contact("c", "n"), coil("q", "a")),
        "POU Main, network 1, contact n: error LD-NOT-BOOL: the contact needs a BOOL variable; 'n' is INT",
    ),
    "coil on a non-BOOL variable": (
        rung("n1", contact("c", "a"), coil("q", "n")),
        "POU Main, network 1, coil n: error LD-NOT-BOOL: the coil needs a BOOL variable; 'n' is INT",
    ),
    "write to a CONSTANT": (
        rung("n1", contact("c", "a"), coil("q", "kc")),
        "POU Main, network 1, coil kc: error ST-CONST-WRITE: 'kc' is a CONSTANT and cannot be assigned",
    ),
    "write to an input": (
        rung("n1", contact("c", "a"), coil("q", "inb")),
        "POU Main, network 1, coil inb: error LD-INPUT-WRITE: 'inb' is an input of Main: assigning it overwrites the caller's value",
    ),
    "unknown function": (
        rung("n1", box("x", "TOM", en=True)),
        "POU Main, network 1, TOM: error LD-UNKNOWN-CALL: unknown function or function block 'TOM' - did you mean 'TON'?",
    ),
    "FB without an instance": (
        rung("n1", box("x", "TON", PT="T#1s")),
        "POU Main, network 1, TON: error LD-NO-INSTANCE: the function block TON needs an instance: declare one (e.g. inst : TON;) and name it in the box",
    ),
    "instance of another FB type": (
        rung("n1", box("x", "TON", instance="c1", PT="T#1s")),
        "POU Main, network 1, TON c1: error LD-INSTANCE-TYPE: 'c1' is a CTU, not a TON instance",
    ),
    "instance that is no FB": (
        rung("n1", box("x", "TON", instance="a", PT="T#1s")),
        "POU Main, network 1, TON a: error LD-INSTANCE-TYPE: 'a' is a BOOL, not a TON instance",
    ),
    "function with an instance": (
        rung("n1", box("x", "ADD", instance="t1", en=True, IN1="1", IN2="2")),
        "POU Main, network 1, ADD t1: error LD-INSTANCE: ADD is a function: it has no instance (remove 't1')",
    ),
    "missing pin": (
        rung("n1", box("x", "ADD", en=True, IN1="n", outputs={"OUT": "n"})),
        "POU Main, network 1, ADD.IN2: error LD-MISSING-PIN: input IN2 of ADD is not connected",
    ),
    "gap in extensible inputs": (
        rung("n1", box("x", "ADD", en=True, IN1="n", IN2="n", IN4="n", outputs={"OUT": "n"})),
        "POU Main, network 1, ADD.IN3: error LD-MISSING-PIN: input IN3 of ADD is not connected",
    ),
    "unknown input pin": (
        rung("n1", box("x", "TON", instance="t1", PX="T#1s")),
        "POU Main, network 1, TON t1.PX: error ST-CALL-ARGS: TON has no parameter 'PX'",
    ),
    "unknown output pin": (
        rung("n1", box("x", "TON", instance="t1", outputs={"QQ": "a"})),
        "POU Main, network 1, TON t1.QQ: error ST-CALL-ARGS: TON has no parameter 'QQ' - did you mean 'Q'?",
    ),
    "function output other than OUT": (
        rung("n1", box("x", "ADD", en=True, IN1="n", IN2="1", outputs={"Q": "n"})),
        "POU Main, network 1, ADD.Q: error LD-UNKNOWN-PIN: ADD is a function: its only output is OUT",
    ),
    "EN connected as an operand": (
        rung("n1", box("x", "ADD", en=True, EN="a", IN1="n", IN2="1")),
        "POU Main, network 1, ADD.EN: error LD-UNKNOWN-PIN: EN is the box's power flow: switch on EN/ENO instead of connecting it",
    ),
    "type mismatch on an input pin": (
        rung("n1", box("x", "TON", instance="t1", PT="5")),
        "POU Main, network 1, TON t1.PT: error ST-TYPE-MISMATCH: input PT of TON: expected TIME, got ANY_INT literal",
    ),
    "type mismatch between generic inputs": (
        rung("n1", box("x", "ADD", en=True, IN1="n", IN2="1.5", outputs={"OUT": "n"})),
        "POU Main, network 1, ADD.IN2: error ST-TYPE-MISMATCH: ADD needs inputs of one type: got INT and ANY_REAL literal; convert one of them with a *_TO_* function",
    ),
    "type mismatch on an output pin": (
        rung("n1", box("x", "TON", instance="t1", outputs={"ET": "n"})),
        "POU Main, network 1, TON t1.ET: error ST-TYPE-MISMATCH: output ET is TIME and cannot be stored in INT without a conversion such as TIME_TO_INT",
    ),
    "type mismatch on a function result": (
        rung("n1", box("x", "GT", en=True, IN1="n", IN2="1", outputs={"OUT": "n"})),
        "POU Main, network 1, GT.OUT: error ST-TYPE-MISMATCH: output OUT of GT ('n'): expected INT, got BOOL without a conversion such as BOOL_TO_INT",
    ),
    "box without a BOOL input": (
        rung("n1", box("x", "ADD", IN1="n", IN2="1")),
        "POU Main, network 1, ADD: error LD-BOX-POWER: ADD has no free BOOL input for the power flow: switch on EN/ENO",
    ),
    "box without a BOOL output": (
        rung("n1", box("x", "SEL", IN0="n", IN1="1")),
        "POU Main, network 1, SEL: error LD-BOX-POWER: SEL has no BOOL output to pass the power flow on: switch on EN/ENO",
    ),
    "unknown jump target": (
        rung("n1", contact("c", "a"), jump("j", "nowhere")),
        "POU Main, network 1, jump to nowhere: error LD-UNKNOWN-LABEL: jump to 'nowhere', but no network of this POU has that label",
    ),
    "jump not at the end of its branch": (
        rung("n1", jump("j", "L"), coil("q", "a")),
        "POU Main, network 1, jump to L: error LD-CONTROL-POSITION: a jump must be the last element of a branch that ends the rung",
    ),
    "return in a branch that does not end the rung": (
        rung("n1", parallel("p", [contact("c", "a"), ret("r")], [contact("d", "b")]), coil("q", "a")),
        "POU Main, network 1, RETURN: error LD-CONTROL-POSITION: a return must be the last element of a branch that ends the rung",
    ),
    "jump feeding a box input": (
        rung("n1", box("x", "TON", instance="t1", PT=[jump("j", "L")])),
        "POU Main, network 1, jump to L: error LD-CONTROL-POSITION: a jump must be the last element of a branch that ends the rung",
    ),
    "parallel with one branch": (
        rung("n1", parallel("p", [contact("c", "a")]), coil("q", "b")),
        "POU Main, network 1, parallel branch: error LD-PARALLEL: the parallel branch has 1 branch(es); it needs at least two",
    ),
    "duplicate element id": (
        rung("n1", contact("c", "a"), coil("c", "b")),
        "POU Main, network 1, coil b: error LD-DUPLICATE-ID: an element of network 1 has the same id 'c': element ids must be unique in the POU (was the file edited by hand?)",
    ),
    "empty operand": (
        rung("n1", contact("c", " "), coil("q", "b")),
        "POU Main, network 1, contact (no operand): error LD-MISSING-OPERAND: the contact has no operand",
    ),
    "operand syntax error": (
        rung("n1", contact("c", "a +"), coil("q", "b")),
        "POU Main, network 1, contact a +: error ST-PARSE: expected an expression, found end of text",
    ),
    "compare contact operand types": (
        rung("n1", compare("c", "GT", "n", "a"), coil("q", "b")),
        "POU Main, network 1, comparison n > a: error ST-TYPE-MISMATCH: '>' needs operands of the same type: INT and BOOL; convert one of them (e.g. BOOL_TO_INT)",
    ),
    "compare contact unknown operand": (
        rung("n1", compare("c", "LT", "n", "zz"), coil("q", "b")),
        "POU Main, network 1, comparison n < zz: error ST-UNKNOWN-VAR: unknown variable 'zz'",
    ),
}


@pytest.mark.parametrize("name", list(CASES))
def test_validation_diagnostic(name):
    network, expected = CASES[name]
    pous = [ld_pou("Main", DECL, network, ld.LdNetwork(id="n2", label="L")), ld_pou("Other", "")]
    assert errors(*pous) == [expected]


def test_duplicate_and_malformed_labels():
    main = ld_pou(
        "Main", "", rung("n1", label="Next"), rung("n2", label="next"), rung("n3", label="1x"), rung("n3", label="10")
    )
    assert errors(main) == [
        'POU Main, network 3 "1x" or network 4 "10" (the same id \'n3\'): error LD-DUPLICATE-ID: an earlier network '
        "has the same id 'n3': network ids must be unique in the POU",
        "POU Main, network 2 \"next\": error LD-DUPLICATE-LABEL: label 'next' is already used by network 1",
        "POU Main, network 3 \"1x\" or network 4 \"10\" (the same id 'n3'): error LD-BAD-LABEL: network label '1x' "
        "must be an identifier or an unsigned integer",
    ]


def test_jump_target_suggestion_and_integer_labels():
    main = ld_pou(
        "Main",
        "",
        rung("n1", jump("j1", "Nxet")),
        rung("n2", jump("j2", "10")),
        rung("n3", label="Next"),
        rung("n4", label="10"),
    )
    assert errors(main) == [
        "POU Main, network 1, jump to Nxet: error LD-UNKNOWN-LABEL: jump to 'Nxet', but no network "
        "of this POU has that label - did you mean 'NEXT'?"
    ]


# ------------------------------------------------------------------ never an exception

_names = st.sampled_from(["a", "b", "n", "kc", "inb", "t1", "zz", "", "a +", "T#1s", "1", "t1.Q"])
_ids = st.text("abc", min_size=1, max_size=2)


def _elements(depth: int):
    leaf = st.one_of(
        st.builds(contact, _ids, _names, st.sampled_from(["no", "nc", "p", "n"])),
        st.builds(coil, _ids, _names, st.sampled_from(["normal", "negated", "set", "reset", "p", "n"])),
        st.builds(compare, _ids, st.sampled_from(["GT", "EQ", "NE"]), _names, _names),
        st.builds(jump, _ids, st.sampled_from(["L", "M", ""])),
        st.builds(ret, _ids),
    )
    if depth == 0:
        return leaf
    series = st.lists(_elements(depth - 1), max_size=3)
    return st.one_of(
        leaf,
        st.builds(lambda i, bs: parallel(i, *bs), _ids, st.lists(series, max_size=3)),
        st.builds(
            lambda i, c, inst, en, inputs, outputs: ld.Box(
                id=i, call=c, instance=inst, en=en, inputs=inputs, outputs=outputs
            ),
            _ids,
            st.sampled_from(["TON", "ADD", "SEL", "CTU", "Other", "NOPE", "AND"]),
            st.sampled_from([None, "t1", "c1", "a"]),
            st.booleans(),
            st.dictionaries(
                st.sampled_from(["IN", "PT", "IN1", "IN2", "G", "CU", "EN", "X"]), st.one_of(_names, series), max_size=3
            ),
            st.dictionaries(st.sampled_from(["Q", "ET", "OUT", "ENO", "CV"]), _names, max_size=2),
        ),
    )


@given(
    st.lists(st.lists(_elements(2), max_size=4), min_size=1, max_size=3),
    st.lists(st.sampled_from([None, "L", "M", "l", "2"]), min_size=3, max_size=3),
)
def test_property_any_ladder_lowers_or_reports_located_diagnostics(rungs, labels):
    networks = [ld.LdNetwork(id=f"n{i}", label=labels[i], elements=elements) for i, elements in enumerate(rungs)]
    result = lower_project(project(ld_pou("Main", DECL, *networks), ld_pou("Other", "")))
    for diagnostic in result.diagnostics:
        assert diagnostic.pou == "Main" and diagnostic.network is not None, diagnostic
    assert (result.program is None) == any(d.severity == "error" for d in result.diagnostics)


def test_a_text_on_several_pins_is_located_on_the_pin_at_fault():
    """Operand texts the LALR parser reads are parsed once per POU; each pin still gets its own copy of the
    tree, so a problem is reported on the pin it is in (here IN1, not G, though both read 'TRUE')."""
    main = ld_pou(
        "Main", DECL, rung("n1", box("s", "SEL", en=True, G="TRUE", IN0="T#1s", IN1="TRUE", outputs={"OUT": "n"}))
    )
    assert errors(main) == [
        "POU Main, network 1, SEL.IN1: error ST-TYPE-MISMATCH: SEL needs inputs of "
        "one type: got TIME and BOOL; convert one of them with a *_TO_* function"
    ]


def test_many_problems_are_reported_without_comparing_each_with_all_before(monkeypatch):
    """A large diagram with a problem in every network: a new diagnostic is looked up, not compared with every
    earlier one (that made 1,000 broken networks take 16 s); repeated ones are still reported once."""
    from ladderlab.model.diagnostics import Diagnostic

    comparisons = []
    original = Diagnostic.__eq__
    monkeypatch.setattr(Diagnostic, "__eq__", lambda self, other: comparisons.append(1) or original(self, other))
    networks = [rung(f"n{i}", contact(f"c{i}", "Strat"), coil(f"q{i}", "a")) for i in range(300)]
    found = errors(ld_pou("Main", DECL, *networks))
    assert len(found) == 300 and found[299] == (
        "POU Main, network 300, contact Strat: error ST-UNKNOWN-VAR: unknown variable 'Strat'"
    )
    assert len(comparisons) < 300


def test_an_in_out_pin_needs_a_variable_not_the_rung():
    """VAR-51: an in-out is passed by reference; a series of contacts is a computed value."""
    bump = ld_pou("Bump", "VAR_IN_OUT x : BOOL; END_VAR VAR_INPUT go : BOOL; END_VAR", kind="function_block")
    main = ld_pou("Main", "VAR a : BOOL; u : Bump; END_VAR", rung("n1", box("b", "Bump", "u", X=[contact("c", "a")])))
    assert errors(main, bump) == [
        "POU Main, network 1, Bump u.X: error LD-IN-OUT: in-out X of Bump needs a variable, not a computed value"
    ]
