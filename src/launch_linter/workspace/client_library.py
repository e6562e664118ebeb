"""Which ROS 2 client library a package's nodes are built on, as its ``package.xml`` says.

Only one answer is proven: ``rclcpp``, for a package built with ``ament_cmake`` that
depends on ``rclcpp`` and names ``rclpy`` in none of its dependencies (a Python node
there would need rclpy). Anything else (an ``ament_python`` package, one that depends on
both, a manifest that cannot be read) is unknown: None.
"""

from __future__ import annotations

from launch_linter.resolve.xml_safe import XmlError, parse_xml, read_regular_file
from launch_linter.workspace.packages import MAX_MANIFEST_BYTES

RCLCPP = "rclcpp"
_DEPENDENCIES = ("depend", "build_depend", "exec_depend", "build_export_depend",
                 "run_depend", "test_depend")


def client_library(manifest: str) -> str | None:
    """``rclcpp`` when the ``package.xml`` at ``manifest`` proves every node of its
    package is an rclcpp node (see the module), else None."""
    try:
        document = parse_xml(read_regular_file(manifest, MAX_MANIFEST_BYTES),
                             text_tags=(*_DEPENDENCIES, "build_type"))
    except (OSError, XmlError):
        return None
    depends: set[str] = set()
    build_types: set[str] = set()
    for child in document.root.children:
        if child.tag in _DEPENDENCIES:
            depends.add(child.text.strip())
        elif child.tag == "export":
            build_types.update(grandchild.text.strip() for grandchild in child.children
                               if grandchild.tag == "build_type")
    if build_types != {"ament_cmake"} or RCLCPP not in depends or "rclpy" in depends:
        return None
    return RCLCPP
