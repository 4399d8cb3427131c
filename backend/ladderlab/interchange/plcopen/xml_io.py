"""PLCopen TC6 XML plumbing shared by the exporter and the importer.

Namespaces, element builders that keep the child order the XSD demands, a
namespace-agnostic reader (TC6 2.01 and the near-identical 2.00 both import),
formatted-text helpers, and LadderLab's own ``addData`` block: the ids and hints
the project model needs for an exact round trip, carried where PLCopen reserves
room for tool data (other tools keep or drop it; nothing depends on it being there).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator
from decimal import Decimal

from ...model.diagnostics import Diagnostic
from .xml_safety import ParsedXml

PLCOPEN_NS = "http://www.plcopen.org/xml/tc6_0201"
PLCOPEN_NAMESPACES = (PLCOPEN_NS, "http://www.plcopen.org/xml/tc6_0200")
XHTML_NS = "http://www.w3.org/1999/xhtml"
#: LadderLab's addData: ``<data name=LADDERLAB_DATA>`` holding one ``<ll:info>`` element.
LADDERLAB_NS = "urn:ladderlab:plcopen:1"
LADDERLAB_DATA = LADDERLAB_NS

ET.register_namespace("xhtml", XHTML_NS)
ET.register_namespace("ll", LADDERLAB_NS)


def q(tag: str) -> str:
    """A PLCopen element name for building.

    Built elements are unqualified and the root declares the PLCopen namespace as the
    default (``xmlns``): ElementTree cannot serialise a default namespace together with
    the unqualified attributes PLCopen uses.
    """
    return tag


def sub(parent: ET.Element, tag: str, attrib: dict[str, object] | None = None) -> ET.Element:
    """Append ``<tag>`` with the given attributes (None values left out, others stringified)."""
    clean = {k: _attr(v) for k, v in (attrib or {}).items() if v is not None}
    return ET.SubElement(parent, q(tag), clean)


def _attr(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (float, Decimal)):
        return decimal_text(value)
    return str(value)


def decimal_text(value: float | Decimal) -> str:
    """An ``xsd:decimal`` (no exponent): 150.0 -> '150', 0.5 -> '0.5', 1e-05 -> '0.00001'."""
    exact = value if isinstance(value, Decimal) else Decimal(repr(float(value)))
    text = format(exact.normalize(), "f")
    return "0" if text in ("-0", "") else text


def position(parent: ET.Element, tag: str, x: float | Decimal, y: float | Decimal) -> ET.Element:
    return sub(parent, tag, {"x": decimal_text(x), "y": decimal_text(y)})


def formatted_text(parent: ET.Element, tag: str, text: str) -> ET.Element:
    """``<tag><xhtml:p>text</xhtml:p></tag>`` (the formattedText type of ST bodies, comments, documentation)."""
    holder = sub(parent, tag)
    ET.SubElement(holder, f"{{{XHTML_NS}}}p").text = text
    return holder


def ladderlab_data(
    element: ET.Element, attrib: dict[str, object] | None = None, texts: dict[str, str] | None = None
) -> ET.Element:
    """Append ``<addData>`` with LadderLab's ``<ll:info attr...>`` (and ``<ll:name>text</ll:name>`` children)."""
    add = sub(element, "addData")
    data = sub(add, "data", {"name": LADDERLAB_DATA, "handleUnknown": "discard"})
    info = ET.SubElement(
        data, f"{{{LADDERLAB_NS}}}info", {k: _attr(v) for k, v in (attrib or {}).items() if v is not None}
    )
    for name, text in (texts or {}).items():
        ET.SubElement(info, f"{{{LADDERLAB_NS}}}{name}").text = text
    return add


def ladderlab_tests(add_data: ET.Element, tests: list[tuple[str, str]]) -> None:
    """Carry unit test files (name, text) in the ``<ll:info>`` of ``ladderlab_data``'s result: PLCopen XML
    has no place for them, and a project should come back with its tests."""
    info = add_data[0][0]
    for name, text in tests:
        ET.SubElement(info, f"{{{LADDERLAB_NS}}}test", {"name": name}).text = text


def ladderlab_libraries(add_data: ET.Element, libraries: list[str]) -> None:
    """Carry the project's vendor libraries (``<ll:library name=...>``) in ``ladderlab_data``'s result: PLCopen
    XML has no place for a library reference, and without them the project's calls of LTRUNC & co. fail."""
    info = add_data[0][0]
    for name in libraries:
        ET.SubElement(info, f"{{{LADDERLAB_NS}}}library", {"name": name})


def ladderlab_typing(add_data: ET.Element, typing: str) -> None:
    """Carry the project's type rules (``<ll:typing rules="codesys"/>``, only when not IEC) in ``ladderlab_data``'s
    result: PLCopen XML has no such setting, and the project's CODESYS-typed ST would not build without it."""
    if typing != "iec":
        ET.SubElement(add_data[0][0], f"{{{LADDERLAB_NS}}}typing", {"rules": typing})


def typing_rules(node: ET.Element | None) -> str | None:
    """The type rules carried in the project's ``<ll:info>`` (``ladderlab_typing``), None when there are none."""
    found = node.find(f"{{{LADDERLAB_NS}}}typing") if node is not None else None
    return found.get("rules") if found is not None else None


def library_names(node: ET.Element | None) -> list[str]:
    """The library names carried in the project's ``<ll:info>`` (``ladderlab_libraries``)."""
    if node is None:
        return []
    return [found.get("name", "") for found in node.findall(f"{{{LADDERLAB_NS}}}library")]


def to_bytes(root: ET.Element) -> bytes:
    """Serialise a built document (its root gets the default PLCopen namespace declaration).

    A carriage return in a text (ST typed with CR LF) is written as ``&#13;``: XML parsers
    turn a literal CR LF into LF, the character reference survives.
    """
    root.set("xmlns", PLCOPEN_NS)
    ET.indent(root, space="  ")
    return (ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n").replace(b"\r", b"&#13;")


def local(element: ET.Element) -> str:
    """Tag name without its namespace."""
    tag = element.tag
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def namespace(element: ET.Element) -> str:
    tag = element.tag
    return tag[1:].split("}", 1)[0] if isinstance(tag, str) and tag.startswith("{") else ""


class Reader:
    """Read a parsed PLCopen document in whichever TC6 namespace it uses; collects diagnostics."""

    def __init__(self, parsed: ParsedXml, *, file: str | None = None):
        self.parsed = parsed
        self.ns = namespace(parsed.root)
        self.file = file
        self.diagnostics: list[Diagnostic] = []

    def children(self, element: ET.Element | None, tag: str) -> list[ET.Element]:
        if element is None:
            return []
        return [c for c in element if local(c) == tag and namespace(c) == self.ns]

    def child(self, element: ET.Element | None, tag: str) -> ET.Element | None:
        found = self.children(element, tag)
        return found[0] if found else None

    def path(self, element: ET.Element | None, *tags: str) -> ET.Element | None:
        for tag in tags:
            element = self.child(element, tag)
        return element

    def elements(self, element: ET.Element | None) -> Iterator[ET.Element]:
        """Child elements in a TC6 namespace (skips comments, processing instructions and foreign elements)."""
        for c in element if element is not None else ():
            if isinstance(c.tag, str) and namespace(c) == self.ns:
                yield c

    def line(self, element: ET.Element | None) -> int | None:
        return None if element is None else self.parsed.line(element)

    def report(
        self,
        code: str,
        message: str,
        element: ET.Element | None = None,
        *,
        severity: str = "error",
        pou: str | None = None,
        network: str | None = None,
        item: str | None = None,
    ) -> None:
        self.diagnostics.append(
            Diagnostic(
                severity=severity,
                code=code,
                message=message,
                file=self.file,
                line=self.line(element),
                pou=pou,
                network=network,
                element=item,
            )
        )


CFC_DATA = "http://www.3s-software.com/plcopenxml/cfc"


def data_entries(element: ET.Element | None, reader: Reader, name: str) -> list[ET.Element]:
    """The ``<data name="name">`` entries of ``element``'s addData (vendors' extensions, LadderLab's own)."""
    return [d for d in reader.children(reader.child(element, "addData"), "data") if d.get("name") == name]


def body_language(body: ET.Element | None, reader: Reader) -> tuple[str, ET.Element | None]:
    """The language of a ``<body>`` (``ST`` when it is empty) and its element. CODESYS writes a CFC chart as an
    empty ``<ST>`` with the chart in the body's addData (``.../plcopenxml/cfc``): that is ``CFC``."""
    language = next(reader.elements(body), None)
    charts = data_entries(body, reader, CFC_DATA)
    if charts:
        return "CFC", charts[0]
    return (local(language) if language is not None else "ST"), language


def text_content(element: ET.Element | None) -> str:
    """The text of a formattedText element (``<xhtml:p>``, ``<xhtml:xhtml>``, vendor ``<pre>`` ...), as written.

    Several paragraphs are joined with newlines; text directly inside the element counts when it has no children.
    """
    if element is None:
        return ""
    paragraphs = [c for c in element if isinstance(c.tag, str)]
    if not paragraphs:
        return element.text or ""
    return "\n".join("".join(p.itertext()) for p in paragraphs)


def info(element: ET.Element | None, reader: Reader) -> ET.Element | None:
    """LadderLab's ``<ll:info>`` in ``element``'s addData, or None."""
    for data in data_entries(element, reader, LADDERLAB_DATA):
        return next((c for c in data if local(c) == "info" and namespace(c) == LADDERLAB_NS), None)
    return None


def info_text(node: ET.Element | None, name: str) -> str | None:
    """The text of ``<ll:name>`` inside an ``<ll:info>`` (None when absent)."""
    if node is None:
        return None
    found = node.find(f"{{{LADDERLAB_NS}}}{name}")
    return None if found is None else (found.text or "")


def test_texts(node: ET.Element | None) -> list[tuple[str, str]]:
    """The unit test files carried in the project's ``<ll:info>`` (``<ll:test name=...>text</ll:test>``)."""
    if node is None:
        return []
    return [(found.get("name", ""), found.text or "") for found in node.findall(f"{{{LADDERLAB_NS}}}test")]


def foreign_data(element: ET.Element | None, reader: Reader) -> list[ET.Element]:
    """The ``<data>`` entries of ``element``'s addData that are not LadderLab's."""
    return [d for d in reader.children(reader.child(element, "addData"), "data") if d.get("name") != LADDERLAB_DATA]


def canonical(element: ET.Element) -> tuple:
    """Structure of an element for comparison: local tag, attributes, stripped text, children (whitespace-insensitive).

    Compares an element LadderLab would write (unqualified tags) with one read from a file (qualified tags).
    """
    return (
        local(element),
        tuple(sorted(element.attrib.items())),
        (element.text or "").strip(),
        tuple(canonical(c) for c in element if isinstance(c.tag, str)),
    )
