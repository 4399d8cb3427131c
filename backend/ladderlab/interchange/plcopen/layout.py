"""Deterministic grid layout of LD rungs for export (the project model stores no LD coordinates).

Every element gets a cell (column, row): a series list runs left to right, the
branches of a parallel stack downwards, a box takes a column for the variables
or contact chains feeding its inputs, one for itself and one for the variables
its outputs write; contact chains feeding box inputs (side chains) sit in bands
below the box's pins. Same model, same picture: the layout depends on nothing
but the structure, so exports diff cleanly.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ...model.ld import Box, Compare, LdElement, Parallel

#: Pixel size of a grid cell and the left margin of a rung (rail at x = RAIL_X).
CELL_W = 100
CELL_H = 40
RAIL_X = 20
FIRST_X = 60


@dataclass
class Cell:
    col: int
    row: int


@dataclass
class Layout:
    """Cells of every element (by ``id(element)``), each box's block column, and the rung's size."""

    cells: dict[int, Cell] = field(default_factory=dict)
    block_cols: dict[int, int] = field(default_factory=dict)
    width: int = 0
    height: int = 0


PinRows = Callable[[Box], int]


class _Measure:
    def __init__(self, pin_rows: PinRows):
        self.pin_rows = pin_rows
        self.sizes: dict[int, tuple[int, int]] = {}

    def series(self, items: list[LdElement]) -> tuple[int, int]:
        width, height = 0, 1
        for item in items:
            w, h = self.element(item)
            width, height = width + w, max(height, h)
        return width, height

    def element(self, item: LdElement) -> tuple[int, int]:
        if isinstance(item, Parallel):
            sizes = [self.series(b) for b in item.branches]
            size = (max((w for w, _ in sizes), default=0), sum(h for _, h in sizes) or 1)
        elif isinstance(item, Box):
            sides = [self.series(v) for v in item.inputs.values() if isinstance(v, list)]
            size = (self.left(item) + 2, self.pin_rows(item) + sum(h for _, h in sides))
        elif isinstance(item, Compare):
            size = (2, 3)  # EN, IN1 and IN2 rows
        else:
            size = (1, 1)
        self.sizes[id(item)] = size
        return size

    def left(self, item: Box) -> int:
        """Columns left of a box's block, for its input variables and side chains (at least one)."""
        return max([1, *(self.series(v)[0] for v in item.inputs.values() if isinstance(v, list))])


def layout_rung(items: list[LdElement], pin_rows: PinRows) -> Layout:
    """Cells for one network's series list; columns and rows start at 0."""
    measure = _Measure(pin_rows)
    width, height = measure.series(items)
    layout = Layout(width=width, height=height)
    _place_series(items, 0, 0, measure, layout)
    return layout


def _place_series(items: list[LdElement], col: int, row: int, measure: _Measure, layout: Layout) -> None:
    for item in items:
        _place(item, col, row, measure, layout)
        col += measure.sizes[id(item)][0]


def _place(item: LdElement, col: int, row: int, measure: _Measure, layout: Layout) -> None:
    layout.cells[id(item)] = Cell(col, row)
    if isinstance(item, Parallel):
        for branch in item.branches:
            _place_series(branch, col, row, measure, layout)
            row += measure.series(branch)[1]
    elif isinstance(item, Box):
        layout.block_cols[id(item)] = col + measure.left(item)
        band = row + measure.pin_rows(item)
        for value in item.inputs.values():
            if isinstance(value, list):
                _place_series(value, col, band, measure, layout)
                band += measure.series(value)[1]


def x_of(col: float) -> float:
    return FIRST_X + col * CELL_W


def y_of(top: float, row: float) -> float:
    return top + row * CELL_H
