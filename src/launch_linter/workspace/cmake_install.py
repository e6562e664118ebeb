"""What a ``CMakeLists.txt`` installs into ``share/<package>``, read as text, never run.

CMake is not run (input is untrusted, and a configure step would need the build's whole
environment): the file is scanned for its commands, bounded in bytes, commands and
arguments, and four of them are read:

- ``project(NAME)`` gives ``${PROJECT_NAME}``;
- ``set(VAR value...)`` gives simple variables (a list joined with ``;``, as CMake does);
- ``install(DIRECTORY|FILES|PROGRAMS ... DESTINATION share/...)``, with ``RENAME``,
  ``FILES_MATCHING``, ``PATTERN`` and ``PATTERN ... EXCLUDE``;
- ``ament_auto_package(INSTALL_TO_SHARE dir...)`` (ament_cmake_auto installs each folder
  as ``install(DIRECTORY dir DESTINATION share/${PROJECT_NAME})``).

What cannot be known statically leaves the layout *incomplete* with a reason: a variable
never set, a generator expression, a ``REGEX`` filter, an ``install`` inside a
``function``/``macro``/``foreach`` body, ``add_subdirectory``/``include`` (rules in
another file). An incomplete layout can still explain a path; it can never prove one
absent.
"""

from __future__ import annotations

import os
import re

from launch_linter.workspace.install_rules import InstallRule, Layout, share_relative

MAX_CMAKE_BYTES = 1024 * 1024
MAX_COMMANDS = 20_000
MAX_ARGUMENTS = 5_000
MAX_EXPANSION_DEPTH = 8
MAX_VALUE = 64 * 1024

_NEXT = re.compile(r"#|([A-Za-z_][A-Za-z0-9_]*)[ \t]*\(")
# An unquoted argument may hold escapes (``-DROOT=\"${DIR}\"``): a backslash takes the
# next character, so an escaped quote never opens a quoted argument.
_TOKEN = re.compile(r'[ \t\r\n]+|#|\(|\)|"(?:[^"\\]|\\.)*"?|\[=*\[|\[|'
                    r'(?:[^ \t\r\n()#"\\\[]|\\[\s\S]?)+')
_VARIABLE = re.compile(r"\$\{([A-Za-z0-9_./+-]*)\}")
_BRACKET_OPEN = re.compile(r"\[(=*)\[")
_BODY_OPENERS = {"function": "endfunction", "macro": "endmacro", "foreach": "endforeach",
                 "while": "endwhile"}
_INSTALL_KEYWORDS = frozenset({
    "DESTINATION", "TYPE", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS", "PERMISSIONS",
    "USE_SOURCE_PERMISSIONS", "OPTIONAL", "MESSAGE_NEVER", "CONFIGURATIONS", "COMPONENT",
    "EXCLUDE_FROM_ALL", "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE", "RENAME",
    "NAMELINK_COMPONENT",
})


class Argument:
    __slots__ = ("quoted", "text")

    def __init__(self, text: str, quoted: bool) -> None:
        self.text = text
        self.quoted = quoted


def commands(text: str) -> list[tuple[str, list[Argument], int]]:
    """The commands of a CMake file: (lower-case name, arguments, line), comments left
    out. Regular expressions step from a moving position: linear in the text."""
    found: list[tuple[str, list[Argument], int]] = []
    position, length = 0, len(text)
    line, counted = 1, 0
    while position < length and len(found) < MAX_COMMANDS:
        match = _NEXT.search(text, position)
        if match is None:
            break
        if match.group(0) == "#":
            position = _skip_comment(text, match.start())
            continue
        line += text.count("\n", counted, match.start())
        counted = match.start()
        arguments, position = _arguments(text, match.end())
        found.append((match.group(1).lower(), arguments, line))
    return found


def _skip_comment(text: str, position: int) -> int:
    bracket = _BRACKET_OPEN.match(text, position + 1)
    if bracket is not None:
        end = text.find("]" + bracket.group(1) + "]", bracket.end())
        return len(text) if end < 0 else end + len(bracket.group(0))
    end = text.find("\n", position)
    return len(text) if end < 0 else end + 1


def _arguments(text: str, position: int) -> tuple[list[Argument], int]:
    """The arguments from after ``(`` to the matching ``)``; nested parentheses are kept
    as words (``if((a) AND b)``), counted, not recursed into."""
    arguments: list[Argument] = []
    depth, length = 0, len(text)
    while position < length:
        match = _TOKEN.match(text, position)
        assert match is not None  # every character starts some token
        token = match.group(0)
        position = match.end()
        first = token[0]
        if first in " \t\r\n":
            continue
        if first == "#":
            position = _skip_comment(text, match.start())
        elif first == "(":
            depth += 1
        elif first == ")":
            if depth == 0:
                break
            depth -= 1
        elif first == '"':
            _add(arguments, token[1:-1 if len(token) > 1 and token.endswith('"') else None]
                 .replace('\\"', '"'), True)
        elif first == "[" and len(token) > 1:
            closer = "]" + token[1:-1] + "]"
            end = text.find(closer, position)
            end = length if end < 0 else end
            _add(arguments, text[position:end], True)
            position = end + len(closer)
        else:
            _add(arguments, token, False)
    return arguments, position


def _add(arguments: list[Argument], text: str, quoted: bool) -> None:
    if len(arguments) < MAX_ARGUMENTS:
        arguments.append(Argument(text, quoted))


class Variables:
    def __init__(self, package_name: str) -> None:
        self.values: dict[str, str] = {
            "PROJECT_NAME": package_name,
            "CMAKE_CURRENT_SOURCE_DIR": ".", "CMAKE_SOURCE_DIR": ".",
            "PROJECT_SOURCE_DIR": ".", "CMAKE_CURRENT_LIST_DIR": ".",
            "CMAKE_INSTALL_DATADIR": "share",
            "CATKIN_PACKAGE_SHARE_DESTINATION": "share/" + package_name,
        }

    def expand(self, text: str) -> str | None:
        """``text`` with ``${VAR}`` replaced (innermost first, as CMake nests them); None
        when a variable is not known or a generator expression is met."""
        if "$<" in text:
            return None
        for _ in range(MAX_EXPANSION_DEPTH):
            if "${" not in text:
                return text
            missing = False

            def value(match: re.Match[str]) -> str:
                nonlocal missing
                found = self.values.get(match.group(1))
                if found is None:
                    missing = True
                    return ""
                return found

            text = _VARIABLE.sub(value, text)
            if missing or len(text) > MAX_VALUE:
                return None
        return None if "${" in text else text

    def words(self, arguments: list[Argument]) -> list[str] | None:
        """The arguments as CMake passes them: unquoted ones split on ``;``."""
        out: list[str] = []
        for argument in arguments:
            expanded = self.expand(argument.text)
            if expanded is None:
                return None
            if argument.quoted:
                out.append(expanded)
            else:
                out.extend(piece for piece in expanded.split(";") if piece)
        return out


def read_cmake_layout(text: str, package_name: str, origin: str) -> Layout:
    """The install rules of one ``CMakeLists.txt`` (its text) into ``share/<package>``."""
    layout = Layout()
    if len(text) > MAX_CMAKE_BYTES:
        layout.unread(f"{origin}: longer than {MAX_CMAKE_BYTES} bytes, read in part")
        text = text[:MAX_CMAKE_BYTES]
    variables = Variables(package_name)
    closers: list[str] = []
    for name, arguments, line in commands(text):
        if closers:
            if name == closers[-1]:
                closers.pop()
            elif name in _BODY_OPENERS:
                closers.append(_BODY_OPENERS[name])
            elif name in ("install", "ament_auto_package"):
                layout.unread(f"{origin}:{line}: install rules in a loop or function body")
            continue
        if name in _BODY_OPENERS:
            closers.append(_BODY_OPENERS[name])
        elif name == "project" and arguments:
            project = variables.expand(arguments[0].text)
            if project:
                variables.values["PROJECT_NAME"] = project
        elif name == "set" and arguments:
            set_variable(variables, arguments)
        elif name in ("add_subdirectory", "include") and arguments and not (
                name == "include" and arguments[0].text in ("GNUInstallDirs",)):
            layout.unread(f"{origin}:{line}: {name}({arguments[0].text}) may install more")
        elif name == "install":
            _install(layout, variables, arguments, f"{origin}:{line}")
        elif name == "ament_auto_package":
            _auto_package(layout, variables, arguments, f"{origin}:{line}")
    return layout


def set_variable(variables: Variables, arguments: list[Argument]) -> None:
    name = variables.expand(arguments[0].text)
    if not name:
        return
    words = variables.words([a for a in arguments[1:]
                             if a.quoted or a.text not in ("CACHE", "PARENT_SCOPE", "FORCE")])
    if words is None or (len(arguments) > 2 and any(
            a.text == "CACHE" and not a.quoted for a in arguments)):
        # A cache entry can be set by the user at configure time: not known here.
        variables.values.pop(name, None)
        return
    variables.values[name] = ";".join(words)


def _install(layout: Layout, variables: Variables, arguments: list[Argument],
             origin: str) -> None:
    if not arguments or arguments[0].text not in ("DIRECTORY", "FILES", "PROGRAMS"):
        return
    kind = arguments[0].text
    words = variables.words(arguments[1:])
    raw = [a.text for a in arguments[1:]]
    if words is None:
        if any(_mentions_share(w) for w in raw):
            layout.unread(f"{origin}: install({kind}) with a value not known statically")
        return
    sources: list[str] = []
    index = 0
    while index < len(words) and words[index] not in _INSTALL_KEYWORDS:
        sources.append(words[index])
        index += 1
    options = words[index:]
    destination = _after(options, "DESTINATION")
    if destination is None:
        return
    under = share_relative(destination, variables.values["PROJECT_NAME"])
    if under is None:
        return
    rename = _after(options, "RENAME")
    includes, excludes, exact = _filters(options)
    for source in sources:
        if os.path.isabs(source) or source.startswith("$"):
            layout.unread(f"{origin}: install source {source!r} is outside the package")
            continue
        if kind == "DIRECTORY":
            # CMake: the last component of a folder is appended to the destination, unless
            # the name ends with a slash (then its contents go straight there).
            stripped = source.rstrip("/")
            target = under if source.endswith("/") or not stripped else _join(
                under, os.path.basename(stripped))
            layout.add(InstallRule("directory", os.path.normpath(stripped or "."), target,
                                   includes, excludes, exact, origin))
        else:
            target = _join(under, rename if rename and len(sources) == 1
                           else os.path.basename(source))
            layout.add(InstallRule("file", os.path.normpath(source), target, (), (), True,
                                   origin))


def _auto_package(layout: Layout, variables: Variables, arguments: list[Argument],
                  origin: str) -> None:
    words = variables.words(arguments)
    if words is None:
        layout.unread(f"{origin}: ament_auto_package with a value not known statically")
        return
    if "INSTALL_TO_SHARE" not in words:
        return
    for folder in words[words.index("INSTALL_TO_SHARE") + 1:]:
        if folder.isupper():
            break
        stripped = folder.rstrip("/")
        layout.add(InstallRule("directory", os.path.normpath(stripped),
                               os.path.basename(stripped), (), (), True, origin))


def _mentions_share(word: str) -> bool:
    return "share" in word or "SHARE" in word or "DATADIR" in word


def _after(options: list[str], keyword: str) -> str | None:
    for index, word in enumerate(options[:-1]):
        if word == keyword:
            return options[index + 1]
    return None


def _filters(options: list[str]) -> tuple[tuple[str, ...], tuple[str, ...], bool]:
    """(patterns a file must match when FILES_MATCHING is given, EXCLUDE patterns, whether
    the filters are modelled exactly: REGEX is not, CMake's regular expressions differ)."""
    includes: list[str] = []
    excludes: list[str] = []
    exact = "REGEX" not in options
    matching = "FILES_MATCHING" in options
    for index, word in enumerate(options[:-1]):
        if word != "PATTERN":
            continue
        pattern = options[index + 1]
        if index + 2 < len(options) and options[index + 2] == "EXCLUDE":
            excludes.append(pattern)
        elif matching:
            includes.append(pattern)
    if matching and not includes and exact:
        includes.append("\x00")  # FILES_MATCHING with no PATTERN installs nothing
    return tuple(includes), tuple(excludes), exact


def _join(folder: str, name: str) -> str:
    return name if not folder else folder + "/" + name
