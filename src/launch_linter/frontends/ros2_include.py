"""Includes in ROS 2 launch files: where the included file is and what it requires.

The file is looked for as launch opens it (relative to the including file's folder, then
the working directory) and, when it is not there, through the package index
(:meth:`~launch_linter.workspace.packages.PackageIndex.locate`): a share path is read from
the source file its package's install rules name; absent or unknown is decided there.
"""

from __future__ import annotations

import os

from launch_linter.frontends.ros2_actions import Action, DeclareArg, Group
from launch_linter.resolve import reads
from launch_linter.resolve.ros2_substitution import Call, Subs, Text, written
from launch_linter.workspace.packages import Located, PackageIndex


def environment_names(subs: Subs, depth: int = 0) -> list[str]:
    """The environment variables (written as literal names) that ``subs`` reads."""
    names: list[str] = []
    if depth > 32:
        return names
    for sub in subs:
        if isinstance(sub, Call):
            if sub.name in ("env", "optenv") and sub.args:
                first = sub.args[0]
                if all(isinstance(part, Text) for part in first):
                    names.append("".join(part.text for part in first if isinstance(part, Text)))
            for argument in sub.args:
                names.extend(environment_names(argument, depth + 1))
    return names


def required_arguments(actions: tuple[Action, ...]) -> list[str]:
    """Arguments an included file declares unconditionally and without a default."""
    found: list[str] = []
    pending: list[Action] = list(reversed(actions))  # the next action last: a stack
    while pending:
        action = pending.pop()
        if isinstance(action, Group) and action.condition is None:
            pending.extend(reversed(action.actions))
        elif isinstance(action, DeclareArg) and action.condition is None and (
            action.default is None
        ) and all(isinstance(sub, Text) for sub in action.name):
            found.append(written(action.name))
    return found


def _locate(path: str, including_file: str) -> str | None:
    candidates = [path] if os.path.isabs(path) else [
        os.path.join(os.path.dirname(including_file), path), os.path.abspath(path),
    ]
    for candidate in candidates:
        if reads.is_file(candidate):
            return os.path.abspath(candidate)
    # A folder, device or FIFO of that name is found, so that reading it says what it is.
    for candidate in candidates:
        if reads.exists(candidate):
            return os.path.abspath(candidate)
    return None


def find_included(path: str, including_file: str, packages: PackageIndex
                  ) -> tuple[str | None, Located | None]:
    """(the file to read or None, how the package index judged a file that is not there)."""
    absolute = _locate(path, including_file)
    if absolute is not None:
        return absolute, None
    located = packages.locate(
        path if os.path.isabs(path) else os.path.join(os.path.dirname(including_file), path),
        near=os.path.dirname(including_file))
    return located.path, located
