"""``$(find pkg)``: locate ROS packages under package roots the way rospkg does.

A package is a folder with a ``package.xml`` (named by its ``<name>`` element) or a
``manifest.xml`` (named by the folder). The crawl does not descend into a package, skips
hidden folders, prunes folders holding ``CATKIN_IGNORE`` and stops below
``rospack_nosubdirs``. Earlier roots win. The crawl is bounded.
"""

from __future__ import annotations

import os
from pathlib import Path

from launch_linter.frontends.xml_safe import XmlError, parse_xml

MAX_DIRECTORIES = 50_000
MAX_WALK_UP = 32


class PackageIndex:
    """Packages found under ``roots``, crawled lazily on first use."""

    def __init__(self, roots: list[str]) -> None:
        self.roots = [os.path.abspath(r) for r in roots]
        self._packages: dict[str, str] | None = None

    def find(self, name: str) -> str | None:
        if self._packages is None:
            self._packages = self._crawl()
        return self._packages.get(name)

    def _crawl(self) -> dict[str, str]:
        found: dict[str, str] = {}
        budget = MAX_DIRECTORIES
        for root in self.roots:
            if not os.path.isdir(root):
                continue
            for directory, subdirs, files in os.walk(root):
                budget -= 1
                if budget <= 0:
                    return found
                subdirs.sort()
                if "CATKIN_IGNORE" in files:
                    subdirs[:] = []
                    continue
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
            with open(os.path.join(directory, "package.xml"), "rb") as handle:
                document = parse_xml(handle.read(1024 * 1024))
        except (OSError, XmlError):
            return None
        for child in document.root.children:
            if child.tag == "name":
                return child.text.strip() or None
        return None
    if "manifest.xml" in files:
        return os.path.basename(directory)
    return None


def default_package_roots(launch_file: str) -> list[str]:
    """The enclosing workspace of ``launch_file``: walk up to a folder holding ``src/``
    (a catkin/colcon workspace, whose ``src`` is the root) or, failing that, to the
    nearest ``package.xml`` (whose parent folder is the root)."""
    directory = Path(launch_file).resolve().parent
    package_parent: Path | None = None
    for _ in range(MAX_WALK_UP):
        if package_parent is None and (directory / "package.xml").is_file():
            package_parent = directory.parent
        if package_parent is not None and (directory / "src").is_dir():
            return [str(directory / "src")]
        if directory.parent == directory:
            break
        directory = directory.parent
    return [str(package_parent)] if package_parent is not None else []
