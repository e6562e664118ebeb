"""Whether a parameter file reaches a node launched without a name, under the names its
program gives its nodes (the knowledge base's ``node_names`` entries,
:meth:`launch_linter.knowledge.KnowledgeBase.node_names`).

A name is relative to the namespace the node is launched in; a ``*`` in its last part
stands for text the program makes up at run time (a random suffix, a plugin's name).
"""

from __future__ import annotations

from collections.abc import Sequence

from launch_linter.frontends.params import key_matches, node_full_name, node_keys

_MADE_UP = "zZ0madeUp"
"""Stands for a ``*`` of a name when a key's own last name cannot: a name no key spells."""


def unmatched_default_keys(document: object, names: Sequence[str], namespace: str
                           ) -> list[tuple[str, tuple[str, ...]]] | None:
    """The node keys of a ROS 2 parameter file (each with its path of keys) when it has
    some and none reaches any node of the process (``names`` under ``namespace``). A
    ``*`` of a name is first given the key's own last name (``/mavros/**/conn`` reaches
    the plugin node ``mavros/*``), so a key is unmatched only when no name the program
    could make up matches it. None when one matches or the file has no node key."""
    keys = node_keys(document)
    for key, _ in keys:
        last = key.rstrip("/").rsplit("/", 1)[-1]
        filler = _MADE_UP if "*" in last else last
        for name in names:
            full = node_full_name(name.replace("*", filler), namespace)
            if key_matches(key, full):
                return None
    return keys or None
