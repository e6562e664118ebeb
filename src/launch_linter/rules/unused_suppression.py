"""A `launch-linter:` suppression comment that suppresses nothing.

## What it does
Reports each rule named in a `<!-- launch-linter: disable=… -->` comment (or a `#` comment
in YAML and Python launch files) that silenced no diagnostic: `disable=` covers the next
element (the first one that starts on a later line than the comment ends), `disable-file=`
the whole file. It also reports unknown rule ids in a directive and comments that start
with `launch-linter:` but are not a directive. Rules that did not run (`--select`,
`--ignore`) are not reported, since whether they would have matched is unknown.

## Why is this bad?
A stale suppression hides nothing today but will hide a real mistake tomorrow, and a
misspelt rule id silences nothing at all while looking as if it did.

## Example
```xml
<launch>
  <!-- launch-linter: disable=dup_sig -->
  <node pkg="tf2_ros" type="static_transform_publisher" name="base_to_laser"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="base_to_laser"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext

ID = "unused_suppression"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.INFO


def check(context: RuleContext) -> Iterable[Finding]:
    # Whether a suppression is used depends on every other rule's diagnostics, so the
    # engine reports these after all rules ran (``suppressions.apply_suppressions``).
    return ()
