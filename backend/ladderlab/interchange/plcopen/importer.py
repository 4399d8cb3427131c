"""PLCopen XML (TC6 v2.01, and the near-identical 2.00) -> Project, with located diagnostics.

Reads a whole ``<project>`` or a single ``<pou>`` document (RuSTy's CFC files).
Declarations become ST text printed from the typed XML (``plcopen_vars``), ST
bodies stay text, LD and FBD bodies go through ``plcopen_ld_import`` and
``plcopen_fbd_import``; data types, global variables (of every configuration and
resource) and tasks fill the project's TYPE text, VAR_GLOBAL text and task list.

Never raises on bad input: hostile or malformed XML (``xml_safety``) gives
``project=None`` and an error; everything else is imported as far as it goes.
SFC bodies with their actions and transitions go through ``plcopen_sfc_import``.
IL POUs and other tools' addData have no place in the project and are reported
as warnings; Bachmann/RuSTy's textual declarations and negated jumps/returns are
understood and kept.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections import Counter as Tally
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import cast, get_args

from ...model.cfc import CfcBody
from ...model.diagnostics import Diagnostic
from ...model.fbd import FbdBody
from ...model.ld import LdBody
from ...model.project import LibraryName, Pou, PouAction, Project, TestFile, Typing
from ...st import ast
from ...st.parser import parse_declarations, parse_source
from ...st.printer import print_declarations, print_source, print_type
from ...storage.errors import ProjectLoadError
from ...storage.text_files import xml_for_parser
from .blocks import Signatures
from .body import (
    IdMaker,
    attach_headers,
    claimed_ids,
    group_by_ladderlab,
    read_network_list,
)
from .codesys_cfc import CALLTYPE_DATA, ELEMENTTYPE_DATA, CodesysChart, chart_element
from .configuration import MIXED_DATA, QUALIFIED_ONLY, read_gvls, read_instances
from .exporter import diagram_writer
from .fbd_import import FbdImporter, fbd_groups, place_comments
from .graph import read_graph, resolve_continuations
from .instance_args import INPUTASSIGNMENTS_DATA
from .ld_import import LdImporter, ld_groups
from .methods import (
    ACCESS_DATA,
    INHERITANCE_DATA,
    INTERFACE_DATA,
    METHOD_DATA,
    PLAINTEXT_DATA,
    PROPERTY_DATA,
    call_after_init,
    read_extends,
    read_fb_modifiers,
    read_implements,
    read_interfaces,
    read_methods,
    read_properties,
    with_attribute,
)
from .sfc_import import SfcImporter
from .vars import ATTRIBUTES_DATA, KIND_BY_LIST, VarReader, parse_type_text, write_data_type, write_type, write_var_list
from .xml_io import (
    CFC_DATA,
    LADDERLAB_DATA,
    PLCOPEN_NAMESPACES,
    Reader,
    body_language,
    canonical,
    data_entries,
    foreign_data,
    info,
    info_text,
    library_names,
    local,
    namespace,
    test_texts,
    text_content,
    typing_rules,
)
from .xml_safety import XmlInputError, parse_untrusted_xml

KIND = {"program": "program", "functionBlock": "function_block", "function": "function"}
_HEADER = re.compile(r"^(PROGRAM|FUNCTION_BLOCK|FUNCTION)\s", re.IGNORECASE)
BACHMANN = "www.bachmann.at/plc/plcopenxml"
POU_DATA = "http://www.3s-software.com/plcopenxml/pou"
DATATYPE_DATA = "http://www.3s-software.com/plcopenxml/datatype"
#: The CODESYS attribute LadderLab reads from an element's attributes entry, by the element's tag
#: the CODESYS attributes read where they stand (a method's or POU's call_after_init, a property's monitoring)
_READ_ATTRIBUTE = {
    "dataType": {"pack_mode"},
    "globalVars": {QUALIFIED_ONLY},
    "interface": {"call_after_init", "monitoring"},
}
_UNDERSTOOD = {
    (INPUTASSIGNMENTS_DATA, "InputAssignments"),  # an instance's FB_init arguments, read with it (instance_args.py)
    (CFC_DATA, "CFC"),  # a POU's chart (codesys_cfc.py); a method's, action's or transition's is reported
    (CALLTYPE_DATA, "CallType"),
    (ELEMENTTYPE_DATA, "ElementType"),  # a vendorElement's: reported where it is
    (POU_DATA, "pou"),
    (DATATYPE_DATA, "dataType"),
    (MIXED_DATA, "MixedAttrsVarList"),
    (BACHMANN, "textDeclaration"),
    (BACHMANN, "negated"),
    (METHOD_DATA, "Method"),
    (INHERITANCE_DATA, "Inheritance"),
    (PROPERTY_DATA, "Property"),
    (PLAINTEXT_DATA, "InterfaceAsPlainText"),
    (ACCESS_DATA, "AccessModifiers"),
    (INTERFACE_DATA, "Interface"),
}


def _declarations(r, reader: VarReader, interface: ET.Element | None, pou: ET.Element | None = None) -> str:
    """The ST text of an interface's typed variable lists, after its ``<documentation>`` (CODESYS writes there the
    comment above a POU's or method's VAR blocks, without its ``//``: put back on each line), else the ``pou``'s
    own (TC6's ``<pou><documentation>``)."""
    lists = [c for c in r.elements(interface) if local(c) in KIND_BY_LIST]
    documented = r.child(interface, "documentation")
    comment = text_content(documented if documented is not None else r.child(pou, "documentation")).strip("\n")
    lines = [f"//{line}" for line in comment.splitlines()] if comment.strip() else []
    return "\n".join([*lines, print_declarations([reader.var_block(c) for c in lists]).rstrip()]).strip()


def _method_interface(r, reader: VarReader, interface: ET.Element) -> tuple[str, str | None]:
    """A CODESYS method's declarations and result type."""
    holder = r.child(interface, "returnType")
    return _declarations(r, reader, interface), print_type(reader.type(holder)) if holder is not None else None


@dataclass
class ImportResult:
    """The imported project (None when the document could not be read at all) and every diagnostic."""

    project: Project | None
    diagnostics: list[Diagnostic] = field(default_factory=list)


def import_plcopen(data: bytes, *, name: str | None = None, file: str | None = None) -> ImportResult:
    """Read a PLCopen XML document; ``name`` overrides the project name, ``file`` locates the diagnostics."""
    try:
        data = xml_for_parser(data, file or "document")  # a document that is not UTF-8 and says nothing else
    except ProjectLoadError as err:
        return ImportResult(None, err.diagnostics)
    try:
        parsed = parse_untrusted_xml(data, file=file)
    except XmlInputError as err:
        return ImportResult(None, [err.diagnostic])
    reader = Reader(parsed, file=file)
    root = parsed.root
    if namespace(root) not in PLCOPEN_NAMESPACES or local(root) not in ("project", "pou"):
        reader.report(
            "PLCOPEN-NOT-PLCOPEN",
            f"the root element is <{local(root)}> in namespace "
            f"'{namespace(root) or 'none'}'; a PLCopen TC6 document has <project> (or <pou>) in "
            f"'{PLCOPEN_NAMESPACES[0]}'",
            root,
        )
        return ImportResult(None, reader.diagnostics)
    if namespace(root) != PLCOPEN_NAMESPACES[0]:
        reader.report(
            "PLCOPEN-VERSION",
            f"the document uses '{namespace(root)}'; it is read as TC6 v2.01",
            root,
            severity="warning",
        )
    project = _Importer(reader, name).project(root)
    return ImportResult(project, reader.diagnostics)


class _Importer:
    def __init__(self, reader: Reader, name: str | None):
        self.reader = reader
        self.name = name
        self.foreign: Tally[str] = Tally()

    def project(self, root: ET.Element) -> Project:
        r = self.reader
        configurations = r.children(r.path(root, "instances", "configurations"), "configuration")
        if local(root) == "pou":
            pou_nodes, header = [root], None
        else:
            pou_nodes, header = r.children(r.path(root, "types", "pous"), "pou"), r.child(root, "contentHeader")
            pou_nodes += self.application_entries(configurations, POU_DATA, "pou")
        ours = info(root, r)
        name = self.name or (header.get("name") if header is not None else None) or "imported"
        interfaces = [self.interface(node) for node in pou_nodes]
        signatures = Signatures([p for p in interfaces if p is not None])
        pous = [self.pou(node, p, signatures) for node, p in zip(pou_nodes, interfaces) if p is not None]
        self.collect_foreign(root)
        data_types = r.children(r.path(root, "types", "dataTypes"), "dataType") + self.application_entries(
            configurations, DATATYPE_DATA, "dataType"
        )
        types = self.types(data_types, info_text(ours, "types"))
        types = _with_interfaces(
            types, read_interfaces(root, r, lambda holder: _method_interface(r, VarReader(r), holder))
        )
        carried = info_text(ours, "globals")
        read_list = lambda lists, own: self.globals(lists, own if own is not None else carried)  # noqa: E731
        globals_, configuration, tasks = read_instances(r, configurations, read_list)
        gvls = read_gvls(r, configurations, self.globals)
        for data_name, count in sorted(self.foreign.items()):
            r.report(
                "PLCOPEN-ADDDATA",
                f"addData '{data_name}' ({count} place{'s' if count > 1 else ''}) is "
                "another tool's data that LadderLab cannot carry; it was dropped",
                root,
                severity="warning",
            )
        tests = [TestFile(name=test, text=text) for test, text in test_texts(ours)]
        libraries = self.libraries(ours, root)
        return Project(
            name=name,
            types=types,
            globals=globals_,
            gvls=gvls,
            pous=[p for p in pous if p is not None],
            tasks=tasks,
            configuration=configuration,
            tests=tests,
            libraries=libraries,
            typing=self.typing(ours, root),
        )

    def application_entries(self, configurations: list[ET.Element], data_name: str, tag: str) -> list[ET.Element]:
        """The POUs or data types of CODESYS's applications: a whole project's export writes what is under an
        application in the resource's addData (``.../plcopenxml/pou``, ``.../plcopenxml/datatype``), what is
        outside one in ``types``."""
        r = self.reader
        return [
            element
            for configuration in configurations
            for resource in r.children(configuration, "resource")
            for data in data_entries(resource, r, data_name)
            for element in r.children(data, tag)
        ]

    def typing(self, ours: ET.Element | None, root: ET.Element) -> Typing:
        """The type rules LadderLab's data names (IEC when none); unknown rules are reported, and IEC is used."""
        rules = typing_rules(ours)
        if rules is None or rules in get_args(Typing):
            return cast(Typing, rules or "iec")
        self.reader.report(
            "PLCOPEN-UNSUPPORTED",
            f"type rules '{rules}' are not ones LadderLab knows ({', '.join(get_args(Typing))}); IEC rules are used",
            root,
            severity="warning",
        )
        return "iec"

    def libraries(self, ours: ET.Element | None, root: ET.Element) -> list[LibraryName]:
        """The vendor libraries LadderLab's data names; one it does not ship is reported and left out."""
        known: list[LibraryName] = []
        for name in library_names(ours):
            if name in get_args(LibraryName):
                known.append(cast(LibraryName, name))
            else:
                self.reader.report(
                    "PLCOPEN-UNSUPPORTED",
                    f"library '{name}' is not one LadderLab ships ({', '.join(get_args(LibraryName))}); "
                    "it was left out, and calls of its functions are unknown",
                    root,
                    severity="warning",
                )
        return known

    # ------------------------------------------------------------ addData bookkeeping

    def note_foreign(self, entries: list[ET.Element], holder: str) -> None:
        for data in entries:
            kinds = {(data.get("name", ""), local(c)) for c in data if isinstance(c.tag, str)}
            if self.only_attribute(data, _READ_ATTRIBUTE.get(holder)):
                continue  # a STRUCT's pack_mode, read with its data type (vars.py); a GVL's qualified_only
            if not kinds or not kinds <= _UNDERSTOOD:
                self.foreign[data.get("name", "")] += 1

    def only_attribute(self, data: ET.Element, read: set[str] | None) -> bool:
        """Whether a CODESYS attributes entry holds only attributes of ``read`` (those read where they stand)."""
        r = self.reader
        names = {a.get("Name") for holder in r.children(data, "Attributes") for a in r.children(holder, "Attribute")}
        return read is not None and data.get("name") == ATTRIBUTES_DATA and bool(names) and names <= read

    def collect_foreign(self, root: ET.Element) -> None:
        """Count other tools' addData entries anywhere in the document (those not understood are reported)."""
        for parent in root.iter():
            for element in parent:
                if (
                    isinstance(element.tag, str)
                    and local(element) == "addData"
                    and namespace(element) == self.reader.ns
                ):
                    entries = [d for d in self.reader.children(element, "data") if d.get("name") != LADDERLAB_DATA]
                    self.note_foreign(entries, local(parent))

    # ------------------------------------------------------------ POUs

    def interface(self, node: ET.Element) -> Pou | None:
        """The POU with its declarations (body still empty): enough for block signatures."""
        r = self.reader
        name, pou_type = node.get("name", ""), node.get("pouType", "")
        if pou_type not in KIND:
            r.report(
                "PLCOPEN-POU",
                f"POU '{name}' has pouType '{pou_type}'; expected program, functionBlock or function",
                node,
                pou=name,
            )
            return None
        interface = r.child(node, "interface")
        reader = VarReader(r, name)
        ours = info(interface, r)
        lists = [c for c in r.elements(interface) if local(c) in KIND_BY_LIST]
        declarations = _declarations(r, reader, interface, node)
        carried = info_text(ours, "declarations")
        if carried is not None and self.same(lists, carried, _declaration_elements):
            declarations = carried
        return_type = None
        if KIND[pou_type] == "function":
            holder = r.child(interface, "returnType")
            return_type = print_type(reader.type(holder)) if holder is not None else None
            wanted = ours.get("returnType") if ours is not None else None
            if wanted and holder is not None and self.same([holder], wanted, _return_type_elements):
                return_type = wanted
        if not any(r.children(c, "variable") for c in lists):
            declarations, return_type = self.text_declaration(interface, declarations, return_type)
        if KIND[pou_type] == "function" and return_type is None:
            r.report("PLCOPEN-POU", f"function '{name}' has no return type", node, pou=name)
        declarations = with_attribute(declarations, call_after_init(node, interface, r))
        oo = ours.attrib if ours is not None else {}
        return Pou(
            name=name,
            kind=KIND[pou_type],
            language="st",
            return_type=return_type,
            declarations=declarations,
            methods=read_methods(node, ours, r, lambda holder: _method_interface(r, reader, holder)),
            properties=read_properties(node, ours, r, lambda holder: _method_interface(r, reader, holder)),
            extends=oo.get("extends") or read_extends(interface, r),
            implements=[i.strip() for i in oo.get("implements", "").split(",") if i.strip()]
            or read_implements(node, r),
            **(
                {"abstract": oo.get("abstract") == "true", "final": oo.get("final") == "true"}
                if ours is not None
                else read_fb_modifiers(node, r)
            ),
        )

    def text_declaration(
        self, interface: ET.Element | None, declarations: str, return_type: str | None
    ) -> tuple[str, str | None]:
        """Bachmann/RuSTy keep the interface as ST text in addData; use it when the typed lists are empty.

        The text starts with the POU header (``FUNCTION main : DINT``), which gives a function's return type.
        """
        for data in foreign_data(interface, self.reader):
            holder = next((c for c in data if local(c) == "textDeclaration"), None)
            content = next((c for c in holder if local(c) == "content"), None) if holder is not None else None
            if data.get("name") != BACHMANN or content is None:
                continue
            lines = [line.strip() for line in (content.text or "").strip().splitlines()]
            if lines and _HEADER.match(lines[0]):
                header, lines = lines[0], lines[1:]
                if return_type is None and ":" in header:
                    return_type = header.split(":", 1)[1].strip().rstrip(";").strip()
            return "\n".join(lines).strip(), return_type
        return declarations, return_type

    def pou(self, node: ET.Element, pou: Pou, signatures: Signatures) -> Pou | None:
        made = self._pou_body(node, pou, signatures)
        bodies = self.reader.children(node, "body")
        first = next(self.reader.elements(bodies[0]), None) if bodies else None
        if made is None or (first is not None and local(first) == "SFC"):
            return made
        actions = self.actions(node, made)
        return made.model_copy(update={"actions": actions}) if actions else made

    def actions(self, node: ET.Element, pou: Pou) -> list[PouAction]:
        """A function block's ``<actions>`` outside SFC (CODESYS, IL-08): the ones written in ST; any other is
        reported and left out."""
        r = self.reader
        found: list[PouAction] = []
        for item in r.children(r.child(node, "actions"), "action"):
            tag, language = body_language(r.child(item, "body"), r)  # a CODESYS CFC chart is not ST
            if pou.kind == "function_block" and language is not None and tag == "ST":
                found.append(PouAction(name=item.get("name", ""), body=text_content(language)))
                continue
            what = "a function block's" if pou.kind == "function_block" else "an SFC POU's or a function block's"
            r.report(
                "PLCOPEN-UNSUPPORTED",
                f"action '{item.get('name', '')}' of POU {pou.name} was not imported: LadderLab imports "
                f"{what} actions with ST bodies",
                item,
                severity="warning",
                pou=pou.name,
            )
        return found

    def _pou_body(self, node: ET.Element, pou: Pou, signatures: Signatures) -> Pou | None:
        r = self.reader
        bodies = r.children(node, "body")
        first = next(r.elements(bodies[0]), None) if bodies else None
        if first is None or local(first) != "SFC":
            for tag in ("transitions",):
                for item in r.children(r.child(node, tag), tag[:-1]):
                    r.report(
                        "PLCOPEN-UNSUPPORTED",
                        f"{tag[:-1]} '{item.get('name', '')}' of POU {pou.name} was not imported: only SFC POUs "
                        f"have {tag} in LadderLab",
                        item,
                        severity="warning",
                        pou=pou.name,
                    )
        if len(bodies) > 1:
            r.report(
                "PLCOPEN-POU",
                f"POU {pou.name} has {len(bodies)} bodies; only the first is imported",
                bodies[1],
                severity="warning",
                pou=pou.name,
            )
        body = bodies[0] if bodies else None
        tag, language = body_language(body, r)
        if tag == "CFC":
            assert language is not None
            cfc = chart_element(language)
            if cfc is None:
                r.report(
                    "PLCOPEN-UNSUPPORTED",
                    f"POU {pou.name}'s CODESYS chart entry holds no <CFC>; the POU was imported as an empty chart",
                    language,
                    pou=pou.name,
                )
            chart = CodesysChart(r, pou.name, signatures).body(cfc) if cfc is not None else CfcBody()
            return pou.model_copy(update={"language": "cfc", "body": chart})
        if tag in ("ST", "IL"):  # IL bodies are IL text like ST bodies are ST text (docs/il.md)
            return pou.model_copy(update={"body": text_content(language), "language": tag.lower()})
        assert body is not None and language is not None
        if tag == "SFC":
            importer = SfcImporter(
                r,
                pou.name,
                lambda holder, what: self.diagram(holder, pou.name, signatures),
                lambda holder, networks: diagram_writer(holder, networks, signatures, pou.name),
            )
            return pou.model_copy(update={"language": "sfc", "body": importer.body(node, body, language)})
        made = self.diagram(body, pou.name, signatures)
        if made is None:
            return pou
        return pou.model_copy(update={"language": made[0], "body": made[1]})

    def diagram(self, body: ET.Element, pou: str, signatures: Signatures) -> tuple[str, LdBody | FbdBody] | None:
        """The LD or FBD networks of a ``<body>`` (a POU's, or an SFC action's or transition's)."""
        r = self.reader
        language = next(r.elements(body), None)
        tag = local(language) if language is not None else ""
        if language is None or tag not in ("LD", "FBD"):
            return None
        graph = read_graph(language, r, pou, signatures)
        listing = read_network_list(body, r)
        ids = IdMaker(claimed_ids(graph, listing))
        groups = group_by_ladderlab(graph, r, listing)
        if tag == "LD":
            resolve_continuations(graph, r, pou)
            foreign = groups is None
            groups = groups or attach_headers(ld_groups(graph), graph, r)
            return "ld", LdImporter(graph, r, pou, signatures, ids, foreign=foreign).body(groups)
        relative, orders = groups is not None, {}
        if groups is None:
            groups, orders = fbd_groups(graph, r)
            place_comments(groups, graph)
        made = FbdImporter(graph, r, pou, ids).body(groups, orders, relative=relative)
        if relative and listing is not None and listing.chart and len(made.networks) == 1:
            return "cfc", CfcBody(networks=made.networks)  # a chart LadderLab wrote (issue 26)
        return "fbd", made

    # ------------------------------------------------------------ project texts

    @staticmethod
    def same(actual: list[ET.Element], carried: str, regenerate: Callable[[str], list[ET.Element] | None]) -> bool:
        """Does the carried text still say what the typed XML says (no other tool changed it)?"""
        expected = regenerate(carried)
        return expected is not None and [canonical(e) for e in expected] == [canonical(e) for e in actual]

    def types(self, elements: list[ET.Element], carried: str | None) -> str:
        if carried is not None and self.same(elements, carried, _type_elements):
            return carried
        reader = VarReader(self.reader)
        decls = [reader.data_type(e) for e in elements]
        return print_source(ast.Source([ast.TypeBlock(decls)])).rstrip() if decls else ""

    def globals(self, lists: list[ET.Element], carried: str | None) -> str:
        """A VAR_GLOBAL text from ``<globalVars>`` lists (the carried text when it still says the same)."""
        if carried is not None and self.same(lists, carried, _declaration_elements):
            return carried
        reader = VarReader(self.reader)
        return print_declarations([reader.var_block(g, "VAR_GLOBAL") for g in lists]).rstrip()


# ---------------------------------------------------------------- regenerating typed XML from carried texts


def _with_interfaces(types: str, interfaces: list[tuple[str, str]]) -> str:
    """The types text with the INTERFACEs another tool's addData declares that it does not already have."""
    parsed = parse_source(types)
    items = parsed.ast.items if parsed.ast is not None else []
    known = {item.name.upper() for item in items if isinstance(item, ast.InterfaceDecl)}
    added = [text for name, text in interfaces if name.upper() not in known]
    return "\n\n".join([types, *added] if types else added)


def _declaration_elements(text: str) -> list[ET.Element] | None:
    parsed = parse_declarations(text)
    if parsed.ast is None or not parsed.ok:
        return None
    holder = ET.Element("interface")
    for block in parsed.ast:
        write_var_list(holder, block)
    return list(holder)


def _type_elements(text: str) -> list[ET.Element] | None:
    parsed = parse_source(text)
    allowed = (ast.TypeBlock, ast.InterfaceDecl)  # INTERFACEs have no dataType: only the carried text has them
    if parsed.ast is None or not parsed.ok or any(not isinstance(i, allowed) for i in parsed.ast.items):
        return None
    holder = ET.Element("dataTypes")
    for item in parsed.ast.items:
        for decl in item.decls if isinstance(item, ast.TypeBlock) else []:
            write_data_type(holder, decl)
    return list(holder)


def _return_type_elements(text: str) -> list[ET.Element] | None:
    spec = parse_type_text(text)
    if spec is None:
        return None
    holder = ET.Element("returnType")
    write_type(holder, spec)
    return [holder]
