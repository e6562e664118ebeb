"""What ``ros2 launch`` can run of a ROS 2 workspace: launch files, node executables.

``ros2 launch <package> <file>`` finds a file in the package's installed share folder
only (ament_index's ``get_package_share_directory``), and a launch file reaches another
only by an include that names it. A file that its package's install rules (read
statically: :meth:`PackageIndex.installs`) provably never install, and that no launch
file near it names (:func:`named_by_another_file`, a superset of its includers), is run
by nothing; so is a ROS 1 launch file (rostest's ``<test>``, ``$(find)``, ...) left in an
ament package that no launch file names and no rule read installs: navigation2's
``nav2_costmap_2d/test/simple_driving_test.xml``, a rostest file kept since the port to
ROS 2 and copied with the package into other workspaces. What ``ros2 launch`` would
refuse in such a file is true of its text but stops nothing.

So is an XML launch file whose name only ROS 1 launch files write (:func:`ros1_fragment`):
roslaunch reads every file an ``<include file=...>`` names as roslaunch XML, whatever its
name (roslaunch's ``xmlloader.py``: ``XmlLoader._include_tag`` hands the substituted
``file`` to ``_parse_launch``, no suffix looked at), and a ROS 2 launch file cannot include
a ROS 1 one; a MoveIt setup-assistant config whose manifest was switched to ament_cmake
keeps ``planning_pipeline.launch.xml`` that only its ``move_group.launch`` includes.

A node of a package built in the workspace starts only if the package installs its
executable into ``lib/<package>`` (:mod:`launch_linter.workspace.executables`, read
statically): :func:`missing_executable` says so when the package's build files, read
completely, install no executable of that name.
"""

from __future__ import annotations

import os
from collections.abc import Callable

from launch_linter.frontends.xml_dialect import (
    is_ros2_xml,
    reads_as_python,
    ros1_sign,
    without_comments,
)
from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file
from launch_linter.workspace.mentions import MAX_FILE_BYTES, every_writer, named_by_another_file
from launch_linter.workspace.packages import MAX_WALK_UP, PackageIndex


def why_never_launched(path: str, data: bytes | None, packages: PackageIndex) -> str | None:
    """Why the ROS 2 launch file ``path`` (``data``: its bytes, if read) is never run by
    ``ros2 launch`` (a sentence), or None when it may be run (installed, named by another
    launch file or by a CMake command, a test's, or unknown)."""
    fragment_of = ros1_fragment(path) if path.lower().endswith(".xml") else None
    if fragment_of is not None:
        return (f"ros2 launch never runs this file: only ROS 1 launch files name it "
                f"({fragment_of}), roslaunch reads every file an <include> names as ROS 1 "
                "launch XML, and no ROS 2 launch file names it")
    installs = packages.installs(path)
    if named_by_another_file(path) is not None or _named_by_cmake(path, packages):
        return None
    xml = data is not None and not path.lower().endswith((".yaml", ".yml")) and not (
        reads_as_python(path, data))
    sign = ros1_sign(data) if xml and data is not None else None
    if installs:
        if sign is None or not marked_as_copy(path):
            return None
        return (f"nothing runs this launch file: a ROS 1 launch file ({sign}) in a ROS 2 "
                "package, whose name marks it as a kept copy, that no launch file names")
    if installs is False:
        what = f"a ROS 1 launch file ({sign}): " if sign else ""
        return (f"nothing runs this launch file: {what}its package's install rules install "
                "it nowhere and no launch file names it, so ros2 launch cannot find it")
    if sign is not None:
        return (f"nothing runs this launch file: a ROS 1 launch file ({sign}) left in a ROS 2 "
                "package: no launch file names it and no install rule read installs it")
    return None


def ros1_fragment(path: str) -> str | None:
    """A ROS 1 launch file naming ``path`` when every launch file near it that writes its
    name (:func:`every_writer`) is a ``*.launch`` file read as ROS 1 (no sign of ROS 2
    launch XML) that writes it outside comments; None when none does, when another
    writer is not (ROS 2, Python, YAML, an ``*.xml``), or when the writers are unknown."""
    writers = every_writer(path)
    if not writers:
        return None
    name = os.path.basename(path).encode("utf-8", "surrogateescape")
    for writer in writers:
        if not writer.lower().endswith(".launch"):
            return None
        try:
            data = read_regular_file(writer, MAX_FILE_BYTES)
        except (OSError, NotRegularFile):
            return None
        if reads_as_python(writer, data) or is_ros2_xml(data) or (
                name not in without_comments(data)):  # a comment naming it includes nothing
            return None
    return os.path.basename(writers[0])


_COPY_MARKS = ("old", "orig", "bak", "backup", "copy")
"""Words that mark a file as a kept copy of another (``old_small_warehouse.launch.xml``
beside ``small_warehouse.launch.py``; ``control.launch_ORIG.py``)."""


def marked_as_copy(path: str) -> bool:
    """Whether the file's name, without its suffixes, starts or ends with a word of
    :data:`_COPY_MARKS` (``old_x``, ``x_old``, ``x-backup``, ``x copy``; not ``bold``)."""
    name = os.path.basename(path).lower()
    stem = name.split(".", 1)[0]
    words = [w for w in stem.replace("-", "_").replace(" ", "_").split("_") if w]
    suffixes = name.split(".")[1:]
    return bool(words) and (words[0] in _COPY_MARKS or words[-1] in _COPY_MARKS or any(
        part.split("_")[-1] in _COPY_MARKS for part in suffixes))


def _named_by_cmake(path: str, packages: PackageIndex) -> bool:
    """Whether a command of a ``CMakeLists.txt`` between the file's folder and its
    package's names the file (``add_launch_test(test/x.launch.py)``, ``add_ros_test``,
    ``ament_add_test(... COMMAND x.launch.py)``: a test that runs it); comments aside."""
    manifest = packages.package_xml_of(path)
    if manifest is None:
        return False
    # Imported here: only a refused file of a ROS 2 package needs its CMake files read.
    from launch_linter.workspace.cmake_install import MAX_CMAKE_BYTES, commands

    name = os.path.basename(path)
    top = os.path.dirname(manifest)
    folder = os.path.dirname(os.path.abspath(path))
    for _ in range(MAX_WALK_UP):
        try:
            data = read_regular_file(os.path.join(folder, "CMakeLists.txt"), MAX_CMAKE_BYTES)
        except (OSError, NotRegularFile):
            data = b""
        text = data.decode("utf-8", "replace")
        if name in text and any(name in argument.text for _, arguments, _ in commands(text)
                                for argument in arguments):
            return True
        if folder == top or os.path.dirname(folder) == folder:
            return False
        folder = os.path.dirname(folder)
    return False


def missing_executable(packages: PackageIndex, package: str, executable: str | None,
                       display: Callable[[str], str]) -> str | None:
    """Why ``Node(package=package, executable=executable)`` cannot start, when
    ``package`` is a ROS 2 package of the linted workspace whose build files, read
    completely, install no such executable; None otherwise (unknown included)."""
    found = None if not executable else packages.executables(package)
    if found is None or found[1].reasons or executable in found[1].names:
        return None
    directory, installed = found
    names = sorted(installed.names)
    listed = ", ".join(names[:8]) + (f" and {len(names) - 8} more" if len(names) > 8 else "")
    return (f"package '{package}' ({display(directory)}) installs no executable "
            f"'{executable}' into lib/{package}: its {installed.origin} install "
            f"{listed or 'none'}; ros2 launch stops: \"executable '{executable}' not found "
            f"on the libexec directory\"")
