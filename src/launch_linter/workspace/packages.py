"""``$(find pkg)``: locate ROS packages under package roots the way rospkg does.

A package is a folder with a ``package.xml`` (named by its ``<name>`` element) or a
``manifest.xml`` (named by the folder); a metapackage (``<export><metapackage/>``) is not
one, as rospkg's ``RosPack`` skips it. The crawl follows symbolic links, does not descend
into a package, skips hidden folders, prunes folders holding ``CATKIN_IGNORE`` and stops
below ``rospack_nosubdirs``. Earlier roots win; within a root, the first package found
(folders in sorted order, for reproducible results) wins. The crawl is bounded.
"""

from __future__ import annotations

import os

from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import XmlError, parse_xml, read_regular_file

MAX_DIRECTORIES = 50_000
MAX_WALK_UP = 32
MAX_MANIFEST_BYTES = 1024 * 1024


class PackageIndex:
    """Packages found under ``roots``, crawled lazily on first use."""

    def __init__(self, roots: list[str]) -> None:
        self.roots = [os.path.abspath(r) for r in roots]
        self._packages: dict[str, str] | None = None
        self._read = reads.ReadLog()
        """What the crawl read: every file that asks for a package depends on it."""

    def find(self, name: str) -> str | None:
        if self._packages is None:
            with reads.recording() as self._read:
                self._packages = self._crawl()
        reads.depend_on(self._read)
        return self._packages.get(name)

    def _crawl(self) -> dict[str, str]:
        found: dict[str, str] = {}
        budget = MAX_DIRECTORIES
        seen: set[tuple[int, int]] = set()
        for root in self.roots:
            if not reads.is_dir(root):
                continue
            for directory, subdirs, files in os.walk(root, followlinks=True):
                budget -= 1
                if budget <= 0:
                    return found
                try:
                    info = os.stat(directory)
                except OSError:
                    subdirs[:] = []
                    continue
                if (info.st_dev, info.st_ino) in seen:
                    # A symbolic link back to a folder already crawled (a loop): skip it.
                    subdirs[:] = []
                    continue
                seen.add((info.st_dev, info.st_ino))
                # What the crawl finds changes when an entry of a folder it listed does.
                reads.note_folder(directory, info, subdirs, files)
                subdirs.sort()
                if "CATKIN_IGNORE" in files:
                    subdirs[:] = []
                    continue
                if "package.xml" in files or "manifest.xml" in files:
                    name = _package_name(directory, files)
                    if name is not None:
                        found.setdefault(name, directory)
                    subdirs[:] = []
                    continue
                if "rospack_nosubdirs" in files:
                    subdirs[:] = []
                    continue
                subdirs[:] = [d for d in subdirs if not d.startswith(".")]
        return found


def _package_name(directory: str, files: list[str]) -> str | None:
    if "package.xml" in files:
        try:
            data = read_regular_file(os.path.join(directory, "package.xml"), MAX_MANIFEST_BYTES)
            document = parse_xml(data, text_tags=("name",))
        except (OSError, XmlError):
            return None
        name: str | None = None
        for child in document.root.children:
            if child.tag == "name" and name is None:
                name = child.text.strip(" \n\r\t") or None
            elif child.tag == "export" and any(
                grandchild.tag == "metapackage" for grandchild in child.children
            ):
                return None
        return name
    return os.path.basename(directory)


def default_package_roots(launch_file: str) -> list[str]:
    """The enclosing workspace of ``launch_file``: from the package that holds it (the
    nearest folder up with a ``package.xml``), walk up to a folder whose ``src/`` holds
    that package (a catkin/colcon workspace: the root is its ``src``); without one, the
    package's parent folder is the root. A file outside any package has no roots."""
    # os.path.realpath, not Path.resolve: on Python 3.8 resolve() leaves a reference cycle
    # (a recursive closure) behind for every call; os.path, not pathlib, which (with
    # urllib.parse) would be start-up time for every run.
    directory = os.path.dirname(os.path.realpath(launch_file))
    package: str | None = None
    for _ in range(MAX_WALK_UP):
        if reads.is_file(os.path.join(directory, "package.xml")):
            package = directory
            break
        parent = os.path.dirname(directory)
        if parent == directory:
            return []
        directory = parent
    if package is None:
        return []
    # A package's own ``src`` (its C++ sources) is not a workspace: only a ``src`` that
    # holds the package counts.
    directory = os.path.dirname(package)
    for _ in range(MAX_WALK_UP):
        source = os.path.join(directory, "src")
        if package.startswith(source + os.sep) and reads.is_dir(source):
            return [source]
        parent = os.path.dirname(directory)
        if parent == directory:
            break
        directory = parent
    return [os.path.dirname(package)]


def nearest_package_xml(launch_file: str) -> str | None:
    """The ``package.xml`` of the package that holds ``launch_file`` (walking up)."""
    directory = os.path.dirname(os.path.abspath(launch_file))
    for _ in range(MAX_WALK_UP):
        candidate = os.path.join(directory, "package.xml")
        if reads.is_file(candidate):
            return candidate
        parent = os.path.dirname(directory)
        if parent == directory:
            return None
        directory = parent
    return None


def package_ros_version(manifest: str) -> int | None:
    """Which ROS a ``package.xml`` builds for: 2 for an ``ament_*`` build type (or
    buildtool), 1 for catkin; None when it does not say (or cannot be read)."""
    try:
        document = parse_xml(
            read_regular_file(manifest, MAX_MANIFEST_BYTES),
            text_tags=("build_type", "buildtool_depend"),
        )
    except (OSError, XmlError):
        return None
    build_type: str | None = None
    buildtools: list[str] = []
    for child in document.root.children:
        if child.tag == "export":
            for grandchild in child.children:
                if grandchild.tag == "build_type" and build_type is None:
                    build_type = grandchild.text.strip()
        elif child.tag == "buildtool_depend":
            buildtools.append(child.text.strip())
    if build_type is not None:
        if build_type.startswith("ament"):
            return 2
        if build_type == "catkin":
            return 1
        return None
    if any(tool.startswith("ament") for tool in buildtools):
        return 2
    if "catkin" in buildtools:
        return 1
    # ``ament_python`` packages often name no buildtool; without a build type a
    # format-1 manifest is ROS 1 (ROS 2 packages use format 2 or 3).
    if document.root.get("format") in (None, "1"):
        return 1
    return None
