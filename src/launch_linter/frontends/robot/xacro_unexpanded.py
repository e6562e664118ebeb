"""What xacro leaves unexpanded or drops without stopping, per the xacro a distribution ships.

Two faults of the source that xacro does not always refuse:

- A macro called without the ``xacro:`` prefix (``<ptu_d46 name="ptu"/>``), or a directive
  written so (``<insert_block name="origin"/>``, ``<property .../>``). The xacro of
  Noetic (1.14, ros/xacro noetic-devel 7045754) and of ROS 2 (2.x, the ros2 branch
  9d05b0e) calls a macro only for a tag that starts with ``xacro:``
  (``handle_macro_call``: ``elif not node.tagName.startswith('xacro:'): return False``);
  any other element is copied into the output as it is, so the call stays an unknown
  element (which urdfdom skips) and the macro's links, joints and plugins are missing.
  Melodic's (1.13, melodic-devel e2ba976) and older, and Dashing's and Eloquent's, expand
  it with a deprecation warning (``allow_non_prefixed_tags``): ``xacro_values.LEGACY_DISTROS``.
- A ``${`` or ``$(`` never closed (``rpy="0 ${pi/2 0"``). xacro reads a text with a lexer
  of four patterns (``LEXER``: ``$$`` before a bracket, ``${...}``, ``$(...)``, other text);
  since 1.13.5 (ros/xacro 72808e0, "catch invalid expression syntax", on melodic-devel,
  noetic-devel, dashing-devel and ros2) a position none of them matches stops xacro
  (``XacroException('invalid expression: ' + rest)``). Before (1.11 of Kinetic, 1.12 of
  Lunar and older: ``QuickLexer.next`` ends without a token) the rest of the text is
  dropped without a word: ``rpy="0 ${pi/2 0"`` becomes ``rpy="0 "``.
"""

from __future__ import annotations

import re

from launch_linter.frontends.robot.xacro_values import LEGACY_DIRECTIVES, _Refused, _Table
from launch_linter.resolve.xml_safe import Element

SILENT_LEXER_DISTROS = frozenset({"hydro", "indigo", "jade", "kinetic", "lunar"})
"""Distributions whose xacro (< 1.13.5) drops the rest of a text its lexer cannot read
instead of stopping: ros/xacro kinetic-devel 33fabd8 (1.11.3), lunar-devel bc2ab3a,
indigo-devel 5c97169, jade-devel e4e0da2, hydro-devel (``QuickLexer.next``)."""

_TOKENS = (
    re.compile(r"\$\$+[{(]"),
    re.compile(r"\$\{[^}]*\}"),
    re.compile(r"\$\([^)]*\)"),
    re.compile(r"[^$]+|\$[^{($]+|\$$"),
)
"""xacro >= 1.13.5's ``LEXER`` (noetic-devel 7045754 ``src/xacro/__init__.py``), unanchored
so that they match at a position."""
_SILENT_TOKENS = (
    re.compile(r"\$\$+\{"),
    re.compile(r"\$\{[^}]*\}"),
    re.compile(r"\$\([^)]*\)"),
    re.compile(r"(?:[^$]|\$[^{(]|\$$)+"),
)
"""xacro 1.11's ``LEXER`` (kinetic-devel 33fabd8)."""


def unlexed_at(text: str, silent: bool) -> int | None:
    """Where xacro's lexer finds no token in ``text`` (None when it reads it all): the
    position where xacro stops (or, ``silent``, from which it drops the text)."""
    tokens = _SILENT_TOKENS if silent else _TOKENS
    position = 0
    while position < len(text):
        for token in tokens:
            match = token.match(text, position)
            if match is not None and match.end() > position:
                position = match.end()
                break
        else:
            return position
    return None


def unprefixed_call_of(element: Element, params: list[str]) -> bool:
    """Whether ``element`` (a tag named like a macro defined by then) is written as a call
    of that macro: each attribute is one of its parameters and its element children are
    as many as its block parameters. An element that is not (a Gazebo ``<noise>`` beside
    a ``noise`` macro) is taken as the element it is."""
    names = {p for p in params if not p.startswith("*")}
    blocks = sum(1 for p in params if p.startswith("*"))
    return set(element.attrib) <= names and len(element.children) == blocks


DIRECTIVES = LEGACY_DIRECTIVES.union({"include"})
"""The xacro directives a legacy xacro reads without the prefix (an ``<include>`` only
without element children: Gazebo's ``<include><uri>`` is not xacro's)."""


def unprefixed_call(element: Element, table: _Table) -> bool:
    """Whether the unprefixed ``element`` (one a legacy xacro reads as xacro's:
    ``xacro_values.legacy_tag``) is a directive or a call of a macro defined by then that
    the xacro of Noetic and ROS 2 leaves unexpanded (see :func:`unprefixed_call_of`)."""
    if element.tag in DIRECTIVES:
        return True
    macro = table.find_macro(element.tag)
    return macro is not None and unprefixed_call_of(element, macro.params)


def lexed(text: str, distro: str | None) -> tuple[str, str | None]:
    """``text`` as xacro's lexer reads it on ``distro`` (not known: as Noetic's and ROS 2's
    xacro): raises :class:`_Refused` where xacro >= 1.13.5 stops; for an older xacro the
    text it keeps and what it drops (else None)."""
    silent = distro in SILENT_LEXER_DISTROS
    stop = unlexed_at(text, silent)
    if stop is None:
        return text, None
    rest = text[stop:]
    opened = rest[:2] if rest[:2] in ("${", "$(") else rest[:1]
    if not silent:
        raise _Refused(f"invalid expression: {rest!r} (a '{opened}' never closed)")
    return text[:stop], (f"the text {rest!r} after a '{opened}' never closed is dropped "
                         f"(xacro before 1.13.5, {distro}'s)")
