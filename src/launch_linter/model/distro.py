"""The target ROS distribution: given, configured, from ``ROS_DISTRO``, or seen in the files.

Facts used by the rules (checked in ros2/geometry2 and launch_ros; see docs/severity.md):
- ``static_transform_publisher`` flags (``--frame-id`` …) arrived in tf2_ros 0.19.0
  (ros2/geometry2#392, October 2021): Humble has them, Foxy and Galactic do not.
- From Humble on, the positional form still works with "Old-style arguments are
  deprecated"; Rolling removed it (ros2/geometry2#790).
- launch_ros's Foxy-era ``Node(node_executable=, node_name=, node_namespace=)`` were
  replaced by ``executable``, ``name``, ``namespace`` and removed after Foxy.
"""

from __future__ import annotations

ROS1_DISTROS: tuple[str, ...] = ("indigo", "jade", "kinetic", "lunar", "melodic", "noetic")
ROS2_DISTROS: tuple[str, ...] = (
    "dashing", "eloquent", "foxy", "galactic", "humble", "iron", "jazzy", "kilted", "lyrical",
    "rolling",
)
"""In release order; rolling last (it is always the newest). Indigo and Jade (ROS 1, 2014
and 2015) are targets of many repositories still read: a knowledge entry's open run
(``until``) holds them only where its sources say so (docs/knowledge.md)."""

NO_FLAGS: tuple[str, ...] = ("dashing", "eloquent", "foxy", "galactic")
"""Distributions whose static_transform_publisher knows no flags: positional only."""
POSITIONAL_DEPRECATED: tuple[str, ...] = ("humble", "iron", "jazzy", "kilted")
"""Positional still works, with a deprecation warning."""
POSITIONAL_REMOVED: tuple[str, ...] = ("lyrical", "rolling")
"""Positional rejected: the node stops with 'Frame id must not be empty' (Rolling since
ros2/geometry2#790; Lyrical branched from it: ctu-mrs/mrs_uav_managers#37 changes its
arguments "for Lyrical compatibility")."""
LEGACY_KEYWORDS_OK: tuple[str, ...] = ("dashing", "eloquent", "foxy")
"""Distributions whose launch_ros still takes ``node_executable=``/``node_name=``."""

def uses_flags(tokens: tuple[str, ...]) -> bool:
    """Whether a ROS 2 static_transform_publisher's arguments use flags (``--frame-id``
    ...), which its program reads from Humble on."""
    return any(t.startswith("--") and t != "--ros-args" for t in tokens)


FOXY_EVIDENCE = "foxy-keywords"
"""The note a front-end leaves when a file uses Foxy-era ``Node`` keywords."""


def normalise(name: str | None) -> str | None:
    """``Humble`` → ``humble``; None or empty → None; unknown names are kept (lower case)."""
    if name is None:
        return None
    name = name.strip().lower()
    return name or None


def is_known(name: str) -> bool:
    return name in ROS1_DISTROS or name in ROS2_DISTROS


def describe(names: tuple[str, ...]) -> str:
    """``humble, iron, jazzy and kilted``, capitalised as the distributions are named."""
    titled = [n.capitalize() for n in names]
    return titled[0] if len(titled) == 1 else ", ".join(titled[:-1]) + " and " + titled[-1]
