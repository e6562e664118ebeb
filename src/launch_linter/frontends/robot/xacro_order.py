"""xacro's processing order per distribution and call, and what the legacy order refuses.

Before Melodic, xacro processes a document in the *legacy* order unless it is called with
``--inorder`` (``-i``): ros/xacro kinetic-devel 33fabd8 (1.11.3) and lunar-devel bc2ab3a
(1.12.2), ``src/xacro/cli.py`` (``set_defaults(in_order=False)``); jade-devel e4e0da2
(1.10.7) the same; indigo-devel 5c97169 (1.9.5) has only that order. From Melodic
(melodic-devel e2ba976, 1.13) in-order is the default and ``--legacy`` asks for the old
one; Noetic and the ROS 2 xacro have no legacy order.

In the legacy order ``process_doc`` first replaces every include of the whole document
(``process_includes``: every element, inside macros and conditionals too, before any
property, macro or arg is read), evaluating each file name with no properties at all
(``eval_text(filename_spec, None)``): a ``${name}`` in it stops xacro with "variable
filename is supported with --inorder option only" (kinetic-devel ``get_include_files``;
indigo's ``eval_text(..., {})`` stops alike).
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Iterator, Mapping, Sequence

from launch_linter.frontends.robot.xacro_globals import xacro_defines
from launch_linter.frontends.robot.xacro_values import legacy_tags
from launch_linter.model.robot import DescriptionFault, FaultKind
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml, read_launch_bytes

LEGACY_ORDER_DISTROS = frozenset({"hydro", "indigo", "jade", "kinetic", "lunar"})
"""Distributions whose xacro runs in the legacy order unless given ``--inorder``."""
LEGACY_OPTION_DISTROS = frozenset({"melodic"})
"""Distributions whose xacro runs in the legacy order when given ``--legacy``."""
MAX_EXPRESSION = 256
MAX_NESTING = 16
"""Longest ``${...}`` of a file name judged, and most brackets or unary signs in it (a
file name's expression is short; a deeper one would strain Python 3.8's parser, which
says so on stderr): beyond them nothing is claimed."""
_EXPRESSION = re.compile(r"(?<!\$)\$\{([^}]*)\}")
"""A ``${...}`` of xacro's lexer (``$${`` is an escaped dollar)."""
IN_ORDER_OPTIONS = frozenset({"--inorder", "-i", "--check-order"})
"""Options that ask for in-order processing (``--check-order`` implies it)."""


def legacy_order(env: Mapping[str, str], options: Sequence[str]) -> bool:
    """Whether the target distribution's xacro, called with ``options``, processes the
    document in the legacy order. Not known (no distribution), it is not assumed."""
    distro = env.get("ROS_DISTRO")
    if distro in LEGACY_ORDER_DISTROS:
        return not any(option in IN_ORDER_OPTIONS for option in options)
    return distro in LEGACY_OPTION_DISTROS and "--legacy" in options


def property_needed(expression: str) -> str | None:
    """The first name that ``expression`` (the text of one ``${...}``) reads and that no
    xacro symbol defines: evaluated with no properties, it stops xacro. None when there
    is none, and when the expression binds names of its own (a lambda, a comprehension)
    or is no Python the linter reads (then nothing is claimed)."""
    if len(expression) > MAX_EXPRESSION or sum(
            expression.count(sign) for sign in "([{-+~") > MAX_NESTING:
        return None
    try:
        tree = ast.parse(expression.strip(), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    names: list[tuple[int, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, (ast.Lambda, ast.comprehension)):
            return None
        if isinstance(node, ast.Name) and not xacro_defines(node.id):
            names.append((node.col_offset, node.id))
    return min(names)[1] if names else None


def legacy_include_refusal(filename: str) -> str | None:
    """Why the legacy order stops on an include whose ``filename`` attribute is written
    as given: a ``${...}`` reading a name no xacro symbol defines; None otherwise."""
    for match in _EXPRESSION.finditer(filename):
        name = property_needed(match.group(1))
        if name is not None:
            return (f"variable filename is supported with --inorder option only: "
                    f"'{name}' in {match.group(0)} is read before any property")
    return None


def legacy_order_refusal(files: Sequence[str], env: Mapping[str, str],
                         options: Sequence[str], display: Callable[[str], str]
                         ) -> tuple[DescriptionFault, ...]:
    """The include the legacy order stops on, when the xacro call runs in that order:
    the first include (in the order the files were read, each in document order, inside
    macros and conditionals too, as ``process_includes`` walks them) whose file name
    needs a property. Every file an in-order expansion reads is one the legacy order
    tries (it replaces every include, taken or not), so the one found stops it."""
    if not legacy_order(env, options):
        return ()
    unprefixed = legacy_tags(env)
    for path in files:
        try:
            root = parse_xml(read_launch_bytes(path)).root
        except (OSError, XmlError):
            continue  # a YAML file read by load_yaml, or one xacro could not read
        for element in _document_order(root):
            if element.tag == "xacro:include" or (
                    unprefixed and element.tag == "include" and not element.children):
                refusal = legacy_include_refusal(element.attrib.get("filename", ""))
                if refusal is not None:
                    return (DescriptionFault(display(path), element.line, FaultKind.REFUSED,
                                             f"<{element.tag}>: {refusal}"),)
    return ()


def _document_order(root: Element) -> Iterator[Element]:
    stack = [root]
    while stack:
        element = stack.pop()
        yield element
        stack.extend(reversed(element.children))
