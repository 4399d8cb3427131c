"""Parse untrusted XML without the classic XML attacks, keeping each element's source line.

PLCopen files come from users and other tools, so parsing must never expand
entities (billion laughs), fetch external resources (XXE, remote DTDs) or read a
document too large to hold: documents over ``MAX_XML_BYTES`` are refused before
the parser sees them, and entity declarations or external references stop the
parse. Every refusal is a located ``Diagnostic`` (raised as ``XmlInputError``),
never a raw parser exception.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from defusedxml.common import DTDForbidden, EntitiesForbidden, ExternalReferenceForbidden
from defusedxml.ElementTree import DefusedXMLParser

from ... import limits
from ...model.diagnostics import Diagnostic

#: Larger documents are refused unread (the biggest real PLCopen projects are a few MB).
MAX_XML_BYTES = 20 * 1024 * 1024


class XmlInputError(Exception):
    """The document was refused; ``diagnostic`` says why and where."""

    def __init__(self, diagnostic: Diagnostic):
        super().__init__(diagnostic.format())
        self.diagnostic = diagnostic


@dataclass
class ParsedXml:
    """The element tree and the 1-based source line of every element (by ``id(element)``)."""

    root: ET.Element
    lines: dict[int, int] = field(default_factory=dict)

    def line(self, element: ET.Element) -> int | None:
        return self.lines.get(id(element))


class TooDeep(Exception):
    """The document nests elements deeper than ``limits.XML_DEPTH`` (raised while it is parsed)."""


class _LineRecorder(ET.TreeBuilder):
    """Tree builder that notes the parser's current line for each element it opens and refuses a document
    nested deeper than the limit: whatever reads the tree recurses once per level."""

    def __init__(self) -> None:
        super().__init__()
        self.expat = None
        self.lines: dict[int, int] = {}
        self.depth = 0
        self.max_depth = limits.XML_DEPTH.value

    def start(self, tag, attrs):
        self.depth += 1
        if self.depth > self.max_depth:
            raise TooDeep
        element = super().start(tag, attrs)
        if self.expat is not None:
            self.lines[id(element)] = self.expat.CurrentLineNumber
        return element

    def end(self, tag):
        self.depth -= 1
        return super().end(tag)


def parse_untrusted_xml(data: bytes, *, file: str | None = None, max_bytes: int = MAX_XML_BYTES) -> ParsedXml:
    """Parse ``data`` safely; raises ``XmlInputError`` for oversize, hostile or malformed documents."""
    if len(data) > max_bytes:
        raise XmlInputError(
            Diagnostic(
                code="XML-TOO-LARGE",
                file=file,
                message=f"the document is {len(data):,} bytes; documents over {max_bytes:,} bytes are refused unread",
            )
        )
    builder = _LineRecorder()
    parser = DefusedXMLParser(target=builder, forbid_dtd=False, forbid_entities=True, forbid_external=True)
    builder.expat = parser.parser
    parser.parser.StartDoctypeDeclHandler = _refuse_external_dtd
    try:
        parser.feed(data)
        root = parser.close()
    except EntitiesForbidden as err:
        raise XmlInputError(
            _refusal(
                "XML-ENTITY",
                f"the document declares the entity '{err.name}'; entity declarations are refused "
                "(they allow entity-expansion and external-entity attacks)",
                builder,
                file,
            )
        ) from err
    except ExternalReferenceForbidden as err:
        raise XmlInputError(
            _refusal(
                "XML-EXTERNAL",
                f"the document refers to the external resource '{err.sysid}'; external "
                "entities and DTDs are never fetched",
                builder,
                file,
            )
        ) from err
    except DTDForbidden as err:
        raise XmlInputError(
            _refusal(
                "XML-EXTERNAL",
                f"the document type declaration names the external DTD '{err.sysid or err.pubid}'; "
                "external DTDs are never fetched",
                builder,
                file,
            )
        ) from err
    except TooDeep as err:
        raise XmlInputError(_refusal("XML-TOO-DEEP", limits.XML_DEPTH.too_deep("the document"), builder, file)) from err
    except (ValueError, LookupError) as err:  # expat: an encoding it cannot read (UTF-7, UTF-16 declared in ASCII...)
        raise XmlInputError(
            Diagnostic(
                code="XML-ENCODING",
                file=file,
                line=1,
                message=f"the document's encoding cannot be read ({err}); save it as UTF-8",
            )
        ) from err
    except ET.ParseError as err:
        line, column = err.position
        raise XmlInputError(
            Diagnostic(
                code="XML-SYNTAX",
                file=file,
                line=line,
                column=column + 1,
                message=f"not well-formed XML: {_reason(err)}",
            )
        ) from err
    return ParsedXml(root, builder.lines)


def _refuse_external_dtd(name: str, sysid: str | None, pubid: str | None, has_internal_subset: bool) -> None:
    """A plain ``<!DOCTYPE x>`` is harmless; one naming an external DTD is refused, not silently ignored."""
    if sysid or pubid:
        raise DTDForbidden(name, sysid, pubid)


def _refusal(code: str, message: str, builder: _LineRecorder, file: str | None) -> Diagnostic:
    line = builder.expat.CurrentLineNumber if builder.expat is not None else None
    return Diagnostic(code=code, file=file, line=line, message=message)


def _reason(err: ET.ParseError) -> str:
    """expat's message without the ``line x, column y`` it already carries in ``position``."""
    return str(err).split(": line ")[0]
