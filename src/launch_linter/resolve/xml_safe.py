"""A small, safe XML reader on top of expat that keeps line and column numbers.

Launch files come from strangers. This reader refuses any DTD entity declaration (the
defence against "billion laughs" and external entities), never fetches anything, bounds
the nesting depth, the number of elements and the input size, and builds a plain tree
without recursion.

It is also on the hot path of every lint run, so the expat handlers are kept minimal:
character data is only collected inside the elements that ask for it.
"""

from __future__ import annotations

from collections.abc import Collection
from xml.parsers import expat

MAX_BYTES = 8 * 1024 * 1024
MAX_DEPTH = 200
MAX_ELEMENTS = 200_000
MAX_TEXT = 1024 * 1024
"""Most characters of text kept per element."""


_HANDLERS = ("StartElementHandler", "EndElementHandler", "CharacterDataHandler",
             "CommentHandler", "EntityDeclHandler", "ExternalEntityRefHandler")


def read_launch_bytes(path: str) -> bytes:
    """A launch file's bytes, one byte past the size limit at most (so that an oversized
    file is reported as such without being read whole)."""
    with open(path, "rb") as handle:
        return handle.read(MAX_BYTES + 1)


class XmlError(Exception):
    """The text is not acceptable XML; ``line``/``column`` are 1-based."""

    def __init__(self, message: str, line: int = 1, column: int = 1) -> None:
        super().__init__(message)
        self.message = message
        self.line = line
        self.column = column


class Element:
    """An XML element: tag, attributes in document order, children, 1-based position."""

    __slots__ = ("attrib", "children", "column", "line", "tag", "text")

    def __init__(self, tag: str, attrib: dict[str, str], line: int, column: int) -> None:
        self.tag = tag
        self.attrib = attrib
        self.line = line
        self.column = column
        self.children: list[Element] = []
        self.text = ""
        """Character data directly inside, kept only for the tags the caller named."""

    def get(self, name: str) -> str | None:
        return self.attrib.get(name)

    def __repr__(self) -> str:
        return f"<Element {self.tag} at {self.line}:{self.column}>"


class XmlDocument:
    __slots__ = ("collected", "comments", "element_lines", "root")

    def __init__(
        self,
        root: Element,
        comments: list[tuple[int, str]],
        element_lines: list[int],
        collected: list[Element],
    ) -> None:
        self.root = root
        self.comments = comments
        """(line the comment ends on, text) in document order."""
        self.element_lines = element_lines
        """Start line of every element, in document order (for suppressions)."""
        self.collected = collected
        """Every element whose tag the caller asked to collect, in document order."""


def parse_xml(
    data: bytes,
    text_tags: Collection[str] = (),
    collect: Collection[str] = (),
) -> XmlDocument:
    """Parse ``data`` into an :class:`XmlDocument`, or raise :class:`XmlError`.

    ``text_tags``: elements whose character data is kept in ``Element.text``.
    ``collect``: tags whose elements are also listed in ``XmlDocument.collected``.
    """
    if len(data) > MAX_BYTES:
        raise XmlError(f"file is {len(data)} bytes, larger than the {MAX_BYTES}-byte limit")
    parser = expat.ParserCreate()
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    parser.buffer_text = True
    stack: list[Element] = []
    roots: list[Element] = []
    comments: list[tuple[int, str]] = []
    element_lines: list[int] = []
    collected: list[Element] = []
    line_of = element_lines.append
    push = stack.append
    pop = stack.pop
    # Character data is wanted only inside ``text_tags``: the handler is switched on when
    # such an element starts and restored when it ends, so other elements cost nothing.
    wanting: list[Element] = []

    def chars(text: str) -> None:
        top = stack[-1]
        if top is wanting[-1] and len(top.text) < MAX_TEXT:
            top.text += text[: MAX_TEXT - len(top.text)]

    def start(tag: str, attrs: dict[str, str]) -> None:
        line = parser.CurrentLineNumber
        element = Element(tag, attrs, line, parser.CurrentColumnNumber + 1)
        line_of(line)
        if stack:
            if len(stack) >= MAX_DEPTH:
                raise XmlError(f"elements nested deeper than {MAX_DEPTH} levels",
                               line, element.column)
            stack[-1].children.append(element)
        else:
            roots.append(element)
        if len(element_lines) > MAX_ELEMENTS:
            raise XmlError(f"more than {MAX_ELEMENTS} elements", line, element.column)
        if tag in collect:
            collected.append(element)
        if tag in text_tags:
            wanting.append(element)
            parser.CharacterDataHandler = chars
        push(element)

    def end(tag: str) -> None:
        element = pop()
        if wanting and element is wanting[-1]:
            wanting.pop()
            if not wanting:
                parser.CharacterDataHandler = None

    def comment(text: str) -> None:
        comments.append((parser.CurrentLineNumber + text.count("\n"), text))

    def entity_decl(name: str, *rest: object) -> None:
        raise XmlError(
            f"entity declaration '{name}' refused (DTD entities are not allowed)",
            parser.CurrentLineNumber, parser.CurrentColumnNumber + 1,
        )

    def external_ref(*rest: object) -> int:
        raise XmlError("external entity reference refused",
                       parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CommentHandler = comment
    parser.EntityDeclHandler = entity_decl
    parser.ExternalEntityRefHandler = external_ref
    try:
        parser.Parse(data, True)
    except expat.ExpatError as exc:
        message = expat.errors.messages.get(exc.code, str(exc))
        raise XmlError(message, exc.lineno, exc.offset + 1) from None
    except RecursionError:
        raise XmlError("document too deeply nested") from None
    finally:
        # The handlers refer to the parser: without this cycle the parser and everything
        # the handlers hold (the whole tree) are freed at once, not by a later garbage
        # collection, whose passes over them cost more than the parsing.
        for handler in _HANDLERS:
            setattr(parser, handler, None)
    if not roots:
        raise XmlError("no root element")
    return XmlDocument(roots[0], comments, element_lines, collected)
