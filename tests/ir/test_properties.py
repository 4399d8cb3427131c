"""Property: lowering any ST body never raises, never drops code it cannot explain (IR-INTERNAL), and what
lowers without errors satisfies the IR invariants. Bodies come from the ST round-trip strategies, so most
are ill-typed: the checker's errors must not trip the lowering either."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir.lower_project import lower_project
from ladderlab.model import Pou, Project
from ladderlab.st.printer import print_statements
from tests.ir.invariants import check_program
from tests.st.test_properties import _statements

# Every name the ST strategies use, declared with a mix of types so that some bodies check cleanly.
DECLARATIONS = """VAR
    a : INT; b : REAL; Start : BOOL; T1 : TON; IN : BOOL; Q : WORD;
    x_1 : ARRAY [1..3] OF INT; counter : DINT; PT : TIME; S : STRING;
END_VAR"""


@given(st.lists(_statements(2), min_size=1, max_size=4))
def test_lowering_random_bodies_never_raises(body):
    project = Project(
        name="p",
        pous=[Pou(name="Main", kind="program", language="st", declarations=DECLARATIONS, body=print_statements(body))],
    )
    result = lower_project(project)
    assert [d.format() for d in result.diagnostics if d.code == "IR-INTERNAL"] == []
    if result.program is not None:
        check_program(result.program)
