"""A file has node N but not the node M that usually comes with it.

## What it does
Uses the mined `name_implication` beliefs: "a file with a static transform node named N
also has one named M". For each file that has N but no M, it reports the first node
named N. The message gives the belief's support: `n` files of mature repositories have
N, `e` of them also have M, and the z-score (p0 = 0.9). Only beliefs with z at or above
`--min-z` (default 1.0) are used.

## Why is this bad?
Node names follow the structure they describe: `link2_broadcaster` is the second of a
chain that starts with `link1_broadcaster`. A file that keeps one member of such a set
without the other has often lost a node while copying or editing, and the frame that
node published is missing from the tree.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="link2_broadcaster"
        args="0.5 0 0 0 0 0 link1 link2 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="link1_broadcaster"
        args="0 0 0.1 0 0 0 base_link link1 100"/>
  <node pkg="tf" type="static_transform_publisher" name="link2_broadcaster"
        args="0.5 0 0 0 0 0 link1 link2 100"/>
</launch>
```

## Known problems
Names are chosen freely and the same name can mean different things in different
projects; treat the message as a question. A file with a node whose name depends on an
unresolved substitution is not judged.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._may_implied import implications, name_of, name_unresolved

ID = "name_implication"
CATEGORY = Category.MAY_IMPLIED
SEVERITY = Severity.WARNING


def check(context: RuleContext) -> Iterator[Finding]:
    return implications(context, ID, name_of, name_unresolved, "node")
