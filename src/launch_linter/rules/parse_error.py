"""The file is not a well-formed launch file.

## What it does
Reports a file that cannot be read as XML (syntax errors, bytes that are not text, a DTD
entity declaration, nesting deeper than 200 elements, more than 8 MiB), or whose root
element is not `<launch>`. The linter never expands entities or fetches anything. A tag
left without its `>` (`</group` and then `<node` on a later line) is reported where the
tag starts; expat stops at the next `<`, which the message names too.

## Why is this bad?
roslaunch refuses the whole file, so none of its transforms are published.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="a" args="0 0 0 0 0 0 map odom 100">
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="a" args="0 0 0 0 0 0 map odom 100"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "parse_error"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
