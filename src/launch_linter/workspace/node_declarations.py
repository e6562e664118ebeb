"""The parameters a workspace node declares, read from its source, never built or run.

A ROS 2 node made with the defaults (``allow_undeclared_parameters`` false) keeps the
parameter overrides a launch file gives it and applies one only when the node declares
that name: rclcpp stores them (humble 99f1d8d ``node_parameters.cpp`` lines 98-114) and
``declare_parameter`` consults them; an override no declaration consults is never applied
and nothing reports it. rclpy does the same (``Node.declare_parameter`` reads
``_parameter_overrides``).

For a package of the linted workspace, the executable's sources are found from its
install rules read as text: ``add_executable``/``ament_auto_add_executable`` (and the
libraries of the same ``CMakeLists.txt`` it links, ``rclcpp_components_register_node``'s
``EXECUTABLE``) or ``setup.py``'s ``console_scripts``; its package-local headers and
modules are read with it. The declared names are the literal first arguments of
``declare_parameter`` calls, and the parameters of the ``generate_parameter_library``
YAML files of the same ``CMakeLists.txt`` the executable links (the library's generated
``ParamListener`` declares each, its name the YAML's keys below the one top key joined
with ``.``: generate_parameter_library 1.2.0 b647598
``generate_parameter_library_py/parse_yaml.py``, ``preprocess_inputs`` line 753,
``parse_dict`` 969-990, one root element 856-862; read with PyYAML, unknown without it). Anything
else leaves the set unknown, never guessed: a declaration whose name is not a literal,
``declare_parameters``, ``allow_undeclared_parameters``,
``automatically_declare_parameters_from_overrides``, a ``ParamListener`` whose YAML is not
read, a ``__map_`` parameter (names made from another parameter's value), a source or
module not found, a variable in a target's sources, no declaration at all (it may be in a
library of another package). Bounded in files and bytes.
"""

from __future__ import annotations

import ast
import os
import re

from launch_linter.resolve.xml_safe import read_file_within
from launch_linter.workspace.cmake_install import commands

MAX_FILE_BYTES = 2 * 1024 * 1024
"""Most bytes read of one source file or install-rules file."""
MAX_FILES = 100
"""Most source files read for one executable."""
MAX_TARGETS = 50
"""Most library targets followed from one executable."""

_UNKNOWABLE = re.compile(
    rb"allow_undeclared_parameters|automatically_declare_parameters_from_overrides"
    rb"|\bdeclare_parameters\b|\bParamListener\b|\bgenerate_parameter_library\b")
_UNKNOWABLE_GENERATED = re.compile(
    rb"allow_undeclared_parameters|automatically_declare_parameters_from_overrides"
    rb"|\bdeclare_parameters\b")
"""What leaves a node's declarations unknown once its generated parameter library's YAML
is read (``ParamListener`` then declares what the YAML says)."""
_LISTENER = re.compile(rb"\bParamListener\s*>?\s*\(")
_LISTENER_BARE = re.compile(rb"\bParamListener\s*>?\s*\(\s*(?:this|node|node_)?\s*\)")
"""A ``ParamListener`` made from the node alone; a second argument is a prefix of every
name it declares (``ParamListener(node, prefix)``), and anything else is not read."""
MAX_GENERATED_PARAMETERS = 5000
"""Most parameters read from one executable's generate_parameter_library YAML files."""
_DECLARE = re.compile(rb"\bdeclare_parameter\b")
_LITERAL = re.compile(
    rb"\s*(?:<[^;(){}]{0,200}>)?\s*\(\s*(?:\"([^\"\\\n]*)\"|'([^'\\\n]*)')\s*[,)]")
_CPP_INCLUDE = re.compile(rb"^\s*#\s*include\s*\"([^\"\n]+)\"", re.MULTILINE)
_CPP_SUFFIXES = (".cpp", ".cc", ".cxx", ".c++", ".hpp", ".h", ".hh", ".hxx")
_TARGET_WORDS = frozenset({
    "WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "STATIC", "SHARED", "MODULE", "OBJECT",
})
_LINK_WORDS = frozenset({"PUBLIC", "PRIVATE", "INTERFACE"})


def declared_parameters(root: str, executable: str) -> tuple[tuple[str, ...], str] | None:
    """(the names the executable's node declares, the file shown as their source) for the
    package in folder ``root``; None when they cannot be known completely."""
    found = _sources(root, executable)
    if found is None:
        return None
    sources, python, generated = found
    names = _declared(sources, root, python, bool(generated))
    if names is None:
        return None
    for path in generated:
        from_yaml = _generated_parameters(path)
        if from_yaml is None:
            return None
        names.update(from_yaml)
    if not names:
        return None
    return tuple(sorted(names)), os.path.relpath((generated or sources)[0], root)


def declared_in_part(root: str, executable: str) -> tuple[tuple[str, ...], str] | None:
    """(the names that the readable sources of a C++ executable's own target declare with
    a literal name, the first source) when :func:`declared_parameters` cannot know them
    all (a linked library with generated sources, a name that is not a literal): names
    it surely declares, never a complete list; None when none is found."""
    cmake = os.path.join(root, "CMakeLists.txt")
    data = _read(cmake) if os.path.isfile(cmake) else None
    if data is None:
        return None
    found = _cmake_sources(data.decode("utf-8", "replace"), root, executable, partial=True)
    sources = found[0] if found is not None else []
    if not sources:
        return None
    names = _declared(sources, root, False, partial=True)
    if not names:
        return None
    return tuple(sorted(names)), os.path.relpath(sources[0], root)


def _read(path: str) -> bytes | None:
    """The whole file, or None: a declaration in a part left unread would be missed."""
    try:
        return read_file_within(path, MAX_FILE_BYTES)
    except (OSError, ValueError):  # FileTooLarge and NotRegularFile included
        return None


def _sources(root: str, executable: str) -> tuple[list[str], bool, list[str]] | None:
    """(source files, whether Python, generate_parameter_library YAML files linked)."""
    cmake = os.path.join(root, "CMakeLists.txt")
    if os.path.isfile(cmake):
        data = _read(cmake)
        if data is None:
            return None
        found = _cmake_sources(data.decode("utf-8", "replace"), root, executable)
        return None if found is None else (found[0], False, found[1])
    setup = os.path.join(root, "setup.py")
    if os.path.isfile(setup):
        data = _read(setup)
        if data is None:
            return None
        module = _console_script(data, executable)
        if module is None:
            return None
        path = os.path.join(root, *module.split(".")) + ".py"
        return ([path], True, []) if os.path.isfile(path) else None
    return None


def _cmake_sources(text: str, root: str, executable: str, partial: bool = False
                   ) -> tuple[list[str], list[str]] | None:
    """The source files of ``executable`` and of the libraries of this file it links, and
    the YAML files of the generated parameter libraries among them (``partial``: of the
    targets whose sources are all listed, the others left out)."""
    project = ""
    sources: dict[str, list[str] | None] = {}
    generated: dict[str, str | None] = {}
    links: dict[str, list[str]] = {}
    registered: dict[str, str] = {}
    for name, arguments, _line in commands(text):
        words = [a.text for a in arguments]
        if name == "project" and words:
            project = words[0]
            continue
        words = [w.replace("${PROJECT_NAME}", project) for w in words]
        if name in ("add_executable", "add_library", "ament_auto_add_executable",
                    "ament_auto_add_library") and words:
            files = [w for w in words[1:] if w not in _TARGET_WORDS]
            unknown = not files or any("$" in f or f in ("ALIAS", "IMPORTED") for f in files)
            sources[words[0]] = None if unknown else files
        elif name == "target_link_libraries" and words:
            links.setdefault(words[0], []).extend(w for w in words[1:] if w not in _LINK_WORDS)
        elif name == "rclcpp_components_register_node" and "EXECUTABLE" in words:
            at = words.index("EXECUTABLE")
            if at + 1 < len(words):
                registered[words[at + 1]] = words[0]
        elif name == "generate_parameter_library" and words:
            # generate_parameter_library(TARGET YAML [VALIDATE_HEADER]): a header library.
            yaml_file = words[1] if len(words) > 1 else ""
            generated[words[0]] = (None if not yaml_file or "$" in yaml_file
                                   else os.path.normpath(os.path.join(root, yaml_file)))
    start = registered.get(executable, executable)
    if start not in sources:
        return None
    out: list[str] = []
    yamls: list[str] = []
    todo, seen = [start], {start}
    while todo:
        target = todo.pop()
        listed = sources[target]
        if len(seen) > MAX_TARGETS:
            return None
        if listed is None:
            if partial:
                continue
            return None
        out.extend(os.path.normpath(os.path.join(root, f)) for f in listed)
        for library in links.get(target, ()):
            if library in generated and library not in seen:
                seen.add(library)
                path = generated[library]
                if path is None:
                    if partial:
                        continue
                    return None
                yamls.append(path)
            elif library in sources and library not in seen:
                seen.add(library)
                todo.append(library)
    return out, yamls


def _generated_parameters(path: str) -> set[str] | None:
    """The parameters a generate_parameter_library YAML file declares: below its one top
    key (the generated class's namespace), a mapping whose first value is a mapping groups
    the entries below it, any other entry is a parameter (``parse_dict``), named by its
    keys joined with ``.``. None when not read completely (no PyYAML, not YAML, a
    ``__map_`` parameter, too many)."""
    data = _read(path)
    if data is None:
        return None
    try:
        # Imported on use: PyYAML stays out of the standard-library core.
        import yaml  # type: ignore[import-untyped]
    except ImportError:
        return None
    try:
        document = yaml.safe_load(data)
    except (yaml.YAMLError, RecursionError, ValueError):
        return None
    if not isinstance(document, dict) or len(document) != 1:
        return None
    names: set[str] = set()
    todo: list[tuple[str, object]] = [("", next(iter(document.values())))]
    while todo:
        prefix, value = todo.pop()
        if not isinstance(value, dict):
            return None
        for key, item in value.items():
            if not isinstance(key, str) or key.startswith("__"):
                return None  # __map_ parameters: names made from a value
            name = f"{prefix}.{key}" if prefix else key
            if isinstance(item, dict) and item and isinstance(next(iter(item.values())), dict):
                todo.append((name, item))
            else:
                names.add(name)
            if len(names) + len(todo) > MAX_GENERATED_PARAMETERS:
                return None
    return names


def _console_script(data: bytes, executable: str) -> str | None:
    """The module of ``executable``'s ``console_scripts`` entry in a ``setup.py`` written
    as literals (parsed, never run); None when not found or not literal."""
    # Imported here: executables.py (with the setup.py evaluator) costs start-up time
    # that only an ament_python node needs.
    from launch_linter.workspace.executables import console_script

    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError):
        return None
    for node in ast.walk(tree):
        if not isinstance(node, ast.Dict):
            continue
        for key, value in zip(node.keys, node.values):
            if not (isinstance(key, ast.Constant) and key.value == "console_scripts"):
                continue
            if not isinstance(value, (ast.List, ast.Tuple)):
                return None
            for item in value.elts:
                if not (isinstance(item, ast.Constant) and isinstance(item.value, str)):
                    return None
                script = console_script(item.value)
                if script is not None and script[0] == executable:
                    module = script[1].partition(":")[0].strip()
                    return module or None
    return None


def _declared(sources: list[str], root: str, python: bool, generated: bool = False,
              partial: bool = False) -> set[str] | None:
    """The literal names declared in ``sources`` and the package-local files they
    include or import; None when any declaration cannot be read (``generated``: the
    executable's generated parameter libraries are read, so ``ParamListener`` is known;
    ``partial``: the literal names of the files that can be read, the rest left out)."""
    unknowable = _UNKNOWABLE_GENERATED if generated else _UNKNOWABLE
    names: set[str] = set()
    todo = list(dict.fromkeys(sources))
    seen = set(todo)
    while todo:
        if len(seen) > MAX_FILES:
            return None
        path = todo.pop()
        data = _read(path)
        if data is None or (unknowable.search(data) and not partial):
            if partial:
                continue
            return None
        if generated and len(_LISTENER.findall(data)) != len(_LISTENER_BARE.findall(data)):
            return None  # a listener given a prefix, or made otherwise: names not known
        for call in _DECLARE.finditer(data):
            literal = _LITERAL.match(data, call.end())
            if literal is None:
                if partial:
                    continue
                return None
            names.add((literal.group(1) or literal.group(2) or b"").decode("utf-8", "replace"))
        local = _imports(data, path, root) if python else _includes(data, path, root)
        if local is None:
            if partial:
                continue
            return None
        for other in local:
            if other not in seen:
                seen.add(other)
                todo.append(other)
    return names


def _includes(data: bytes, path: str, root: str) -> list[str]:
    """The package's own headers ``path`` includes with quotes (others are libraries')."""
    out: list[str] = []
    for match in _CPP_INCLUDE.finditer(data):
        name = match.group(1).decode("utf-8", "replace")
        for folder in (os.path.dirname(path), os.path.join(root, "include"), root):
            candidate = os.path.normpath(os.path.join(folder, name))
            if candidate.endswith(_CPP_SUFFIXES) and os.path.isfile(candidate):
                out.append(candidate)
                break
    return out


def _imports(data: bytes, path: str, root: str) -> list[str] | None:
    """The package's own modules ``path`` imports (its top-level package's, or relative);
    None when one of them is not found as a file."""
    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError):
        return None
    here = os.path.dirname(path)
    package = os.path.relpath(here, root).split(os.sep)[0]
    out: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] != package:
                    continue
                found = _module_file(root, alias.name.split("."))
                if found is None:
                    return None
                out.append(found)
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0:
                if not node.module or node.module.split(".")[0] != package:
                    continue
                folder, parts = root, node.module.split(".")
            else:
                folder = here
                for _ in range(node.level - 1):
                    folder = os.path.dirname(folder)
                parts = node.module.split(".") if node.module else []
            found = _module_file(folder, parts)
            if found is None:
                return None
            out.append(found)
            for alias in node.names:
                # A submodule imported by name; any other name is the module's own.
                sub = _module_file(folder, [*parts, alias.name])
                if sub:
                    out.append(sub)
    return [f for f in out if f]


def _module_file(folder: str, parts: list[str]) -> str | None:
    """The file of module ``parts`` under ``folder`` (a package's ``__init__.py``); ""
    for a package folder without one (nothing to read); None when not found."""
    candidate = os.path.join(folder, *parts)
    if parts and os.path.isfile(candidate + ".py"):
        return candidate + ".py"
    if os.path.isfile(os.path.join(candidate, "__init__.py")):
        return os.path.join(candidate, "__init__.py")
    return "" if os.path.isdir(candidate) else None
