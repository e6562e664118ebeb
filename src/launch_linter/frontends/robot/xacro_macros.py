"""What a xacro macro's definition shows on its own, before any call: block parameters
it never inserts, and parameters its body reads as ``$(arg)``.

``$(arg X)`` is resolved by xacro's ``eval_extension`` through roslaunch's
``resolve_args`` with xacro's ``substitution_args_context['arg']``: the xacro args of the
command line and of ``<xacro:arg>``, one table for the whole document. A macro's
parameters live in the symbol table ``handle_macro_call`` makes for the call
(``scoped_symbols = Table(symbols)``), which only ``${X}`` reads (ros/xacro
src/xacro/__init__.py at 7045754: ``eval_extension``, ``handle_macro_call``). So in a
macro body ``$(arg X)`` never sees the parameter X: the value a call gives X is ignored,
and where no arg X is declared xacro stops. A macro defined in another macro's body is
only defined, and called, while the outer macro's call runs: its calls see the outer
parameters too (the call's table has the outer call's as parent), so the parameters of
every enclosing macro count. Block parameters (``*X``, ``**X``) are not values
(``${X}`` does not read them either): they do not count.

Scanning a macro needs the text of every element (the expander's parse keeps only the
texts it evaluates), so a file is parsed again for it, but only when a cheap look at its
bytes finds an ``$(arg X)`` whose X is a word of some ``params`` attribute. A use is
placed at its own line, found in the file's text after the element's start: an attribute
value in the element's start tag, a text after it; the element's line when the text does
not show it as written (an entity inside the use).
"""

from __future__ import annotations

import bisect
import re
import typing
from collections.abc import Callable, Iterator

from launch_linter.frontends.robot.xacro_values import _PARAM, _PREFIX, _unquoted
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml

MAX_USES = 1000
"""Uses of a parameter as an arg reported per file (the expander keeps 1,000 problems)."""
TEXT_WINDOW = 65_536
"""Characters after an element's start tag searched for a use in its text."""

# ``$$(`` is xacro's escape for a literal ``$(``: a ``$(`` after a ``$`` is not a use.
_USE = re.compile(r"(?<!\$)\$\(\s*arg\s+([^\s()$]+)\s*\)")
# The look at the bytes may find more than there is (an escaped use, an attribute named
# ``xparams``): it only decides whether to scan; without a look-behind or a word boundary
# the patterns start with a literal, which the regex engine searches for fast.
_USE_BYTES = re.compile(rb"\$\(\s*arg\s+([^\s()$]+)\s*\)")
_PARAMS_BYTES = re.compile(rb"""params\s*=\s*(?:"([^"]*)"|'([^']*)')""")
_PARAM_NAME = re.compile(rb"[*\s]*([^\s:=*]+)")
_START_TAG = re.compile(r"""<[^\s/>]+(?:\s+[^\s=/>]+\s*=\s*(?:"[^"]*"|'[^']*'))*\s*/?>""")
_NEWLINE = re.compile(r"\r\n|\r|\n")


class ParamArg(typing.NamedTuple):
    """``$(arg name)`` in the body of ``macro``, whose parameter ``name`` is; ``line`` is
    the use's own line, ``element_line`` the line of the element holding it."""

    macro: str
    name: str
    line: int
    element_line: int


class _EveryTag:
    """Every tag, as the ``text_tags`` of :func:`parse_xml`: keep all texts."""

    def __contains__(self, tag: object) -> bool:
        return True

    def __iter__(self) -> Iterator[str]:
        return iter(())

    def __len__(self) -> int:
        return 0


def macro_params(text: str) -> tuple[list[str], dict[str, tuple[str | None, str | None]]]:
    """A macro's ``params`` attribute: the names in order (block ones with their ``*``)
    and, for those with a default, (the name it forwards with ``^``/``^|``, the default)."""
    params: list[str] = []
    defaults: dict[str, tuple[str | None, str | None]] = {}
    for match in _PARAM.finditer(text):
        param, sep, forward, default = match.groups()
        params.append(param)
        if not sep:
            continue
        if forward:
            defaults[param] = (param, default if forward == "^|" else None)
        else:
            # A quoted default (xyz:='0 0 0') keeps its spaces; xacro reads it as the
            # text inside the quotes.
            defaults[param] = (None, _unquoted(default))
    return params, defaults


def never_inserted(element: Element, params: list[str], legacy: bool,
                   charge: Callable[[], None]) -> list[str]:
    """The block parameters (``*origin``, ``**content``) of the macro ``element`` that
    no ``insert_block`` of its body may insert (one named by an expression may insert
    any; unprefixed too, for a legacy xacro)."""
    tags = {_PREFIX + "insert_block"} | ({"insert_block"} if legacy else set())
    return [param for param in params if param.startswith("*")
            and not _inserts(element, param.lstrip("*"), tags, charge)]


def _inserts(element: Element, block: str, tags: set[str],
             charge: Callable[[], None]) -> bool:
    for child in element.children:
        charge()
        if child.tag in tags:
            name = child.attrib.get("name", "")
            if name == block or "$" in name:
                return True
        if _inserts(child, block, tags, charge):
            return True
    return False


def _may_have_uses(data: bytes) -> bool:
    """Whether some ``$(arg X)`` of the file's bytes names a word of some ``params``
    attribute (what a use needs; most files have none, and are not parsed again)."""
    used = {m.group(1) for m in _USE_BYTES.finditer(data)}
    if not used:
        return False
    for match in _PARAMS_BYTES.finditer(data):
        words = (match.group(1) if match.group(1) is not None else match.group(2)).split()
        for word in words:
            name = _PARAM_NAME.match(word)
            if name is not None and name.group(1) in used:
                return True
    return False


def params_read_as_args(data: bytes, legacy: bool) -> dict[tuple[int, int], list[ParamArg]]:
    """The uses of ``$(arg X)`` in the file ``data`` where X is a (non-block) parameter
    of an enclosing macro, by the (line, column) of the outermost macro holding each."""
    if not _may_have_uses(data):
        return {}
    try:
        root = parse_xml(data, _EveryTag(), directives=False).root
    except XmlError:
        return {}
    macro_tags = {_PREFIX + "macro"} | ({"macro"} if legacy else set())
    # (outermost macro, element, macro, name, whether in the text) of each use.
    found: list[tuple[Element, Element, str, str, bool]] = []

    def uses(text: str, scopes: list[dict[str, str]], element: Element,
             outermost: Element | None, in_text: bool) -> None:
        if outermost is None or "$(" not in text:
            return
        for match in _USE.finditer(text):
            name = match.group(1)
            # The innermost macro with that parameter (nesting is bounded by the
            # reader's depth: scopes are looked through, never copied).
            macro = next((scope[name] for scope in reversed(scopes) if name in scope), None)
            if macro is not None and len(found) < MAX_USES:
                found.append((outermost, element, macro, name, in_text))

    def visit(element: Element, scopes: list[dict[str, str]],
              outermost: Element | None) -> None:
        # A macro's own attributes (the defaults of a nested one) are read where it is
        # defined: in the enclosing scope; its body in its own.
        for text in element.attrib.values():
            uses(text, scopes, element, outermost, False)
        if element.tag in macro_tags:
            name = element.attrib.get("name", "")
            own = {param: name for param in macro_params(element.attrib.get("params", ""))[0]
                   if not param.startswith("*")}
            scopes, outermost = [*scopes, own], outermost or element
        uses(element.text, scopes, element, outermost, True)
        for child in element.children:
            if len(found) < MAX_USES:
                visit(child, scopes, outermost)

    visit(root, [], None)
    if not found:
        return {}
    lines = _Lines(data)
    out: dict[tuple[int, int], list[ParamArg]] = {}
    for outermost, element, macro, name, in_text in found:
        use = ParamArg(macro, name, lines.of_use(element, name, in_text), element.line)
        out.setdefault((outermost.line, outermost.column), []).append(use)
    return out


class _Lines:
    """Where in a file's text a use is written: found after its element's start, each
    use after the one before it in the same element (so one element's uses are found in
    one pass over its start tag and the window after it)."""

    def __init__(self, data: bytes) -> None:
        self.text = data.decode("utf-8", "replace")
        self.starts = [0] + [m.end() for m in _NEWLINE.finditer(self.text)]
        self.cursors: dict[tuple[int, int, bool], int] = {}
        self.tag_ends: dict[tuple[int, int], tuple[int, int] | None] = {}

    def _start_tag(self, element: Element) -> tuple[int, int] | None:
        key = (element.line, element.column)
        if key not in self.tag_ends:
            self.tag_ends[key] = None
            if element.line <= len(self.starts):
                start = self._tag_start(element)
                match = None if start < 0 else _START_TAG.match(self.text, start)
                if match is not None:
                    self.tag_ends[key] = (start, match.end())
        return self.tag_ends[key]

    def _tag_start(self, element: Element) -> int:
        """Where the element's ``<tag`` starts: at its column (expat counts characters),
        else its first on its line; -1 when not found."""
        line_start = self.starts[element.line - 1]
        start = line_start + element.column - 1
        opening = "<" + element.tag
        if self.text.startswith(opening, start):
            return start
        end = (self.starts[element.line] if element.line < len(self.starts)
               else len(self.text))
        return self.text.find(opening, line_start, end)

    def of_use(self, element: Element, name: str, in_text: bool) -> int:
        tag = self._start_tag(element)
        if tag is None:
            return element.line
        start, end = tag
        key = (element.line, element.column, in_text)
        cursor = self.cursors.get(key, end if in_text else start)
        stop = end + TEXT_WINDOW if in_text else end
        while True:
            match = _USE.search(self.text, cursor, stop)
            if match is None:
                return element.line
            cursor = self.cursors[key] = match.end()
            if match.group(1) == name:
                return bisect.bisect_right(self.starts, match.start())
