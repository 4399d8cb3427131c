"""Object orientation in PLCopen XML, the way CODESYS writes it (TC6 XML has no place for it).

A function block's METHODs: ``<pou><addData><data name=".../plcopenxml/method" handleUnknown="implementation">
<Method name="M"><interface>returnType, var lists</interface><body><ST>text</ST></body></Method></data>`` - one
``data`` per method; PROPERTYs: ``<data name=".../plcopenxml/property"><Property name="P"><interface><returnType>
</interface><GetAccessor><interface/><body/></GetAccessor><SetAccessor>...</SetAccessor></Property></data>`` (either
accessor first); EXTENDS: ``<interface><addData><data name=".../plcopenxml/pouinheritance"><Inheritance>
<Extends>Base</Extends></Inheritance>``; IMPLEMENTS: the header of the declaration CODESYS writes as text
(``.../plcopenxml/interfaceasplaintext``: ``FUNCTION_BLOCK F EXTENDS B IMPLEMENTS I1, I2``). What CODESYS does not
say in typed XML (PRIVATE, FINAL, ABSTRACT, the texts as typed) travels in LadderLab's ``<ll:info>`` (``methods``,
``properties``: the model's JSON). INTERFACEs live in the project's types text, which LadderLab's addData carries
verbatim (docs/plcopen.md).
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable

from ...model.project import Accessor, Method, Pou, Property
from ...st.parser import parse_declarations
from .vars import parse_type_text, write_type, write_var_list
from .xml_io import Reader, formatted_text, info_text, local, sub, text_content

METHOD_DATA = "http://www.3s-software.com/plcopenxml/method"
INHERITANCE_DATA = "http://www.3s-software.com/plcopenxml/pouinheritance"
PROPERTY_DATA = "http://www.3s-software.com/plcopenxml/property"
PLAINTEXT_DATA = "http://www.3s-software.com/plcopenxml/interfaceasplaintext"
_IMPLEMENTS = re.compile(r"\bIMPLEMENTS\s+([A-Za-z_][\w\s,]*)", re.IGNORECASE)


def oo_attributes(pou: Pou) -> dict[str, object]:
    """What LadderLab's ``<ll:info>`` of a POU's interface says beyond CODESYS's data."""
    return {
        "extends": pou.extends,
        "implements": ", ".join(pou.implements) or None,
        "abstract": pou.abstract or None,
        "final": pou.final or None,
    }


def oo_texts(pou: Pou) -> dict[str, str]:
    """The methods and properties as the model holds them (JSON), in LadderLab's ``<ll:info>``."""
    texts = {}
    if pou.methods:
        texts["methods"] = json.dumps([m.model_dump(mode="json") for m in pou.methods])
    if pou.properties:
        texts["properties"] = json.dumps([p.model_dump(mode="json") for p in pou.properties])
    return texts


def read_properties(
    node: ET.Element, ours: ET.Element | None, reader: Reader, declarations: Callable[[ET.Element], tuple]
) -> list[Property]:
    """A function block's PROPERTYs: LadderLab's own JSON when it carries it, else CODESYS's property entries (the
    type from the interface's returnType, each accessor's variables read by ``declarations``)."""
    carried = info_text(ours, "properties")
    if carried:
        return [Property.model_validate(item) for item in json.loads(carried)]
    found = []
    for element in _entries(node, reader, PROPERTY_DATA, "Property"):
        interface = reader.child(element, "interface")
        _, type_text = declarations(interface) if interface is not None else ("", None)
        accessors: dict[str, Accessor] = {}
        for kind, tag in (("get", "GetAccessor"), ("set", "SetAccessor")):
            accessor = next((c for c in element if isinstance(c.tag, str) and local(c) == tag), None)
            if accessor is not None:
                holder = reader.child(accessor, "interface")
                text = declarations(holder)[0] if holder is not None else ""
                accessors[kind] = Accessor(declarations=text, body=_st_body(accessor, reader))
        found.append(Property(name=element.get("name", ""), type=type_text or "", **accessors))
    return found


def read_implements(node: ET.Element, reader: Reader) -> list[str]:
    """The INTERFACEs a function block IMPLEMENTS, from the header of CODESYS's declaration text."""
    for data in reader.children(reader.child(node, "addData"), "data"):
        if data.get("name") == PLAINTEXT_DATA:
            holder = next((c for c in data if isinstance(c.tag, str) and local(c) == "InterfaceAsPlainText"), None)
            header = text_content(holder).strip().split("\n", 1)[0] if holder is not None else ""
            found = _IMPLEMENTS.search(header)
            if found:
                return [name.strip() for name in found.group(1).split(",") if name.strip()]
    return []


def _entries(node: ET.Element, reader: Reader, data_name: str, tag: str) -> list[ET.Element]:
    """The ``<tag>`` elements of the ``data_name`` entries in ``node``'s addData (CODESYS: one per entry)."""
    return [
        element
        for data in reader.children(reader.child(node, "addData"), "data")
        if data.get("name") == data_name
        for element in data
        if isinstance(element.tag, str) and local(element) == tag
    ]


def _st_body(element: ET.Element, reader: Reader) -> str:
    """The ST text of a method's or accessor's ``<body>``."""
    body = reader.child(element, "body")
    st = next((c for c in reader.elements(body) if local(c) == "ST"), None) if body is not None else None
    return text_content(st) if st is not None else ""


def write_inheritance(interface_data: ET.Element, pou: Pou) -> None:
    """CODESYS's EXTENDS, in the interface's ``<addData>`` (``interface_data``)."""
    if pou.extends:
        data = sub(interface_data, "data", {"name": INHERITANCE_DATA, "handleUnknown": "implementation"})
        sub(sub(data, "Inheritance"), "Extends").text = pou.extends


def write_methods(node: ET.Element, pou: Pou) -> ET.Element | None:
    """The POU's ``<addData>`` with one CODESYS entry per METHOD and PROPERTY and, for IMPLEMENTS, CODESYS's
    declaration text (None when it has none of them)."""
    if not (pou.methods or pou.properties or pou.implements):
        return None
    add = sub(node, "addData")
    if pou.implements:
        header = f"FUNCTION_BLOCK {pou.name}" + (f" EXTENDS {pou.extends}" if pou.extends else "")
        data = sub(add, "data", {"name": PLAINTEXT_DATA, "handleUnknown": "implementation"})
        text = f"{header} IMPLEMENTS {', '.join(pou.implements)}\n{pou.declarations}"
        formatted_text(data, "InterfaceAsPlainText", text)
    for method in pou.methods:
        data = sub(add, "data", {"name": METHOD_DATA, "handleUnknown": "implementation"})
        element = sub(data, "Method", {"name": method.name})
        interface = sub(element, "interface")
        spec = parse_type_text(method.return_type) if method.return_type else None
        if spec is not None:
            write_type(sub(interface, "returnType"), spec)
        for block in parse_declarations(method.declarations).ast or []:
            write_var_list(interface, block)
        formatted_text(sub(element, "body"), "ST", method.body)
    for prop in pou.properties:
        data = sub(add, "data", {"name": PROPERTY_DATA, "handleUnknown": "implementation"})
        element = sub(data, "Property", {"name": prop.name})
        spec = parse_type_text(prop.type)
        if spec is not None:
            write_type(sub(sub(element, "interface"), "returnType"), spec)
        for tag, accessor in (("GetAccessor", prop.get), ("SetAccessor", prop.set)):
            if accessor is not None:
                holder = sub(element, tag)
                interface = sub(holder, "interface")
                for block in parse_declarations(accessor.declarations).ast or []:
                    write_var_list(interface, block)
                formatted_text(sub(holder, "body"), "ST", accessor.body)
    return add


def read_methods(
    node: ET.Element, ours: ET.Element | None, reader: Reader, declarations: Callable[[ET.Element], str]
) -> list[Method]:
    """A function block's METHODs: LadderLab's own JSON when it carries it, else CODESYS's method entries (their
    interface read by ``declarations``; PUBLIC, the default, since CODESYS's typed XML does not say)."""
    carried = info_text(ours, "methods")
    if carried:
        return [Method.model_validate(item) for item in json.loads(carried)]
    methods = []
    for data in reader.children(reader.child(node, "addData"), "data"):
        if data.get("name") != METHOD_DATA:
            continue
        for element in (c for c in data if isinstance(c.tag, str) and local(c) == "Method"):
            interface = reader.child(element, "interface")
            text, return_type = declarations(interface) if interface is not None else ("", None)
            methods.append(
                Method(
                    name=element.get("name", ""),
                    return_type=return_type,
                    declarations=text,
                    body=_st_body(element, reader),
                )
            )
    return methods


def read_extends(interface: ET.Element | None, reader: Reader) -> str | None:
    """CODESYS's EXTENDS of a function block's interface."""
    for data in reader.children(reader.child(interface, "addData"), "data"):
        if data.get("name") == INHERITANCE_DATA:
            for holder in (c for c in data if isinstance(c.tag, str) and local(c) == "Inheritance"):
                extends = next((c for c in holder if isinstance(c.tag, str) and local(c) == "Extends"), None)
                if extends is not None and (extends.text or "").strip():
                    return extends.text.strip()
    return None
