"""``moveit_configs_utils.MoveItConfigsBuilder``, the way every MoveIt 2 config package's
launch files build the robot description they give ``robot_state_publisher`` and
``move_group``: only the robot description is modelled.

Read from moveit2 ``moveit_configs_utils/moveit_configs_builder.py`` (Humble to Rolling):
``MoveItConfigsBuilder(robot_name, robot_description="robot_description",
package_name=None)`` finds the package ``package_name or robot_name + "_moveit_config"``;
``.robot_description(file_path=None, mappings=None)`` sets ``{robot_description:
load_xacro(<package share> / file_path, mappings)}`` (an absolute ``file_path`` stands
alone, as ``Path /`` makes it); with no ``file_path`` the file comes from the package's
``.setup_assistant`` (not read: unknown). Every other loader returns the builder;
``.to_moveit_configs()`` loads the default description if none was set, and its
``robot_description`` attribute is that dictionary. ``to_dict()`` holds every other MoveIt
parameter too, which the linter does not read: it stays unknown.
"""

from __future__ import annotations

import ast

from launch_linter.frontends.ros2_python.values import (
    LazyStr,
    MoveItBuilderVal,
    MoveItConfigsVal,
    SubsVal,
)
from launch_linter.frontends.ros2_python.xacro_call import Calls, Unknowns, xacro_command
from launch_linter.resolve.ros2_substitution import Call, Subs, Text

BUILDER_LOADERS = frozenset({
    "robot_description_semantic", "robot_description_kinematics", "joint_limits",
    "moveit_cpp", "trajectory_execution", "planning_scene_monitor", "planning_pipelines",
    "cartesian_limits", "pilz_cartesian_limits", "sensors_3d",
})
"""The builder's loaders of other parameters: each returns the builder."""


def builder(interp: Calls, args: list[object], kwargs: dict[str, object],
            node: ast.Call) -> object:
    robot = interp.arg(args, kwargs, 0, "robot_name")
    parameter = interp.arg(args, kwargs, 1, "robot_description")
    package = interp.arg(args, kwargs, 2, "package_name")
    if parameter is None:
        parameter = "robot_description"
    if not isinstance(parameter, str):
        return interp.unknown(node, "MoveItConfigsBuilder with an unknown parameter name")
    if package is None:
        if not isinstance(robot, (str, LazyStr)):
            return interp.unknown(node, "MoveItConfigsBuilder of an unknown robot name")
        package = LazyStr((*interp.subs(robot, node, "robot name"), Text("_moveit_config")))
    return MoveItBuilderVal(interp.subs(package, node, "package name"), parameter)


def builder_method(interp: Calls, target: MoveItBuilderVal, name: str, args: list[object],
                   kwargs: dict[str, object], node: ast.Call) -> object:
    if name == "robot_description":
        file_path = interp.arg(args, kwargs, 0, "file_path")
        mappings = interp.arg(args, kwargs, 1, "mappings")
        return MoveItBuilderVal(target.package, target.parameter,
                                _xacro(interp, target, file_path, mappings, node))
    if name in BUILDER_LOADERS:
        return target
    if name == "to_moveit_configs" and not args:
        description = target.description
        if description is None:
            description = _xacro(interp, target, None, None, node)
        return MoveItConfigsVal(target.parameter, description)
    return interp.unknown(node, f"MoveItConfigsBuilder.{name}() is not modelled")


def configs_attribute(interp: Unknowns, target: MoveItConfigsVal, name: str,
                      node: ast.AST) -> object:
    if name == "robot_description":
        return {target.parameter: target.description}
    return interp.unknown(node, f"MoveIt configs' '{name}' is not read (only its robot "
                                f"description is modelled)")


def _xacro(interp: Calls, target: MoveItBuilderVal, file_path: object, mappings: object,
           node: ast.AST) -> object:
    """``load_xacro(<package share> / file_path, mappings)`` as the ``xacro`` command
    ``robot_state_publisher`` would be given (unknown when the file or a mapping is)."""
    if file_path is None:
        return interp.unknown(node, "MoveItConfigsBuilder's default robot description "
                                    "comes from the package's .setup_assistant, which the "
                                    "linter does not read")
    if not isinstance(file_path, (str, LazyStr, SubsVal)):
        return interp.unknown(node, "robot description file path not known")
    path = interp.subs(file_path, node, "file path")
    if not _absolute(path):
        share = (Call("find-pkg-share", (target.package,), interp.segment(node)),)
        path = (Call("path-join", (share, path), interp.segment(node)),)
    return xacro_command(interp, path, mappings, node)


_ABSOLUTE_CALLS = ("find-pkg-share", "find-pkg-prefix", "dirname", "filename")


def _absolute(path: Subs) -> bool:
    """Whether a path starts at the root (a package's share folder, ``/...``): ``Path /``
    then drops the package folder before it."""
    if not path:
        return False
    first = path[0]
    if isinstance(first, Text):
        return first.text.startswith("/")
    if isinstance(first, Call):
        if first.name == "path-join":
            return bool(first.args) and _absolute(first.args[0])
        return first.name in _ABSOLUTE_CALLS
    return False
