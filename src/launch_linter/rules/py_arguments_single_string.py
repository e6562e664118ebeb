"""Several static transform arguments written as one argv item.

## What it does
Reports a ROS 2 `static_transform_publisher` one of whose arguments holds several words,
typically a Python launch file's `arguments=['0 0 0.2 0 0 0 base_link laser']`. Launch
passes each list item to the program as one argument and never splits it at spaces (the
same happens in XML to a quoted `'...'` part of `args`). The message gives the words the
author meant; the transform is checked as if they had been written separately.

## Why is this bad?
The program sees one argument it cannot parse and stops with "Extra unparsed arguments
on command-line" (ros2/geometry2#82), so the transform is never published.

## Example
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="laser_tf"
        args="'--z 0.2 --frame-id base_link --child-frame-id laser'"/>
</launch>
```
The usual form of the mistake, in a Python launch file:
```python
Node(package='tf2_ros', executable='static_transform_publisher',
     arguments=['--z 0.2 --frame-id base_link --child-frame-id laser'])
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="laser_tf"
        args="--z 0.2 --frame-id base_link --child-frame-id laser"/>
</launch>
```
In Python, one list item per word:
```python
Node(package='tf2_ros', executable='static_transform_publisher',
     arguments=['--z', '0.2', '--frame-id', 'base_link', '--child-frame-id', 'laser'])
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import ArgIssue, ArgIssueKind
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "py_arguments_single_string"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR


def message(issue: ArgIssue) -> str | None:
    """The diagnostic for ``issue``, or None when it is another rule's kind."""
    if issue.kind is not ArgIssueKind.SINGLE_STRING:
        return None
    (item,) = issue.words
    return (
        f"the argument {item!r} is one argv item holding {len(item.split())} words: the "
        f"program does not split it and stops with 'Extra unparsed arguments on "
        f"command-line'; give each word as its own item"
    )


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        for issue in transform.arg_issues:
            text = message(issue)
            if text is not None:
                yield finding_at(transform, text)
