"""A name a Python launch file uses but binds nowhere: Python raises NameError.

## What it does
Reports a name that a ROS 2 Python launch file evaluates on the way through
`generate_launch_description()` (outside an `if` the linter cannot decide) although the
file binds it nowhere: no assignment, import, `def`, `class`, parameter or `except ... as`
anywhere in the file, and it is no builtin. A file that may bind names unseen (a star
import, `exec`, `globals()`, `setattr`, ...) or that catches `NameError` is not judged.

## Why is this bad?
Python raises `NameError: name 'x' is not defined` when it evaluates the name, so `ros2
launch` stops ("Caught exception in launch") before it starts a node. The usual cause is a
rename done in one place only: a variable renamed where it is defined but not where it
is used (`decalre_config_file_cmd` left in `ld.add_action(...)` after the definition was
corrected), or a name copied from another launch file.

## Example
```python
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument


def generate_launch_description():
    declare_config_file_cmd = DeclareLaunchArgument('config_file', default_value='a.yaml')
    ld = LaunchDescription()
    ld.add_action(decalre_config_file_cmd)
    return ld
```

## Use instead
```python
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument


def generate_launch_description():
    declare_config_file_cmd = DeclareLaunchArgument('config_file', default_value='a.yaml')
    ld = LaunchDescription()
    ld.add_action(declare_config_file_cmd)
    return ld
```
"""
from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "py_name_error"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
