"""Launch files of a ROS 2 package that ``ros2 launch`` never runs.

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
"""

from __future__ import annotations

from launch_linter.frontends.xml_dialect import reads_as_python, ros1_sign
from launch_linter.workspace.mentions import named_by_another_file
from launch_linter.workspace.packages import PackageIndex


def why_never_launched(path: str, data: bytes | None, packages: PackageIndex) -> str | None:
    """Why the ROS 2 launch file ``path`` (``data``: its bytes, if read) is run by nothing,
    or None when it may be run (installed, named by another launch file, or unknown)."""
    installs = packages.installs(path)
    if installs or named_by_another_file(path) is not None:
        return None
    xml = data is not None and not path.lower().endswith((".yaml", ".yml")) and not (
        reads_as_python(path, data))
    sign = ros1_sign(data) if xml and data is not None else None
    if installs is False:
        what = f"a ROS 1 launch file ({sign}): " if sign else ""
        return (f"{what}its package's install rules install it nowhere and no launch file "
                "names it, so ros2 launch cannot find it")
    if sign is not None:
        return (f"a ROS 1 launch file ({sign}) left in a ROS 2 package: no launch file "
                "names it and no install rule read installs it")
    return None
