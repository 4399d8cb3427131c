"""An instance's FB_init arguments in PLCopen XML (``fb : F(n := 3)``, st/fb_init.py).

TC6 XML types a variable ``<derived name="F"/>`` and has no place for them. CODESYS writes them in its addData
entry ``inputassignments`` (``<InputAssignments><InputAssignment><Value>3</Value>...``, by position, as its
compiler reads them); LadderLab writes that entry too, each value with its input's ``<Name>``, and the exact ST of the
type in its own addData (``instance``), which is all an array's per-element arguments can travel in (a file
without it gives the array's elements none). The import takes
LadderLab's text when there is one, else CODESYS's values: by name, or by position (``F(1, 'a')``).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable

from ...iec.elementary import elementary
from ...st import ast
from ...st.fb_init import instance_spec
from ...st.parser import parse_type
from ...st.printer import print_expression, print_type
from .xml_io import Reader, data_entries, sub, text_content

INPUTASSIGNMENTS_DATA = "http://www.3s-software.com/plcopenxml/inputassignments"


def _block(name: str) -> bool:
    """A type name that may be a function block's (anything but an elementary or string type)."""
    return elementary(name) is None and name.upper() not in ("STRING", "WSTRING")


def split_instance_type(spec: ast.TypeSpec) -> tuple[ast.TypeSpec, str | None]:
    """The type to write as TC6 XML, and the declaration's whole type as ST when it carries FB_init arguments."""
    plain, written = instance_spec(spec, _block)
    return plain, print_type(spec) if written is not None else None


def write_input_assignments(add_data: ET.Element, spec: ast.TypeSpec) -> None:
    """CODESYS's entry for one instance's arguments (an array's have none in CODESYS's format)."""
    _, written = instance_spec(spec, _block)
    if written is None or isinstance(spec, ast.ArrayType):
        return
    data = sub(add_data, "data", {"name": INPUTASSIGNMENTS_DATA, "handleUnknown": "implementation"})
    assignments = sub(data, "InputAssignments")
    for name, value, _ in written[0]:
        assignment = sub(assignments, "InputAssignment")
        if name is not None:
            sub(assignment, "Name").text = name
        sub(assignment, "Value").text = print_expression(value)


def read_instance_type(
    variable: ET.Element,
    spec: ast.TypeSpec,
    carried: str | None,
    reader: Reader,
    expression: Callable[[str, ET.Element], ast.Expr],
    problem: Callable[[str, ET.Element], None],
) -> ast.TypeSpec:
    """The variable's type with its FB_init arguments: LadderLab's ``carried`` ST, else CODESYS's entry."""
    if carried:
        parsed = parse_type(carried)
        if parsed.ast is not None and parsed.ok:
            return parsed.ast
        problem(f"the instance type '{carried}' does not parse; its FB_init arguments are dropped", variable)
    values = [
        (text_content(reader.child(a, "Name")).strip() or None, text_content(reader.child(a, "Value")).strip(), a)
        for data in data_entries(variable, reader, INPUTASSIGNMENTS_DATA)
        for holder in reader.children(data, "InputAssignments")
        for a in reader.children(holder, "InputAssignment")
    ]
    if not values:
        return spec
    if not isinstance(spec, ast.NamedType):
        problem("FB_init arguments of a variable that is not one function block instance are dropped", variable)
        return spec
    args = [(name, expression(value, node)) for name, value, node in values]
    if all(name is not None for name, _ in args):
        return ast.EnumType([ast.EnumValue(name, value) for name, value in args], base=spec.name)
    if all(name is None for name, _ in args):  # (one alone prints as ``F(3)``, which reads back as a sized type)
        return ast.PositionalArgsType(spec.name, [value for _, value in args])
    problem("FB_init arguments given partly by name and partly by position are dropped", variable)
    return spec
