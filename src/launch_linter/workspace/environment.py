"""Where packages come from besides the linted sources: a sourced ROS environment and a
built workspace beside ``src/``, in the order ROS looks (an overlay before its underlay).

The order of a package search, first found wins:

1. ``--package-path`` folders (or the ``package-path`` configuration key), else the
   enclosing workspace of each linted file (its ``src/``): the sources being linted;
2. that workspace's own build output beside ``src/``: ``install/`` (colcon, merged or
   isolated), ``install_isolated/``, ``devel/``, ``devel_isolated/`` (catkin);
3. ``AMENT_PREFIX_PATH`` prefixes in their order (what ``ament_index`` searches in ROS 2);
4. ``ROS_PACKAGE_PATH`` folders in their order (what ``rospack`` crawls in ROS 1);
5. ``CMAKE_PREFIX_PATH`` prefixes in their order (catkin install and devel spaces).

A *prefix* holds installed packages as ``<prefix>/share/<package>``; a *source folder*
is crawled for ``package.xml`` as rospkg does. Installed files are read when a launch
file names them, never linted as inputs.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence

from launch_linter.resolve import reads

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Tuple

    Place = Tuple[str, str]
    """(``prefix`` or ``source``, folder)."""

PREFIX = "prefix"
SOURCE = "source"
BUILT_BESIDE_SOURCES = ("install", "install_isolated", "devel", "devel_isolated")
MAX_ENTRIES = 256


def environment_places(environ: Mapping[str, str]) -> tuple[Place, ...]:
    """The package places a sourced shell's variables give, in search order."""
    places: list[Place] = []
    for variable, kind in (("AMENT_PREFIX_PATH", PREFIX), ("ROS_PACKAGE_PATH", SOURCE),
                           ("CMAKE_PREFIX_PATH", PREFIX)):
        for entry in environ.get(variable, "").split(os.pathsep)[:MAX_ENTRIES]:
            if entry.strip():
                places.append((kind, os.path.abspath(entry.strip())))
    return _unique(places)


def built_beside(roots: Sequence[str]) -> tuple[Place, ...]:
    """The build output of each root that is a workspace's ``src/``."""
    places: list[Place] = []
    for root in roots:
        absolute = os.path.abspath(root)
        if os.path.basename(absolute) != "src":
            continue
        workspace = os.path.dirname(absolute)
        for name in BUILT_BESIDE_SOURCES:
            folder = os.path.join(workspace, name)
            if reads.is_dir(folder):
                places.append((PREFIX, folder))
    return tuple(places)


def _unique(places: list[Place]) -> tuple[Place, ...]:
    seen: set[Place] = set()
    out: list[Place] = []
    for place in places:
        if place not in seen:
            seen.add(place)
            out.append(place)
    return tuple(out)
