"""The API the code generator uses: registry, specialisation, checked forms, inline templates."""

from __future__ import annotations

import ast
import builtins
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.stdlib import INLINE_NAMES, STANDARD_FUNCTIONS, function_template, make_function

ISSUE_FUNCTIONS = [
    "TRUNC",
    "ABS",
    "SQRT",
    "LN",
    "LOG",
    "EXP",
    "SIN",
    "COS",
    "TAN",
    "ASIN",
    "ACOS",
    "ATAN",
    "EXPT",
    "ADD",
    "MUL",
    "SUB",
    "DIV",
    "MOD",
    "MOVE",
    "AND",
    "OR",
    "XOR",
    "NOT",
    "SHL",
    "SHR",
    "ROL",
    "ROR",
    "SEL",
    "MAX",
    "MIN",
    "LIMIT",
    "MUX",
    "GT",
    "GE",
    "EQ",
    "LE",
    "LT",
    "NE",
    "LEN",
    "LEFT",
    "RIGHT",
    "MID",
    "CONCAT",
    "INSERT",
    "DELETE",
    "REPLACE",
    "FIND",
    "ADD_TIME",
    "SUB_TIME",
    "MUL_TIME",
    "DIV_TIME",
    "MULTIME",
    "DIVTIME",
    "ADD_TOD_TIME",
    "ADD_DT_TIME",
    "SUB_DATE_DATE",
    "SUB_TOD_TIME",
    "SUB_TOD_TOD",
    "SUB_DT_TIME",
    "SUB_DT_DT",
    "CONCAT_DATE_TOD",
    "DT_TO_TOD",
    "DT_TO_DATE",
    "INT_TO_REAL",
    "REAL_TO_INT",
    "INT_TO_STRING",
    "TIME_TO_TOD",
    "USINT_TO_UDINT",
]


@pytest.mark.parametrize("name", ISSUE_FUNCTIONS)
def test_every_function_of_the_issue_is_registered(name):
    assert STANDARD_FUNCTIONS[name].name == name
    assert re.fullmatch(r"FUN-\d\d", STANDARD_FUNCTIONS[name].spec)


@pytest.mark.parametrize(
    "name, extensible",
    [
        ("ADD", True),
        ("MUL", True),
        ("AND", True),
        ("GT", True),
        ("MUX", True),
        ("CONCAT", True),
        ("NE", False),
        ("SUB", False),
    ],
)
def test_extensibility_FUN_03(name, extensible):
    assert STANDARD_FUNCTIONS[name].extensible is extensible


def test_names_are_case_insensitive():
    assert make_function("add", ["INT", "INT"], "INT")(1, 2) == 3


@pytest.mark.parametrize(
    "name, types, error",
    [
        ("FOO", ["INT"], ValueError),
        ("ADD", ["INT"], TypeError),  # too few inputs
        ("SUB", ["INT"] * 3, TypeError),  # not extensible
        ("ADD", ["MYTYPE", "MYTYPE"], ValueError),
    ],
)
def test_bad_requests_are_rejected(name, types, error):
    with pytest.raises(error):
        make_function(name, types, "INT")


def test_specialised_callables_are_cached():
    assert make_function("ADD", ("INT", "INT"), "INT") is make_function("ADD", ["INT", "INT"], "INT")


def test_polymorphic_functions_accept_any_type_name():
    """SEL, MUX, MOVE and comparisons never look at the value type (enums, structs pass through)."""
    assert make_function("SEL", ["BOOL", "TColor", "TColor"])(True, "red", "green") == "green"
    assert make_function("EQ", ["TColor", "TColor"])("red", "red") is True


@given(st.integers(-(2**15), 2**15 - 1), st.integers(-(2**15), 2**15 - 1))
def test_checked_form_gives_the_same_value(a, b):
    for name in ("ADD", "SUB", "MUL", "MAX", "GT"):
        fast = make_function(name, ["INT", "INT"], "INT")
        checked = make_function(name, ["INT", "INT"], "INT", checked=True)
        assert checked(a, b)[0] == fast(a, b)


# --- inline templates --------------------------------------------------------------------------------

TEMPLATED = [
    ("ADD", ["INT", "INT", "INT"], "INT", (30000, 2767, 1)),
    ("SUB", ["UINT", "UINT"], "UINT", (0, 1)),
    ("MUL", ["REAL", "REAL"], "REAL", (0.1, 3.0)),
    ("DIV", ["DINT", "DINT"], "DINT", (-7, 2)),
    ("DIV", ["LREAL", "LREAL"], "LREAL", (1.0, 0.0)),
    ("MOD", ["INT", "INT"], "INT", (-7, 2)),
    ("ABS", ["INT"], "INT", (-32768,)),
    ("SQRT", ["REAL"], "REAL", (2.0,)),
    ("EXPT", ["REAL", "INT"], "REAL", (2.0, 3)),
    ("AND", ["BOOL", "BOOL", "BOOL"], "BOOL", (True, True, False)),
    ("OR", ["WORD", "WORD"], "WORD", (0x00FF, 0x0F0F)),
    ("NOT", ["BYTE"], "BYTE", (0xF0,)),
    ("NOT", ["BOOL"], "BOOL", (False,)),
    ("SHL", ["BYTE", "INT"], "BYTE", (0x0F, 2)),
    ("GT", ["INT", "INT"], "BOOL", (2, 1)),
    ("LIMIT", ["INT", "INT", "INT"], "INT", (0, 150, 100)),
    ("MOVE", ["INT"], "INT", (5,)),
    ("INT_TO_SINT", ["INT"], "SINT", (200,)),
    ("REAL_TO_INT", ["REAL"], "INT", (2.5,)),
    ("SINT_TO_INT", ["SINT"], "INT", (-5,)),
    ("ADD_TOD_TIME", ["TOD", "TIME"], "TOD", (82_800_000, 7_200_000)),
    ("SUB_DT_DT", ["DT", "DT"], "TIME", (10**12, 0)),
    ("CONCAT", ["STRING", "STRING"], "STRING[3]", ("ab", "cd")),
    ("LEN", ["STRING"], "INT", ("abc",)),
]


@pytest.mark.parametrize("name, types, result, args", TEMPLATED)
def test_templates_evaluate_each_argument_once_in_order(name, types, result, args):
    template = function_template(name, types, result)
    assert template is not None
    seen = []

    def arg(i):
        seen.append(i)
        return args[i]

    source = template.format(*(f"arg({i})" for i in range(len(args))))
    value = eval(source, {**INLINE_NAMES, "arg": arg})
    assert seen == list(range(len(args)))
    assert value == make_function(name, types, result)(*args)


@pytest.mark.parametrize("name, types, result, args", TEMPLATED)
def test_templates_only_name_inline_names_and_builtins(name, types, result, args):
    tree = ast.parse(function_template(name, types, result).format(*["arg"] * len(args)), mode="eval")
    names = {node.id for node in ast.walk(tree) if isinstance(node, ast.Name)} - {"arg"}
    assert all(n in INLINE_NAMES or hasattr(builtins, n) for n in names)


@pytest.mark.parametrize(
    "name, types",
    [
        ("SEL", ["BOOL", "INT", "INT"]),  # evaluates only one input
        ("MUX", ["INT", "INT", "INT"]),
        ("MAX", ["INT", "INT"]),  # uses an input twice
        ("GT", ["INT", "INT", "INT"]),  # chained comparison short-circuits
        ("LEFT", ["STRING", "INT"]),  # per-call helper
        ("STRING_TO_INT", ["STRING"]),
    ],
)
def test_no_template_where_inlining_could_change_evaluation(name, types):
    assert function_template(name, types, "INT") is None


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("ADD", ["INT", "INT"], (32767, 1), -32768),  # FUN-02: the result has the inputs' type
        ("MUL", ["REAL", "REAL"], (0.1, 1.0), 0.10000000149011612),
        ("DIV", ["SINT", "SINT"], (-128, -1), -128),
        ("TRUNC", ["LREAL"], (2.0**40,), 0),  # APB-06 [REC]: DINT
        ("CONCAT", ["STRING", "STRING"], ("x" * 50, "y" * 50), "x" * 50 + "y" * 30),  # STRING = STRING[80]
    ],
)
def test_result_type_defaults(name, types, args, expected):
    assert make_function(name, types)(*args) == expected


# --- contract with the checker's catalogue (st/stdlib.py) --------------------------------------------


def test_runtime_has_every_catalogued_function_with_the_same_arity():
    from ladderlab.iec.stdlib import FUNCTIONS

    assert set(FUNCTIONS) <= set(STANDARD_FUNCTIONS)
    for name, entry in FUNCTIONS.items():
        runtime = STANDARD_FUNCTIONS[name]
        assert (runtime.inputs, runtime.extensible) == (len(entry.inputs), entry.extensible), name


def test_runtime_fbs_have_the_catalogued_pins():
    from ladderlab.engine.stdlib import STANDARD_FBS
    from ladderlab.iec.stdlib import FUNCTION_BLOCKS

    for name, entry in FUNCTION_BLOCKS.items():
        cls = STANDARD_FBS[name]
        assert tuple(p.name for p in entry.inputs) == cls.INPUTS, name
        assert tuple(p.name for p in entry.outputs) == cls.OUTPUTS, name
