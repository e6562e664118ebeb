"""The install layout of a ROS 2 package found in source: what lands in ``share/<pkg>``.

ament_cmake packages say it in ``CMakeLists.txt`` (:mod:`.cmake_install`), ament_python
ones in ``setup.py``/``setup.cfg`` ``data_files`` (:mod:`.python_install`). Each file
is read bounded, as text, and never run; one that cannot be read makes the layout
incomplete, which can explain paths but never prove one absent.
"""

from __future__ import annotations

import os

from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file
from launch_linter.workspace.cmake_install import MAX_CMAKE_BYTES, read_cmake_layout
from launch_linter.workspace.install_rules import Layout
from launch_linter.workspace.python_install import (
    MAX_SETUP_BYTES,
    read_setup_cfg,
    read_setup_py,
)


def read_layout(directory: str, package: str) -> Layout:
    """Every install rule into ``share/<package>`` that the package's build files give."""
    layout = Layout()
    for name, limit in (("CMakeLists.txt", MAX_CMAKE_BYTES), ("setup.py", MAX_SETUP_BYTES),
                        ("setup.cfg", MAX_SETUP_BYTES)):
        path = os.path.join(directory, name)
        if not os.path.lexists(path):
            continue
        try:
            data = read_regular_file(path, limit)
        except (OSError, NotRegularFile) as exc:
            layout.unread(f"{name} not read: {exc.strerror or exc}")
            continue
        if name == "CMakeLists.txt":
            layout.extend(read_cmake_layout(data.decode("utf-8", "replace"), package, name))
        elif name == "setup.py":
            layout.extend(read_setup_py(data, directory, package, name))
        else:
            layout.extend(read_setup_cfg(data.decode("utf-8", "replace"), directory, package,
                                         name))
    return layout
