"""The names ROS 2 programs give their nodes when the launch file names none, read from
their sources: a parameter file given to such a node reaches it only under those names.

A name is relative to the namespace the node is launched in; a ``*`` in its last part
stands for text the program makes up at run time (a random suffix, a plugin's name).
"""

from __future__ import annotations

from collections.abc import Sequence

from launch_linter.frontends.params import key_matches, node_full_name, node_keys

DEFAULT_NODE_NAMES: dict[tuple[str, str], tuple[str, ...]] = {
    # mavros/src/mavros_node.cpp 38, 65, 83 and include/mavros/plugin.hpp 81-88 (each
    # plugin a node named after it under the UAS node's full name), mavlink/mavros ros2
    # f8f462d.
    ("mavros", "mavros_node"): ("mavros_node", "mavros_router", "mavros", "mavros/*"),
    # tf2_ros/src/static_transform_broadcaster_program.cpp 70 (dashing 2b639fa: one fixed
    # name) and static_transform_broadcaster_node.cpp 40-66 (foxy d1dc38b, humble d0dbd51,
    # rolling 1b005c6: the name and 16 random characters), ros2/geometry2.
    ("tf2_ros", "static_transform_publisher"): (
        "static_transform_publisher", "static_transform_publisher_*"),
    # src/imuPreintegration.cpp 46, 207, 522-523 (two nodes in one process),
    # featureExtraction.cpp 41, imageProjection.cpp 90, mapOptmization.cpp 153,
    # TixiaoShan/LIO-SAM ros2 0f4908b; the same names on ros2 9d039fd.
    ("lio_sam", "lio_sam_imuPreintegration"): (
        "lio_sam_imu_preintegration", "lio_sam_transformFusion"),
    ("lio_sam", "lio_sam_imageProjection"): ("lio_sam_imageProjection",),
    ("lio_sam", "lio_sam_featureExtraction"): ("lio_sam_featureExtraction",),
    ("lio_sam", "lio_sam_mapOptimization"): ("lio_sam_mapOptimization",),
}
"""``(package, executable)``: the names of the nodes the program runs in its process."""

_MADE_UP = "zZ0madeUp"
"""Stands for a ``*`` of a name when a key's own last name cannot: a name no key spells."""


def default_node_names(package: str, executable: str | None) -> tuple[str, ...]:
    """The names of the nodes ``package``'s ``executable`` runs when none is given; empty
    when the linter does not know them."""
    return DEFAULT_NODE_NAMES.get((package, executable or ""), ())


def unmatched_default_keys(document: object, names: Sequence[str], namespace: str
                           ) -> list[tuple[str, tuple[str, ...]]] | None:
    """The node keys of a ROS 2 parameter file (each with its path of keys) when it has
    some and none reaches any node of the process (``names`` under ``namespace``). A
    ``*`` of a name is first given the key's own last name (``/mavros/**/conn`` reaches
    the plugin node ``mavros/*``), so a key is unmatched only when no name the program
    could make up matches it. None when one matches or the file has no node key."""
    keys = node_keys(document)
    for key, _ in keys:
        last = key.rstrip("/").rsplit("/", 1)[-1]
        filler = _MADE_UP if "*" in last else last
        for name in names:
            full = node_full_name(name.replace("*", filler), namespace)
            if key_matches(key, full):
                return None
    return keys or None
