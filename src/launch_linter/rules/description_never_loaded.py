"""A robot description that nothing loads, whose findings say nothing of a running robot.

## What it does
Reports, once, a URDF or xacro file linted on its own that no robot is made from: its
package's install rules (CMake `install()` for ament and catkin packages, setup.py
`data_files`, read statically and completely) install it nowhere, so no other workspace
can load it, and no file of its own workspace outside `test`/`tests` folders writes its
name (a launch file, a xacro include, a Gazebo `model.config`, a node's source) or a tail
a built name could end with (`$(arg model).urdf.xacro`). What the other rules find in the
robot it makes (urdfdom's refusals, the tf tree, frames) is then reported at info; this
finding says why, once per file, and only when it lowered something. What xacro makes of
the file's text (`xacro_*` rules, `parse_error`) keeps its level: the package's tests,
or a user, still run xacro on it.

## Why is this bad?
It is not: it says why the file's findings are not warnings. A description is only a
robot when something loads it (robot_state_publisher, Gazebo, MoveIt); a test fixture
that only a package's tests run through xacro, or a draft nobody names, makes no robot.
Delete the leftover, or install it and load it, if it is meant to run.

## Example
```xml
<!-- my_description/tests/two_cameras.urdf, not installed, named by no file -->
<robot name="two_cameras">
  <link name="base_link"/>
  <link name="camera_link"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
    <origin xyz="0 0 0" rpy="0 0 3.14"/>
  </joint>
</robot>
```
```xml
<package format="3"><name>my_description</name>
  <export><build_type>ament_cmake</build_type></export></package>
```
```xml
<!-- CMakeLists.txt -->
install(DIRECTORY urdf DESTINATION share/${PROJECT_NAME})
```

## Use instead
```xml
<!-- my_description/tests/two_cameras.urdf, installed with the package -->
<robot name="two_cameras">
  <link name="base_link"/>
  <link name="camera_link"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
    <origin xyz="0 0 0" rpy="0 0 3.14"/>
  </joint>
</robot>
```
```xml
<package format="3"><name>my_description</name>
  <export><build_type>ament_cmake</build_type></export></package>
```
```xml
<!-- CMakeLists.txt -->
install(DIRECTORY . DESTINATION share/${PROJECT_NAME})
```
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import DESCRIPTION_NEVER_LOADED, Category, Severity
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, Rule, RuleContext, frontend_findings

ID = DESCRIPTION_NEVER_LOADED
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "two_cameras.urdf"
EXAMPLE_INCLUDED = ("package.xml", "CMakeLists.txt")
XACRO_TEXT_RULES = frozenset(("parse_error", "xacro_arg_ignored", "xacro_error",
                              "xacro_param_as_arg", "xacro_unexpanded", "xacro_unused_block"))
"""Rules about what xacro makes of the file's text: true whoever runs xacro on it (the
package's tests do), so they keep their level."""


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)


def at_info_if_never_loaded(tree: LaunchTree, found: list[tuple[Rule, Finding]],
                            ) -> list[tuple[Rule, Finding]]:
    """``found`` (each rule's findings on ``tree``) at info when nothing loads the
    description ``tree`` is made from: it makes no running robot. This rule's finding
    says why once, and only when it lowered something (such files are common)."""
    if not any(p.rule == ID and p.path == tree.root for p in tree.problems):
        return found
    robot = [(rule, f) for rule, f in found if rule.id not in XACRO_TEXT_RULES]
    lowered = any((f.severity or rule.severity) is not Severity.INFO for rule, f in robot)
    return [(rule, replace(f, severity=Severity.INFO) if rule.id not in XACRO_TEXT_RULES
             else f) for rule, f in found if lowered or rule.id != ID]
