"""What xacro goes past without expanding: a macro call without `xacro:`, a `${` never closed.

## What it does
Reports, in a xacro description (loaded by a launch file or linted on its own):
- an element written without the `xacro:` prefix whose tag names a macro defined by then
  and that reads as its call (each attribute is a parameter of the macro, and it has as
  many element children as the macro has block parameters), or names a directive
  (`property`, `arg`, `macro`, `if`, `unless`, `insert_block`, and `include` without
  element children, as a legacy xacro reads them), for the xacro of Noetic and
  of every ROS 2 distribution, and when the distribution is not known (with `--ros-distro`
  Melodic, Kinetic or older, Dashing or Eloquent, that xacro expands it: nothing is said);
  a joint that names a link such a call would have made is `urdf_missing_link`'s, whose
  message names the call;
- with `--ros-distro` Kinetic, Lunar or older (xacro before 1.13.5), a `${` or `$(` never
  closed (`rpy="0 ${pi/2 0"`), whose text that xacro drops. Newer xacro stops there:
  `xacro_error` reports it.

## Why is this bad?
The xacro of Noetic (1.14) and ROS 2 (2.x) calls a macro only for a tag written
`xacro:name` (ros/xacro noetic-devel 7045754 and ros2 9d05b0e, `handle_macro_call`); any
other element is copied to the output as it is (and `eval_all` reads only `xacro:` tags
as directives: an unprefixed `<property>` defines nothing, an `<insert_block>` inserts
nothing). The call stays an unknown element, which urdfdom skips, so none of the macro's
links, joints, sensors or Gazebo plugins are in the description: a joint that names one
of its links is refused (`urdf_missing_link`), a frame it defines never reaches tf, a
plugin it adds never loads. Melodic's xacro (1.13) still
expanded it, with "deprecated: xacro tags should be prepended with 'xacro' xml
namespace" (Kinetic's 1.11 warned so for a directive, and expanded a call without a
word), which is why such files break when a robot moves to Noetic or ROS 2.

Warning: 473 of 473 judged findings true (97 calls, 376 directives) in 4 of 20 whole
repositories, two of them at the parent of their maintainers' prefix fix
(docs/evaluation/xacro_unexpanded.md); no element named like a macro or a directive but
meant as itself was met.

xacro before 1.13.5 reads a text token by token and stops at a `${`/`$(` that is never
closed, dropping the rest without a word (`QuickLexer.next`, kinetic-devel 33fabd8):
`rpy="0 ${pi/2 0"` becomes `rpy="0 "`, which urdfdom refuses ("3 expected"), and a name
loses its end. xacro 1.13.5 and newer stop with "invalid expression".

## Example
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="camera" params="parent">
    <link name="camera_link"/>
    <joint name="camera_joint" type="fixed">
      <parent link="${parent}"/>
      <child link="camera_link"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <camera parent="base_link"/>
</robot>
```

## Use instead
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="camera" params="parent">
    <link name="camera_link"/>
    <joint name="camera_joint" type="fixed">
      <parent link="${parent}"/>
      <child link="camera_link"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:camera parent="base_link"/>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import FaultKind
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import robots_of

ID = "xacro_unexpanded"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf.xacro"


_DIRECTIVE_LOST = {
    "property": "defines no property",
    "arg": "declares no arg",
    "macro": "defines no macro (its body is read as elements where it stands)",
    "include": "includes nothing",
    "if": "tests nothing: its content stays wrapped in an <if> element that urdfdom skips",
    "unless": "tests nothing: its content stays wrapped in an <unless> element that "
              "urdfdom skips",
    "insert_block": "inserts nothing: the block the call passes is dropped",
}
"""What an unprefixed directive does not do on Noetic's and ROS 2's xacro (``eval_all``
reads only ``xacro:`` tags as directives and copies any other element)."""


def _not_expanded(tag: str, distro: str | None) -> str:
    who = (f"{distro.capitalize()}'s xacro" if distro
           else "the xacro of Noetic and ROS 2 (Melodic's reads it with a deprecation "
                "warning, older ones silently; target distribution not given)")
    if tag in _DIRECTIVE_LOST:
        return (f"<{tag}> is the directive <xacro:{tag}> without the xacro: prefix: {who} "
                f"copies it as a plain element, so it {_DIRECTIVE_LOST[tag]}; write "
                f"<xacro:{tag}>")
    return (f"<{tag}> calls macro '{tag}' without the xacro: prefix: {who} does not expand "
            f"it, so the call stays an unknown <{tag}> element that urdfdom skips and none of "
            f"the macro's links, joints or plugins reach the description; write <xacro:{tag}>")


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        for fault in robot.faults:
            if fault.kind is not FaultKind.UNEXPANDED:
                continue
            when = (f" when {' and '.join(fault.conditions)}" if fault.conditions else "")
            if fault.name is not None:
                message = _not_expanded(fault.name, context.distro)
            else:
                message = f"xacro{when}: {fault.message}; close the expression"
            yield Finding(fault.path, fault.line, 1, message)
