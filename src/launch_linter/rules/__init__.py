"""The rule registry: every rule module, in the order of the rules table."""

from __future__ import annotations

from launch_linter.rules import (
    bad_arity,
    bad_number,
    bad_quaternion,
    camera_frame_not_optical,
    component_default_frames,
    conflicting_transform,
    dup_name,
    dup_sig,
    duplicate_publisher,
    frame_authority,
    frame_param_slash,
    frame_without_publisher,
    int_suffix,
    leading_slash,
    multiple_parents,
    name_implication,
    name_null_disp,
    name_null_rot,
    ned_transform,
    node_second_parent,
    optical_frame_rotation,
    parse_error,
    py_arguments_single_string,
    quaternion_order,
    rep105_order,
    reversed_name,
    robot_frame_collision,
    ros2_bad_flag,
    ros2_positional_args,
    ros2_removed_keyword,
    ros2_schema,
    ros2_undeclared_arg,
    roslaunch_error,
    rot_degrees,
    rounded_pi,
    self_transform,
    sensor_null,
    sig_implication,
    sig_null_disp,
    sig_null_rot,
    sim_time_mismatch,
    tf_cycle,
    unresolved,
    unused_suppression,
    urdf_duplicate_name,
    urdf_empty_robot,
    urdf_missing_link,
    urdf_root,
    xacro_error,
    xacro_unused_block,
)
from launch_linter.rules._api import Rule, RuleContext, rule_from_module

RULE_MODULES = (
    self_transform,
    dup_name,
    dup_sig,
    reversed_name,
    rot_degrees,
    int_suffix,
    ned_transform,
    sensor_null,
    sig_implication,
    name_implication,
    sig_null_disp,
    name_null_disp,
    sig_null_rot,
    name_null_rot,
    bad_arity,
    bad_number,
    bad_quaternion,
    leading_slash,
    multiple_parents,
    tf_cycle,
    parse_error,
    roslaunch_error,
    unresolved,
    unused_suppression,
    ros2_positional_args,
    ros2_bad_flag,
    ros2_removed_keyword,
    py_arguments_single_string,
    component_default_frames,
    conflicting_transform,
    optical_frame_rotation,
    frame_authority,
    duplicate_publisher,
    node_second_parent,
    frame_param_slash,
    frame_without_publisher,
    robot_frame_collision,
    sim_time_mismatch,
    camera_frame_not_optical,
    rep105_order,
    quaternion_order,
    ros2_schema,
    urdf_root,
    urdf_duplicate_name,
    urdf_missing_link,
    urdf_empty_robot,
    xacro_error,
    xacro_unused_block,
    rounded_pi,
    ros2_undeclared_arg,
)

RULES: tuple[Rule, ...] = tuple(rule_from_module(m) for m in RULE_MODULES)
RULES_BY_ID: dict[str, Rule] = {r.id: r for r in RULES}


def rules_for_profile(profile: str) -> tuple[Rule, ...]:
    """The rules as a profile sees them: ``study`` gives each the study's severity and
    leaves out the rules that cannot fire without a target distribution."""
    if profile != "study":
        return RULES
    from dataclasses import replace

    from launch_linter.rules._profiles import STUDY_EXCLUDED, study_severity

    return tuple(
        replace(r, severity=study_severity(r.id, r.severity))
        for r in RULES
        if r.id not in STUDY_EXCLUDED
    )

__all__ = ["RULES", "RULES_BY_ID", "Rule", "RuleContext", "rules_for_profile"]
