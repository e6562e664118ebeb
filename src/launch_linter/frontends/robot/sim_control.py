"""The controller manager a simulator's ros2_control plugin starts, and its controllers.

In a ROS 2 simulation the controller manager is no launched node: the description's
``<gazebo><plugin filename="libgazebo_ros2_control.so">`` (gazebo_ros2_control) or
``gz_ros2_control-system`` / ``ign_ros2_control-system`` (gz_ros2_control) starts it.
Both plugins hand every ``<parameters>`` element to rcl as ``--params-file`` (several are
allowed, read in order) and name the manager ``controller_manager`` in the namespace of
``<ros><namespace>`` (gz_ros2_control puts a ``/`` before one written without it);
``<controller_manager_name>`` renames it where the plugin reads it (gazebo_ros2_control
master, gz_ros2_control humble on). Sources: ros-controls/gazebo_ros2_control
``gazebo_ros2_control/src/gazebo_ros2_control_plugin.cpp`` (humble 42d875b 205-225 and
363-369: name fixed; master 3e6d3f4 258-280 and 352-363) and ros-controls/gz_ros2_control
``gz_ros2_control/src/gz_ros2_control_plugin.cpp`` (rolling e19b0ef 295-335 and 438-446;
humble 4cb90a2 ``ign_ros2_control_plugin.cpp`` 296-320). The files are read as a
launched ``ros2_control_node``'s ``parameters=[...]``: the manager's section gives the
controllers (``NAME.type``), each controller its own section; the plugin's
``<ros><remapping>`` rules (the plugin's record's ``remappings``) are the manager's too.
"""

from __future__ import annotations

import os
from collections.abc import Callable

from launch_linter.frontends.params import (
    CONTROLLER_MANAGER_NAME,
    PlacedDocument,
    controllers_of,
    read_yaml_file_placed,
    ros2_file_params,
)
from launch_linter.model.record import replace
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord

ROS2_CONTROL_PLUGINS = ("libgazebo_ros2_control.so", "gz_ros2_control-system",
                        "libgz_ros2_control-system.so", "ign_ros2_control-system",
                        "libign_ros2_control-system.so")
"""The ``filename``s of the simulators' ros2_control plugins."""
PARAMETERS_ELEMENT = "parameters"
MANAGER_NAME_ELEMENT = "controller_manager_name"


def simulated_controllers(plugin: NodeRecord, display: Callable[[str], str] | None = None
                          ) -> tuple[NodeRecord, list[NodeRecord]]:
    """A ros2_control plugin's record with what it could not read (``unread``: a
    ``<parameters>`` path not resolved, relative, or a file not read; its controllers are
    then not all known) and the controllers its files give, each at its own section's
    keys (``display`` shows a file's path). Other plugins are returned as they are."""
    if plugin.plugin not in ROS2_CONTROL_PLUGINS:
        return plugin, []
    placed: list[PlacedDocument] = []
    unread: list[str] = []
    for key, path in plugin.params:
        if key != PARAMETERS_ELEMENT:
            continue
        if path == UNKNOWN_VALUE:
            unread.append(f"a <{PARAMETERS_ELEMENT}> file of {plugin.plugin} is not resolved")
            continue
        path = path.strip()
        if not os.path.isabs(path):
            # rcl opens it from the simulator's working directory, which no file says.
            unread.append(f"<{PARAMETERS_ELEMENT}> {path!r} of {plugin.plugin} is relative "
                          f"to the simulator's working directory")
            continue
        document, why, keys = read_yaml_file_placed(path)
        if why is not None:
            unread.append(why)
            continue
        placed.append(PlacedDocument(document, path if display is None else display(path),
                                     keys))
    name = plugin.given(MANAGER_NAME_ELEMENT) or CONTROLLER_MANAGER_NAME
    params: list[tuple[str, str]] = []
    for each in placed:
        params.extend(ros2_file_params(each.document, name, plugin.namespace))
    plugin = replace(plugin, unread=plugin.unread + tuple(unread))
    manager = replace(plugin, params=tuple(params))
    return plugin, controllers_of(manager, [each.document for each in placed], placed)


__all__ = ["ROS2_CONTROL_PLUGINS", "simulated_controllers"]
