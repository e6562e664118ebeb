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
import re
import typing
from collections.abc import Sequence
from typing import NamedTuple

from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import XmlError, parse_xml, read_regular_file
from launch_linter.workspace.discovery import walk
from launch_linter.workspace.environment import PREFIX

if typing.TYPE_CHECKING:
    from launch_linter.workspace.environment import Place
    from launch_linter.workspace.executables import Executables
    from launch_linter.workspace.install_rules import Layout

MAX_DIRECTORIES = 50_000
MAX_WALK_UP = 32
BUILD_FILES = ("CMakeLists.txt", "setup.py", "setup.cfg")
"""The files that hold a ROS 2 package's install rules (ament_cmake, ament_python)."""
MAX_MANIFEST_BYTES = 1024 * 1024
MAX_PREFIX_ENTRIES = 20_000


class Located(NamedTuple):
    """Where a file named by a launch file or description is, as ROS would find it."""

    path: str | None
    """The file to read (a source file for an installed path), None when not found."""
    absent: bool
    """Provably absent: its package is found and no install rule provides it, or it is
    in the linted tree and not there. False with ``path`` None: unknown (``reason``)."""
    reason: str = ""


class PackageIndex:
    """Packages found under ``roots`` (source folders, crawled as rospkg does) and then
    in ``places`` (:mod:`.environment`: installed prefixes, ``<prefix>/share/<package>``,
    and further source folders), in that order, crawled lazily on first use; the
    earlier place wins (an overlay before its underlay). A package found in source is
    installed by its install rules (see :meth:`locate`)."""

    def __init__(self, roots: list[str], places: Sequence[Place] = ()) -> None:
        self.roots = [os.path.abspath(r) for r in roots]
        self.places = tuple((kind, os.path.abspath(folder)) for kind, folder in places)
        self._packages: dict[str, str] | None = None
        self._twice: dict[str, list[str]] = {}
        """Names found in more than one folder of ``roots``: colcon refuses to build such a
        workspace and rospack takes whichever its path lists first, so which copy is
        built is unknown (sibling clones of a fork beside the package)."""
        self._installed: set[str] = set()
        self._layouts: dict[str, tuple[Layout | None, reads.ReadLog]] = {}
        self._catkin_layouts: dict[str, tuple[Layout | None, reads.ReadLog]] = {}
        self._manifests: dict[str, tuple[str | None, reads.ReadLog]] = {}
        self._builds: dict[str, tuple[BuildDeclarations | None, reads.ReadLog]] = {}
        self._executables: dict[str, tuple[Executables | None, reads.ReadLog]] = {}
        self._read = reads.ReadLog()
        """What the crawl read: every file that asks for a package depends on it."""

    @property
    def key(self) -> tuple[object, ...]:
        """What the packages found depend on (a cache key)."""
        return (*self.roots, *self.places)

    def find(self, name: str) -> str | None:
        return self._all().get(name)

    def package_xml_of(self, path: str) -> str | None:
        """:func:`nearest_package_xml` of ``path``, walked up once per folder in this
        index's life (a run): the launch files of one folder share the walk, and each
        depends on what it looked at (``reads.remembered``)."""
        directory = os.path.dirname(os.path.abspath(path))
        return reads.remembered(self._manifests, directory, lambda: nearest_package_xml(path))

    def ros_version_of(self, path: str) -> int | None:
        """Which ROS the package holding ``path`` builds for, as its nearest
        ``package.xml`` says (None: no manifest, or it does not say)."""
        manifest = self.package_xml_of(path)
        return None if manifest is None else self.build_ros_version(manifest)

    def build_ros_version(self, manifest: str, building_for: int | None = None) -> int | None:
        """:func:`package_ros_version` with the manifest parsed once in this index's life:
        the engine (which ROS a launch file is) and the install layout (``building_for``
        2) both ask it, and each asker depends on what the parse read."""
        declarations = reads.remembered(self._builds, manifest,
                                        lambda: read_build_declarations(manifest))
        return None if declarations is None else declarations.ros_version(building_for)

    def _all(self) -> dict[str, str]:
        if self._packages is None:
            with reads.recording() as self._read:
                self._packages = self._crawl()
        reads.depend_on(self._read)
        return self._packages

    def _crawl(self) -> dict[str, str]:
        found: dict[str, str] = {}
        crawl = _Crawl(found, self._twice)
        for root in self.roots:
            crawl.source(root)
        # Further source places overlay one another in their order (ROS_PACKAGE_PATH):
        # the same name there is not ambiguous.
        crawl.twice = None
        for kind, folder in self.places:
            if kind != PREFIX:
                crawl.source(folder)
                continue
            for name, share in installed_packages(folder).items():
                if name not in found:
                    found[name] = share
                    self._installed.add(share)
        return found

    def locate(self, path: str, near: str | None = None,
               ros_version: int | None = None) -> Located:
        """The file that ``path`` names, the way ROS finds it: the path itself if it
        exists; else, inside a package found in source, the source file its install
        rules install there (``FindPackageShare`` names the share folder, which the
        source folder stands for); else absent when that is proven (see
        :class:`Located`), unknown otherwise. ``near`` is a folder of the linted tree
        (the including file's): a path under it or a source root can be proven absent.
        ``ros_version`` 1 is a ROS 1 file's ``$(find)``: a ROS 2 package found here is not
        the one roslaunch finds, so nothing is proven absent in it."""
        path = os.path.normpath(os.path.abspath(path))
        if reads.is_file(path):
            return Located(path, False)
        if reads.exists(path):
            # A folder, device or FIFO: found, so that reading it says what it is.
            return Located(path, False)
        owner = self._owner(path)
        if owner is not None:
            return self._in_package(path, *owner, ros_version=ros_version)
        inside = [*self.roots, *([near] if near else [])]
        if any(_under(path, os.path.abspath(root)) for root in inside):
            return Located(None, True, "not found")
        return Located(None, False, "it is outside the linted workspace and no package "
                       "found holds it; the machine that runs the launch may have it")

    def installed(self, path: str) -> str | None:
        """Where the source file ``path`` of a ROS 2 package found in source is
        installed, as the share folder is spelled here (the package's source folder
        stands for ``share/<pkg>``): ``<pkg>/bringup/launch/x.launch.py`` installed by
        ``install(DIRECTORY bringup/launch DESTINATION share/<pkg>)`` is
        ``<pkg>/launch/x.launch.py``. None when no rule installs it, or when the rules
        install it to more than one place."""
        path = os.path.normpath(os.path.abspath(path))
        owner = self._owner(path)
        if owner is None or owner[1] in self._installed:
            return None
        layout = self._layout(*owner)
        if layout is None:
            return None
        relative = os.path.relpath(path, owner[1]).replace(os.sep, "/")
        targets = set(layout.installed_as(relative))
        if len(targets) != 1:
            return None
        return os.path.normpath(os.path.join(owner[1], targets.pop()))

    def executables(self, name: str) -> tuple[str, Executables] | None:
        """The folder of the ROS 2 package ``name`` found in source and what it installs
        into ``lib/<name>`` (:mod:`.executables`, read once per run); None when it is not
        such a package (not found, installed, a ROS 1 package, a name in two folders)."""
        directory = self.find(name)
        if directory is None or directory in self._installed or name in self._twice:
            return None
        manifest = os.path.join(directory, "package.xml")
        if not reads.is_file(manifest) or self.build_ros_version(manifest, 2) != 2:
            return None
        # Imported here: only a node of a workspace package needs its build files read.
        from launch_linter.workspace.executables import read_executables

        found = reads.remembered(self._executables, directory,
                                 lambda: read_executables(directory, name))
        return None if found is None else (directory, found)

    def in_source(self, name: str) -> bool:
        """Whether the package ``name`` is found in source under a linted root (not an
        installed prefix, not a further source place): its own build file, not a
        release, decides what it builds; two copies of it under the roots count."""
        directory = self.find(name)
        if directory is None or directory in self._installed:
            return False
        return name in self._twice or any(_under(directory, root) for root in self.roots)

    def installs(self, path: str, catkin: bool = False) -> bool | None:
        """Whether the install rules of the ROS 2 package found in source that holds
        ``path`` install it (anywhere in its share folder): False only when every rule
        was read and none installs it (``ros2 launch <pkg> <file>`` cannot find it);
        None when that is unknown (no such package, an installed copy, a ROS 1 package
        unless ``catkin``, a name in two folders, rules not all read). With ``catkin``,
        a catkin package's rules (``${CATKIN_PACKAGE_SHARE_DESTINATION}``) are read too:
        what a binary install of it ships (its devel space runs from source)."""
        path = os.path.normpath(os.path.abspath(path))
        owner = self._owner(path)
        if owner is None or owner[1] in self._installed or owner[0] in self._twice:
            return None
        layout = self._layout(*owner) or (self._catkin_layout(*owner) if catkin else None)
        if layout is None:
            return None
        relative = os.path.relpath(path, owner[1]).replace(os.sep, "/")
        if layout.installed_as(relative):
            return True
        # No build file beside the manifest: its rules were never read (a partial copy),
        # which proves nothing about what the package installs.
        if layout.reasons or not any(os.path.lexists(os.path.join(owner[1], name))
                                     for name in BUILD_FILES):
            return None
        return False

    def _owner(self, path: str) -> tuple[str, str] | None:
        best: tuple[str, str] | None = None
        for name, directory in self._all().items():
            if _under(path, directory) and (best is None or len(directory) > len(best[1])):
                best = (name, directory)
        return best

    def _in_package(self, path: str, name: str, directory: str,
                    ros_version: int | None = None) -> Located:
        if directory in self._installed:
            return Located(None, True, f"not in the installed share folder of '{name}'")
        copies = self._twice.get(name)
        if copies is not None:
            return Located(None, False, f"package '{name}' is found in {len(copies)} places "
                           f"({', '.join(copies[:3])}): which one is built is unknown")
        layout = self._layout(name, directory)
        if ros_version == 1 and layout is not None:
            return Located(None, False, f"package '{name}' found here builds for ROS 2; "
                           "the ROS 1 package of that name that roslaunch finds is not in "
                           "the linted paths")
        if layout is None or (not layout.rules and not layout.reasons):
            return Located(None, True, "not found")
        relative = os.path.relpath(path, directory).replace(os.sep, "/")
        explained = layout.explain(relative)
        for source in explained.sources:
            candidate = os.path.normpath(os.path.join(directory, source))
            if reads.exists(candidate):
                return Located(candidate, False)
        if explained.sources and explained.complete:
            sources = " or ".join(explained.sources[:3])
            return Located(None, True, f"package '{name}' installs share/{name}/{relative} "
                           f"from {sources}, which is not there")
        why = "; ".join(explained.reasons[:3])
        return Located(None, False, f"share/{name}/{relative} is not explained by the install "
                       f"rules of package '{name}'" + (f" ({why})" if why else ""))

    def _layout(self, name: str, directory: str) -> Layout | None:
        """The install layout of a ROS 2 package found in source; None for ROS 1 (catkin
        runs from the source folder: ``$(find)`` is it, in the devel space)."""
        def read() -> Layout | None:
            manifest = os.path.join(directory, "package.xml")
            ros2 = reads.is_file(manifest) and self.build_ros_version(manifest, 2) == 2
            # Imported here: install rules are read only when a file is not where the
            # source folder would have it.
            from launch_linter.workspace.install_layout import read_layout

            return read_layout(directory, name) if ros2 else None

        # Every file that asks depends on the install rules read.
        return reads.remembered(self._layouts, directory, read)

    def _catkin_layout(self, name: str, directory: str) -> Layout | None:
        """The install layout of a catkin (ROS 1) package found in source; None for
        any other package."""
        def read() -> Layout | None:
            manifest = os.path.join(directory, "package.xml")
            ros1 = reads.is_file(manifest) and self.build_ros_version(manifest, 1) == 1
            from launch_linter.workspace.install_layout import read_layout

            return read_layout(directory, name) if ros1 else None

        return reads.remembered(self._catkin_layouts, directory, read)



class _Crawl:
    """One bounded crawl of source folders, shared by every folder of an index."""

    def __init__(self, found: dict[str, str],
                 twice: dict[str, list[str]] | None = None) -> None:
        self.found = found
        self.twice = twice
        """Where a name already found turns up again (None: not recorded)."""
        self.budget = MAX_DIRECTORIES
        self.seen: set[tuple[int, int]] = set()

    def source(self, root: str) -> None:
        if not reads.is_dir(root):
            return
        for directory, subdirs, files in walk(root, followlinks=True):
            self.budget -= 1
            if self.budget <= 0:
                return
            try:
                info = os.stat(directory)
            except OSError:
                subdirs[:] = []
                continue
            if (info.st_dev, info.st_ino) in self.seen:
                # A symbolic link back to a folder already crawled (a loop): skip it.
                subdirs[:] = []
                continue
            self.seen.add((info.st_dev, info.st_ino))
            # What the crawl finds changes when an entry of a folder it listed does.
            reads.note_folder(directory, info, subdirs, files)
            subdirs.sort()
            if "CATKIN_IGNORE" in files:
                subdirs[:] = []
                continue
            if "package.xml" in files or "manifest.xml" in files:
                name = _package_name(directory, files)
                if name is not None:
                    first = self.found.setdefault(name, directory)
                    if first != directory and self.twice is not None:
                        self.twice.setdefault(name, [first]).append(directory)
                subdirs[:] = []
                continue
            if "rospack_nosubdirs" in files:
                subdirs[:] = []
                continue
            subdirs[:] = [d for d in subdirs if not d.startswith(".")]


def _under(path: str, folder: str) -> bool:
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)


def installed_packages(prefix: str) -> dict[str, str]:
    """The packages an installed prefix holds, name to ``<prefix>/share/<name>``: those
    the ament index registers (``share/ament_index/resource_index/packages/<name>``)
    and every ``share/<name>`` with a ``package.xml`` (catkin installs, and ament ones);
    for a colcon isolated install (``install/<pkg>/share/<pkg>``), each sub-prefix."""
    share = os.path.join(prefix, "share")
    found: dict[str, str] = {}
    if not reads.is_dir(share):
        try:
            entries = sorted(reads.list_folder(prefix))[:MAX_PREFIX_ENTRIES]
        except OSError:
            return found
        for entry in entries:
            isolated = os.path.join(prefix, entry, "share", entry)
            if reads.is_dir(isolated):
                found.setdefault(entry, isolated)
        return found
    index = os.path.join(share, "ament_index", "resource_index", "packages")
    names: list[str] = []
    for folder in (index, share):
        try:
            names.extend(sorted(reads.list_folder(folder))[:MAX_PREFIX_ENTRIES])
        except OSError:
            continue
    for name in names:
        directory = os.path.join(share, name)
        if name in found or not reads.is_dir(directory):
            continue
        if reads.is_file(os.path.join(index, name)) or reads.is_file(
                os.path.join(directory, "package.xml")):
            found[name] = directory
    return found


_MANIFEST_NAMES: dict[tuple[str, int, int, int, int], str | None] = {}
"""Package name of each ``package.xml`` read, by path and identity: a run whose launch
files lie in many packages crawls one workspace many times (each package's roots), and
reads each manifest once."""
MAX_REMEMBERED_MANIFESTS = 20_000


def _package_name(directory: str, files: list[str]) -> str | None:
    if "package.xml" in files:
        path = os.path.join(directory, "package.xml")
        try:
            info = os.stat(path)
        except OSError:
            return None
        key = (path, info.st_dev, info.st_ino, info.st_size, info.st_mtime_ns)
        if key not in _MANIFEST_NAMES or reads.too_recent(info):
            # (A file changed in the last moments is read again: its time cannot tell
            # the results cache that it stays unchanged, its content can.)
            if len(_MANIFEST_NAMES) >= MAX_REMEMBERED_MANIFESTS:
                _MANIFEST_NAMES.clear()
            _MANIFEST_NAMES[key] = manifest_name(path)
        else:
            reads.note_status(path, info)  # the name read before, from this very file
        return _MANIFEST_NAMES[key]
    return os.path.basename(directory)


def manifest_name(path: str) -> str | None:
    """The package name a ``package.xml`` declares (None for a metapackage or none)."""
    try:
        data = read_regular_file(path, MAX_MANIFEST_BYTES)
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


def default_package_roots(launch_file: str) -> list[str]:
    """The enclosing workspace of ``launch_file``: from the package that holds it (the
    nearest folder up with a ``package.xml``), walk up to a folder whose ``src/`` holds
    that package (a catkin/colcon workspace: the root is its ``src``); without one, the
    package's parent folder is the root, and then the repository that holds the package
    a few folders further up (``repo/moveit_cfgs/<pkg>`` beside ``repo/<pkg>_support``:
    cloned into a workspace's ``src``, all its packages are built together). A file
    outside any package has the repository that holds it, within a few folders, as its
    root (``repo/ros_ws/launch/x.launch`` beside ``repo/ros_ws/src/<pkg>``: roslaunch
    finds ``$(find pkg)`` on the ROS_PACKAGE_PATH that sourcing the workspace built from
    that repository sets); outside any package and repository it has no roots."""
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
            break
        directory = parent
    if package is None:
        holder = _repository_holding(os.path.dirname(os.path.realpath(launch_file)))
        return [] if holder is None else [holder]
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
    return [os.path.dirname(package), *_repository_above(os.path.dirname(package))]


MAX_REPOSITORY_DEPTH = 3
"""Folders above a package's parent searched for its repository's ``.git`` (further up,
a ``.git`` is more likely a home folder kept in git than the package's repository)."""


def _repository_above(folder: str) -> list[str]:
    """The folder above ``folder`` (not ``folder`` itself) that holds a ``.git``, when
    there is one within ``MAX_REPOSITORY_DEPTH`` folders."""
    holder = _repository_holding(folder)
    return [] if holder is None or holder == folder else [holder]


def _repository_holding(folder: str) -> str | None:
    """``folder`` or the folder above it that holds a ``.git``, within
    ``MAX_REPOSITORY_DEPTH`` folders."""
    directory = folder
    for _ in range(MAX_REPOSITORY_DEPTH):
        if reads.exists(os.path.join(directory, ".git")):
            return directory
        parent = os.path.dirname(directory)
        if parent == directory:
            break
        directory = parent
    return None


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


_ROS_VERSION_CONDITION = re.compile(r"\s*\$ROS_VERSION\s*(==|!=)\s*([12])\s*$")


def _holds(condition: str | None, ros_version: int | None) -> bool | None:
    """Whether a manifest element's ``condition`` (REP 149) holds when building for
    ``ros_version``: True without one; None when it is not the plain
    ``$ROS_VERSION == N`` / ``!= N`` form or the version is not given."""
    if condition is None or not condition.strip():
        return True
    match = _ROS_VERSION_CONDITION.match(condition)
    if match is None or ros_version is None:
        return None
    return (ros_version == int(match.group(2))) == (match.group(1) == "==")


class BuildDeclarations:
    """What a ``package.xml`` says about its build, parsed once: its ``<export>``'s
    ``build_type`` and its ``buildtool_depend`` elements in document order, each with its
    condition, and the manifest's format; :meth:`ros_version` answers for any target."""

    __slots__ = ("declared", "format")

    def __init__(self, declared: tuple[tuple[str, str | None, str], ...],
                 manifest_format: str | None) -> None:
        self.declared = declared
        """``(tag, condition, text)``: tag ``build_type`` or ``buildtool_depend``."""
        self.format = manifest_format

    def ros_version(self, building_for: int | None = None) -> int | None:
        """Which ROS the package builds for: 2 for an ``ament_*`` build type (or
        buildtool), 1 for catkin; None when it does not say. A package that builds for
        both (``<build_type condition="$ROS_VERSION == 1">catkin</build_type>`` beside
        ``ament_python`` for 2) says which only for ``building_for`` given."""
        build_type: str | None = None
        buildtools: list[str] = []
        for tag, condition, text in self.declared:
            if tag == "build_type" and build_type is not None:
                continue
            holds = _holds(condition, building_for)
            if holds is None:
                return None
            if holds and tag == "build_type":
                build_type = text
            elif holds:
                buildtools.append(text)
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
        if self.format in (None, "1"):
            return 1
        return None


def read_build_declarations(manifest: str) -> BuildDeclarations | None:
    """A ``package.xml``'s :class:`BuildDeclarations`, None when it cannot be read."""
    try:
        document = parse_xml(
            read_regular_file(manifest, MAX_MANIFEST_BYTES),
            text_tags=("build_type", "buildtool_depend"),
        )
    except (OSError, XmlError):
        return None
    declared: list[tuple[str, str | None, str]] = []
    for child in document.root.children:
        if child.tag == "export":
            declared.extend(("build_type", grandchild.get("condition"), grandchild.text.strip())
                            for grandchild in child.children if grandchild.tag == "build_type")
        elif child.tag == "buildtool_depend":
            declared.append(("buildtool_depend", child.get("condition"), child.text.strip()))
    return BuildDeclarations(tuple(declared), document.root.get("format"))


def package_ros_version(manifest: str, building_for: int | None = None) -> int | None:
    """Which ROS a ``package.xml`` builds for (:meth:`BuildDeclarations.ros_version`);
    None when it does not say or cannot be read."""
    declarations = read_build_declarations(manifest)
    return None if declarations is None else declarations.ros_version(building_for)
