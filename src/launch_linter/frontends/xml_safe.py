"""A small, safe XML reader on top of expat that keeps line and column numbers.

Launch files come from strangers. This reader refuses any DTD entity declaration (the
defence against "billion laughs" and external entities), never fetches anything, bounds
the nesting depth and the input size, and builds a plain tree iteratively.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from xml.parsers import expat

MAX_BYTES = 8 * 1024 * 1024
MAX_DEPTH = 200
MAX_ELEMENTS = 200_000


class XmlError(Exception):
    """The text is not acceptable XML; ``line``/``column`` are 1-based."""

    def __init__(self, message: str, line: int = 1, column: int = 1) -> None:
        super().__init__(message)
        self.message = message
        self.line = line
        self.column = column


@dataclass(slots=True)
class Element:
    """An XML element: tag, attributes in document order, children, 1-based position."""

    tag: str
    attrib: dict[str, str]
    line: int
    column: int
    children: list[Element] = field(default_factory=list)
    text: str = ""

    def get(self, name: str) -> str | None:
        return self.attrib.get(name)


@dataclass(slots=True)
class XmlDocument:
    root: Element
    comments: list[tuple[int, str]]
    """(line the comment ends on, text) in document order."""
    element_lines: list[int]
    """Start line of every element, in document order (for suppressions)."""


def parse_xml(data: bytes) -> XmlDocument:
    """Parse ``data`` into an :class:`XmlDocument`, or raise :class:`XmlError`."""
    if len(data) > MAX_BYTES:
        raise XmlError(f"file is {len(data)} bytes, larger than the {MAX_BYTES}-byte limit")
    parser = expat.ParserCreate()
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    stack: list[Element] = []
    roots: list[Element] = []
    comments: list[tuple[int, str]] = []
    element_lines: list[int] = []

    def position() -> tuple[int, int]:
        return parser.CurrentLineNumber, parser.CurrentColumnNumber + 1

    def start(tag: str, attrs: dict[str, str]) -> None:
        line, column = position()
        if len(stack) >= MAX_DEPTH:
            raise XmlError(f"elements nested deeper than {MAX_DEPTH} levels", line, column)
        if len(element_lines) >= MAX_ELEMENTS:
            raise XmlError(f"more than {MAX_ELEMENTS} elements", line, column)
        element = Element(tag, dict(attrs), line, column)
        element_lines.append(line)
        if stack:
            stack[-1].children.append(element)
        else:
            roots.append(element)
        stack.append(element)

    def end(tag: str) -> None:
        stack.pop()

    def chars(text: str) -> None:
        if stack and len(stack[-1].text) < 65536:
            stack[-1].text += text

    def comment(text: str) -> None:
        comments.append((parser.CurrentLineNumber + text.count("\n"), text))

    def entity_decl(name: str, *rest: object) -> None:
        line, column = position()
        raise XmlError(f"entity declaration '{name}' refused (DTD entities are not allowed)", line, column)

    def external_ref(*rest: object) -> int:
        line, column = position()
        raise XmlError("external entity reference refused", line, column)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    parser.CommentHandler = comment
    parser.EntityDeclHandler = entity_decl
    parser.ExternalEntityRefHandler = external_ref
    try:
        parser.Parse(data, True)
    except XmlError:
        raise
    except expat.ExpatError as exc:
        raise XmlError(expat.errors.messages[exc.code], exc.lineno, exc.offset + 1) from None
    except RecursionError:
        raise XmlError("document too deeply nested") from None
    if not roots:
        raise XmlError("no root element")
    return XmlDocument(roots[0], comments, element_lines)
