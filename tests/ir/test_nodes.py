"""diagram_origin: the same Origin as the dataclass constructor makes (equal, same hash, frozen, same repr)."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir.nodes import Origin, diagram_origin

_TEXT = st.text(min_size=1, max_size=8)


@given(_TEXT, _TEXT, st.none() | _TEXT)
def test_diagram_origin_is_the_constructors_origin(pou: str, network: str, element: str | None) -> None:
    made = diagram_origin(pou, network, element)
    expected = Origin(pou, network=network, element=element)
    assert made == expected and hash(made) == hash(expected) and repr(made) == repr(expected)
    assert dataclasses.asdict(made) == dataclasses.asdict(expected)  # every field set, none left out
    with pytest.raises(dataclasses.FrozenInstanceError):
        made.element = "other"  # type: ignore[misc]
