"""Calls of launch classes that Python itself refuses while launch loads the file.

A ``*.launch.py`` file runs ``generate_launch_description()`` before anything starts: a
launch class called with more positional arguments than its ``__init__`` takes raises
``TypeError``, and ``EmitEvent`` given something that is not an event raises
``RuntimeError``; launch stops and no process of the file starts. Both are reported as
``roslaunch_error`` at the call.

The signatures are read from the classes' source, the same on every branch from Foxy to
Rolling: ros2/launch ``foxy`` acfe0766, ``humble`` f31c1ff1, ``jazzy`` 09403fce,
``rolling`` 02595baf (``launch/launch/actions/*.py``, ``launch/launch/substitutions/*.py``);
ros2/launch_ros ``foxy`` 68e2b62, ``humble`` 25a207c, ``jazzy`` 62c56e5, ``rolling``
f9ab937 (``launch_ros/launch_ros/actions/*.py``, ``launch_ros/launch_ros/substitutions/
find_package.py``). Classes whose signature changed between those branches
(``PythonExpression`` gained ``python_modules`` in Iron) are left out.
"""

from __future__ import annotations

from collections.abc import Mapping

POSITIONAL_LIMITS: Mapping[str, tuple[str, int]] = {
    # class name: (the module launch exports it from, positional parameters of __init__)
    "PathJoinSubstitution": ("launch.substitutions", 1),  # (substitutions)
    "LaunchConfiguration": ("launch.substitutions", 1),  # (variable_name, *, default)
    "EnvironmentVariable": ("launch.substitutions", 1),  # (name, *, default_value)
    "Command": ("launch.substitutions", 1),  # (command, *, on_stderr)
    "TextSubstitution": ("launch.substitutions", 0),  # (*, text)
    "DeclareLaunchArgument": ("launch.actions", 1),  # (name, *, default_value, ...)
    "IncludeLaunchDescription": ("launch.actions", 1),  # (launch_description_source, *, ...)
    "ExecuteProcess": ("launch.actions", 0),  # (*, cmd, ...)
    "GroupAction": ("launch.actions", 1),  # (actions, *, scoped, ...)
    "TimerAction": ("launch.actions", 0),  # (*, period, actions, ...)
    "LogInfo": ("launch.actions", 0),  # (*, msg)
    "EmitEvent": ("launch.actions", 0),  # (*, event)
    "RegisterEventHandler": ("launch.actions", 1),  # (event_handler)
    "SetLaunchConfiguration": ("launch.actions", 2),  # (name, value)
    "Node": ("launch_ros.actions", 0),  # (*, executable, package, ...)
    "SetParameter": ("launch_ros.actions", 2),  # (name, value)
    "PushRosNamespace": ("launch_ros.actions", 1),  # (namespace)
    "FindPackageShare": ("launch_ros.substitutions", 1),  # (package)
    "FindPackagePrefix": ("launch_ros.substitutions", 1),  # (package)
}
"""Launch classes whose ``__init__`` takes a fixed number of positional arguments."""

_ACTION_MODULES = ("launch.actions", "launch_ros.actions")


def _exported_from(dotted: str, module: str) -> bool:
    """``dotted`` names a class of ``module`` (imported from it or from one of its files)."""
    return dotted.startswith(module + ".")


def positional_refusal(dotted: str, given: int) -> str | None:
    """Python's ``TypeError`` for a launch class given ``given`` positional arguments, or
    None when the class takes them (or its signature is not known)."""
    name = dotted.rsplit(".", 1)[-1]
    known = POSITIONAL_LIMITS.get(name)
    if known is None or not _exported_from(dotted, known[0]) or given <= known[1]:
        return None
    module, limit = known
    takes = ("only keyword arguments" if limit == 0 else
             f"{limit} positional argument{'s' if limit > 1 else ''}")
    return (f"{name}() takes {takes} but {given} were given: Python raises TypeError while "
            f"launch loads the file ({module}.{name}.__init__, Foxy to Rolling)")


def is_action_class(dotted: str) -> bool:
    """``dotted`` names a class of ``launch.actions`` or ``launch_ros.actions``: an action,
    never an event (``launch.actions.Shutdown`` is the action, ``launch.events.Shutdown``
    the event)."""
    return any(_exported_from(dotted, module) for module in _ACTION_MODULES)
