"""What a ROS 2 include needs from its text: the file it names, the environment variables
it reads, and the arguments the included file requires (helpers of :mod:`ros2_run`)."""

from __future__ import annotations

import os

from launch_linter.frontends.ros2_actions import Action, DeclareArg, Group
from launch_linter.resolve.ros2_substitution import Call, Subs, Text, written


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
    pending: list[Action] = list(actions)
    while pending:
        action = pending.pop(0)
        if isinstance(action, Group) and action.condition is None:
            pending[:0] = action.actions
        elif isinstance(action, DeclareArg) and action.condition is None and (
            action.default is None
        ) and all(isinstance(sub, Text) for sub in action.name):
            found.append(written(action.name))
    return found


def locate_include(path: str, including_file: str) -> str | None:
    """The file an include names, relative to the including file or the current folder."""
    candidates = [path] if os.path.isabs(path) else [
        os.path.join(os.path.dirname(including_file), path), os.path.abspath(path),
    ]
    for candidate in candidates:
        if os.path.isfile(candidate):
            return os.path.abspath(candidate)
    # A folder, device or FIFO of that name is found, so that reading it says what it is.
    for candidate in candidates:
        if os.path.exists(candidate):
            return os.path.abspath(candidate)
    return None
