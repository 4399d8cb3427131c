"""Object orientation in PLCopen XML, the way CODESYS writes it (TC6 XML has no place for it).

A function block's METHODs: ``<pou><addData><data name=".../plcopenxml/method" handleUnknown="implementation">
<Method name="M"><interface>returnType, var lists</interface><body><ST>text</ST></body></Method></data>`` - one
``data`` per method; EXTENDS: ``<interface><addData><data name=".../plcopenxml/pouinheritance"><Inheritance>
<Extends>Base</Extends></Inheritance>``. What CODESYS does not say in typed XML (PRIVATE, FINAL, ABSTRACT,
IMPLEMENTS, the texts as typed) travels in LadderLab's ``<ll:info>`` (``methods``: the model's JSON).
INTERFACEs live in the project's types text, which LadderLab's addData carries verbatim (docs/plcopen.md).
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections.abc import Callable

from ...model.project import Method, Pou, Property
from ...st.parser import parse_declarations
from .vars import parse_type_text, write_type, write_var_list
from .xml_io import Reader, formatted_text, info_text, local, sub, text_content

METHOD_DATA = "http://www.3s-software.com/plcopenxml/method"
INHERITANCE_DATA = "http://www.3s-software.com/plcopenxml/pouinheritance"


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


def read_properties(ours: ET.Element | None) -> list[Property]:
    """LadderLab's own PROPERTYs (CODESYS's property data is not read yet)."""
    carried = info_text(ours, "properties")
    return [Property.model_validate(item) for item in json.loads(carried)] if carried else []


def write_inheritance(interface_data: ET.Element, pou: Pou) -> None:
    """CODESYS's EXTENDS, in the interface's ``<addData>`` (``interface_data``)."""
    if pou.extends:
        data = sub(interface_data, "data", {"name": INHERITANCE_DATA, "handleUnknown": "implementation"})
        sub(sub(data, "Inheritance"), "Extends").text = pou.extends


def write_methods(node: ET.Element, pou: Pou) -> ET.Element | None:
    """The POU's ``<addData>`` with one CODESYS method entry per METHOD (None when it has none)."""
    if not pou.methods:
        return None
    add = sub(node, "addData")
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
            body = reader.child(element, "body")
            st = next((c for c in reader.elements(body) if local(c) == "ST"), None) if body is not None else None
            text, return_type = declarations(interface) if interface is not None else ("", None)
            methods.append(
                Method(
                    name=element.get("name", ""),
                    return_type=return_type,
                    declarations=text,
                    body=text_content(st) if st is not None else "",
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
