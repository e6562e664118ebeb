"""A launch argument's text that reads as a boolean, tested for truth in Python.

## What it does
Reports a Python launch file that tests for truth (`if`, `elif`, `not`, `x if ... else y`)
a text launch reads as a boolean, `'true'` or `'false'` in any case: typically
`if LaunchConfiguration('use_x').perform(context):` in an `OpaqueFunction`, whose value
(the argument's default or the value given) is `'false'` or `'True'`. The text's value is
resolved as launch would (defaults, `--args`); a value the linter does not know is not
judged.

## Why is this bad?
`perform()` returns the argument's text, and Python's truth of a text is its being
non-empty: `'false'` is true. Every boolean value of the argument takes the same side, so
launching with `use_x:=false` does what `use_x:=true` does (autowarefoundation/
sample_sensor_kit_launch#92: `output_as_sensor_frame:=false` still transformed the point
cloud to the sensor frame). Launch's own conditions compare the text instead
(ros2/launch evaluate_condition_expression_impl.py: `'true'`/`'1'` and `'false'`/`'0'`,
lowered).

## Example
```python
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    frame = 'lidar' if LaunchConfiguration('sensor_frame').perform(context) else ''
    return [Node(package='filters', executable='filter',
                 parameters=[{'output_frame': frame}])]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('sensor_frame', default_value='false'),
                              OpaqueFunction(function=setup)])
```

## Use instead
```python
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    sensor_frame = LaunchConfiguration('sensor_frame').perform(context).lower() == 'true'
    frame = 'lidar' if sensor_frame else ''
    return [Node(package='filters', executable='filter',
                 parameters=[{'output_frame': frame}])]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('sensor_frame', default_value='false'),
                              OpaqueFunction(function=setup)])
```

## Known problems
A warning, on a thin sample (docs/evaluation/py_text_truth.jsonl): none in the corpus's
709 ROS 2 Python launch files (their performed boolean arguments are compared); in public
files found by the text `).perform(context):`, 3 findings in 2 files of other robots, all
true (a Scout's `simulation` choosing nav2's parameters and use_sim_time, a rover's `local`
choosing a hard-coded description path); the non-empty tests of file, map and prefix
arguments there (texts that are no boolean words) are silent. `'1'` and `'0'`, which
launch's conditions also read, are left out: a number's text may be tested on purpose.
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "py_text_truth"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.py"


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
