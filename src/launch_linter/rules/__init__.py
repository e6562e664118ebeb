"""The rule registry: every rule module, in the order of the rules table (``_catalog``)."""

from __future__ import annotations

from types import ModuleType

from launch_linter.rules._catalog import RULE_IDS

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any

    from launch_linter.rules._api import Rule, RuleContext

    RULE_MODULES: tuple[ModuleType, ...]
    """The rule modules, in the rules table's order (``_catalog``)."""
    RULES: tuple[Rule, ...]
    RULES_BY_ID: dict[str, Rule]

_LOADED = ("RULE_MODULES", "RULES", "RULES_BY_ID")
_API = ("Rule", "RuleContext")


def _load() -> None:
    # The imports written out: the standalone linter's embedding follows what it reads.
    from launch_linter.rules import (
        bad_arity,
        bad_number,
        bad_quaternion,
        camera_frame_not_optical,
        camera_streams_one_frame,
        component_default_frames,
        conflicting_transform,
        controller_tf_unrouted,
        description_never_loaded,
        dup_name,
        dup_sig,
        duplicate_publisher,
        file_never_launched,
        frame_authority,
        frame_param_slash,
        frame_without_publisher,
        gazebo_reference_unknown,
        int_suffix,
        joint_states_two_publishers,
        leading_slash,
        multiple_parents,
        name_implication,
        name_null_disp,
        name_null_rot,
        namespace_pushed_twice,
        ned_transform,
        node_executable_missing,
        node_param_undeclared,
        node_second_parent,
        optical_frame_rotation,
        optical_rotated_twice,
        param_value_refused,
        parse_error,
        plugin_frame_unprefixed,
        plugin_param_case,
        py_arguments_single_string,
        py_name_error,
        py_string_as_bool,
        quaternion_order,
        rep105_order,
        reversed_name,
        robot_frame_collision,
        ros1_ignored_attribute,
        ros1_spawner_namespace,
        ros1_unused_arg,
        ros2_bad_flag,
        ros2_include_arg_misspelt,
        ros2_missing_keyword,
        ros2_param_empty_list,
        ros2_param_file_missing,
        ros2_param_file_refused,
        ros2_param_file_unmatched,
        ros2_param_type,
        ros2_positional_args,
        ros2_removed_keyword,
        ros2_schema,
        ros2_undeclared_arg,
        ros2_unused_include_arg,
        roslaunch_error,
        rot_degrees,
        rounded_pi,
        self_transform,
        sensor_null,
        sig_implication,
        sig_null_disp,
        sig_null_rot,
        sim_clock_not_bridged,
        sim_plugin_missing,
        sim_time_mismatch,
        sim_time_not_forwarded,
        tf_cycle,
        unresolved,
        unused_suppression,
        urdf_duplicate_name,
        urdf_empty_robot,
        urdf_mimic_unknown,
        urdf_missing_link,
        urdf_plugin_outside_gazebo,
        urdf_repeated_origin,
        urdf_root,
        use_sim_time_misspelt,
        xacro_arg_ignored,
        xacro_error,
        xacro_param_as_arg,
        xacro_unexpanded,
        xacro_unused_block,
    )

    # The modules just imported, by id (the import above names each one once).
    modules = {value.ID: value for value in dict(locals()).values()
               if isinstance(value, ModuleType)}
    from launch_linter.rules._api import rule_from_module

    ordered = tuple(modules[rule_id] for rule_id in RULE_IDS)
    rules = tuple(rule_from_module(module) for module in ordered)
    globals().update(RULE_MODULES=ordered, RULES=rules, RULES_BY_ID={r.id: r for r in rules})


def __getattr__(name: str) -> Any:
    """The rules, their modules and their API imported on first use: a run answered by
    the results cache runs no rule (``_catalog`` gives what it needs: the ids and
    categories)."""
    if name in _LOADED:
        _load()
        return globals()[name]
    if name in _API:
        from launch_linter.rules import _api

        value = getattr(_api, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def rules_for_profile(profile: str) -> tuple[Rule, ...]:
    """The rules as a profile sees them: ``study`` gives each the study's severity and
    leaves out the rules that cannot fire without a target distribution."""
    rules: tuple[Rule, ...] = __getattr__("RULES")
    if profile != "study":
        return rules
    from launch_linter.model.record import replace
    from launch_linter.rules._profiles import STUDY_EXCLUDED, study_severity

    return tuple(
        replace(r, severity=study_severity(r.id, r.severity))
        for r in rules
        if r.id not in STUDY_EXCLUDED
    )


__all__ = ["RULES", "RULES_BY_ID", "Rule", "RuleContext", "rules_for_profile"]
