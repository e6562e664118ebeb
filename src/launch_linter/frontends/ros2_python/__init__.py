"""ROS 2 Python launch files, read as a syntax tree: never imported, never executed.

``ros2 launch`` imports a ``*.launch.py`` file and calls its ``generate_launch_description()``.
The linter parses the file with :func:`ast.parse` and interprets a small, safe part of
Python over the tree: literals, names, lists/tuples/dicts, ``+``/``*``/``%`` on known
values, f-strings, comparisons, ``if``/``for`` over known values, comprehensions, calls of
functions defined in the same file (bounded), and the launch classes it models
(``LaunchDescription``, ``Node``, ``DeclareLaunchArgument``, ``LaunchConfiguration``,
``GroupAction``, ``PushRosNamespace``, ``IncludeLaunchDescription`` and its sources,
``ComposableNodeContainer``/``LoadComposableNodes``/``ComposableNode``, ``TimerAction``,
``OpaqueFunction``, ``RegisterEventHandler``, the substitution classes, ``IfCondition``
and friends, ``get_package_share_directory``, ``os.path.join``, ``os.environ``). Launch
substitutions stay unevaluated until the actions run, exactly as in launch, so
``DeclareLaunchArgument`` defaults and ``LaunchConfiguration`` values are known when they
are statically known. Anything else is *unknown*: it carries the line and text of the
expression, so the transform that depends on it is reported as unresolved with that place.
An ``if`` on an unknown value runs both branches, each under a presence condition.

Nothing from the file is imported, no attribute of a real object is looked up, and every
loop, call depth and value size is bounded.
"""

from __future__ import annotations

from launch_linter.frontends.ros2_python.reader import read_python

__all__ = [
    "read_python",
]
