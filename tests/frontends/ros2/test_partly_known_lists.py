"""``unknown + [Node(...), ...]``: the known operand's launch entities are read, the unknown
part is said not followed (precision trial, IntelRealSense/realsense-ros: the pointcloud
examples write ``rs_launch.declare_configurable_parameters(...) + [..., Node(...)]`` and
lost every node)."""

from __future__ import annotations

from ros2_helpers import Load

TEMPLATE = """\
from launch import LaunchDescription
from launch_ros.actions import Node
import helpers


def generate_launch_description():
    tf = Node(package="tf2_ros", executable="static_transform_publisher",
              arguments={arguments})
    return LaunchDescription({entities})
"""
ARGS = "['0', '0', '1', '0', '0', '0', 'base_link', 'camera_link']"


def unfollowed(tree: object) -> list[str]:
    return [p.message for p in tree.problems  # type: ignore[attr-defined]
            if "launch entity not followed" in p.message]


def test_the_known_part_of_a_sum_with_an_unknown_list_is_read(load: Load) -> None:
    for entities in ("helpers.declare(a) + [tf]", "[tf] + helpers.declare(a)",
                     "helpers.declare(a) + helpers.declare(b) + [tf]"):
        tree = load({"a.launch.py": TEMPLATE.format(arguments=ARGS, entities=entities)},
                    "a.launch.py")
        assert [(t.parent, t.child) for t in tree.transforms] == [("base_link", "camera_link")]
        assert len(unfollowed(tree)) == entities.count("helpers.declare")


def test_an_unknown_value_alone_is_still_not_followed(load: Load) -> None:
    tree = load({"a.launch.py": TEMPLATE.format(arguments=ARGS, entities="helpers.declare(a)")},
                "a.launch.py")
    assert tree.transforms == ()
    assert len(unfollowed(tree)) == 1


def test_arguments_with_an_unknown_part_stay_unknown(load: Load) -> None:
    # Its words are not counted: the unknown part may be any number of arguments.
    tree = load({"a.launch.py": TEMPLATE.format(arguments="helpers.extra() + " + ARGS,
                                                entities="[tf]")}, "a.launch.py")
    assert not [p for p in tree.problems if p.rule in ("bad_arity", "roslaunch_error")]
    (transform,) = tree.transforms
    assert transform.child is None and transform.unresolved
