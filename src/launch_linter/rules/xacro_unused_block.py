"""A xacro macro block parameter that the macro never inserts.

## What it does
Reports a `xacro:macro` with a block parameter (`*origin`, `**content`) that no
`xacro:insert_block` in its body inserts (an `insert_block` whose name is an expression
counts as inserting any block).

## Why is this bad?
xacro accepts the call, takes the block from the caller and drops it without a word: an
`<origin>` passed to place a sensor is ignored and the sensor sits at the macro's own
origin. The macro's interface promises something its body does not do.

Info: of 6 judged findings 1 was a defect (pr2_description drops the measured Kinect
origin); the other 5 were callers passing a placeholder block the macro does not need
(docs/severity.md, precision trials 3 and 4).

## Example
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="sensor" params="parent *origin">
    <link name="sensor_link"/>
    <joint name="sensor_joint" type="fixed">
      <parent link="${parent}"/>
      <child link="sensor_link"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:sensor parent="base_link">
    <origin xyz="0.2 0 0.1" rpy="0 0 0"/>
  </xacro:sensor>
</robot>
```

## Use instead
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="sensor" params="parent *origin">
    <link name="sensor_link"/>
    <joint name="sensor_joint" type="fixed">
      <xacro:insert_block name="origin"/>
      <parent link="${parent}"/>
      <child link="sensor_link"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:sensor parent="base_link">
    <origin xyz="0.2 0 0.1" rpy="0 0 0"/>
  </xacro:sensor>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import FaultKind
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import robots_of

ID = "xacro_unused_block"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.urdf.xacro"


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        for fault in robot.faults:
            if fault.kind is FaultKind.DROPPED:
                yield Finding(fault.path, fault.line, 1,
                              f"{fault.message}: xacro takes the block every call passes "
                              f"and silently drops it")
