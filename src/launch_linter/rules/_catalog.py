"""Every rule's id and category, in the order of the rules table, written out so that a
run needs no rule module to know them: one answered by the results cache runs no rule, yet
validates ids (``--select``, the configuration, suppressions) and selects the rules.
``tests/test_registry.py`` checks it against the rule modules (a new rule is added to both).
"""

from __future__ import annotations

from launch_linter.model.diagnostic import Category

CATALOG: tuple[tuple[str, Category], ...] = (
    ("self_transform", Category.MUST),
    ("dup_name", Category.MUST),
    ("dup_sig", Category.MUST),
    ("reversed_name", Category.MAY_SEMANTIC),
    ("rot_degrees", Category.MAY_SEMANTIC),
    ("int_suffix", Category.MAY_SEMANTIC),
    ("ned_transform", Category.MAY_SEMANTIC),
    ("sensor_null", Category.MAY_SEMANTIC),
    ("sig_implication", Category.MAY_IMPLIED),
    ("name_implication", Category.MAY_IMPLIED),
    ("sig_null_disp", Category.MAY_IMPLIED),
    ("name_null_disp", Category.MAY_IMPLIED),
    ("sig_null_rot", Category.MAY_IMPLIED),
    ("name_null_rot", Category.MAY_IMPLIED),
    ("bad_arity", Category.TF),
    ("bad_number", Category.TF),
    ("bad_quaternion", Category.TF),
    ("leading_slash", Category.TF),
    ("multiple_parents", Category.TF),
    ("tf_cycle", Category.TF),
    ("parse_error", Category.LAUNCH),
    ("roslaunch_error", Category.LAUNCH),
    ("unresolved", Category.LAUNCH),
    ("unused_suppression", Category.LAUNCH),
    ("ros2_positional_args", Category.TF),
    ("ros2_bad_flag", Category.TF),
    ("ros2_removed_keyword", Category.LAUNCH),
    ("py_arguments_single_string", Category.TF),
    ("component_default_frames", Category.TF),
    ("conflicting_transform", Category.TF),
    ("optical_frame_rotation", Category.TF),
    ("frame_authority", Category.TF),
    ("duplicate_publisher", Category.TF),
    ("node_second_parent", Category.TF),
    ("frame_param_slash", Category.TF),
    ("frame_without_publisher", Category.TF),
    ("robot_frame_collision", Category.TF),
    ("plugin_frame_unprefixed", Category.TF),
    ("sim_time_mismatch", Category.TF),
    ("sim_time_not_forwarded", Category.TF),
    ("sim_clock_not_bridged", Category.TF),
    ("node_executable_missing", Category.LAUNCH),
    ("camera_frame_not_optical", Category.TF),
    ("optical_rotated_twice", Category.TF),
    ("camera_streams_one_frame", Category.TF),
    ("rep105_order", Category.TF),
    ("quaternion_order", Category.TF),
    ("ros2_schema", Category.LAUNCH),
    ("urdf_root", Category.TF),
    ("urdf_duplicate_name", Category.TF),
    ("urdf_missing_link", Category.TF),
    ("urdf_empty_robot", Category.TF),
    ("urdf_repeated_origin", Category.TF),
    ("urdf_mimic_unknown", Category.TF),
    ("urdf_plugin_outside_gazebo", Category.TF),
    ("gazebo_reference_unknown", Category.TF),
    ("ros1_spawner_namespace", Category.LAUNCH),
    ("sim_plugin_missing", Category.TF),
    ("xacro_error", Category.TF),
    ("xacro_unused_block", Category.TF),
    ("xacro_param_as_arg", Category.TF),
    ("xacro_unexpanded", Category.TF),
    ("xacro_arg_ignored", Category.TF),
    ("rounded_pi", Category.TF),
    ("ros2_undeclared_arg", Category.LAUNCH),
    ("py_name_error", Category.LAUNCH),
    ("ros2_unused_include_arg", Category.LAUNCH),
    ("ros1_unused_arg", Category.LAUNCH),
    ("ros1_ignored_attribute", Category.LAUNCH),
    ("plugin_param_case", Category.TF),
    ("ros2_param_file_unmatched", Category.LAUNCH),
    ("ros2_missing_keyword", Category.LAUNCH),
    ("ros2_param_type", Category.LAUNCH),
    ("use_sim_time_misspelt", Category.TF),
    ("ros2_param_file_missing", Category.LAUNCH),
    ("param_value_refused", Category.LAUNCH),
    ("node_param_undeclared", Category.LAUNCH),
    ("namespace_pushed_twice", Category.TF),
    ("controller_tf_unrouted", Category.TF),
    ("joint_states_two_publishers", Category.TF),
    ("file_never_launched", Category.LAUNCH),
    ("ros2_param_empty_list", Category.LAUNCH),
    ("ros2_param_file_refused", Category.LAUNCH),
    ("description_never_loaded", Category.TF),
    ("py_string_as_bool", Category.LAUNCH),
    ("ros2_include_arg_misspelt", Category.LAUNCH),
)
"""(id, category) of every rule, in the rules table's order (the rule modules' names)."""

RULE_IDS = tuple(rule_id for rule_id, _ in CATALOG)

CATEGORY_OF = dict(CATALOG)

CATEGORY_NAMES = frozenset(category.value for _, category in CATALOG)

__all__ = ["CATALOG", "CATEGORY_NAMES", "CATEGORY_OF", "RULE_IDS"]
