"""Whether launch XML is ROS 2's: the signs only ROS 2 launch XML has.

XML is ROS 1 unless it uses what only ROS 2 launch XML has: any action tag that launch or
launch_ros exposes and roslaunch does not (``<executable>``, ``<let>``, ``<set_env>``,
``<set_parameter>``, ``<push-ros-namespace>``, the composable-node tags, ...
:data:`ROS2_ONLY_TAGS`), a substitution only ROS 2 has (``$(var ...)``,
``$(find-pkg-share ...)``, ...), a ``<node>`` with ``exec=`` or ``ros_args=``, or an
``<include>`` of a Python or YAML launch file (not ``<param from=...>``: ROS 1 files
write it for ``<remap from=...>``). :mod:`launch_linter.frontends.dispatch` picks the
front-end with it, and the ROS 1 loader does not follow an include of such a file.
:func:`reads_as_python` tells a Python script named ``*.launch`` from XML.
"""

from __future__ import annotations

import re

# What only ROS 2 launch XML has. Every file is tested, so the tests are ordered by cost:
# one pattern for the tags only ROS 2 has and one for its substitutions (a regular
# expression that starts with a fixed character skips to it quickly), then, each behind a
# word that any match contains (a substring test is far cheaper than a pattern), the
# ``exec`` of a node and the include of a Python or YAML launch file.
ROS2_ONLY_TAGS: tuple[str, ...] = (
    "append_env", "composable_node", "executable", "let", "load_composable_node", "log",
    "node_container", "push-ros-namespace", "push_ros_namespace", "reset", "reset_env",
    "ros_timer", "set_env", "set_parameter", "set_parameters_from_file", "set_remap",
    "set_ros_log_dir", "set_use_sim_time", "shutdown", "timer", "unset_env",
)
"""The action tags of ``frontends.ros2_schema.ACTIONS`` (with the nested
``composable_node``) that roslaunch has no tag for (it has ``arg``, ``group``,
``include`` and ``node`` too); a test keeps the two lists in step."""
ROS2_ONLY_SUBSTITUTIONS: tuple[str, ...] = (
    "var", "find-pkg-share", "find-pkg-prefix", "find-exec", "exec-in-pkg", "file-content",
    "command", "not", "and", "or", "equals", "not-equals", "path-join",
)
"""Substitutions ROS 2 launch has and roslaunch does not (roslaunch has ``arg``, ``find``,
``env``, ``optenv``, ``anon``, ``dirname`` and ``eval``)."""
_ROS2_TAG = re.compile(
    rb"<(?:" + b"|".join(re.escape(tag.encode()) for tag in sorted(
        ROS2_ONLY_TAGS, key=len, reverse=True)) + rb")[\s/>]"
)
_ROS2_SUBSTITUTION = re.compile(
    rb"\$\((?:" + b"|".join(re.escape(name.encode()) for name in sorted(
        ROS2_ONLY_SUBSTITUTIONS, key=len, reverse=True)) + rb")[\s)]"
)
# ``[^<>]*`` rather than ``[^>]*``: a tag's scan stops at the next ``<``, where the next
# candidate starts, so the scans never overlap and the search is linear in the file size
# (a file of many unclosed ``<node `` would otherwise be quadratic).
_ROS2_WORD_SIGNS = (
    (b"exec", re.compile(rb"<node\s[^<>]*\bexec\s*=")),
    (b"ros_args", re.compile(rb"<node\s[^<>]*\bros_args\s*=")),
    (b"<include",
     re.compile(rb"""<include\s[^<>]*\bfile\s*=\s*["'][^"'<>]*\.(?:py|ya?ml)["']""")),
)


def _has_ros2_sign(data: bytes) -> bool:
    if _ROS2_TAG.search(data) is not None or _ROS2_SUBSTITUTION.search(data) is not None:
        return True
    for word, pattern in _ROS2_WORD_SIGNS:  # a loop, not any(): no generator per file
        if word in data and pattern.search(data) is not None:
            return True
    return False


def is_ros2_xml(data: bytes) -> bool:
    """Whether launch XML uses anything that only ROS 2 launch XML has."""
    if not _has_ros2_sign(data):
        return False
    # A sign may sit inside a comment; only then is the costlier check needed.
    return _has_ros2_sign(without_comments(data))


_ROS1_SIGNS = (
    (b"<test", re.compile(rb"<test[\s/>]"), "a rostest <test>"),
    (b"$(find", re.compile(rb"\$\(find\s"), "$(find)"),
    (b"<rosparam", re.compile(rb"<rosparam[\s/>]"), "<rosparam>"),
    (b"type", re.compile(rb"<node\s[^<>]*\btype\s*="), "<node type=>"),
)
"""What only ROS 1 launch XML has (roslaunch's ``<test>`` and ``<rosparam>`` tags, its
``$(find pkg)``, a node's ``type``), each behind a word any match contains; ``[^<>]*`` as
in :data:`_ROS2_WORD_SIGNS`, so the scans stay linear."""


def ros1_sign(data: bytes) -> str | None:
    """The first sign that launch XML is ROS 1's (outside comments): None when it has
    none, or when it has one of ROS 2's too (:func:`is_ros2_xml`)."""
    if is_ros2_xml(data):
        return None
    uncommented: bytes | None = None
    for word, pattern, sign in _ROS1_SIGNS:
        if word not in data:
            continue
        if uncommented is None:
            uncommented = without_comments(data)
        if pattern.search(uncommented) is not None:
            return sign
    return None


def without_comments(data: bytes) -> bytes:
    """``data`` without its ``<!-- ... -->`` comments (an unclosed one runs to the end), in
    linear time: a lazy regular expression rescans the rest of the file for each unclosed
    ``<!--``."""
    pieces: list[bytes] = []
    position = 0
    while True:
        start = data.find(b"<!--", position)
        if start < 0:
            pieces.append(data[position:])
            break
        pieces.append(data[position:start])
        end = data.find(b"-->", start + 4)
        if end < 0:
            break
        position = end + 3
    return b"".join(pieces)


def reads_as_python(path: str, data: bytes) -> bool:
    """Whether ROS 2 reads the launch file ``path`` as Python: a ``*.py`` file, or a file
    of another name whose first line is a ``#!`` naming python (nav2's
    ``test_case_py.launch``). ros2 launch reads a file its XML and YAML front-ends refuse
    as Python (launch's ``get_launch_description_from_any_launch_file`` tries the
    front-ends, then Python), and no XML starts with ``#!``."""
    if path.lower().endswith(".py"):
        return True
    first = data[:512].lstrip(b"\xef\xbb\xbf").split(b"\n", 1)[0]
    return first.startswith(b"#!") and b"python" in first

