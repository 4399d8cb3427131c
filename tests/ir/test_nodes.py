"""diagram_origin: the same Origin as the dataclass constructor makes (equal, same hash, frozen, same repr); the IR
nodes have slots, and their fast copy is ``dataclasses.replace``."""

from __future__ import annotations

import dataclasses
import inspect

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir import nodes
from ladderlab.ir.nodes import Origin, diagram_origin
from ladderlab.ir.types import BOOL

_TEXT = st.text(min_size=1, max_size=8)


@given(_TEXT, _TEXT, st.none() | _TEXT)
def test_diagram_origin_is_the_constructors_origin(pou: str, network: str, element: str | None) -> None:
    made = diagram_origin(pou, network, element)
    expected = Origin(pou, network=network, element=element)
    assert made == expected and hash(made) == hash(expected) and repr(made) == repr(expected)
    assert dataclasses.asdict(made) == dataclasses.asdict(expected)  # every field set, none left out
    with pytest.raises(dataclasses.FrozenInstanceError):
        made.element = "other"  # type: ignore[misc]


def test_every_ir_node_has_slots_and_no_instance_dict() -> None:
    """A 50,000-network build keeps millions of IR nodes: a ``__dict__`` each took ~130 MB more at the peak and one
    object more per node for the build's collection (issue 27, benchmarks/build.py)."""
    classes = [c for c in vars(nodes).values() if isinstance(c, type) and dataclasses.is_dataclass(c)]
    assert len(classes) > 25
    assert [c.__name__ for c in classes if c.__module__ == nodes.__name__ and "__slots__" not in vars(c)] == []
    assert not hasattr(diagram_origin("P", "n1", "c1"), "__dict__")


@given(_TEXT, st.integers(), _TEXT)
def test_node_copy_is_dataclasses_replace(name: str, line: int, element: str) -> None:
    """The box templates' copy (no __post_init__, no frozen checks) makes what ``dataclasses.replace`` makes."""
    var = nodes.Var("local", name, BOOL)
    origin = nodes.Origin("P", line=line)
    assign = nodes.Assign(var, nodes.Const(True, BOOL), origin)
    other = diagram_origin("P", "n2", element)
    assert nodes.node_copy(assign, {"origin": other}) == dataclasses.replace(assign, origin=other)
    assert nodes.node_fields(assign) == {f.name: getattr(assign, f.name) for f in dataclasses.fields(assign)}


def test_quick_init_sets_the_fields_as_the_dataclass_init_does() -> None:
    """``quick_init``'s constructor (issue 27) takes the dataclass's parameters with their defaults, positionally and
    by name, sets every field and leaves the node frozen, equal and hashable by value."""
    inits = {c: getattr(c.__init__, "__code__", None) for c in vars(nodes).values() if isinstance(c, type)}
    quick = [c for c, code in inits.items() if code is not None and "set_" in "".join(code.co_names)]
    assert {c.__name__ for c in quick} >= {"Origin", "Const", "Var", "Unary", "Binary", "Call", "Member"}
    for cls in quick:
        fields = dataclasses.fields(cls)
        parameters = list(inspect.signature(cls.__init__).parameters.values())[1:]
        assert [(p.name, p.default) for p in parameters] == [
            (f.name, inspect.Parameter.empty if f.default is dataclasses.MISSING else f.default) for f in fields
        ]
        values = [object() for _ in fields]
        for made in (cls(*values), cls(**{f.name: v for f, v in zip(fields, values)})):
            assert [getattr(made, f.name) for f in fields] == values
            assert made == cls(*values) and hash(made) == hash(cls(*values))
            with pytest.raises(dataclasses.FrozenInstanceError):
                setattr(made, fields[0].name, None)
        required = [f for f in fields if f.default is dataclasses.MISSING]
        made = cls(*values[: len(required)])
        assert [getattr(made, f.name) for f in fields[len(required) :]] == [f.default for f in fields[len(required) :]]
