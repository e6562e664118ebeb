"""Robot-description sources and frame-relevant nodes, as the launch front-ends see them.

The front-ends hand over resolved values (``Value``s, holes included); this module decides
whether they give a ``robot_description`` and how (xacro command, URDF file, literal text)
and keeps the node parameters that the frame-authority rule reads.
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence

from launch_linter.frontends.params import ros1_controllers
from launch_linter.frontends.robot.describe import (
    SearchedPrefixes,
    Word,
    literal_kind,
    xacro_command,
    xacro_options,
    xacro_wrapper,
)
from launch_linter.frontends.tokens import shell_words
from launch_linter.model.record import replace
from launch_linter.model.robot import (
    UNKNOWN_VALUE,
    DescriptionKind,
    DescriptionSource,
    NodeRecord,
)
from launch_linter.model.transform import Condition
from launch_linter.resolve import reads
from launch_linter.resolve.value import (
    Hole,
    Value,
    environment_variable,
    holes,
    resolved_text,
    text_of,
)

DESCRIPTION_PARAM = "robot_description"
FRAME_NODE_PACKAGES = frozenset({
    "robot_state_publisher", "amcl", "nav2_amcl", "slam_toolbox", "gmapping",
    "slam_gmapping", "cartographer_ros", "hector_mapping", "robot_localization",
    "fuse_optimizers", "rtabmap_ros", "rtabmap_slam", "diff_drive_controller",
    "controller_manager", "husky_base", "jackal_base", "turtlebot3_bringup",
    "turtlebot3_node", "kobuki_node", "rf2o_laser_odometry", "laser_scan_matcher",
    "map_server", "nav2_map_server", "karto", "slam_karto", "lama_ros", "iris_lama_ros",
})
FRAME_PARAMS = ("world_frame", "map_frame", "odom_frame", "base_link_frame", "publish_tf",
                "tf_broadcast", "enable_odom_tf", "publish_odom_tf", "provide_odom_frame",
                "publish_frame_projected_to_2d", "two_d_mode", "mode", "transform_publish_period",
                "global_frame_id", "odom_frame_id", "base_frame_id", "base_frame",
                "pub_map_odom_transform")

MAX_GLOBAL_PARAMS = 20000
_PLACEHOLDER = re.compile("\x00([0-9]+)\x00")
_YAML_LINE = re.compile(r"^\s*([A-Za-z_][\w/]*)\s*:\s*([^#\n]*?)\s*(?:#.*)?$", re.MULTILINE)


def is_description_name(name: str | None) -> bool:
    return name is not None and (name == DESCRIPTION_PARAM
                                 or name.endswith("/" + DESCRIPTION_PARAM))


def words_of(value: Value) -> list[Word]:
    """The words of a command as the shell splits them (roslaunch uses ``shlex``), each
    with whether it is resolved. A hole stands in as a placeholder without spaces, so
    that the spaces of a ``$(find pkg)`` written in it do not split it."""
    written: list[str] = []
    pieces: list[str] = []
    for part in value:
        if isinstance(part, str):
            pieces.append(part)
        else:
            pieces.append(f"\x00{len(written)}\x00")
            written.append(part.text)
    marked = "".join(pieces)
    # shlex's own splitter only where quotes or backslashes need it (shell_words).
    split, refused = shell_words(marked)
    if refused is not None:
        split = marked.split()
    return [(_PLACEHOLDER.sub(lambda m: written[int(m.group(1))], word), "\x00" not in word)
            for word in split]


def from_ros1_param(values: dict[str, Value], path: str, line: int, column: int,
                    condition: Condition, directory: str, written: str = ""
                    ) -> DescriptionSource | None:
    """The description a ROS 1 ``<param name="robot_description" ...>`` gives
    (``written``: its ``command`` attribute as written)."""
    command = values.get("command")
    if command is not None:
        words = words_of(command)
        if len(words) == 2 and words[0][0].rsplit("/", 1)[-1] == "cat":
            file = words[1][0] if words[1][1] else None
            return DescriptionSource(path, line, column, DescriptionKind.FILE,
                                     _absolute(file, directory), condition=condition,
                                     reason=None if file else f"{words[1][0]!r} is not resolved")
        parsed = xacro_command(words, command)
        if parsed is None:
            return DescriptionSource(path, line, column, DescriptionKind.XACRO, None,
                                     condition=condition,
                                     reason=f"command {text_of(command)!r} is not a xacro call")
        file, args, reason, open_args = parsed
        return DescriptionSource(path, line, column, DescriptionKind.XACRO,
                                 _absolute(file, directory), args, condition, reason=reason,
                                 open_args=open_args,
                                 open_file=None if file else _open_word(words, command),
                                 near=_judged_in(directory, words, file, written),
                                 xacro_options=xacro_options(words),
                                 wrapper=xacro_wrapper(words))
    textfile = values.get("textfile")
    if textfile is not None:
        file = resolved_text(textfile)
        return DescriptionSource(path, line, column, DescriptionKind.FILE,
                                 _absolute(file, directory), condition=condition,
                                 reason=None if file else _why(textfile))
    value = values.get("value")
    if value is not None:
        text = resolved_text(value)
        if text is not None and literal_kind(text):
            return DescriptionSource(path, line, column, DescriptionKind.LITERAL, None,
                                     condition=condition, text=text)
    return None


def _judged_in(directory: str, words: list[Word], file: str | None, written: str) -> str:
    """The folder a missing description file is judged in (``DescriptionSource.near``):
    the launch file's own; the file's own when the command as written names it from
    ``$(dirname)`` and its folder is here, a path relative to the launch file that is the
    same on every machine (as a ``<rosparam file>`` is judged:
    ``ros1_checks._checkable_path``)."""
    if file is None or not any(resolved and text == file for text, resolved in words):
        return directory
    # The word as written is $(dirname) and plain text: the same path on every machine
    # (matched by its value, not its place: a substitution may give no word or several).
    dirname = "$(dirname)"
    written_here = any(
        raw.startswith(dirname) and "$(" not in raw[len(dirname):]
        and file == directory + raw[len(dirname):]
        for raw in (word.strip("'\"") for word in _written_words(written)))
    folder = os.path.dirname(_absolute(file, directory) or directory)
    # Its folder here, the file not: the layout around the launch file is this one (a
    # folder not here may be another repository's, cloned beside it elsewhere).
    return folder if written_here and reads.is_dir(folder) else directory


def _written_words(written: str) -> list[str]:
    """A command attribute as written, split at the spaces outside ``$(...)`` and
    quotes (the words before substitution)."""
    words: list[str] = []
    current: list[str] = []
    depth, quote = 0, ""
    for position, char in enumerate(written):
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif written.startswith("$(", position):
            depth += 1
        elif char == ")" and depth:
            depth -= 1
        elif char.isspace() and not depth:
            if current:
                words.append("".join(current))
                current = []
            continue
        current.append(char)
    if current:
        words.append("".join(current))
    return words


def _absolute(file: str | None, directory: str) -> str | None:
    if file is None:
        return None
    return file if os.path.isabs(file) else os.path.normpath(os.path.join(directory, file))


def _why(value: Value) -> str:
    reasons = [p.reason for p in value if isinstance(p, Hole)]
    return "; ".join(reasons) or "unresolved"


def params_from_yaml(text: str) -> list[tuple[str, str]]:
    """The frame parameters set in ``<rosparam>`` text (flat ``key: value`` lines only)."""
    found: list[tuple[str, str]] = []
    for match in _YAML_LINE.finditer(text):
        key = match.group(1).rsplit("/", 1)[-1]
        if key in FRAME_PARAMS:
            found.append((key, match.group(2).strip("'\"")))
    return found


def from_ros2_value(value: Value, command: Value | None, path: str, line: int,
                    column: int, condition: Condition, node: str | None
                    ) -> DescriptionSource | None:
    """The description a ROS 2 ``robot_description`` parameter gives: ``command`` is the
    resolved text of its ``Command``/``$(command ...)`` when it has one."""
    if command is not None:
        parsed = xacro_command(words_of(command), command)
        if parsed is None:
            return DescriptionSource(path, line, column, DescriptionKind.XACRO, None,
                                     condition=condition, node=node,
                                     reason=f"command {text_of(command)!r} is not a xacro call")
        file, args, reason, open_args = parsed
        return DescriptionSource(path, line, column, DescriptionKind.XACRO,
                                 _absolute(file, "/"), args, condition, node, reason=reason,
                                 open_args=open_args,
                                 open_file=None if file else _open_word(words_of(command),
                                                                        command),
                                 xacro_options=xacro_options(words_of(command)),
                                 wrapper=xacro_wrapper(words_of(command)))
    text = resolved_text(value)
    if text is not None and literal_kind(text):
        return DescriptionSource(path, line, column, DescriptionKind.LITERAL, None,
                                 condition=condition, node=node, text=text)
    if text is None and value:
        # A value only launch knows (a configuration an includer passes, a helper's return):
        # the robot is there but unread, which is said once rather than left silent.
        return DescriptionSource(path, line, column, DescriptionKind.FILE, None,
                                 condition=condition, node=node, reason=_why(value))
    return None


TF_PREFIX = "tf_prefix"


def with_node_params(nodes: Sequence[NodeRecord], params: Sequence[tuple[str, str]],
                     unread: Sequence[str] = (),
                     tf_prefixes: Sequence[tuple[str | None, str]] = ()) -> list[NodeRecord]:
    """``nodes`` with the parameters set outside them by their private name
    (``NODE/param``, any namespace before it; a node's own ``<param>`` comes first), the
    reasons why parameters beside them were not read, the ``tf_prefix`` a
    robot_state_publisher finds from its namespace up, and the ros_control controllers
    that parameters load (``NAME/type``) at the first controller manager."""
    if not params and not unread and not tf_prefixes:
        return list(nodes)
    by_name: dict[str, list[tuple[str, str]]] = {}
    for key, value in params[:MAX_GLOBAL_PARAMS]:
        parts = key.strip("/").split("/")
        for i, part in enumerate(parts[:-1]):
            by_name.setdefault(part, []).append(("/".join(parts[i + 1:]), value))
    out: list[NodeRecord] = []
    managed = False
    searched = SearchedPrefixes(tf_prefixes)
    for node in nodes:
        extra = tuple(by_name.get(node.name, ())) if node.name is not None else ()
        if (node.package == "robot_state_publisher" and searched
                and node.given(TF_PREFIX) is None and all(k != TF_PREFIX for k, _ in extra)):
            # searchParam from the node's private namespace up: its own tf_prefix first,
            # else the one set in the closest namespace around it.
            found = _searched(node.namespace, searched)
            if found:
                extra += ((TF_PREFIX, found),)
        if extra or unread:
            node = replace(node, params=node.params + extra,
                           unread=node.unread + tuple(unread[:3]))
        out.append(node)
        if node.package == "controller_manager" and not managed:
            managed = True
            out.extend(ros1_controllers(params[:MAX_GLOBAL_PARAMS], node))
    return out


def _searched(namespace: str | None, tf_prefixes: SearchedPrefixes) -> str:
    """The ``tf_prefix`` searchParam finds from ``namespace`` up (unknown when the
    namespace is not resolved, unless every one is set at the root)."""
    if namespace is None:
        if tf_prefixes.unknown or set(tf_prefixes.by_scope) - {""}:
            return UNKNOWN_VALUE
        namespace = "/"
    return tf_prefixes.find(namespace)


def from_file_value(value: Value, path: str, line: int, column: int, condition: Condition,
                    node: str | None, directory: str) -> DescriptionSource:
    """A description read from the URDF file that ``value`` names."""
    file = resolved_text(value)
    return DescriptionSource(path, line, column, DescriptionKind.FILE,
                             _absolute(file, directory), condition=condition, node=node,
                             reason=None if file else _why(value),
                             open_file=None if file else _open_file(value, text_of(value)))


def _open_word(words: Sequence[Word], command: Value) -> tuple[str, str, str] | None:
    """:func:`_open_file` for the file word of a xacro call: an unresolved word that is
    neither an option nor an argument (the words before it name xacro, and may be
    unresolved too: ``$(find xacro)/xacro`` without the xacro package)."""
    for text, resolved in words:
        if not resolved and ":=" not in text and not text.startswith("-"):
            found = _open_file(command, text)
            if found is not None:
                return found
    return None


def _open_file(value: Value, word: str) -> tuple[str, str, str] | None:
    """(path before, text after, variable) when the file named by ``word`` (written in
    ``value``) is unknown only through one environment variable inside its file name:
    ``$(find pkg)/urdf/$(env MODEL).urdf``, ``'turtlebot3_' + os.environ['MODEL']``."""
    inside = [hole for hole in holes(value) if hole.text in word]
    if len(inside) != 1 or word.count(inside[0].text) != 1:
        return None
    variable = environment_variable(inside[0])
    before, _, after = word.partition(inside[0].text)
    if variable is None or "/" in after or not os.path.isabs(before):
        return None
    return before, after, variable
