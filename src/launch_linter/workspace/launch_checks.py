"""Launch files that a catkin package only hands to ``roslaunch_add_file_check``.

``roslaunch_add_file_check(FILE)`` makes a test that loads ``FILE`` with roslaunch's
parser and never starts it. Packages write aggregates for it (abb's
``tests/roslaunch_test_*.xml``: one ``<group ns>`` per launch file of the package, each
only to be parsed): such a file is not one running system, so robots of its groups do
not share a tf tree. A file counts as one only with proof: its package's
``CMakeLists.txt`` (read as text, never run) names it in ``roslaunch_add_file_check``
and installs nothing it lies in (no ``install(DIRECTORY|FILES ...)`` argument names the
file or a folder above it, and no argument is left unresolved).
"""

from __future__ import annotations

import os

from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file
from launch_linter.workspace.packages import PackageIndex

MAX_CMAKE_BYTES = 1024 * 1024
"""The bound cmake_install puts on a CMakeLists.txt (not imported from it: see below)."""
MAX_LOOP_DEPTH = 16
"""Nested ``foreach`` loops followed; deeper, an install in them is not read (no proof)."""
MAX_INSTALLED = 20_000
"""Install items (after expanding loops) compared with the file: a file whose loops make
more proves nothing (without the bound a 1 MiB file of one long loop around many installs
is a billion comparisons)."""
_CHECK_KEYWORDS = frozenset({"USE_TEST_DEPENDENCIES", "DEPENDENCIES"})
_INSTALL_LISTS = frozenset({"DIRECTORY", "FILES", "PROGRAMS"})


def _installed_items(texts: list[str]) -> list[str]:
    """The files and folders an ``install`` call names: the words after ``DIRECTORY``,
    ``FILES`` or ``PROGRAMS`` up to the next keyword (``DESTINATION``, ``PATTERN``...)."""
    items: list[str] = []
    taking = False
    for text in texts:
        if text in _INSTALL_LISTS:
            taking = True
        elif text.isupper() and text.replace("_", "").isalpha():
            taking = False
        elif taking:
            items.append(text)
    return items


def only_parse_checked(path: str, packages: PackageIndex) -> bool:
    """Whether the launch file ``path`` is proven to be only a parse-check input
    (``packages``: the run's index, which finds each folder's package once)."""
    manifest = packages.package_xml_of(path)
    if manifest is None:
        return False
    folder = os.path.dirname(manifest)
    try:
        data = read_regular_file(os.path.join(folder, "CMakeLists.txt"), MAX_CMAKE_BYTES)
    except (OSError, NotRegularFile):
        return False
    text = data.decode("utf-8", "replace")
    if "roslaunch_add_file_check" not in text:
        return False
    # Imported only here: the CMake reader's install rules are dataclasses, which a run
    # over launch files of packages without parse checks never needs (start-up time).
    from launch_linter.workspace.cmake_install import commands

    relative = os.path.relpath(os.path.abspath(path), folder).replace(os.sep, "/")
    checked = False
    loops: list[tuple[str, list[str]]] = []
    compared = 0
    for name, arguments, _line in commands(text):
        texts = [a.text for a in arguments]
        if name == "foreach":
            if len(loops) >= MAX_LOOP_DEPTH:
                return False
            loops.append(_loop(texts))
        elif name == "endforeach":
            if loops:
                loops.pop()
        elif name == "roslaunch_add_file_check":
            for text in texts:
                if text in _CHECK_KEYWORDS:
                    break
                checked = checked or os.path.normpath(text).replace(os.sep, "/") == relative
        elif name == "install":
            for text in _installed_items(texts):
                items = _expanded(text, loops)
                compared += len(items)
                if compared > MAX_INSTALLED:
                    return False
                for item in items:
                    if "$" in item or "*" in item:
                        return False
                    named = os.path.normpath(item).replace(os.sep, "/").strip("/")
                    if named and (relative == named or relative.startswith(named + "/")):
                        return False
    return checked


def _loop(texts: list[str]) -> tuple[str, list[str]]:
    """A ``foreach(var item...)``: its variable and literal items. A loop over a list
    variable, ``IN LISTS``, ``RANGE`` or an unresolved item has no items known here, so
    ``${var}`` stays unresolved in its body."""
    if not texts:
        return ("", [])
    variable, items = texts[0], texts[1:]
    if any("$" in item or item in ("IN", "RANGE", "LISTS", "ITEMS") for item in items):
        return (variable, [])
    return (variable, items)


def _expanded(text: str, loops: list[tuple[str, list[str]]]) -> list[str]:
    """``text`` once per item of the innermost enclosing literal ``foreach`` whose
    variable it names (``install(DIRECTORY ${dir}/ ...)`` inside ``foreach(dir config
    launch urdf)``, abb's support packages); itself otherwise."""
    for variable, items in reversed(loops):
        reference = "${" + variable + "}"
        if variable and items and reference in text:
            return [text.replace(reference, item) for item in items]
    return [text]
