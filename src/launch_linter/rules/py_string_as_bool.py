"""A Python launch file tests a launch argument's text, or its LaunchConfiguration, for truth.

## What it does
Reports a truth test (`if`, `while`, `... if ... else ...`, `assert`, `not`, `and`/`or`,
`bool(...)`) in a ROS 2 Python launch file of what a launch argument is not:
- the text of an argument that the file declares with a `true`/`false` default or
  choices, `LaunchConfiguration('x').perform(context)`, `context.launch_configurations['x']`
  or `.get('x')` (in an `OpaqueFunction`'s function, usually);
- the substitution object `LaunchConfiguration('x')` itself, also compared with a text
  (`LaunchConfiguration('x') == 'true'`);
directly or through a variable its function (or the module) assigns once. Read from the
syntax tree; nothing is run. Also, from the file's interpreted values, any text that
launch reads as a boolean (`'true'`/`'false'` in any case, its value resolved as launch
would: defaults, `--arg`, helper functions) tested for truth by Python, wherever the
argument is declared (autowarefoundation/sample_sensor_kit_launch#92:
`if LaunchConfiguration("output_as_sensor_frame").perform(context):` with an argument
declared in another file); one finding per test.

## Why is this bad?
`LaunchConfiguration('x')` is a `Substitution` object that defines neither `__bool__`,
`__len__` nor `__eq__` (launch 3.4.3, launch/substitution.py): Python takes it as true
and equal to nothing but itself, so `if LaunchConfiguration('debug'):` always holds and
`== 'true'` never does, whatever the argument says (moveit2_tutorials'
jupyter_notebook_prototyping.launch.py always starts its servo and joystick nodes).
Every launch argument is text: launch's `LaunchConfiguration.perform` returns
`context.launch_configurations[name]`, a `str`, whether the value came from the default or
from the command line. Python takes every non-empty string as true, so `if x:` holds for
`'false'` as much as for `'true'`, and the branch meant for `true` always runs (and `not x`
never does). ros_gz's gz_sim.launch.py tested `on_exit_shutdown` (default `'false'`) this
way and always attached `Shutdown()` to Gazebo's exit (ros_gz#617); clearpath_gz's
robot_spawn.launch.py tested `not generate.perform(context)` and never spawned the robot
with `generate:=false` (clearpath_simulator#82).

## Example
```python
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction, Shutdown
from launch.substitutions import LaunchConfiguration


def launch_gz(context):
    on_exit_shutdown = LaunchConfiguration('on_exit_shutdown').perform(context)
    if on_exit_shutdown:
        return [Shutdown()]
    return []


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('on_exit_shutdown', default_value='false'),
        OpaqueFunction(function=launch_gz),
    ])
```

## Use instead
```python
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction, Shutdown
from launch.substitutions import LaunchConfiguration


def launch_gz(context):
    on_exit_shutdown = LaunchConfiguration('on_exit_shutdown').perform(context)
    if on_exit_shutdown.lower() == 'true':
        return [Shutdown()]
    return []


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('on_exit_shutdown', default_value='false'),
        OpaqueFunction(function=launch_gz),
    ])
```

## Known problems
The value-based criterion (hold-out batch 8, engineer batch8b) was judged as
`py_text_truth` before the two were merged: 3 findings in 2 public files, all true, none in
the corpus's 709 Python launch files; `'1'`/`'0'`, which launch's conditions also read, are
left out (a number's text may be tested on purpose). The syntax scan reads a file for
these tests only when one of its lines mentions a read (or a variable
assigned from one) together with a test word (`if `, `not `, ` and `, `==`, ...): a test
whose condition spreads over lines that separate the two is not seen. Only arguments the
same file declares with a literal `true`/`false` default or choices are
judged (an argument declared elsewhere, or with a default that is not a switch, may be
meant to be tested for being empty). A variable assigned more than once in the function,
or a parameter, is not followed.
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "py_string_as_bool"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.py"


def check(context: RuleContext) -> Iterable[Finding]:
    if context.study:
        return ()
    return frontend_findings(context, ID)
