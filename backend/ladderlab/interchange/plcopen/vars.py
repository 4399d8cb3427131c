"""ST declarations <-> PLCopen typed variable lists, data types and initial values.

The project keeps TYPE and VAR blocks as ST text; PLCopen wants typed XML. Export
parses the text with the project's ST parser and writes ``<variable>``/``<dataType>``
elements; import builds ST AST nodes from the XML and prints them with the ST
printer, so both directions share one grammar. Declaration comments travel as
``<documentation>``; ``R_EDGE``/``F_EDGE`` (which PLCopen cannot express) travel in
LadderLab's addData.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ...iec.elementary import canonical_type_name, elementary
from ...st import ast
from ...st.parser import parse_expression, parse_type
from ...st.printer import print_expression, print_type
from .instance_args import read_instance_type, split_instance_type, write_input_assignments
from .xml_io import Reader, data_entries, formatted_text, info, ladderlab_data, local, sub, text_content

#: Elementary types the XSD names directly (TIME_OF_DAY and DATE_AND_TIME are spelled TOD and DT there).
XSD_ELEMENTARY = (
    "BOOL",
    "BYTE",
    "WORD",
    "DWORD",
    "LWORD",
    "SINT",
    "INT",
    "DINT",
    "LINT",
    "USINT",
    "UINT",
    "UDINT",
    "ULINT",
    "REAL",
    "LREAL",
    "TIME",
    "DATE",
    "DT",
    "TOD",
)
_XSD_SPELLING = {"TIME_OF_DAY": "TOD", "DATE_AND_TIME": "DT"}
#: CODESYS's attribute pragmas of a declaration: ``<data name=...><Attributes><Attribute Name= Value=/>``
ATTRIBUTES_DATA = "http://www.3s-software.com/plcopenxml/attributes"
_GENERIC = (
    "ANY",
    "ANY_DERIVED",
    "ANY_ELEMENTARY",
    "ANY_MAGNITUDE",
    "ANY_NUM",
    "ANY_REAL",
    "ANY_INT",
    "ANY_BIT",
    "ANY_STRING",
    "ANY_DATE",
)

#: VAR block keyword <-> interface list element.
LIST_BY_KIND = {
    "VAR": "localVars",
    "VAR_TEMP": "tempVars",
    "VAR_INPUT": "inputVars",
    "VAR_OUTPUT": "outputVars",
    "VAR_IN_OUT": "inOutVars",
    "VAR_EXTERNAL": "externalVars",
    "VAR_GLOBAL": "globalVars",
    "VAR_ACCESS": "accessVars",
}
KIND_BY_LIST = {v: k for k, v in LIST_BY_KIND.items()}
#: VAR block qualifier <-> varList boolean attribute.
_QUALIFIERS = {"CONSTANT": "constant", "RETAIN": "retain", "NON_RETAIN": "nonretain", "PERSISTENT": "persistent"}


# ---------------------------------------------------------------- export


def write_type(parent: ET.Element, spec: ast.TypeSpec) -> None:
    """Append the dataType choice element for ``spec`` to ``parent`` (a ``<type>`` or ``<baseType>``)."""
    if isinstance(spec, ast.NamedType):
        name = canonical_type_name(spec.name)
        name = _XSD_SPELLING.get(name, name)
        if name in XSD_ELEMENTARY or name in _GENERIC:
            sub(parent, name)
        elif name in ("STRING", "WSTRING"):
            sub(parent, name.lower())
        else:
            sub(parent, "derived", {"name": spec.name})
    elif isinstance(spec, ast.SizedType):
        sub(parent, spec.name.lower(), {"length": print_expression(spec.size)})
    elif isinstance(spec, ast.SubrangeType):
        info_ = elementary(spec.base)
        node = sub(parent, "subrangeSigned" if info_ is None or info_.signed else "subrangeUnsigned")
        sub(node, "range", {"lower": print_expression(spec.low), "upper": print_expression(spec.high)})
        write_type(sub(node, "baseType"), ast.NamedType(spec.base))
    elif isinstance(spec, ast.ArrayType):
        node = sub(parent, "array")
        for bounds in spec.ranges:
            low, high = ("*", "*") if bounds is None else (print_expression(bounds[0]), print_expression(bounds[1]))
            sub(node, "dimension", {"lower": low, "upper": high})
        write_type(sub(node, "baseType"), spec.element)
    elif isinstance(spec, ast.PointerType) and spec.kind == "REFERENCE TO":
        # TC6 XML has no implicitly dereferenced reference: its ST text as a derived type, which reads back
        sub(parent, "derived", {"name": print_type(spec)})
    elif isinstance(spec, ast.PointerType):
        write_type(sub(sub(parent, "pointer"), "baseType"), spec.target)
    elif isinstance(spec, ast.EnumType):
        enum = sub(parent, "enum")
        values = sub(enum, "values")
        for value in spec.values:
            sub(
                values,
                "value",
                {"name": value.name, "value": None if value.value is None else print_expression(value.value)},
            )
        if spec.base:  # TC6 XML: enum's optional baseType
            write_type(sub(enum, "baseType"), ast.NamedType(spec.base))
    elif isinstance(spec, ast.StructType):
        node = sub(parent, "struct")
        for decl in spec.members:
            write_variables(node, decl)
    elif isinstance(spec, (ast.InstanceArgsType, ast.PositionalArgsType)):  # (outside a variable: a build error)
        sub(parent, "derived", {"name": spec.name})
    else:  # pragma: no cover - the union is closed
        raise TypeError(f"not an ST type node: {spec!r}")


def write_value(parent: ET.Element, init: ast.Init | None) -> None:
    """Append the value choice (simpleValue / arrayValue / structValue) for ``init`` to ``parent``."""
    if isinstance(init, ast.ArrayInit):
        node = sub(parent, "arrayValue")
        for item in init.items:
            if isinstance(item, ast.RepeatInit):
                write_value(sub(node, "value", {"repetitionValue": item.count}), item.value)
            else:
                write_value(sub(node, "value"), item)
    elif isinstance(init, ast.StructInit):
        node = sub(parent, "structValue")
        for member, value in init.fields:
            write_value(sub(node, "value", {"member": member}), value)
    elif init is None:
        sub(parent, "simpleValue")
    else:
        sub(parent, "simpleValue", {"value": print_expression(init)})


def write_variables(parent: ET.Element, decl: ast.VarDecl) -> None:
    """One ``<variable>`` per declared name (``a, b : INT`` becomes two); an instance's FB_init arguments in addData
    (instance_args.py)."""
    spec, instance = split_instance_type(decl.type)
    for name in decl.names:
        variable = sub(parent, "variable", {"name": name.name or "", "address": name.address})
        write_type(sub(variable, "type"), spec)
        if decl.init is not None:
            write_value(sub(variable, "initialValue"), decl.init)
        if decl.edge or instance:
            add_data = ladderlab_data(variable, {"edge": decl.edge, "instance": instance})
            write_input_assignments(add_data, decl.type)
        if decl.comment:
            formatted_text(variable, "documentation", decl.comment)


def write_var_list(parent: ET.Element, block: ast.VarBlock) -> ET.Element:
    attrs = {attr: True for word, attr in _QUALIFIERS.items() if word in block.qualifiers}
    node = sub(parent, LIST_BY_KIND.get(block.kind, "localVars"), attrs)
    for decl in block.decls:
        write_variables(node, decl)
    return node


def write_documentation(interface: ET.Element, declarations: str) -> None:
    """The ``//`` lines that open a declarations text as the interface's ``<documentation>``, without the ``//``: where
    CODESYS writes the comment above a POU's or method's VAR blocks (the import puts the ``//`` back)."""
    lines = []
    for line in declarations.splitlines():
        if not line.startswith("//"):
            break
        lines.append(line[2:])
    if lines:
        formatted_text(interface, "documentation", "\n".join(lines))


def write_data_type(parent: ET.Element, decl: ast.TypeDecl) -> None:
    node = sub(parent, "dataType", {"name": decl.name})
    write_type(sub(node, "baseType"), decl.type)
    if decl.init is not None:
        write_value(sub(node, "initialValue"), decl.init)
    if decl.pack_mode is not None:  # CODESYS's attribute pragmas travel in its own addData entry
        data = sub(sub(node, "addData"), "data", {"name": ATTRIBUTES_DATA, "handleUnknown": "implementation"})
        sub(sub(data, "Attributes"), "Attribute", {"Name": "pack_mode", "Value": decl.pack_mode})


def parse_type_text(text: str) -> ast.TypeSpec | None:
    """A type written as text (a function's ``return_type``), or None when it is not one."""
    parsed = parse_type(text)
    return parsed.ast if parsed.ok else None


# ---------------------------------------------------------------- import


class VarReader:
    """Builds ST AST declarations from XML; problems become diagnostics of ``reader`` for ``pou``."""

    def __init__(self, reader: Reader, pou: str | None = None):
        self.reader = reader
        self.pou = pou

    def _problem(self, message: str, element: ET.Element, severity: str = "warning") -> None:
        self.reader.report("PLCOPEN-DECL", message, element, severity=severity, pou=self.pou)

    def expression(self, text: str, element: ET.Element) -> ast.Expr:
        """An ST expression from an attribute; text that does not parse is kept verbatim (and reported)."""
        parsed = parse_expression(text)
        if parsed.ast is not None and parsed.ok:
            return parsed.ast
        self._problem(f"'{text}' is not an ST expression; kept as written", element)
        return ast.Name(text.strip())

    def type(self, holder: ET.Element | None) -> ast.TypeSpec:
        """The type inside a ``<type>``/``<baseType>``/``<returnType>`` element."""
        choice = next(self.reader.elements(holder), None)
        if choice is None:
            if holder is not None:
                self._problem("a type element is empty; assumed BOOL", holder, "error")
            return ast.NamedType("BOOL")
        tag = local(choice)
        upper = tag.upper()
        if upper in XSD_ELEMENTARY or upper in _GENERIC:
            return ast.NamedType(upper)
        if upper in ("STRING", "WSTRING"):
            length = choice.get("length")
            if length:
                return ast.SizedType(upper, self.expression(length, choice))
            return ast.NamedType(upper)
        if tag == "derived" and choice.get("name", "").upper().startswith("REFERENCE "):
            spec = parse_type(choice.get("name", "")).ast
            if isinstance(spec, ast.PointerType):
                return spec
        if tag == "derived":
            return ast.NamedType(choice.get("name", ""))
        if tag == "array":
            ranges = []
            for dim in self.reader.children(choice, "dimension"):
                low, high = dim.get("lower", ""), dim.get("upper", "")
                ranges.append(None if low == "*" else (self.expression(low, dim), self.expression(high, dim)))
            return ast.ArrayType(ranges, self.type(self.reader.child(choice, "baseType")))
        if tag in ("subrangeSigned", "subrangeUnsigned"):
            bounds = self.reader.child(choice, "range")
            base = self.type(self.reader.child(choice, "baseType"))
            low = self.expression(bounds.get("lower", "0"), bounds) if bounds is not None else ast.IntLit(0)
            high = self.expression(bounds.get("upper", "0"), bounds) if bounds is not None else ast.IntLit(0)
            return ast.SubrangeType(base.name if isinstance(base, ast.NamedType) else "INT", low, high)
        if tag == "pointer":
            return ast.PointerType("REF_TO", self.type(self.reader.child(choice, "baseType")))
        if tag == "enum":
            values = [
                ast.EnumValue(v.get("name", ""), self.expression(v.get("value"), v) if v.get("value") else None)
                for v in self.reader.children(self.reader.child(choice, "values"), "value")
            ]
            base_type = self.reader.child(choice, "baseType")
            base = self.type(base_type) if base_type is not None else None
            return ast.EnumType(values, base=base.name if isinstance(base, ast.NamedType) else None)
        if tag == "struct":
            return ast.StructType(self.declarations(choice))
        self._problem(f"unknown type element <{tag}>; kept as the type name {tag}", choice, "error")
        return ast.NamedType(tag)

    def value(self, holder: ET.Element | None) -> ast.Init | None:
        """The initial value inside an ``<initialValue>`` (or an array/struct ``<value>``)."""
        choice = next(self.reader.elements(holder), None)
        if choice is None:
            return None
        tag = local(choice)
        if tag == "simpleValue":
            text = choice.get("value")
            return None if text is None else self.expression(text, choice)
        if tag == "arrayValue":
            items: list = []
            for value in self.reader.children(choice, "value"):
                item = self.value(value)
                count = value.get("repetitionValue", "1")
                if count.strip() != "1" and count.strip().isdigit():
                    items.append(ast.RepeatInit(int(count), item))
                elif item is not None:
                    items.append(item)
            return ast.ArrayInit(items)
        if tag == "structValue":
            return ast.StructInit([(v.get("member", ""), self.value(v)) for v in self.reader.children(choice, "value")])
        self._problem(f"unknown value element <{tag}>; the initial value is dropped", choice)
        return None

    def declarations(self, var_list: ET.Element) -> list[ast.VarDecl]:
        decls = []
        for variable in self.reader.children(var_list, "variable"):
            name = variable.get("name") or None
            address = variable.get("address") or None
            extra = info(variable, self.reader)
            spec = self.type(self.reader.child(variable, "type"))
            carried = extra.get("instance") if extra is not None else None
            decl = ast.VarDecl(
                [ast.DeclName(name, address)],
                read_instance_type(variable, spec, carried, self.reader, self.expression, self._problem),
                self.value(self.reader.child(variable, "initialValue")),
                extra.get("edge") if extra is not None else None,
            )
            comment = text_content(self.reader.child(variable, "documentation")).strip()
            decl.comment = comment or None
            decls.append(decl)
        return decls

    def var_block(self, var_list: ET.Element, kind: str | None = None) -> ast.VarBlock:
        qualifiers = [word for word, attr in _QUALIFIERS.items() if var_list.get(attr) in ("true", "1")]
        return ast.VarBlock(kind or KIND_BY_LIST[local(var_list)], qualifiers, self.declarations(var_list))

    def data_type(self, element: ET.Element) -> ast.TypeDecl:
        r = self.reader
        attributes = [
            attribute
            for data in data_entries(element, r, ATTRIBUTES_DATA)
            for holder in r.children(data, "Attributes")
            for attribute in r.children(holder, "Attribute")
        ]
        pack_mode = next((a.get("Value") for a in attributes if a.get("Name") == "pack_mode"), None)
        if pack_mode is not None and ("'" in pack_mode or "}" in pack_mode):
            self._problem(
                f"the pack_mode {pack_mode!r} cannot be written as a pragma; it is left out", element, "error"
            )
            pack_mode = None
        return ast.TypeDecl(
            element.get("name", ""),
            self.type(r.child(element, "baseType")),
            self.value(r.child(element, "initialValue")),
            pack_mode=pack_mode,
        )
