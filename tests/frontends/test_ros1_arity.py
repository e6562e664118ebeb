"""Argument lists of ROS 1 static transform publishers, read through the loader."""

from __future__ import annotations

import textwrap
from pathlib import Path

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.transform import RotationKind, StaticTransform


def load_one(tmp_path: Path, package: str, args: str) -> StaticTransform:
    path = tmp_path / "t.launch"
    path.write_text(textwrap.dedent(f"""\
        <launch>
          <node pkg="{package}" type="static_transform_publisher" name="n"
                args="{args}"/>
        </launch>
        """))
    (transform,) = load_tree(str(path), LoadOptions()).transforms
    return transform


def test_tf_ypr_with_period(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf", "1 2 3 0.1 0.2 0.3 base_link laser 100")
    assert (t.form, t.arity_issue, t.period_ms) == ("ypr", None, 100.0)
    assert (t.parent, t.child, t.translation) == ("base_link", "laser", (1.0, 2.0, 3.0))
    assert t.rotation is not None and t.rotation.values == (0.1, 0.2, 0.3)


def test_tf_quaternion_with_period(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf", "0 0 0 0 0 0.7071 0.7071 odom base 20")
    assert t.rotation is not None and t.rotation.kind is RotationKind.QUATERNION
    assert (t.parent, t.child, t.period_ms, t.arity_issue) == ("odom", "base", 20.0, None)


def test_tf_without_a_period(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf", "0 0 0 0 0 0 base_link laser")
    assert (t.parent, t.child, t.period_ms) == ("base_link", "laser", None)
    assert t.arity_issue is not None and "usage" in t.arity_issue


def test_tf2_given_a_period(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "0 0 0.1 0 0 0 base_link laser 100")
    assert (t.form, t.parent, t.child, t.period_ms) == ("ypr", "base_link", "laser", 100.0)
    assert t.arity_issue is not None and "takes no period" in t.arity_issue
    assert t.signature == ("base_link", "laser")


def test_tf2_real_quaternion_is_not_a_period(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "0 0 0.1 0 0 0 1 base_link laser")
    assert (t.form, t.arity_issue, t.period_ms) == ("quaternion", None, None)
    assert t.rotation is not None and t.rotation.values == (0.0, 0.0, 0.0, 1.0)


def test_tf2_one_arg_parameter_form(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "/static_tf/laser")
    assert (t.form, t.arity_issue, t.parent, t.child) == ("param", None, None, None)
    assert t.unresolved_names == ()


def test_args_spanning_lines_with_any_whitespace(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf", "0.1\n      0.2\t0.3\r\n   0 0 0\n base_link   laser\n 100")
    assert t.tokens == ("0.1", "0.2", "0.3", "0", "0", "0", "base_link", "laser", "100")
    assert (t.parent, t.child, t.period_ms, t.arity_issue) == ("base_link", "laser", 100.0, None)


def test_remap_words_are_removed_before_counting(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "0 0 0 0 0 0 base_link laser tf_static:=/r/tf_static")
    assert t.tokens[-1] == "tf_static:=/r/tf_static"
    assert (t.form, t.arity_issue, t.child) == ("ypr", None, "laser")


def test_atof_on_junk_numbers(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "0x10 1e-3 .5 1,57 pi/2 x base_link laser")
    assert t.translation == (16.0, 0.001, 0.5)
    assert t.rotation is not None and t.rotation.values == (1.0, 0.0, 0.0)
    assert [(n.index, n.written) for n in t.number_issues] == [(3, "1,57"), (4, "pi/2"), (5, "x")]


def test_quoted_words_are_shell_split(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "0 0 0 0 0 0 'base link' &quot;laser frame&quot;")
    assert (t.parent, t.child) == ("base link", "laser frame")
    assert t.args == "0 0 0 0 0 0 'base link' \"laser frame\""


def test_wrong_counts(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf2_ros", "0 0 0 base_link laser")
    assert t.form == "invalid" and t.rotation is None
    assert t.arity_issue is not None and "not 5" in t.arity_issue


def test_a_hole_counts_as_one_word_when_that_gives_a_valid_form(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf", "0 0 0 0 0 0 base_link $(arg child) 100")
    assert (t.form, t.parent, t.child_written) == ("ypr", "base_link", "$(arg child)")
    assert t.unresolved_names == ("child",)


def test_a_hole_that_may_be_several_words(tmp_path: Path) -> None:
    t = load_one(tmp_path, "tf", "0 0 0 $(arg rotation) base_link camera 100")
    assert t.form == "unknown"
    assert t.unresolved_names == ("arity", "translation", "rotation", "parent", "child")
    assert t.parent is None and t.rotation is None
