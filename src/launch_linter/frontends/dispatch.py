"""Pick the front-end for a launch file by its name and content.

``*.py`` files are ROS 2 Python launch files and ``*.yaml``/``*.yml`` files ROS 2 YAML
launch files. XML is ROS 1 unless it uses what only ROS 2 launch XML has: any action tag
that launch or launch_ros exposes and roslaunch does not (``<executable>``, ``<let>``,
``<set_env>``, ``<set_parameter>``, ``<push-ros-namespace>``, the composable-node tags,
... :data:`ROS2_ONLY_TAGS`), a substitution only ROS 2 has (``$(var ...)``,
``$(find-pkg-share ...)``, ...), a ``<node>`` with ``exec=`` or ``ros_args=``, or an
``<include>`` of a Python or YAML launch file (not ``<param from=...>``: ROS 1 files
write it for ``<remap from=...>``). Both ROS
versions use ``.launch`` and ``.launch.xml``, so the suffix does not decide (the engine
lets the package's build type decide for ``*.xml`` files).
"""

from __future__ import annotations

import re

from launch_linter.frontends.robot.describe import attach_robot
from launch_linter.frontends.robot.standalone import load_description
from launch_linter.frontends.ros1 import LoadOptions, Ros1Loader, load_ros1
from launch_linter.model.launch import LaunchTree
from launch_linter.resolve.xml_safe import read_launch_bytes
from launch_linter.workspace.discovery import is_description_name

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
    return (
        _ROS2_TAG.search(data) is not None
        or _ROS2_SUBSTITUTION.search(data) is not None
        or any(word in data and pattern.search(data) for word, pattern in _ROS2_WORD_SIGNS)
    )


def is_ros2_xml(data: bytes) -> bool:
    """Whether launch XML uses anything that only ROS 2 launch XML has."""
    if not _has_ros2_sign(data):
        return False
    # A sign may sit inside a comment; only then is the costlier check needed.
    return _has_ros2_sign(without_comments(data))


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


def front_end(path: str, data: bytes | None, ros_version: int | None = None) -> str:
    """``ros2`` or ``ros1``: which loader reads ``path`` (``data``: its bytes, if read).

    ``ros_version`` (from ``--ros`` or the package) decides for XML when given."""
    name = path.lower()
    if name.endswith((".py", ".yaml", ".yml")):
        return "ros2"
    if ros_version is not None:
        return "ros2" if ros_version == 2 else "ros1"
    return "ros2" if data is not None and is_ros2_xml(data) else "ros1"


def load_tree(path: str, options: LoadOptions, data: bytes | None = None) -> LaunchTree:
    """Read the launch tree rooted at ``path`` with the front-end its format needs."""
    if is_description_name(path):
        return load_description(path, options.args, options.packages, options.robots,
                                options.display_path, options.env, data)
    if data is None and not path.lower().endswith((".py", ".yaml", ".yml")):
        try:
            data = read_launch_bytes(path)
        except OSError:
            # The ROS 1 loader reports the file as unreadable.
            return load_ros1(path, options, None)
    if front_end(path, data, options.ros_version) == "ros2":
        # Imported when first needed: the ROS 2 front-ends are most of the start-up time
        # of a run over ROS 1 files only.
        from launch_linter.frontends.ros2_launch import Ros2Loader

        loader: Ros1Loader | Ros2Loader = Ros2Loader(options)
    else:
        loader = Ros1Loader(options)
    tree = loader.load(path, data)
    if tree.descriptions:
        tree = attach_robot(tree, options.packages, options.robots, options.display_path,
                            dict(options.env), loader.include_sites)
    return tree
