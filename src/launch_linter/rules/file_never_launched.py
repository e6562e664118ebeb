"""A launch file of a ROS 2 package that nothing runs, whose refusals are only its text's.

## What it does
Reports, once, a ROS 2 launch file that `ros2 launch` refuses (`ros2_schema`,
`roslaunch_error`) but can never run: its package's install rules (CMake `install()`,
`ament_auto_package`, setup.py/setup.cfg `data_files`, read statically) provably never
install it and neither a launch file of the workspace nor a CMake command of its package
(`add_launch_test`, ...) names it, or it is a ROS 1 launch file (a rostest `<test>`,
`$(find)`, `<rosparam>`, a node's `type`) that nothing names and no install rule read
installs, or one installed whose name marks it as a kept copy (`old_x.launch.xml`,
`x_orig`, `x-backup`, `copy of x`); or it is an XML launch file that only ROS 1 launch
files name (`*.launch` files read as ROS 1) and no other launch file does: a roslaunch
fragment (a MoveIt setup-assistant config whose manifest was switched to ament_cmake keeps
`planning_pipeline.launch.xml`, included by its `move_group.launch` only). What
`ros2 launch` would refuse in that file is then reported at info, not error; this finding
says why once.

## Why is this bad?
It is not: it says why the file's refusals are not errors. `ros2 launch <pkg> <file>`
finds files in the package's installed share folder only, and a launch file reaches
another only through an include that names it. A ROS 1 rostest file left in an ament
package (navigation2's `nav2_costmap_2d/test/simple_driving_test.xml`, vendored with the
package) is refused by ROS 2 launch, but nothing launches it. roslaunch reads every file an
`<include>` names as roslaunch XML, whatever its name, and a ROS 2 launch file cannot
include a ROS 1 one: a fragment only ROS 1 files include is never run by `ros2 launch`.
Delete the leftover, or install it and fix it, if it is meant to run.

## Example
```xml
<!-- my_pkg/test/old_test.xml, left from ROS 1; no launch file names it -->
<launch>
  <test test-name="drive" pkg="my_pkg" type="tester"/>
</launch>
```
beside my_pkg's manifest:
```xml
<package format="3"><name>my_pkg</name>
  <export><build_type>ament_cmake</build_type></export></package>
```

## Use instead
```xml
<!-- my_pkg/launch/drive.launch.xml, installed by install(DIRECTORY launch ...) -->
<launch>
  <node pkg="my_pkg" exec="tester"/>
</launch>
```
```xml
<package format="3"><name>my_pkg</name>
  <export><build_type>ament_cmake</build_type></export></package>
```
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "file_never_launched"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.xml"
EXAMPLE_INCLUDED = "package.xml"


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
