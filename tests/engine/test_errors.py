"""Faults the engine catches to stop a task (issue: division by zero, index and subrange errors)."""

from __future__ import annotations

import pytest

from ladderlab.engine.errors import INDEX_RANGE, SUBRANGE, PlcRuntimeError, check_index, check_subrange


@pytest.mark.parametrize("index, low, high, offset", [(1, 1, 10, 0), (10, 1, 10, 9), (0, 0, 0, 0), (-3, -5, 5, 2)])
def test_check_index_gives_the_offset(index, low, high, offset):
    assert check_index(index, low, high) == offset


@pytest.mark.parametrize("index", [0, 11, -1])
def test_check_index_raises_outside_the_bounds(index):
    with pytest.raises(PlcRuntimeError) as caught:
        check_index(index, 1, 10)
    assert caught.value.code == INDEX_RANGE
    assert caught.value.message == f"array index {index} is outside 1..10"
    assert str(caught.value) == caught.value.message


def test_check_subrange():
    assert check_subrange(5, 0, 5) == 5
    with pytest.raises(PlcRuntimeError) as caught:
        check_subrange(6, 0, 5)
    assert caught.value.code == SUBRANGE and caught.value.message == "6 is outside the subrange 0..5"
