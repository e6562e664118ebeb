"""The attributes roslaunch reads on each tag of a ROS 1 launch file, and the ones it
ignores.

roslaunch's ``XmlLoader._check_attrs`` compares each tag's attributes with the tag's list
and, for any other one (``if`` and ``unless`` aside), only adds the configuration error
``unknown <tag> attribute 'x'`` (printed as a warning when the launch starts): the
attribute has no effect. The lists are ``XmlLoader``'s class attributes, the same on
kinetic-devel (25af588), melodic-devel (2a92e3d) and noetic-devel (845f746) of ros/ros_comm
``tools/roslaunch/src/roslaunch/xmlloader.py``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from launch_linter.resolve.xml_safe import Element

_NODE = frozenset({"pkg", "type", "machine", "name", "args", "output", "respawn",
                   "respawn_delay", "cwd", "ns", "clear_params", "launch-prefix", "required"})
READ_ATTRIBUTES: dict[str, frozenset[str]] = {
    "node": _NODE,
    "test": _NODE | {"test-name", "time-limit", "retry"},
    "include": frozenset({"file", "ns", "clear_params", "pass_all_args"}),
    "group": frozenset({"ns", "clear_params"}),
    "arg": frozenset({"name", "value", "default", "doc"}),
    "param": frozenset({"name", "value", "type", "textfile", "binfile", "command"}),
    "rosparam": frozenset({"command", "ns", "file", "param", "subst_value"}),
    "remap": frozenset({"from", "to"}),
    "env": frozenset({"name", "value"}),
    # The ros-* attributes roslaunch refuses outright (before checking the rest).
    "machine": frozenset({"name", "address", "env-loader", "ssh-port", "user", "password",
                          "default", "timeout", "ros-root", "ros-package-path", "ros-ip",
                          "ros-hostname"}),
}
"""Each tag's attributes as ``XmlLoader`` lists them (``NODE_ATTRS``, ``TEST_ATTRS``,
``INCLUDE_ATTRS``, ``GROUP_ATTRS``, ``ARG_ATTRS``, ``PARAM_ATTRS``, ``ROSPARAM_OPT_ATTRS``,
``REMAP_ATTRS``, ``ENV_ATTRS``, ``MACHINE_ATTRS``)."""
CONDITIONS = frozenset({"if", "unless"})
_ACCEPTED = {tag: read | CONDITIONS for tag, read in READ_ATTRIBUTES.items()}
"""Each tag's attributes that roslaunch reads or judges (``if``/``unless``)."""

CHILD_TAGS: dict[str, frozenset[str]] = {
    "launch": frozenset(READ_ATTRIBUTES),
    "group": frozenset(READ_ATTRIBUTES),
    "node": frozenset({"remap", "param", "rosparam", "env"}),
    "test": frozenset({"remap", "param", "rosparam", "env"}),
    "include": frozenset({"arg", "env"}),
}
"""The tags roslaunch reads inside each tag (``_recurse_load``, ``_node_tag`` and
``_include_tag``): any other there only gets "unrecognized tag" and is skipped whole."""
LOWERED = frozenset({"node", "test", "include"})
"""The tags whose children's names roslaunch lowers before comparing (``tagName.lower()``
in ``_node_tag`` and ``_include_tag``; ``_recurse_load`` compares them as written)."""
UNCHECKED_TAGS = frozenset({"master"})
"""Skipped without a word (``_recurse_load``: "handled non-recursively")."""

_READ_ELSEWHERE = frozenset().union(*READ_ATTRIBUTES.values())
MISTAKEN_PREFIX = "roslaunch reads "
"""How a mistaken attribute's message starts: the rule (ros1_ignored_attribute) warns
for those and says the others at info."""
_DOERS = frozenset({"node", "test", "include", "param", "rosparam", "remap", "env", "arg",
                    "machine"})


def ignored_attributes(launch: Element, step: Callable[[int], None]
                       ) -> Iterator[tuple[Element, Element, str | None, bool]]:
    """Each attribute roslaunch ignores in ``launch``'s tree, with its element's parent,
    the element, the attribute's name and whether
    it is *mistaken*: one roslaunch reads on another tag, written on a tag that starts,
    sets or passes something (a ``<group>`` only scopes: a word there is most often a
    label); and each tag roslaunch ignores where it is (its name None then), mistaken when
    roslaunch reads that tag elsewhere (an ``<arg>`` inside a ``<node>``). ``step`` is
    charged one step per element, for each parent's children at once."""
    pending = [launch]
    while pending:
        parent = pending.pop()
        children = parent.children
        step(len(children))  # one call per parent: a call per element cost a third of the scan
        inner = CHILD_TAGS.get(parent.tag, frozenset())
        # roslaunch lowers the names of a node's and an include's children only.
        lowered = parent.tag in LOWERED
        for element in children:
            tag = element.tag.lower() if lowered else element.tag
            if tag not in inner:
                if tag not in UNCHECKED_TAGS:
                    yield parent, element, None, tag in READ_ATTRIBUTES
                continue
            if not _ACCEPTED[tag].issuperset(element.attrib):  # most elements: one C call
                read = READ_ATTRIBUTES[tag]
                for name in element.attrib:
                    if name not in read and name not in CONDITIONS:
                        yield parent, element, name, tag in _DOERS and name in _READ_ELSEWHERE
            if element.children and tag in CHILD_TAGS:
                pending.append(element)


def other_tags_reading(name: str) -> str:
    """The tags whose attribute ``name`` is, as a message says them (``<node> and <test>``)."""
    tags = [f"<{tag}>" for tag, read in READ_ATTRIBUTES.items() if name in read]
    return tags[0] if len(tags) == 1 else ", ".join(tags[:-1]) + " and " + tags[-1]


def message(parent: Element, element: Element, name: str | None, mistaken: bool) -> str:
    """What ros1_ignored_attribute says of an ignored attribute (``name``) or tag (None)."""
    if name is None:
        effect = (f"roslaunch only warns that it does not recognize <{element.tag}> there "
                  f"and skips it with all it holds")
        return (f"{MISTAKEN_PREFIX}<{element.tag}> elsewhere, not inside <{parent.tag}>: "
                f"{effect}" if mistaken else
                f"<{element.tag}> is not a tag roslaunch reads here: {effect}")
    effect = (f"roslaunch only warns \"unknown <{element.tag}> attribute '{name}'\" and "
              f"goes on: it has no effect")
    return (f"{MISTAKEN_PREFIX}'{name}' on {other_tags_reading(name)}, not on "
            f"<{element.tag}>: {effect}" if mistaken else
            f"<{element.tag}> has no attribute '{name}': {effect}")
