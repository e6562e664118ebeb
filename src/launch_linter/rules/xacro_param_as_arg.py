"""A xacro macro that reads its own parameter as `$(arg X)` instead of `${X}`.

## What it does
Reports, in the body of a `xacro:macro`, each `$(arg X)` where X is a parameter of the
macro (or of a macro it is defined in), with or without a default (`X:=v`, `X:=^`,
`X:=^|v`), at the line the `$(arg X)` is written on. Block parameters (`*X`, `**X`) are
not values and do not count; a `$(arg X)` in the `params` default of the outermost macro
is read where the macro is called, as meant. A `<xacro:arg name="X" default="${X}"/>` in
the body does not make it right: args are global and set once, so every later call gets
the first call's value. It is found in every macro of the files a description reads,
called or not. It is an error where xacro provably stops on it: a
launch file loads the description, every word of its xacro call is known and none gives
X, no `<xacro:arg name="X">` comes before the call, the macro is called and the branch
holding the use is taken (`xacro_error` then leaves this refusal to this rule). Otherwise
a warning: in a `.xacro` file linted on its own the command line that runs xacro may give
X (`xacro robot.urdf.xacro X:=...`), so the file alone proves that the macro ignores
its parameter, not that xacro stops.

## Why is this bad?
xacro resolves `$(arg X)` from its table of args (the command line's and the
`<xacro:arg>`s of the document), never from a macro's parameters, which only `${X}`
reads (ros/xacro `src/xacro/__init__.py` at 7045754: `eval_extension` resolves with
`substitution_args_context`; `handle_macro_call` puts the parameters in the call's
symbol table). So the value each call passes for X is ignored: the macro works in the
one file that declares an arg X with the right value and fails or builds the wrong robot
anywhere else. Where no arg X is declared xacro stops with `Undefined substitution
argument`, `robot_description` is not set and robot_state_publisher publishes nothing.
Reported faults: luxonis/depthai-ros#411, frankarobotics/franka_description#17,
AIRLab-POLIMI/ros2-igus-rebel#2.

## Example
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="camera" params="name parent">
    <link name="${name}_link"/>
    <joint name="${name}_joint" type="fixed">
      <parent link="$(arg parent)"/>
      <child link="${name}_link"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:camera name="front" parent="base_link"/>
</robot>
```

## Use instead
```xml
<robot name="demo" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="camera" params="name parent">
    <link name="${name}_link"/>
    <joint name="${name}_joint" type="fixed">
      <parent link="${parent}"/>
      <child link="${name}_link"/>
    </joint>
  </xacro:macro>
  <link name="base_link"/>
  <xacro:camera name="front" parent="base_link"/>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import FaultKind, RobotModel
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import robots_of

ID = "xacro_param_as_arg"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf.xacro"


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        stops = _stops(robot)
        # The uses of one line, one finding (a macro call passing six of them).
        names: dict[tuple[str, int, str], dict[str, None]] = {}
        for fault in robot.faults:
            if fault.kind is FaultKind.PARAM_AS_ARG and fault.name is not None:
                key = (fault.path, fault.line, fault.message)
                names.setdefault(key, {})[fault.name] = None
        for (path, line, macro), used in names.items():
            listed = list(used)
            uses = ", ".join(f"$(arg {name})" for name in listed)
            instead = ", ".join(f"${{{name}}}" for name in listed)
            parameters = "parameter" if len(listed) == 1 else "parameters"
            # One message whether a launch file loads the file or it is linted on its
            # own, so that the two are one finding, at the launch file's level.
            yield Finding(path, line, 1,
                          f"{macro} reads its own {parameters} as {uses}: $(arg) "
                          f"reads only xacro args (the command line's and <xacro:arg>), "
                          f"never a macro's parameters, so the value a call gives is "
                          f"ignored, and where no such arg is declared xacro stops here "
                          f"(\"Undefined substitution argument\"); write {instead}",
                          severity=(Severity.ERROR
                                    if any((path, line, n) in stops for n in listed)
                                    else None))


def _stops(robot: RobotModel) -> set[tuple[str, int, str]]:
    """Where xacro provably stops on an undeclared arg, in a description a launch file
    loads, outside any undecided ``xacro:if`` (as ``xacro_error`` proves it)."""
    if robot.standalone:
        return set()
    return {(f.path, f.line, f.name) for f in robot.faults
            if f.kind is FaultKind.REFUSED and f.proven and not f.conditions
            and f.name is not None}
