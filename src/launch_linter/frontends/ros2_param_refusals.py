"""Parameter files a ROS 2 node cannot start with, read statically.

Values above ``ros__parameters`` (``ros2_param_file_refused``): rcl's parser takes the
keys above ``ros__parameters`` as node names and namespaces and refuses a value there
("Cannot have a value before ros__parameters at line N"; a sequence there: "Sequences
can only be values and not keys in params"; rcl_yaml_param_parser ``parse.c``
``parse_file_events``: ros2/rcl foxy, humble 6d0fd90e and rolling c19dab55).
``rcl_parse_arguments`` then fails on ``--params-file`` ("Couldn't parse params file",
rcl/src/rcl/arguments.c ``_rcl_parse_param_file``), so ``rcl_init`` fails and no node of
the process starts, rclcpp's or rclpy's. In a file that launch substitutes first
(``allow_substs``) a value is judged only when its substitutions resolve to one plain
line (which stays a scalar after substitution).

Empty lists (``ros2_param_empty_list``): rcl's YAML parser takes ``key: []`` and leaves the
parameter's value with no type set (an empty sequence adds no element, so no array type is
chosen: ``parse.c``, ``YAML_SEQUENCE_START_EVENT``/``YAML_SEQUENCE_END_EVENT``, rolling
c19dab55 lines 833-852). rclcpp turns every parameter of each section that matches the
node into a ``ParameterValue`` while the node is built (``resolve_parameter_overrides``
calls ``parameter_map_from``), and ``parameter_value_from`` throws
``InvalidParameterValueException("No parameter value set")`` for a value with no type
(rclcpp/src/rclcpp/parameter_map.cpp: foxy line 127, humble 99f1d8d and jazzy 985e320
line 147): whatever the node declares, it dies in its constructor. rclpy reads the same
value as "not set" without raising (rclpy/src/rclpy/node.cpp ``_parameter_from_rcl_variant``),
so only nodes proven to be rclcpp's (:mod:`launch_linter.workspace.client_library`) are
judged. ros2/rclcpp#1955 (open) asks for empty lists to be allowed.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence

from launch_linter.frontends.params import (
    MAX_KEY_DEPTH,
    MAX_PARAMS,
    ROS2_SECTION,
    PlacedDocument,
    _ros2_sections_keyed,
    _section_pattern,
    node_full_name,
)
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.robot import NodeRecord
from launch_linter.workspace.client_library import RCLCPP, client_library
from launch_linter.workspace.packages import PackageIndex

RULE = "ros2_param_empty_list"
REFUSED = "ros2_param_file_refused"
_NOT_PLAIN = ("{", "[", "|", ">", "&", "*", "!", "%", "@", "`", "\"", "'")


def empty_lists(document: object, name: str | None, namespace: str | None
                ) -> list[tuple[str, tuple[str, ...]]]:
    """The parameters a ROS 2 parameter file sets to ``[]`` for the node ``namespace/name``
    (dotted names, each with its path of keys in the file). A node of unknown name is
    reached only by a ``/**`` section."""
    full = None if name is None or namespace is None else node_full_name(name, namespace)
    out: list[tuple[str, tuple[str, ...]]] = []
    visits = 0
    for key, section, keys in _ros2_sections_keyed(document):
        if (full is None and key.strip("/") != "**") or (
            full is not None and not _section_pattern(key).match(full)
        ):
            continue
        stack: list[tuple[str, tuple[str, ...], object]] = [("", keys, section)]
        while stack and visits < 4 * MAX_PARAMS:
            prefix, path, value = stack.pop()
            visits += 1
            if isinstance(value, dict):
                for child_key, child in list(value.items())[:MAX_PARAMS]:
                    stack.append((f"{prefix}.{child_key}" if prefix else str(child_key),
                                  (*path, str(child_key)), child))
            elif isinstance(value, list) and not value and prefix:
                out.append((prefix, path))
    return out


def value_above_parameters(document: object) -> tuple[tuple[str, ...], object] | None:
    """The first value of a parameter file that stands above ``ros__parameters`` (its path
    of keys and the value as read), which rcl refuses; None when there is none."""
    stack: list[tuple[tuple[str, ...], object]] = [((), document)]
    visits = 0
    while stack and visits < 4 * MAX_PARAMS:
        path, value = stack.pop()
        visits += 1
        if not isinstance(value, dict):
            if path:
                return path, value
            continue
        items = list(value.items())[:MAX_PARAMS]
        for key, child in reversed(items):
            if key != ROS2_SECTION and len(path) < MAX_KEY_DEPTH:
                stack.append(((*path, str(key)), child))
    return None


def plain_line(text: str) -> bool:
    """``text`` written after ``key: `` stays one plain scalar (no flow collection, block
    scalar, anchor, tag, quote, comment or mapping in it)."""
    return bool(text.strip()) and "\n" not in text and ": " not in text and " #" not in text \
        and not text.lstrip().startswith(_NOT_PLAIN)


class ParamFileChecks:
    """Reports what in the parameter files a node is given stops it: values above
    ``ros__parameters`` (any node), ``[]`` (nodes whose package is proven rclcpp's; each
    package's manifest is read once per tree)."""

    def __init__(self, packages: PackageIndex) -> None:
        self.packages = packages
        self._library: dict[str, str | None] = {}
        self._above: dict[int, tuple[object, tuple[tuple[str, ...], object] | None]] = {}
        """:func:`value_above_parameters` per document (kept: its id stays its own), read
        once per tree though a shared file is given to many nodes."""

    def is_rclcpp(self, package: str) -> bool:
        if package not in self._library:
            folder = self.packages.find(package)
            manifest = None if folder is None else os.path.join(folder, "package.xml")
            self._library[package] = None if manifest is None else client_library(manifest)
        return self._library[package] == RCLCPP

    def problems(self, record: NodeRecord, name: str | None,
                 placed: Sequence[PlacedDocument], resolve: Callable[[str], str | None]
                 ) -> list[Problem]:
        """The node ``record`` (named ``name`` in its parameter files) given ``placed``;
        ``resolve`` gives the text of a value's substitutions (None: unknown)."""
        package, executable, namespace = record.package, record.executable, record.namespace
        node = Location(record.path, record.line, record.column)
        out = [problem for document in placed
               for problem in self._refused(document, node, resolve)]
        if not placed or not self.is_rclcpp(package):
            return out
        for document in placed:
            for parameter, path in empty_lists(document.document, name, namespace):
                line, column = document.keys.get(path, (node.line, node.column))
                shown = document.shown if path in document.keys else node.path
                out.append(Problem(
                    RULE, shown, line, column,
                    f"'{parameter}: []' in the parameter file of {package} {executable}, an "
                    f"rclcpp node: an empty list has no type, so rclcpp throws "
                    f"InvalidParameterValueException ('No parameter value set') while the "
                    f"node starts, whatever it declares, and the node dies; leave the "
                    f"parameter out (its declared default applies) or give it an item",
                    related=(node,)))
        return out

    def _refused(self, document: PlacedDocument, node: Location,
                 resolve: Callable[[str], str | None]) -> list[Problem]:
        kept = self._above.get(id(document.document))
        if kept is None:
            kept = (document.document, value_above_parameters(document.document))
            self._above[id(document.document)] = kept
        found = kept[1]
        if found is None:
            return []
        path, value = found
        if document.substituted and isinstance(value, str) and "$(" in value:
            value = resolve(value)
            if value is None or not plain_line(value):
                return []
        line, column = document.keys.get(path, (node.line, node.column))
        shown = document.shown if path in document.keys else node.path
        return [Problem(
            REFUSED, shown, line, column,
            f"'{'/'.join(path)}' holds a value above ros__parameters: rcl reads the keys "
            f"above ros__parameters as node names and refuses the file ('Cannot have a "
            f"value before ros__parameters'), so rcl_init fails on --params-file and the "
            f"node cannot start; put the values under <node name>: ros__parameters: (or "
            f"/**: ros__parameters:)", related=(node,))]
