"""Object orientation in PLCopen XML, the way CODESYS writes it (TC6 XML has no place for it; docs/plcopen.md).

A function block's METHODs: ``<pou><addData><data name=".../plcopenxml/method" handleUnknown="implementation">
<Method name="M"><interface>returnType, var lists</interface><body><ST>text</ST></body></Method></data>`` - one
``data`` per method; PROPERTYs: ``<data name=".../plcopenxml/property"><Property name="P"><interface><returnType>
</interface><GetAccessor><interface/><body/></GetAccessor><SetAccessor>...</SetAccessor></Property></data>`` (either
accessor first); EXTENDS and IMPLEMENTS: ``<interface><addData><data name=".../plcopenxml/pouinheritance">
<Inheritance><Extends>Base</Extends><Implements>I</Implements>``, IMPLEMENTS also in the header of the declaration
text CODESYS writes (``.../plcopenxml/interfaceasplaintext``: ``FUNCTION_BLOCK F EXTENDS B IMPLEMENTS I1, I2``). A
method's or property's access (``<interface><addData><data name=".../plcopenxml/accessmodifiers"><AccessModifiers
Private="true"/>``, else the specifier of its header text as TwinCAT writes it, PUBLIC when neither says one) and its
header as text (``METHOD PUBLIC FINAL M : INT`` in its ``interfaceasplaintext`` entry or direct child: FINAL and
ABSTRACT, which CODESYS's typed XML does not say). INTERFACEs: the project's ``<addData><data
name=".../plcopenxml/interface"><Interface name="I">`` with ``<Methods>`` and ``<Properties>`` of prototypes
(CODESYS V3.5 SP21, TwinCAT; entries in its addData as a POU's are read too) and EXTENDS in its header text. The
texts as typed travel in LadderLab's ``<ll:info>`` (``methods``, ``properties``: the model's JSON; INTERFACEs in the
project's types text, carried verbatim).
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable

from ...model.project import Accessor, Method, MethodAccess, Pou, Property
from ...st import ast
from ...st.parser import parse_declarations, parse_source
from ...st.pragmas import head_call_after_init, head_monitoring, headed_by, monitoring_pragma, with_call_after_init
from ...st.printer import print_declarations, print_type
from ...storage.st_text import method_header
from .vars import ATTRIBUTES_DATA, parse_type_text, write_documentation, write_type, write_var_list
from .xml_io import Reader, body_language, data_entries, formatted_text, info_text, local, sub, text_content

METHOD_DATA = "http://www.3s-software.com/plcopenxml/method"
INHERITANCE_DATA = "http://www.3s-software.com/plcopenxml/pouinheritance"
PROPERTY_DATA = "http://www.3s-software.com/plcopenxml/property"
PLAINTEXT_DATA = "http://www.3s-software.com/plcopenxml/interfaceasplaintext"
ACCESS_DATA = "http://www.3s-software.com/plcopenxml/accessmodifiers"
INTERFACE_DATA = "http://www.3s-software.com/plcopenxml/interface"
ACCESS: tuple[MethodAccess, ...] = ("PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL")
_INTERFACE_EXTENDS = re.compile(r"^\s*INTERFACE\s+\w+\s+EXTENDS\s+([A-Za-z_][\w\s,]*)", re.IGNORECASE)
_IMPLEMENTS = re.compile(r"\bIMPLEMENTS\s+([A-Za-z_][\w\s,]*)", re.IGNORECASE)
_LEADING = re.compile(r"^(?:\s+|//[^\n]*|\(\*[\s\S]*?\*\)|/\*[\s\S]*?\*/|\{[^}]*\})*")  # comments, pragmas


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
    where = node.get("name", "")
    for element in _entries(node, reader, PROPERTY_DATA, "Property"):
        name = element.get("name", "")
        interface = reader.child(element, "interface")
        _, type_text = declarations(interface) if interface is not None else ("", None)
        accessors: dict[str, Accessor] = {}
        for kind, tag in (("get", "GetAccessor"), ("set", "SetAccessor")):
            accessor = next((c for c in element if isinstance(c.tag, str) and local(c) == tag), None)
            body = _st_body(accessor, reader, f"the {kind.upper()} of {where}.{name}") if accessor is not None else None
            if accessor is not None and body is not None:
                holder = reader.child(accessor, "interface")
                text = declarations(holder)[0] if holder is not None else ""
                accessors[kind] = Accessor(declarations=text, body=body)
        access = _access(element, interface, reader)
        accessors = _monitored(accessors, [element, *([interface] if interface is not None else [])], reader)
        found.append(Property(name=name, type=type_text or "", access=access, **accessors))
    return found


def read_fb_modifiers(node: ET.Element, reader: Reader) -> dict[str, bool]:
    """ABSTRACT and FINAL of a function block, from the header of CODESYS's declaration text."""
    header = _IMPLEMENTS.sub("", _plain_header(node, reader)).upper().split()
    return {"abstract": "ABSTRACT" in header, "final": "FINAL" in header}


def _entries(node: ET.Element | None, reader: Reader, data_name: str, tag: str) -> list[ET.Element]:
    """The ``<tag>`` elements of the ``data_name`` entries in ``node``'s addData (CODESYS: one per entry)."""
    return [
        element
        for data in data_entries(node, reader, data_name)
        for element in data
        if isinstance(element.tag, str) and local(element) == tag
    ]


def _st_body(element: ET.Element, reader: Reader, what: str) -> str | None:
    """The ST text of a method's or accessor's ``<body>`` ("" when it has none). LadderLab's methods and accessors
    are ST: one drawn in FBD or LD (CODESYS allows it), or written in IL, is None after a located warning naming
    ``what`` (a CFC chart too: ``body_language``); it is left out, so a call of it is a located build error rather
    than an empty body's results."""
    tag, language = body_language(reader.child(element, "body"), reader)
    if tag == "ST":
        return text_content(language)
    reader.report(
        "PLCOPEN-UNSUPPORTED",
        f"{what} is written in {tag}; LadderLab's methods and properties are ST, so it was left out",
        element,
        severity="warning",
    )
    return None


def write_inheritance(interface_data: ET.Element, pou: Pou) -> None:
    """CODESYS's EXTENDS and IMPLEMENTS, in the interface's ``<addData>`` (``interface_data``): one ``<Implements>``
    per INTERFACE (a real export shows one; several elements or a comma list are read back alike)."""
    if pou.extends or pou.implements:
        data = sub(interface_data, "data", {"name": INHERITANCE_DATA, "handleUnknown": "implementation"})
        inheritance = sub(data, "Inheritance")
        if pou.extends:
            sub(inheritance, "Extends").text = pou.extends
        for name in pou.implements:
            sub(inheritance, "Implements").text = name


def write_methods(node: ET.Element, pou: Pou) -> ET.Element | None:
    """The POU's ``<addData>`` with one CODESYS entry per METHOD and PROPERTY and, for IMPLEMENTS, CODESYS's
    declaration text for what only its header says (IMPLEMENTS, ABSTRACT, FINAL; None when it has none of them)."""
    if not (pou.methods or pou.properties or pou.implements or pou.abstract or pou.final):
        return None
    add = sub(node, "addData")
    if pou.implements or pou.abstract or pou.final:
        words = ["FUNCTION_BLOCK", "ABSTRACT" if pou.abstract else "", "FINAL" if pou.final else "", pou.name]
        extends = f" EXTENDS {pou.extends}" if pou.extends else ""
        implements = f" IMPLEMENTS {', '.join(pou.implements)}" if pou.implements else ""
        data = sub(add, "data", {"name": PLAINTEXT_DATA, "handleUnknown": "implementation"})
        text = " ".join(w for w in words if w) + f"{extends}{implements}\n{pou.declarations}"
        formatted_text(data, "InterfaceAsPlainText", text)
    for method in pou.methods:
        spec = parse_type_text(method.return_type) if method.return_type else None
        blocks = parse_declarations(method.declarations).ast or []
        element = _write_method(
            add, method.name, spec, blocks, method.access, method_header(method), method.declarations
        )
        formatted_text(sub(element, "body"), "ST", method.body)
    for prop in pou.properties:
        data = sub(add, "data", {"name": PROPERTY_DATA, "handleUnknown": "implementation"})
        element = sub(data, "Property", {"name": prop.name})
        spec = parse_type_text(prop.type)
        interface = sub(element, "interface")
        if spec is not None:
            write_type(sub(interface, "returnType"), spec)
        _write_access(interface, prop.access)
        write_monitoring(interface, prop)
        for tag, accessor in (("GetAccessor", prop.get), ("SetAccessor", prop.set)):
            if accessor is not None:
                holder = sub(element, tag)
                interface = sub(holder, "interface")
                for block in parse_declarations(accessor.declarations).ast or []:
                    write_var_list(interface, block)
                formatted_text(sub(holder, "body"), "ST", accessor.body)
    return add


def _write_method(
    add: ET.Element,
    name: str,
    spec: ast.TypeSpec | None,
    blocks: list[ast.VarBlock],
    access: str,
    header: str,
    declarations: str = "",
) -> ET.Element:
    """One CODESYS method entry in ``add``: its interface (result, variables, access, the comment opening its
    ``declarations``) and header text."""
    data = sub(add, "data", {"name": METHOD_DATA, "handleUnknown": "implementation"})
    element = sub(data, "Method", {"name": name})
    interface = sub(element, "interface")
    if spec is not None:
        write_type(sub(interface, "returnType"), spec)
    for block in blocks:
        write_var_list(interface, block)
    _write_access(interface, access)
    write_call_after_init(interface, declarations)
    write_documentation(interface, declarations)
    plain = sub(sub(element, "addData"), "data", {"name": PLAINTEXT_DATA, "handleUnknown": "implementation"})
    formatted_text(plain, "InterfaceAsPlainText", header)
    return element


def write_interfaces(add: ET.Element, types: str) -> None:
    """The project's INTERFACEs (from its types text) as CODESYS V3.5 SP21 writes them in the project's ``add``(Data):
    ``<Interface name>`` with ``<Methods>`` and ``<Properties>`` (prototypes: typed interface and declaration text)
    and its header text."""
    parsed = parse_source(types, file="types.st")
    for item in parsed.ast.items if parsed.ast is not None else []:
        if not isinstance(item, ast.InterfaceDecl):
            continue
        data = sub(add, "data", {"name": INTERFACE_DATA, "handleUnknown": "implementation"})
        element = sub(data, "Interface", {"name": item.name})
        methods = sub(element, "Methods") if item.methods else None
        for method in item.methods:
            prototype = sub(methods, "Method", {"name": method.name})
            interface = sub(prototype, "interface")
            if method.return_type is not None:
                write_type(sub(interface, "returnType"), method.return_type)
            for block in method.var_blocks:
                write_var_list(interface, block)
            after_header = types.splitlines()[method.span.line : method.span.end_line]  # its comment as typed
            write_documentation(interface, "\n".join(after_header))
            returns = f" : {print_type(method.return_type)}" if method.return_type is not None else ""
            text = f"METHOD {method.name}{returns}\n{print_declarations(method.var_blocks)}".rstrip()
            formatted_text(prototype, "InterfaceAsPlainText", text)
        properties = sub(element, "Properties") if item.properties else None
        for prop in item.properties:
            prototype = sub(properties, "Property", {"name": prop.name})
            write_type(sub(sub(prototype, "interface"), "returnType"), prop.type)
            for accessor in prop.accessors:
                formatted_text(sub(prototype, f"{accessor.kind.capitalize()}Accessor"), "InterfaceAsPlainText", "")
            formatted_text(prototype, "InterfaceAsPlainText", f"PROPERTY {prop.name} : {print_type(prop.type)}")
        extends = f" EXTENDS {', '.join(item.extends)}" if item.extends else ""
        formatted_text(element, "InterfaceAsPlainText", f"INTERFACE {item.name}{extends}")


def read_interfaces(
    root: ET.Element, reader: Reader, declarations: Callable[[ET.Element], tuple[str, str | None]]
) -> list[tuple[str, str]]:
    """The INTERFACEs of CODESYS's (or TwinCAT's) project addData as (name, ST text): method prototypes with their
    variables and result (read by ``declarations``), property prototypes with their accessors, EXTENDS from the
    header text. Methods and properties are listed in ``<Methods>`` / ``<Properties>`` (CODESYS V3.5 SP21,
    TwinCAT) or given as entries of the Interface's addData."""
    found = []
    for element in _entries(root, reader, INTERFACE_DATA, "Interface"):
        name = element.get("name", "")
        header = _plain_header(element, reader)
        extends = _INTERFACE_EXTENDS.match(header)
        lines = [f"INTERFACE {name}" + (f" EXTENDS {extends.group(1).strip()}" if extends else "")]
        for method in _listed(element, reader, "Methods", "Method") + _entries(element, reader, METHOD_DATA, "Method"):
            interface = reader.child(method, "interface")
            text, return_type = declarations(interface) if interface is not None else ("", None)
            lines.append(f"METHOD {method.get('name', '')}" + (f" : {return_type}" if return_type else ""))
            lines += [text] if text else []
            lines.append("END_METHOD")
        properties = _listed(element, reader, "Properties", "Property")
        for prop in properties + _entries(element, reader, PROPERTY_DATA, "Property"):
            lines += _property_prototype(prop, name, reader, declarations)
        found.append((name, "\n".join([*lines, "END_INTERFACE"])))
    return found


def _listed(element: ET.Element, reader: Reader, holder: str, tag: str) -> list[ET.Element]:
    """The ``<tag>`` children of ``element``'s ``<holder>`` lists (``<Methods><Method>``)."""
    return [item for parent in reader.children(element, holder) for item in reader.children(parent, tag)]


def _property_prototype(
    prop: ET.Element, interface_name: str, reader: Reader, declarations: Callable[[ET.Element], tuple[str, str | None]]
) -> list[str]:
    """An INTERFACE's PROPERTY as ST lines (``PROPERTY P : T GET END_GET END_PROPERTY``): its type from the typed
    returnType, else its header text (``PROPERTY PUBLIC P : T``); a property with neither is a located warning."""
    name = prop.get("name", "")
    holder = reader.child(prop, "interface")
    type_text = declarations(holder)[1] if holder is not None else None
    header = _plain_header(prop, reader)
    if not type_text and ":" in header:
        type_text = header.split(":", 1)[1].strip().rstrip(";").strip()
    if not type_text:
        reader.report(
            "PLCOPEN-UNSUPPORTED",
            f"the PROPERTY {name} of INTERFACE {interface_name} has no type; it was left out",
            prop,
            severity="warning",
        )
        return []
    kinds = [kind for kind in ("GET", "SET") if reader.children(prop, f"{kind.capitalize()}Accessor")]
    return [f"PROPERTY {name} : {type_text}", *(f"{kind} END_{kind}" for kind in kinds), "END_PROPERTY"]


def _plain_header(element: ET.Element, reader: Reader) -> str:
    """The header line of an element's ``InterfaceAsPlainText`` (in its addData as CODESYS writes it, or a direct
    child as TwinCAT does): its first line after the comments and pragmas that may open it (``// Registers a
    module``, ``{attribute 'reflection'}``); empty when it has none."""
    holders = _entries(element, reader, PLAINTEXT_DATA, "InterfaceAsPlainText") + reader.children(
        element, "InterfaceAsPlainText"
    )
    text = _LEADING.sub("", text_content(holders[0])) if holders else ""
    return text.split("\n", 1)[0].strip()


def _access(element: ET.Element, interface: ET.Element | None, reader: Reader) -> MethodAccess:
    """A CODESYS method's or property's access: its AccessModifiers (``<AccessModifiers Private="true"/>``), else the
    specifier of its header text (``METHOD PRIVATE M``: TwinCAT has no AccessModifiers), else PUBLIC (CODESYS writes
    ``<AccessModifiers />`` for a PUBLIC property)."""
    modifiers = next(iter(_entries(interface, reader, ACCESS_DATA, "AccessModifiers")), None)
    if modifiers is not None:
        return next((a for a in ACCESS if modifiers.get(a.capitalize()) == "true"), "PUBLIC")
    words = _plain_header(element, reader).upper().split(":", 1)[0].split()[1:-1]  # between METHOD and the name
    return next((a for a in ACCESS if a in words), "PUBLIC")


def _write_access(interface: ET.Element, access: str) -> None:
    """``_access`` written back: nothing for PUBLIC."""
    if access != "PUBLIC":
        data = sub(sub(interface, "addData"), "data", {"name": ACCESS_DATA, "handleUnknown": "implementation"})
        sub(data, "AccessModifiers").set(access.capitalize(), "true")


def _modifiers(method: ET.Element, interface: ET.Element | None, reader: Reader) -> dict[str, object]:
    """A CODESYS method's access (``_access``), FINAL and ABSTRACT (its header text)."""
    header = _plain_header(method, reader).upper().split(":", 1)[0].split()
    return {"access": _access(method, interface, reader), "final": "FINAL" in header, "abstract": "ABSTRACT" in header}


def read_methods(
    node: ET.Element, ours: ET.Element | None, reader: Reader, declarations: Callable[[ET.Element], str]
) -> list[Method]:
    """A function block's METHODs: LadderLab's own JSON when it carries it, else CODESYS's method entries (their
    interface read by ``declarations``, access, FINAL and ABSTRACT by ``_modifiers``)."""
    carried = info_text(ours, "methods")
    if carried:
        return [Method.model_validate(item) for item in json.loads(carried)]
    methods = []
    for data in data_entries(node, reader, METHOD_DATA):
        for element in (c for c in data if isinstance(c.tag, str) and local(c) == "Method"):
            pou, name = node.get("name", ""), element.get("name", "")
            body = _st_body(element, reader, f"the method {pou}.{name}")
            if body is None:
                continue
            _report_implicit(element, pou, reader)
            interface = reader.child(element, "interface")
            text, return_type = declarations(interface) if interface is not None else ("", None)
            text = with_attribute(text, call_after_init(element, interface, reader))
            methods.append(
                Method(
                    name=name,
                    **_modifiers(element, interface, reader),  # type: ignore[arg-type]  # values typed by _modifiers
                    return_type=return_type,
                    declarations=text,
                    body=body,
                )
            )
    return methods


_IMPLICIT = {"FB_REINIT": "after an instance was copied in an online change, which LadderLab has not"}


def _report_implicit(method: ET.Element, pou: str, reader: Reader) -> None:
    """A warning for a method CODESYS calls by itself that LadderLab never calls (FB_reinit; FB_init and FB_exit
    it runs as CODESYS does, st/fb_init.py): its statements run only where the program calls it."""
    name = method.get("name", "")
    when = _IMPLICIT.get(name.upper())
    if when is not None:
        reader.report(
            "PLCOPEN-UNSUPPORTED",
            f"method {pou}.{name} was imported as an ordinary method: CODESYS calls it by itself {when}, so its "
            "statements run only where the program calls it",
            method,
            severity="warning",
            pou=pou,
        )


def call_after_init(holder: ET.Element, interface: ET.Element | None, reader: Reader) -> bool:
    """Whether CODESYS marked a POU or method ``{attribute 'call_after_init'}``: the attribute in CODESYS's attributes
    entry of it or of its interface, or the pragma in its declaration text as TwinCAT writes it."""
    names = _attributes([holder, *([interface] if interface is not None else [])], reader)
    texts = _entries(holder, reader, PLAINTEXT_DATA, "InterfaceAsPlainText") + reader.children(
        holder, "InterfaceAsPlainText"
    )
    return "call_after_init" in names or any("'call_after_init'" in text_content(t) for t in texts)


def with_attribute(declarations: str, marked: bool) -> str:
    """A POU's or method's declarations text headed by {attribute 'call_after_init'} when CODESYS marked it so (the
    model keeps the attribute there: st/call_after_init.py)."""
    return with_call_after_init(declarations) if marked and head_call_after_init(declarations) is None else declarations


def write_call_after_init(interface: ET.Element, declarations: str) -> None:
    """CODESYS's attributes entry for {attribute 'call_after_init'} heading ``declarations``, in the interface's
    addData (made when it has none yet: it comes before the documentation)."""
    if head_call_after_init(declarations) is not None:
        _write_attribute(interface, "call_after_init", "")


def _write_attribute(interface: ET.Element, name: str, value: str) -> None:
    """CODESYS's attributes entry holding the attribute ``name`` := ``value`` in the interface's addData (made when it
    has none yet: it comes before the documentation)."""
    add = next((c for c in interface if isinstance(c.tag, str) and local(c) == "addData"), None)
    data = sub(
        add if add is not None else sub(interface, "addData"),
        "data",
        {"name": ATTRIBUTES_DATA, "handleUnknown": "implementation"},
    )
    sub(sub(data, "Attributes"), "Attribute", {"Name": name, "Value": value})


def write_monitoring(interface: ET.Element, prop: Property) -> None:
    """CODESYS's attributes entry for a property's {attribute 'monitoring'} (heading its GET's, else SET's,
    declarations in the model: st/monitoring.py), in the property's interface."""
    accessor = prop.get or prop.set
    found = head_monitoring(accessor.declarations) if accessor is not None else None
    if found is not None:
        _write_attribute(interface, "monitoring", found[0])


def _attributes(holders: list[ET.Element], reader: Reader) -> dict[str, str]:
    """CODESYS's attributes of ``holders`` (their attributes entries): lower-case name -> value."""
    return {
        (attribute.get("Name") or "").lower(): attribute.get("Value") or ""
        for one in holders
        for data in data_entries(one, reader, ATTRIBUTES_DATA)
        for attributes in reader.children(data, "Attributes")
        for attribute in reader.children(attributes, "Attribute")
    }


def _monitored(accessors: dict[str, Accessor], holders: list[ET.Element], reader: Reader) -> dict[str, Accessor]:
    """A property's accessors, the first headed by {attribute 'monitoring'} when CODESYS marked the property so."""
    mode = _attributes(holders, reader).get("monitoring")
    first = next(iter(accessors), None)
    if not mode or first is None or head_monitoring(accessors[first].declarations) is not None:
        return accessors
    headed = headed_by(monitoring_pragma(mode), accessors[first].declarations)
    return {**accessors, first: accessors[first].model_copy(update={"declarations": headed})}


def read_extends(interface: ET.Element | None, reader: Reader) -> str | None:
    """CODESYS's EXTENDS of a function block's interface."""
    found = [name for kind, name in _inheritance(interface, reader) if kind == "Extends"]
    return found[0] if found else None


def read_implements(node: ET.Element, reader: Reader) -> list[str]:
    """The INTERFACEs a function block IMPLEMENTS: ``<Implements>`` of CODESYS's inheritance entry (e!COCKPIT and
    CODESYS V3.5 write them there), else the header of CODESYS's declaration text."""
    listed = [
        name.strip()
        for kind, text in _inheritance(reader.child(node, "interface"), reader)
        if kind == "Implements"
        for name in text.split(",")
        if name.strip()
    ]
    if listed:
        return listed
    found = _IMPLEMENTS.search(_plain_header(node, reader))
    return [name.strip() for name in found.group(1).split(",") if name.strip()] if found else []


def _inheritance(interface: ET.Element | None, reader: Reader) -> list[tuple[str, str]]:
    """(``Extends`` or ``Implements``, the text) of each child of the interface's ``<Inheritance>`` entries."""
    return [
        (local(item), (item.text or "").strip())
        for holder in _entries(interface, reader, INHERITANCE_DATA, "Inheritance")
        for item in holder
        if isinstance(item.tag, str) and local(item) in ("Extends", "Implements") and (item.text or "").strip()
    ]
