"""Frozen data classes shared by every layer: no behaviour beyond small helpers."""
from __future__ import annotations

from launch_linter.model.diagnostic import (
    Belief,
    Category,
    Diagnostic,
    Location,
    Problem,
    Severity,
)
from launch_linter.model.launch import FileRecord, FileStatus, LaunchTree
from launch_linter.model.transform import (
    ArgForm,
    ArgIssue,
    ArgIssueKind,
    Condition,
    ConditionLiteral,
    Field,
    LaunchFormat,
    NumberIssue,
    Rotation,
    RotationKind,
    StaticTransform,
)

__all__ = [
    "ArgForm",
    "ArgIssue",
    "ArgIssueKind",
    "Belief",
    "Category",
    "Condition",
    "ConditionLiteral",
    "Diagnostic",
    "Field",
    "FileRecord",
    "FileStatus",
    "LaunchFormat",
    "LaunchTree",
    "Location",
    "NumberIssue",
    "Problem",
    "Rotation",
    "RotationKind",
    "Severity",
    "StaticTransform",
]
