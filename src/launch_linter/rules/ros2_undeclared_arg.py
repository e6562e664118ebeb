"""A ROS 2 launch configuration read but never declared: `ros2 launch` stops there.

## What it does
Reports a `LaunchConfiguration('x')` (Python), `$(var x)` (XML and YAML) or
`context.launch_configurations['x']` read without a default where no
`DeclareLaunchArgument`/`<arg>`/`arg:` of the launch tree declares `x`, no
`SetLaunchConfiguration`/`<let>` sets it and no include passes it. A declaration made in
Python but never added to the `LaunchDescription` declares nothing. Every substitution an
action performs counts: a node's parameters and remappings as much as its name, a
condition, an `OpaqueFunction`'s `perform(context)`. A read with a default
(`LaunchConfiguration('x', default='0')`, `$(var x 0)`), `LaunchConfigurationEquals` and
`context.launch_configurations.get('x')` never fail and are not reported.

It is an error when the file is launched on its own. It is an info when the read is
under a condition the linter cannot decide, when the tree holds something the linter
does not follow (an include it cannot resolve, an `OpaqueFunction` or launch arguments
it does not read) that could set the configuration, or when another launch file of the
package names the file, which then is (also) an included file whose includer may pass
the argument (that includer, linted as its own root, reports the read if it does not).

## Why is this bad?
`LaunchConfiguration.perform` raises "launch configuration 'x' does not exist" and
`ros2 launch` stops before it starts the nodes after it. `ros2 launch pkg file x:=1`
would set it, but `--show-args` does not list an undeclared argument, so nobody knows to
give it. A misspelt name (`use_sim_tim`) or a declaration left out of the description
are the usual causes.

## Example
```xml
<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="use_sim_time" value="$(var use_sim_time)"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="use_sim_time" default="false"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="use_sim_time" value="$(var use_sim_time)"/>
  </node>
</launch>
```
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.launch import UndeclaredUse
from launch_linter.rules._api import Finding, RuleContext, summarised

ID = "ros2_undeclared_arg"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.xml"


def _doubt(use: UndeclaredUse) -> str | None:
    """Why the read may not fail after all; None when nothing could set it."""
    if use.included_by is not None:
        return (f"unless it is given: {use.root} is also included from {use.included_by}, "
                f"which may pass it")
    if use.open_reason is not None:
        return f"unless something the linter does not follow sets it ({use.open_reason})"
    if use.conditional:
        return "when the condition it is read under holds"
    return None


def message(uses: list[UndeclaredUse]) -> str:
    """One place's reads (same root, same doubt), worded once."""
    first = uses[0]
    doubt = _doubt(first)
    names = summarised([f"'{use.name}'" for use in uses])
    what = (f"launch configuration {names[0]} is" if len(uses) == 1
            else f"launch configurations {', '.join(names)} are")
    misspelt = [f"'{use.similar}' for '{use.name}'" for use in uses if use.similar is not None]
    fix = "declare it with a default, or give the read one" if len(uses) == 1 else (
        "declare them with defaults, or give the reads one")
    if misspelt:
        fix = f"did you mean {', '.join(summarised(misspelt))} (declared)?"
    return (f"{what} read without a default but never declared, set or passed in this "
            f"launch tree: ros2 launch of {first.root} stops with \"launch configuration "
            f"'{first.name}' does not exist\"" + ("" if doubt is None else f" {doubt}")
            + f"; {fix}")


def check(context: RuleContext) -> Iterator[Finding]:
    if context.study:
        return
    places: dict[tuple[str, int, int, str | None], list[UndeclaredUse]] = {}
    for use in context.tree.undeclared:
        places.setdefault((use.path, use.line, use.column, _doubt(use)), []).append(use)
    for (path, line, column, doubt), uses in places.items():
        yield Finding(path, line, column, message(uses),
                      severity=None if doubt is None else Severity.INFO)
