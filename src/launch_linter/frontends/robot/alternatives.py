"""Robots chosen by an environment variable, read as alternatives.

Launch files often pick the robot from the user's shell: ``os.environ['TURTLEBOT3_MODEL']``
in ``turtlebot3_<model>.urdf``, ``$(env ROBOT)``. Without ``--env`` the file is unknown,
but when the variable is one part of a file name in a folder that exists, the files that
could fill it are few and known: each is read as an alternative robot, present under
the condition ``env('X') == 'value'`` (so two alternatives never hold together, and
nothing is concluded from both at once), and an info says so once. More candidates
than :data:`MAX_ALTERNATIVES`, or none, leave the description unread, as before.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable

from launch_linter.model.record import replace
from launch_linter.model.robot import DescriptionSource
from launch_linter.model.transform import Condition, ConditionLiteral
from launch_linter.resolve import reads

MAX_ALTERNATIVES = 8
MAX_LISTED = 2000
"""Folder entries looked at for candidates."""
_FILL = re.compile(r"[A-Za-z0-9_][\w.+-]*\Z")
"""What a variable naming a robot model holds (no quotes, slashes or spaces)."""


def alternatives(source: DescriptionSource, display: Callable[[str], str]
                 ) -> tuple[list[DescriptionSource], str | None]:
    """The alternative sources for ``source`` (whose ``open_file`` is set) and the sentence
    that says what was done; without any, what was found instead (None when the folder
    is not there). ``display`` shows a path."""
    assert source.open_file is not None
    before, after, variable = source.open_file
    folder, start = os.path.split(before)
    pattern = f"{start}${variable}{after}"
    shown = display(folder)
    try:
        names = sorted(reads.list_folder(folder)[:MAX_LISTED])
    except OSError:
        return [], None
    fills = [name[len(start):len(name) - len(after)] for name in names
             if name.startswith(start) and name.endswith(after)
             and len(name) > len(start) + len(after)]
    fills = [fill for fill in fills if _FILL.match(fill)
             and reads.is_file(os.path.join(folder, start + fill + after))]
    if not fills or len(fills) > MAX_ALTERNATIVES:
        count = "no file" if not fills else f"{len(fills)} files (more than {MAX_ALTERNATIVES})"
        return [], f"{count} in {shown} match {pattern}"
    made = [replace(source, file=os.path.join(folder, start + fill + after), reason=None,
                    open_file=None,
                    condition=source.condition & Condition((ConditionLiteral(
                        f"$(eval env('{variable}') == '{fill}')", True),)))
            for fill in fills]
    return made, (f"the description file depends on the environment variable '{variable}' "
                  f"(not given): each of the {len(fills)} files in {shown} that match "
                  f"{pattern} is read as an alternative robot ({', '.join(fills)}); "
                  f"--env {variable}=VALUE picks one")
