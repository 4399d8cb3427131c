"""Property tests: random ASTs round-trip through the printer; random or mutated text never raises."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.st import ast
from ladderlab.st.parser import parse_declarations, parse_expression, parse_source, parse_statements
from ladderlab.st.printer import print_expression, print_source, print_statements

NAMES = st.sampled_from(["a", "b", "Start", "T1", "IN", "Q", "x_1", "counter", "PT", "S"])
BINARY_OPS = st.sampled_from(["OR", "XOR", "AND", "=", "<>", "<", ">", "<=", ">=", "+", "-", "*", "/", "MOD", "**"])

literals = st.one_of(
    st.builds(ast.IntLit, st.integers(0, 2**40), st.sampled_from([10, 16, 2, 8])),
    st.builds(ast.RealLit, st.floats(0, 1e30, allow_nan=False, allow_infinity=False)),
    st.builds(ast.BoolLit, st.booleans()),
    st.builds(ast.StringLit, st.text(alphabet="ab $'\"\n\t\rzé", max_size=8), st.booleans()),
    st.builds(ast.TimeLit, st.just("TIME"), st.integers(-(10**9), 10**9)),
    st.builds(ast.TimeLit, st.just("DATE"), st.integers(-3000, 30000).map(lambda d: d * 86_400_000)),
    st.builds(ast.TimeLit, st.just("TIME_OF_DAY"), st.integers(0, 86_399_999)),
    st.builds(ast.TimeLit, st.just("DATE_AND_TIME"), st.integers(0, 2 * 10**12)),
    st.builds(ast.TypedLit, st.sampled_from(["INT", "BYTE", "DINT"]), st.builds(ast.IntLit, st.integers(-999, 999))),
)
names = st.builds(ast.Name, NAMES)


def _accesses(expressions):
    """Variable access paths over ``expressions`` (the grammar only allows them as bases of . [] ^ ())."""

    def extend(base):
        return st.one_of(
            st.builds(ast.Member, base, NAMES),
            st.builds(ast.Index, base, st.lists(expressions, min_size=1, max_size=3)),
            st.builds(ast.Deref, base),
            st.builds(ast.Call, base, _args(expressions)),
        )

    return st.recursive(names, extend, max_leaves=4)


def _args(expressions):
    formal = st.lists(
        st.one_of(
            st.builds(ast.Arg, NAMES, expressions),
            st.builds(lambda n, v, neg: ast.Arg(n, v, output=True, negated=neg), NAMES, names, st.booleans()),
        ),
        max_size=3,
    )
    positional = st.lists(st.builds(ast.Arg, st.none(), expressions), max_size=3)
    return st.one_of(formal, positional)


def _combine(children):
    return st.one_of(
        st.builds(ast.Binary, BINARY_OPS, children, children),
        st.builds(ast.Unary, st.sampled_from(["-", "NOT"]), children),
        _accesses(children),
    )


expressions = st.recursive(st.one_of(literals, names), _combine, max_leaves=12)


def _statements(depth: int):
    simple = st.one_of(
        st.builds(ast.Assign, _accesses(expressions), expressions),
        st.builds(ast.CallStmt, st.builds(ast.Call, names, _args(expressions))),
        st.builds(ast.Exit),
        st.builds(ast.Return),
        st.builds(ast.Empty),
    )
    if depth == 0:
        return simple
    body = st.lists(_statements(depth - 1), max_size=3)
    labels = st.lists(
        st.one_of(
            st.builds(ast.IntLit, st.integers(0, 99)),
            names,
            st.builds(
                ast.CaseRange, st.builds(ast.IntLit, st.integers(0, 9)), st.builds(ast.IntLit, st.integers(10, 99))
            ),
        ),
        min_size=1,
        max_size=3,
    )
    return st.one_of(
        simple,
        st.builds(ast.If, st.lists(st.tuples(expressions, body), min_size=1, max_size=3), st.none() | body),
        st.builds(
            ast.Case, expressions, st.lists(st.builds(ast.CaseBranch, labels, body), max_size=3), st.none() | body
        ),
        st.builds(ast.For, names, expressions, expressions, st.none() | expressions, body),
        st.builds(ast.While, expressions, body),
        st.builds(ast.Repeat, body, expressions),
    )


statements = st.lists(_statements(2), max_size=4)
type_specs = st.one_of(
    st.builds(ast.NamedType, st.sampled_from(["INT", "BOOL", "TON", "TColor"])),
    st.builds(ast.SizedType, st.just("STRING"), st.builds(ast.IntLit, st.integers(1, 255))),
    st.builds(
        ast.ArrayType,
        st.lists(
            st.tuples(st.builds(ast.IntLit, st.integers(0, 5)), st.builds(ast.IntLit, st.integers(5, 9))),
            min_size=1,
            max_size=3,
        ),
        st.builds(ast.NamedType, st.just("REAL")),
    ),
    st.builds(ast.PointerType, st.sampled_from(["REF_TO", "POINTER TO"]), st.builds(ast.NamedType, st.just("INT"))),
)
var_decls = st.builds(
    ast.VarDecl,
    st.lists(st.builds(ast.DeclName, NAMES), min_size=1, max_size=2),
    type_specs,
    st.none() | expressions,
    st.sampled_from([None, "R_EDGE"]),
)
var_blocks = st.builds(
    ast.VarBlock,
    st.sampled_from(["VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_TEMP"]),
    st.sampled_from([[], ["CONSTANT"], ["RETAIN"]]),
    st.lists(var_decls, max_size=3),
)
# Object orientation (IEC 61131-3 ed. 3, 6.6.5-6.6.6; CODESYS): members of a function block or a program.
MODIFIERS = st.lists(st.sampled_from(["PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL", "FINAL", "ABSTRACT"]), max_size=2)
member_blocks = st.lists(var_blocks, max_size=1)
member_body = st.lists(_statements(1), max_size=2)
methods = st.builds(ast.MethodDecl, NAMES, MODIFIERS, st.none() | type_specs, member_blocks, member_body)
accessors = st.builds(ast.AccessorDecl, st.sampled_from(["GET", "SET"]), member_blocks, member_body)
properties = st.builds(ast.PropertyDecl, NAMES, MODIFIERS, type_specs, st.lists(accessors, max_size=2))
# An INTERFACE's prototypes: methods and accessors without bodies.
prototypes = st.builds(ast.MethodDecl, NAMES, st.just([]), st.none() | type_specs, member_blocks, st.just([]))
property_prototypes = st.builds(
    ast.PropertyDecl,
    NAMES,
    st.just([]),
    type_specs,
    st.lists(st.builds(ast.AccessorDecl, st.sampled_from(["GET", "SET"]), st.just([]), st.just([])), max_size=2),
)
interfaces = st.builds(
    ast.InterfaceDecl,
    NAMES,
    st.lists(NAMES, max_size=2),
    st.lists(prototypes, max_size=2),
    properties=st.lists(property_prototypes, max_size=2),
)


@st.composite
def _pous(draw):
    """A PROGRAM or FUNCTION_BLOCK with METHODs and PROPERTYs; a function block also with ACTIONs, FINAL or
    ABSTRACT, EXTENDS and IMPLEMENTS (a program has none of those: the grammar's ``_program_member``)."""
    kind = draw(st.sampled_from(["PROGRAM", "FUNCTION_BLOCK"]))
    fb = kind == "FUNCTION_BLOCK"
    return ast.Pou(
        kind,
        draw(NAMES),
        None,
        draw(st.lists(var_blocks, max_size=2)),
        draw(statements),
        methods=draw(st.lists(methods, max_size=2)),
        properties=draw(st.lists(properties, max_size=1)),
        actions=draw(st.lists(st.builds(ast.ActionDecl, NAMES, member_body), max_size=1)) if fb else [],
        modifier=draw(st.sampled_from([None, "FINAL", "ABSTRACT"])) if fb else None,
        extends=draw(st.none() | NAMES) if fb else None,
        implements=draw(st.lists(NAMES, max_size=2)) if fb else [],
    )


pous = _pous()


@given(expressions)
def test_expressions_round_trip(tree):
    result = parse_expression(print_expression(tree))
    assert result.diagnostics == []
    assert result.ast == tree


@given(statements)
def test_statements_round_trip(tree):
    result = parse_statements(print_statements(tree))
    assert result.diagnostics == []
    assert result.ast == tree


@given(st.lists(pous, min_size=1, max_size=2))
def test_pous_round_trip(items):
    tree = ast.Source(items)
    result = parse_source(print_source(tree))
    assert result.diagnostics == []
    assert result.ast == tree


@given(st.lists(st.one_of(pous, interfaces), min_size=1, max_size=3))
def test_sources_with_interfaces_round_trip(items):
    tree = ast.Source(items)
    result = parse_source(print_source(tree))
    assert result.diagnostics == []
    assert result.ast == tree


@given(st.binary(max_size=200))
def test_random_bytes_give_diagnostics_never_exceptions(data):
    text = data.decode("latin-1")
    for parse in (parse_source, parse_statements, parse_declarations, parse_expression):
        result = parse(text)
        assert all(d.code.startswith("ST-") and d.line is not None for d in result.diagnostics)


VALID = """FUNCTION_BLOCK Motor
VAR_INPUT start : BOOL R_EDGE; END_VAR
VAR t : TON; n : ARRAY [1..3] OF INT := [3(0)]; END_VAR
t(IN := start, PT := T#12s);
IF t.Q AND n[1] > 0 THEN n[2] := n[1] * 2; ELSE n[3] := -1; END_IF;
CASE n[1] OF 1..5: ; ELSE RETURN; END_CASE;
END_FUNCTION_BLOCK
"""


@given(
    st.lists(
        st.tuples(
            st.integers(0, len(VALID)),
            st.integers(0, 6),
            st.sampled_from(["", ";", "(", ")", "END_IF", "'", "(*", ":=", "x", "\n", "[", "."]),
        ),
        max_size=4,
    )
)
def test_mutated_sources_give_diagnostics_never_exceptions(edits):
    text = VALID
    for position, length, insert in edits:
        text = text[:position] + insert + text[position + length :]
    result = parse_source(text)
    assert result.ast is not None or result.diagnostics
    assert all(d.line is not None for d in result.diagnostics)
