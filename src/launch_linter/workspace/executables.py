"""The executables a ROS 2 package of the workspace installs into ``lib/<package>``.

``ros2 launch`` starts ``Node(package=P, executable=E)`` only when ``<prefix>/lib/P/E``
exists (launch_ros ``get_executable_path``: "executable 'E' not found on the libexec
directory"). The package's build files say what lands there; they are read as text,
never run, bounded like :mod:`.cmake_install`:

- CMake: ``install(TARGETS|PROGRAMS|FILES ... DESTINATION lib/${PROJECT_NAME})`` (with
  ``RENAME``), ``install(DIRECTORY d DESTINATION lib/${PROJECT_NAME})`` (the files under
  ``d``), ``rclcpp_components_register_node(t PLUGIN p EXECUTABLE e)`` (rclcpp
  a0a2a067d ``rclcpp_components_register_node.cmake``: ``add_executable(e)`` and
  ``install(TARGETS e DESTINATION lib/${PROJECT_NAME})``), ``ament_auto_add_executable``
  with ``ament_auto_package`` (installed to ``lib/${PROJECT_NAME}`` unless
  ``INSTALL_TO_PATH``), and the ``CMakeLists.txt`` of each ``add_subdirectory``;
- ament_python: ``setup.py``'s ``entry_points['console_scripts']`` and ``scripts``, and
  ``setup.cfg``'s ``[options.entry_points]`` and ``[options] scripts``, installed to
  ``lib/<package>`` by the ``[install] install_scripts=$base/lib/<package>`` that
  ament_python packages write (without it, setuptools installs them to ``bin``: then not
  known here).

Whatever cannot be read exactly (an unknown variable or destination, an ``install`` in a
function, macro or loop body, ``include`` of a file, ``install(SCRIPT|CODE)``, a target
given another ``OUTPUT_NAME``, ``ament_python_install_package``, a missing subdirectory,
a value the setup.py evaluator does not know, ``**kwargs`` or a ``cmdclass`` in
``setup()``) leaves the list incomplete: it can then say that an executable is
installed, never that one is not.
"""

from __future__ import annotations

import ast
import configparser
import os
import posixpath
from typing import NamedTuple

from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file
from launch_linter.workspace.cmake_install import (
    MAX_ARGUMENTS,
    MAX_CMAKE_BYTES,
    MAX_COMMANDS,
    Variables,
    commands,
    set_variable,
)
from launch_linter.workspace.python_install import (
    MAX_SETUP_BYTES,
    package_files,
    setup_call,
    setup_value,
)

MAX_CMAKE_FILES = 32
"""CMakeLists.txt files read per package (its own and those of ``add_subdirectory``)."""
MAX_NAMES = 20_000
MAX_REASONS = 10
_BODIES = {"function": "endfunction", "macro": "endmacro", "foreach": "endforeach",
           "while": "endwhile"}
_TARGET_KEYWORDS = frozenset({
    "EXPORT", "RUNTIME", "LIBRARY", "ARCHIVE", "OBJECTS", "FRAMEWORK", "BUNDLE",
    "PRIVATE_HEADER", "PUBLIC_HEADER", "RESOURCE", "FILE_SET", "CXX_MODULES_BMI",
    "INCLUDES", "DESTINATION", "PERMISSIONS", "CONFIGURATIONS", "COMPONENT",
    "NAMELINK_COMPONENT", "OPTIONAL", "EXCLUDE_FROM_ALL", "NAMELINK_ONLY", "NAMELINK_SKIP",
    "RENAME", "TYPE", "FILES_MATCHING", "PATTERN", "REGEX", "USE_SOURCE_PERMISSIONS",
})
_INSTALL_CALLS = ("install", "rclcpp_components_register_node", "ament_auto_add_executable",
                  "ament_auto_package", "ament_python_install_package", "add_subdirectory")


class Executables(NamedTuple):
    """What a package installs into ``lib/<package>``."""

    names: frozenset[str]
    reasons: tuple[str, ...]
    """Why ``names`` may be incomplete; empty when every rule was read."""
    origin: str
    """The build files read (``CMakeLists.txt``, ``setup.py``, ...)."""


class _Reading:
    def __init__(self, directory: str, package: str) -> None:
        self.directory = directory
        self.package = package
        self.names: set[str] = set()
        self.reasons: list[str] = []
        self.files = 0

    def unknown(self, reason: str) -> None:
        if len(self.reasons) < MAX_REASONS:
            self.reasons.append(reason)

    def add(self, name: str) -> None:
        if len(self.names) >= MAX_NAMES:
            self.unknown(f"more than {MAX_NAMES} executables")
        elif name:
            self.names.add(name)

    def libexec(self, destination: str) -> bool:
        return posixpath.normpath(destination.strip()) == "lib/" + self.package


def read_executables(directory: str, package: str) -> Executables | None:
    """The executables the package in ``directory`` installs; None without a
    ``CMakeLists.txt``, ``setup.py`` or ``setup.cfg``."""
    reading = _Reading(directory, package)
    read: list[str] = []
    if os.path.lexists(os.path.join(directory, "CMakeLists.txt")):
        read.append("CMakeLists.txt")
        _cmake(reading, "", Variables(package), 0)
    if os.path.lexists(os.path.join(directory, "setup.py")):
        read.append("setup.py")
        _setup_py(reading)
    if os.path.lexists(os.path.join(directory, "setup.cfg")):
        read.append("setup.cfg")
    if not read:
        return None
    if "setup.py" in read or "setup.cfg" in read:
        _setup_cfg(reading)
    return Executables(frozenset(reading.names), tuple(reading.reasons), ", ".join(read))


def _read(reading: _Reading, relative: str, limit: int) -> str | None:
    path = os.path.join(reading.directory, relative)
    try:
        return read_regular_file(path, limit).decode("utf-8", "replace")
    except (OSError, NotRegularFile) as exc:
        reading.unknown(f"{relative} not read: {getattr(exc, 'strerror', None) or exc}")
        return None


def _cmake(reading: _Reading, folder: str, variables: Variables, depth: int) -> None:
    origin = posixpath.join(folder, "CMakeLists.txt")
    reading.files += 1
    if reading.files > MAX_CMAKE_FILES:
        reading.unknown(f"more than {MAX_CMAKE_FILES} CMakeLists.txt files")
        return
    text = _read(reading, origin, MAX_CMAKE_BYTES)
    if text is None:
        return
    closers: list[str] = []
    automatic: list[str] = []
    found = commands(text)
    if len(text) >= MAX_CMAKE_BYTES or len(found) >= MAX_COMMANDS:
        reading.unknown(f"{origin}: read in part (its size)")
    for name, arguments, line in found:
        where = f"{origin}:{line}"
        if len(arguments) >= MAX_ARGUMENTS:
            reading.unknown(f"{where}: {name}() read in part (its arguments)")
        if closers:
            if name == closers[-1]:
                closers.pop()
            elif name in _BODIES:
                closers.append(_BODIES[name])
            elif name in _INSTALL_CALLS:
                reading.unknown(f"{where}: {name} in a function, macro or loop body")
            continue
        if name in _BODIES:
            closers.append(_BODIES[name])
            continue
        words = variables.words(arguments)
        if name == "project" and words:
            variables.values["PROJECT_NAME"] = words[0]
        elif name == "set" and arguments:
            set_variable(variables, arguments)
        elif words is None:
            if name in _INSTALL_CALLS or name in ("include", "set_target_properties"):
                reading.unknown(f"{where}: {name}() with a value not known statically")
        elif name == "install":
            _install(reading, words, folder, where)
        elif name == "rclcpp_components_register_node" and "EXECUTABLE" in words[:-1]:
            reading.add(words[words.index("EXECUTABLE") + 1])
        elif name == "ament_auto_add_executable" and words:
            automatic.append(words[0])
        elif name == "ament_auto_package" and "INSTALL_TO_PATH" not in words:
            for target in automatic:
                reading.add(target)
        elif name == "add_subdirectory" and words:
            _subdirectory(reading, folder, words[0], variables, depth, where)
        elif name == "include" and words and ("/" in words[0] or "." in words[0]):
            reading.unknown(f"{where}: include({words[0]}) may install more")
        elif name in ("set_target_properties", "set_property") and any(
                "OUTPUT_NAME" in word for word in words):
            reading.unknown(f"{where}: a target installed under another OUTPUT_NAME")
        elif name == "ament_python_install_package":
            reading.unknown(f"{where}: ament_python_install_package may install scripts")


def _subdirectory(reading: _Reading, folder: str, child: str, variables: Variables,
                  depth: int, where: str) -> None:
    inner = posixpath.normpath(posixpath.join(folder, child))
    if os.path.isabs(child) or inner.startswith("..") or depth >= 8:
        reading.unknown(f"{where}: add_subdirectory({child}) not read")
        return
    scope = Variables(variables.values["PROJECT_NAME"])
    scope.values.update(variables.values)  # a subdirectory sees its parent's variables
    _cmake(reading, inner, scope, depth + 1)


def _install(reading: _Reading, words: list[str], folder: str, where: str) -> None:
    if not words:
        return
    kind = words[0]
    if kind in ("SCRIPT", "CODE"):
        reading.unknown(f"{where}: install({kind}) runs CMake code")
        return
    destinations = [words[i + 1] for i in range(len(words) - 1) if words[i] == "DESTINATION"]
    if not any(reading.libexec(d) for d in destinations):
        return
    items = []
    for word in words[1:]:
        if word in _TARGET_KEYWORDS:
            break
        items.append(word)
    if kind == "TARGETS":
        for target in items:
            reading.add(target)
    elif kind in ("PROGRAMS", "FILES"):
        rename = words[words.index("RENAME") + 1] if "RENAME" in words[:-1] else None
        for item in items:
            reading.add(rename if rename and len(items) == 1 else posixpath.basename(item))
    elif kind == "DIRECTORY":
        for item in items:
            below = posixpath.normpath(posixpath.join(folder, item.rstrip("/")))
            prefix = "" if below == "." else below + "/"
            for file in package_files(reading.directory):
                if file.startswith(prefix):
                    reading.add(posixpath.basename(file))


def _setup_py(reading: _Reading) -> None:
    text = _read(reading, "setup.py", MAX_SETUP_BYTES)
    if text is None:
        return
    found = setup_call(text.encode("utf-8"), reading.directory)
    if isinstance(found, str):
        reading.unknown(f"setup.py: {found}")
        return
    keywords, evaluate = found
    if None in keywords or "cmdclass" in keywords:
        reading.unknown("setup.py: setup(**...) or a custom cmdclass may install more")
    scripts = keywords.get("scripts")
    if scripts is not None:
        value = setup_value(evaluate, scripts)
        if not isinstance(value, (list, tuple)):
            reading.unknown(f"setup.py: scripts not read ({value})")
        else:
            for item in value:
                reading.add(posixpath.basename(str(item)))
    entry_points = keywords.get("entry_points")
    if entry_points is not None:
        _entry_points(reading, evaluate, entry_points)


def _entry_points(reading: _Reading, evaluate: object, node: ast.expr) -> None:
    if not isinstance(node, ast.Dict):
        reading.unknown("setup.py: entry_points is not a dictionary written in the call")
        return
    for key, value in zip(node.keys, node.values):
        if key is None or not isinstance(key, ast.Constant):
            reading.unknown("setup.py: an entry_points key not known")
            continue
        if key.value != "console_scripts":
            continue
        found = setup_value(evaluate, value)
        if not isinstance(found, (list, tuple, str)):
            reading.unknown(f"setup.py: console_scripts not read ({found})")
            continue
        # setuptools reads the entries with yield_lines: nested lists flattened, each text
        # split into lines, blank lines and comments skipped.
        pending: list[object] = [found]
        while pending:
            entry = pending.pop()
            if isinstance(entry, (list, tuple)):
                pending.extend(entry)
            elif not isinstance(entry, str):
                reading.unknown("setup.py: a console_scripts entry that is not text")
            else:
                for line in entry.splitlines():
                    entry = console_script(line)
                    if entry is not None:
                        reading.add(entry[0])


def console_script(line: str) -> tuple[str, str] | None:
    """The (name, ``module:function`` target) of one ``console_scripts`` entry
    ``name = module:function``, stripped; None for a blank line or a comment, which
    setuptools skips. The one reading of an entry, shared with
    :mod:`.node_declarations` (which follows the target to the node's source)."""
    if not line.strip() or line.strip().startswith("#"):
        return None
    name, _, target = line.partition("=")
    return name.strip(), target.strip()


def _setup_cfg(reading: _Reading) -> None:
    """``[options.entry_points]`` console scripts, and where scripts are installed: without
    ``[install] install_scripts=$base/lib/<package>`` nothing is known to land there."""
    text = None
    if os.path.lexists(os.path.join(reading.directory, "setup.cfg")):
        text = _read(reading, "setup.cfg", MAX_SETUP_BYTES)
    parser = configparser.ConfigParser(interpolation=None)
    try:
        parser.read_string(text or "")
    except configparser.Error:
        reading.unknown("setup.cfg: not parsed")
        return
    target = parser.get("install", "install_scripts", fallback="")
    if posixpath.normpath(target.replace("$base", "").strip().lstrip("/")) != (
            "lib/" + reading.package):
        reading.unknown("setup.cfg does not install scripts to lib/" + reading.package)
    console = parser.get("options.entry_points", "console_scripts", fallback="")
    for line in console.splitlines():
        entry = console_script(line)
        if entry is not None and "=" in line:  # setup.cfg: only `name = target` lines
            reading.add(entry[0])
    for script in parser.get("options", "scripts", fallback="").replace(",", " ").split():
        reading.add(posixpath.basename(script))


__all__ = ["Executables", "console_script", "read_executables"]
