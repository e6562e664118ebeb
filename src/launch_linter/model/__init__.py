"""Frozen data classes shared by every layer: no behaviour beyond small helpers."""
from __future__ import annotations

from launch_linter.model.diagnostic import Belief, Category, Diagnostic, Location, Severity
from launch_linter.model.launch import FileRecord, FileStatus, LaunchTree
from launch_linter.model.transform import (
    Condition,
    ConditionLiteral,
    NumberIssue,
    Rotation,
    RotationKind,
    StaticTransform,
)

__all__ = [
    "Belief",
    "Category",
    "Condition",
    "ConditionLiteral",
    "Diagnostic",
    "FileRecord",
    "FileStatus",
    "LaunchTree",
    "Location",
    "NumberIssue",
    "Rotation",
    "RotationKind",
    "Severity",
    "StaticTransform",
]
