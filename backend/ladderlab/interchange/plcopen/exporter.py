"""Project -> PLCopen XML (TC6 v2.01) document.

Sections: ``types/dataTypes`` from the project's TYPE blocks, ``types/pous`` with
each POU's typed interface (declarations parsed by the ST parser) and body (ST
text in ``<ST><xhtml:p>``, LD and FBD graphs from ``plcopen_ld_export`` and
``plcopen_fbd_export``), and ``instances/configurations`` with the project's
global variables and tasks (one configuration ``config`` with one resource
``resource``; a task's programs are ``pouInstance``s named after the program, the
IR's instance naming).

The original declaration, type and global texts also travel verbatim in
LadderLab's addData, so LadderLab reads its own files back to the same text
(comments and layout included) as long as the typed XML still says the same.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from datetime import UTC, datetime

from ... import __version__
from ...model.cfc import CfcBody
from ...model.diagnostics import Diagnostic
from ...model.fbd import FbdBody
from ...model.ld import LdBody
from ...model.project import Pou, Project
from ...model.sfc import SfcBody
from ...st import ast
from ...st.parser import parse_declarations, parse_source
from .blocks import Signatures
from .body import NETWORK_GAP, Counter, write_network_list
from .configuration import write_instances
from .fbd_export import FbdExporter
from .ld_export import LdExporter
from .methods import oo_attributes, oo_texts, write_call_after_init, write_inheritance, write_interfaces, write_methods
from .sfc_export import write_sfc_pou
from .vars import parse_type_text, write_data_type, write_documentation, write_type, write_var_list
from .xml_io import (
    formatted_text,
    ladderlab_data,
    ladderlab_libraries,
    ladderlab_tests,
    ladderlab_typing,
    q,
    sub,
    to_bytes,
)

POU_TYPE = {"program": "program", "function_block": "functionBlock", "function": "function"}


class PlcopenExportError(Exception):
    """The project cannot be written as PLCopen XML (e.g. declarations that do not parse); see ``diagnostics``."""

    def __init__(self, diagnostics: list[Diagnostic]):
        super().__init__("; ".join(d.format() for d in diagnostics))
        self.diagnostics = diagnostics


def export_plcopen(project: Project, *, now: datetime | None = None) -> bytes:
    """The project as a UTF-8 PLCopen XML document; raises ``PlcopenExportError`` with located diagnostics."""
    return _Exporter(project).document(now or datetime.now(UTC))


class _Exporter:
    def __init__(self, project: Project):
        self.project = project
        self.signatures = Signatures(project.pous)
        self.problems: list[Diagnostic] = []

    def document(self, now: datetime) -> bytes:
        stamp = now.replace(microsecond=0, tzinfo=None).isoformat()
        root = ET.Element(q("project"))
        sub(
            root,
            "fileHeader",
            {
                "companyName": "LadderLab",
                "productName": "LadderLab",
                "productVersion": __version__,
                "creationDateTime": stamp,
            },
        )
        content = sub(root, "contentHeader", {"name": self.project.name, "modificationDateTime": stamp})
        coordinates = sub(content, "coordinateInfo")
        for language in ("fbd", "ld", "sfc"):
            sub(sub(coordinates, language), "scaling", {"x": 1, "y": 1})
        types = sub(root, "types")
        data_types = sub(types, "dataTypes")
        for decl in self.type_decls():
            write_data_type(data_types, decl)
        pous = sub(types, "pous")
        for pou in self.project.pous:
            self.pou(pous, pou)
        self.instances(sub(root, "instances"))
        ours = ladderlab_data(
            root, {"format": self.project.format}, {"types": self.project.types, "globals": self.project.globals}
        )
        ladderlab_tests(ours, [(test.name, test.text) for test in self.project.tests])
        ladderlab_libraries(ours, list(self.project.libraries))
        ladderlab_typing(ours, self.project.typing)
        write_interfaces(ours, self.project.types)
        if self.problems:
            raise PlcopenExportError(self.problems)
        return to_bytes(root)

    # ------------------------------------------------------------ texts

    def type_decls(self) -> list[ast.TypeDecl]:
        parsed = parse_source(self.project.types, file="types.st")
        self.problems += [d for d in parsed.diagnostics if d.severity == "error"]
        items = parsed.ast.items if parsed.ast is not None else []
        return [decl for item in items if isinstance(item, ast.TypeBlock) for decl in item.decls]

    def var_blocks(self, text: str, pou: str | None, file: str | None = None) -> list[ast.VarBlock]:
        parsed = parse_declarations(text, pou=pou, file=file)
        self.problems += [d for d in parsed.diagnostics if d.severity == "error"]
        return parsed.ast or []

    # ------------------------------------------------------------ POUs

    def pou(self, parent: ET.Element, pou: Pou) -> None:
        node = sub(parent, "pou", {"name": pou.name, "pouType": POU_TYPE[pou.kind]})
        interface = sub(node, "interface")
        if pou.kind == "function":
            spec = parse_type_text(pou.return_type or "")
            if spec is None:
                self.problems.append(
                    Diagnostic(
                        code="PLCOPEN-EXPORT",
                        pou=pou.name,
                        message=f"the return type '{pou.return_type}' is not a type",
                    )
                )
            else:
                write_type(sub(interface, "returnType"), spec)
        for block in self.var_blocks(pou.declarations, pou.name):
            write_var_list(interface, block)
        add = ladderlab_data(
            interface,
            {"returnType": pou.return_type, **oo_attributes(pou)},
            {"declarations": pou.declarations, **oo_texts(pou)},
        )
        write_inheritance(add, pou)
        write_call_after_init(interface, pou.declarations)
        write_documentation(interface, pou.declarations)
        if isinstance(pou.body, SfcBody):
            write_sfc_pou(node, pou.body, lambda holder, networks: self.diagram(holder, networks, pou.name))
            return
        if pou.actions:  # a function block's actions outside SFC: TC6 <actions> with ST bodies (IL-08)
            actions = sub(node, "actions")
            for action in pou.actions:
                formatted_text(sub(sub(actions, "action", {"name": action.name}), "body"), "ST", action.body)
        body = sub(node, "body")
        if isinstance(pou.body, (LdBody, FbdBody)):
            self.diagram(body, pou.body, pou.name)
        else:
            formatted_text(body, pou.language.upper(), pou.body)  # ST or IL text
        write_methods(node, pou)

    def diagram(self, body: ET.Element, networks: LdBody | FbdBody, pou: str) -> None:
        """The ``<LD>`` or ``<FBD>`` of a POU's body, or of an SFC action's or transition's."""
        self.problems += diagram_writer(body, networks, self.signatures, pou)

    # ------------------------------------------------------------ configuration

    def instances(self, parent: ET.Element) -> None:
        write_instances(
            self.project, parent, lambda text, file: self.var_blocks(text, None, file), write_var_list, self.problems
        )


def diagram_writer(body: ET.Element, networks: LdBody | FbdBody, signatures: Signatures, pou: str) -> list[Diagnostic]:
    """Write LD or FBD networks into a ``<body>``: one graph, the network list in LadderLab's addData."""
    top, listing = 0.0, []
    if isinstance(networks, LdBody):
        ld = LdExporter(sub(body, "LD"), signatures, Counter())
        for network in networks.networks:
            listing.append((network.id, top, None))
            top = ld.network(network, top) + NETWORK_GAP
        write_network_list(body, listing)
        return []
    fbd = FbdExporter(sub(body, "FBD"), signatures, Counter(), pou)
    chart = isinstance(networks, CfcBody)  # IEC 61131-10 style: an FBD whose executionOrderIds are the order
    for fbd_network in networks.networks:
        offset, bottom = fbd.network(fbd_network, top, explicit=chart)
        listing.append((fbd_network.id, offset, fbd_network.order))
        top = bottom + NETWORK_GAP
    write_network_list(body, listing, chart)
    return fbd.problems
