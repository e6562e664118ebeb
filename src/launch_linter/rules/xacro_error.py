"""What xacro itself refuses: an undefined macro, a missing parameter, an undeclared arg.

## What it does
Reports, in a xacro description that a launch file loads (or a `.xacro` file linted on its
own), each element the real xacro stops on: a call of a macro no `xacro:macro` defines, a
macro call without a parameter that has no default or with one the macro does not have,
blocks that do not match the macro's block parameters, an `insert_block` of an undefined
block, a `$(arg x)` that no `xacro:arg` declares and the xacro call does not give, and a
`${name}` that no property defines by then and that is none of xacro's own symbols (its
math names, the Python builtins and namespaces it exposes, `load_yaml`; listed with their
source in `frontends/robot/xacro_globals.py`, for Noetic's and ROS 2's xacro only), and a
`${...}` that xacro evaluates (in a macro, once it is called) whose brackets or quotes do
not pair, which no Python compiles (`${mass * (h * h + l * l) / 12)}`), and a `${` or
`$(` never closed (`rpy="0 ${pi/2 0"`), which xacro's lexer cannot read (xacro 1.13.5 and
newer; the older xacro of Kinetic and Lunar drops the rest: `xacro_unexpanded`). The same
refusals in any element's text (`<updateRate>$(arg rate)</updateRate>`: xacro evaluates
every text node as it does attributes; a CDATA section is left as written). An expression that
reads a name beginning with `__` (a property `__limits`, an attribute `x.__class__`):
xacro's `safe_eval` refuses it ("Use of invalid name(s)", ros/xacro 9941961, released in
1.13.13, 1.14.9 and 2.0.7; not on Kinetic, Lunar, Dashing, Eloquent), reported once at
the property's definition. A file xacro
reads, the top one or an included one, that is not well-formed XML (`--` inside a comment,
a tag left open): xacro parses each with minidom, which stops on it (a description read as
text, `textfile=` or `cat`, is urdfdom's to parse: unknown; no xacro runs on it, so its
`<xacro:...>` elements are ones urdfdom skips, never reported). A xacro file the launch
file's command names that is provably not there (under the ROS 1 launch file's own
folder; written from `$(dirname)` with its folder there, as a `<rosparam file>` is
judged; or in a ROS 1 package found; a `*.xacro` name, which no build step makes), reported at the
`<param>`. Without `--inorder` on Hydro to Lunar (and with `--legacy` on Melodic), xacro
runs in the legacy order, which replaces every include first, before any property:
an include whose file name reads one (`filename="${arm}_macro.xacro"`) stops it with
"variable filename is supported with --inorder option only" (ros/xacro kinetic-devel
33fabd8, `cli.py` and `get_include_files`).
It is an error when a launch file loads the description (with or without a
robot_state_publisher: roslaunch runs a `<param command="xacro ...">` when it loads the
file, for a Gazebo spawner as much as for robot_state_publisher); info when it sits under an
undecided `xacro:if` and in a `.xacro` file linted on its own (it may be a part that its
includer completes), except a file that is not well-formed, which no includer completes: it
is reported at the file's own line, where expat stops, as for the top file.
When an include could not be read or a directive is not supported before it (the macro,
arg or property may be defined there; for a `${name}`, also a conditional undecided before
it), or the xacro call has unresolved words (they may give
the arg), nothing is proven: it stays an `unresolved` diagnostic. A
`$(arg X)` where X is a parameter of the enclosing macro is left to `xacro_param_as_arg`,
which reports it at the same line and level and says what to write instead.

## Why is this bad?
xacro stops with an error (`unknown macro name: xacro:x`, `Undefined parameters [x]`,
`Undefined substitution argument`, `name 'x' is not defined`, `unmatched ')' ... when
evaluating expression`, `invalid expression`): the launch file's xacro command fails, so
`robot_description` is never set and robot_state_publisher publishes nothing (ROS 1
`roslaunch` stops with
"Invalid <param> tag: Cannot load command parameter"; ROS 2 `ros2 launch` stops on the
failed `Command` substitution).

## Example
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side">
    <link name="${side}_wheel"/>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:wheel/>
</robot>
```

## Use instead
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side">
    <link name="${side}_wheel"/>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:wheel side="left"/>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import OWN_FAULTS, FaultKind
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import robots_of

ID = "xacro_error"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.urdf.xacro"


def check(context: RuleContext) -> Iterator[Finding]:
    # Without a robot_state_publisher the description is a spawner's or a controller
    # manager's: the failed command stops the launch all the same.
    publisher = any(node.package == "robot_state_publisher" for node in context.tree.nodes)
    for robot in robots_of(context):
        effect = ("robot_state_publisher publishes nothing" if publisher or robot.standalone
                  else "the launch stops before any node starts")
        params_as_args = {(f.path, f.line, f.name) for f in robot.faults
                          if f.kind is FaultKind.PARAM_AS_ARG}
        for fault in robot.faults:
            if fault.kind is not FaultKind.REFUSED:
                continue
            if fault.name is not None and (fault.path, fault.line, fault.name) in params_as_args:
                continue  # xacro_param_as_arg's
            if not fault.proven:
                continue  # an ``unresolved`` diagnostic says what was not followed
            when = (f" when {' and '.join(fault.conditions)}" if fault.conditions else "")
            # One message for a launch file's description and the file linted on its own,
            # so that the two are one finding, at the level of the launch file's.
            yield Finding(fault.path, fault.line, 1,
                          f"xacro stops here{when} ({fault.message}): the xacro command "
                          f"fails, so robot_description is not set and {effect}",
                          severity=(Severity.INFO if fault.conditions or (
                              robot.standalone and not fault.message.startswith(OWN_FAULTS))
                                    else None))
