"""Something roslaunch itself refuses to load.

## What it does
Reports what makes roslaunch stop with an error while loading a launch tree: an unknown
substitution, `if` and `unless` on one tag, a condition that is not `true`/`false`/`1`/`0`,
an arg declared twice or overridden, include args that are unused or have no value, a
missing or cyclic include, a node name with a namespace in it, a `<test>` whose
`time-limit` is not a positive number or whose `retry` is not an integer, a `<rosparam>`
whose `file` is empty or missing under a package found with `$(find)` (or under
`$(dirname)`), a `<rosparam>` file or body that is not valid YAML (loader.py's
`load_rosparam`: "contains invalid YAML"; judged on the syntax only, without
`subst_value`), and a `<rosparam>` body that is not a mapping without `param=`. The
linter goes on after each, so one run shows every such problem instead of roslaunch's
first.

## Why is this bad?
roslaunch refuses to start the whole launch tree, so nothing in it runs.

## Example
```xml
<launch>
  <arg name="rate" default="100"/>
  <arg name="rate" default="50"/>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="rate" default="100"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._refusals import refusal_findings

ID = "roslaunch_error"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterable[Finding]:
    return refusal_findings(context, ID)
