"""Parameter-file paths a ROS 2 node cannot open: empty, or provably absent.

launch_ros turns each path in a node's ``parameters=[...]`` into a ``pathlib.Path``
(launch_ros/utilities/evaluate_parameters.py, ``evaluate_parameters``) and, when it is not
a file, logs "Parameter file path is not a file" and leaves it out of the node's command
line (launch_ros/actions/node.py ``_perform_substitutions``, the same in the foxy,
galactic, humble, iron, jazzy and rolling branches: ros2/launch_ros 68e2b62, 31e27eb,
25a207c, 180c4f4, 62c56e5, f9ab937, lines 406-418 to 452-464). An empty path is
``Path('')``, the current folder, never a file. The node then starts without any of the
file's parameters: on its defaults, or it stops when it needs them (champ's
``quadruped_controller_node``: "No links config file provided").

A launch argument of the *root* file declared with an empty default is left to the
command line: whoever runs the file is expected to give it (the same judgement the
ROS 1 loader makes of ``<arg default="">``), so such a path is only ``unresolved``.
"""

from __future__ import annotations

from launch_linter.frontends.ros2_actions import Action, DeclareArg, Group, Where
from launch_linter.resolve.ros2_substitution import Call, Subs, Text, written

MAX_WALKED = 20_000
"""Actions and substitutions looked at per walk (the input decides how many there are)."""


def given_at(subs: Subs, where: Where) -> tuple[int, int] | None:
    """Where a node's own call (written at ``where``) reads the path ``subs`` from a launch
    argument: a ``LaunchConfiguration`` written at or after the call's start; None when
    none is (a shared variable's place would stand for every node that reads it)."""
    start = (where.line, where.column)
    return next((c.at for c in configurations_read(subs) if c.at and c.at >= start), None)


def configurations_read(subs: Subs) -> list[Call]:
    """The ``LaunchConfiguration('name')`` / ``$(var name)`` calls in ``subs`` whose name
    is text, nested ones included, in order; bounded."""
    found: list[Call] = []
    stack = [subs]
    seen = 0
    while stack and seen < MAX_WALKED:
        for sub in stack.pop():
            seen += 1
            if not isinstance(sub, Call):
                continue
            if (sub.name == "var" and sub.args and len(sub.args[0]) == 1
                    and isinstance(sub.args[0][0], Text)):
                found.append(sub)
            stack.extend(sub.args)
    return found


def empty_defaults(actions: tuple[Action, ...]) -> dict[str, Where]:
    """The launch arguments a file declares with an empty literal default, where each is
    declared, its groups walked too; bounded."""
    found: dict[str, Where] = {}
    stack = [actions]
    seen = 0
    while stack and seen < MAX_WALKED:
        for action in stack.pop():
            seen += 1
            if isinstance(action, Group):
                stack.append(action.actions)
            elif (isinstance(action, DeclareArg) and action.default is not None
                  and all(isinstance(sub, Text) for sub in action.name)
                  and all(isinstance(sub, Text) and not sub.text for sub in action.default)):
                found.setdefault("".join(sub.text for sub in action.name
                                         if isinstance(sub, Text)), action.where)
    return found


def reads_configuration(subs: Subs, name: str) -> bool:
    """Whether ``subs`` reads the launch configuration ``name`` (``$(var name)``,
    ``LaunchConfiguration('name')``), also inside other substitutions; bounded by
    :func:`configurations_read`'s walk."""
    return any(written(call.args[0]) == name for call in configurations_read(subs))
