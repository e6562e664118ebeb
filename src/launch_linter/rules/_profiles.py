"""Profiles: ``default`` (severities from measured precision) and ``study``.

The ``study`` profile restores the categories and severities of the study the linter
reproduces, and turns off the context checks added since (each rule asks
``RuleContext.study``), so that ``evaluate`` gives the same Table IV. See docs/severity.md.
"""

from __future__ import annotations

from launch_linter.model.diagnostic import Severity

PROFILES: tuple[str, ...] = ("default", "study")

STUDY_SEVERITY: dict[str, Severity] = {
    "leading_slash": Severity.WARNING,
    "reversed_name": Severity.WARNING,
    "sensor_null": Severity.WARNING,
    "int_suffix": Severity.WARNING,
    "ros2_positional_args": Severity.WARNING,
    # Rules the study did not have, whose default level rose after the study profile
    # was fixed: the profile keeps the level it had.
    "camera_frame_not_optical": Severity.INFO,
    "duplicate_publisher": Severity.INFO,
    "robot_frame_collision": Severity.INFO,
    "sim_time_mismatch": Severity.INFO,
}
"""The study's level of each rule whose default level differs now."""


STUDY_EXCLUDED: tuple[str, ...] = ("ros2_removed_keyword",)
"""Rules that need a target distribution, which the study's evaluation never has."""


def study_severity(rule_id: str, default: Severity) -> Severity:
    return STUDY_SEVERITY.get(rule_id, default)
