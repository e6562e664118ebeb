"""A ``.urdf`` or ``.xacro`` file linted as an input of its own, as ``check_urdf`` reads
it: its expansion (xacro args from ``--arg``, the others at their defaults) becomes a tree
of one description, so that the URDF structure rules and the tree rules see its joints
even when no launch file loads it.

A file that another description of its package includes is a part (macros, a sensor, an
arm meant to be attached): alone it may lack the links, args and macros its includer
gives, so it is checked only through its includer."""

from __future__ import annotations

import contextlib
import os
import re
from collections.abc import Callable, Mapping

from launch_linter.frontends.robot.describe import RobotCache, read_description
from launch_linter.model.diagnostic import DESCRIPTION_NEVER_LOADED, Problem
from launch_linter.model.launch import FileStatus, LaunchTree
from launch_linter.model.record import replace
from launch_linter.model.robot import DescriptionKind, DescriptionSource
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import (
    XmlError,
    parse_xml,
    read_launch_bytes,
    read_regular_file,
)
from launch_linter.workspace.discovery import DESCRIPTION_SUFFIXES, walk
from launch_linter.workspace.packages import PackageIndex

_INCLUDE = re.compile(rb"""<xacro:include\s[^<>]*?filename\s*=\s*["']([^"'<>]*)["']""")
MAX_PACKAGE_DEPTH = 4
"""Folders walked up from a description to find its package (``package.xml``)."""
MAX_SCANNED = 300
"""Most description files of one package read to find which are included."""
MAX_SCANNED_BYTES = 1 << 18


def load_description(path: str, args: Mapping[str, str], packages: PackageIndex,
                     cache: RobotCache | None, display: Callable[[str], str],
                     env: Mapping[str, str], data: bytes | None = None) -> LaunchTree:
    """The tree of the description file ``path``, or of ``data`` as if it were that file;
    its root, files and problems named as every path is shown (``display``)."""
    shown = display(path)
    if data is None and os.path.basename(path) in _included_names(_package_of(path), cache):
        return LaunchTree(shown, FileStatus.OK, (), (), (shown,))
    try:
        text = data if data is not None else read_launch_bytes(path)
        if parse_xml(text).root.tag != "robot":
            return LaunchTree(shown, FileStatus.OK, (), (), (shown,))
    except OSError as exc:
        return LaunchTree(shown, FileStatus.UNREADABLE, (), (Problem(
            "parse_error", shown, 1, 1, f"cannot read: {exc.strerror or exc}"),), (shown,))
    except XmlError as exc:
        return LaunchTree(shown, FileStatus.PARSE_ERROR, (), (Problem(
            "parse_error", shown, exc.line, 1, f"not well-formed XML: {exc.message}"),),
            (shown,))
    if path.lower().endswith(".urdf") and b"<xacro:" not in text:
        # A URDF is read as it is, as check_urdf and a launch file's open().read() do (one
        # with xacro elements is xacro whatever its name).
        source = DescriptionSource(shown, 1, 1, DescriptionKind.LITERAL, None,
                                   text=text.decode("utf-8", "replace"))
    else:
        # Text linted as if it were the file (which need not exist) is expanded as it is.
        given = data.decode("utf-8", "replace") if data is not None else None
        source = DescriptionSource(shown, 1, 1, DescriptionKind.XACRO, os.path.abspath(path),
                                   tuple(sorted(args.items())), text=given)
    robot, problems = read_description(source, packages, cache or RobotCache(), display,
                                       dict(env), standalone=True)
    if robot is None:
        return LaunchTree(shown, FileStatus.OK, (), tuple(problems), (shown,))
    ros = packages.ros_version_of(path)
    if ros is not None:
        # No launch file says which ROS runs the description: its package's build type
        # does (catkin: ROS 1, ament: ROS 2), for each plugin whose parameters' spelling
        # does not. The versions' plugins differ (ROS 1's camera utilities stamp /world
        # without a <frameName>, ROS 2's camera the sensor's link).
        robot = replace(robot, plugins=tuple(
            p if p.ros is not None else replace(p, ros=ros) for p in robot.plugins))
    reason = why_never_loaded(path, packages)
    if reason is not None:
        problems = [*problems, Problem(
            DESCRIPTION_NEVER_LOADED, shown, 1, 0,
            f"nothing loads this robot description: {reason}; what is wrong in the "
            "robot it makes is reported at info")]
    return LaunchTree(shown, FileStatus.OK, (), tuple(problems), (shown,),
                      descriptions=(source,), joints=robot.joints, robots=(robot,))


def why_never_loaded(path: str, packages: PackageIndex) -> str | None:
    """Why nothing runs the description ``path`` as a robot, or None when something
    may (installed, named by a file of the workspace, or unknown).

    A binary install of its package ships only what its install rules install (read
    completely: ``PackageIndex.installs``; ROS 2 and catkin), so another workspace cannot
    load a file they leave out; in its own workspace (a catkin devel space runs from
    source), only a file that writes its name can load it
    (:func:`launch_linter.workspace.loaders.loader_of`)."""
    if packages.installs(path, catkin=True) is not False:
        return None
    # Imported here: only a description no install rule ships needs the workspace read.
    from launch_linter.workspace.loaders import loader_of

    if loader_of(path) is not None:
        return None
    return ("its package's install rules, read completely, install it nowhere, and no "
            "file of the workspace outside test folders names it (no launch file, xacro "
            "include, model.config or program)")



def _package_of(path: str) -> str:
    """The package folder of ``path`` (the nearest with a ``package.xml``), or its folder."""
    folder = os.path.dirname(os.path.abspath(path))
    candidate = folder
    for _ in range(MAX_PACKAGE_DEPTH):
        if reads.is_file(os.path.join(candidate, "package.xml")):
            return candidate
        parent = os.path.dirname(candidate)
        if parent == candidate:
            break
        candidate = parent
    return folder


def _included_names(package: str, cache: RobotCache | None) -> frozenset[str]:
    """The file names that the descriptions of ``package`` include (bounded scan); once
    per run and package, and every file that asks depends on what the scan read."""
    if cache is None:
        return _scan_included_names(package)
    return reads.remembered(cache.included, package, lambda: _scan_included_names(package))


def _scan_included_names(package: str) -> frozenset[str]:
    names: set[str] = set()
    scanned = 0
    for directory, subdirs, files in walk(package):
        with contextlib.suppress(OSError):  # a folder gone since it was listed
            # A description added or removed here changes what is included.
            reads.note_folder(directory, os.stat(directory), subdirs, files,
                              reads.suffix_listing(DESCRIPTION_SUFFIXES))
        subdirs.sort()
        for name in sorted(files):
            if not name.lower().endswith(DESCRIPTION_SUFFIXES) or scanned >= MAX_SCANNED:
                continue
            scanned += 1
            try:
                data = read_regular_file(os.path.join(directory, name), MAX_SCANNED_BYTES)
            except OSError:
                continue
            for match in _INCLUDE.finditer(data):
                target = match.group(1).decode("utf-8", "replace")
                names.add(target.rstrip("/").rsplit("/", 1)[-1])
    return frozenset(names)
