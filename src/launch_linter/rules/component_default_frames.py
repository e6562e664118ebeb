"""A static transform component left with its default frames `/frame` and `/child`.

## What it does
Reports a `tf2_ros::StaticTransformBroadcasterNode` composable node (`ComposableNode` in
Python, `<composable_node>` in XML or YAML) that is not given a `frame_id` or a
`child_frame_id` parameter. The component then uses its defaults, `/frame` and
`/child`. Parameters read from a file the linter does not open are not reported.

## Why is this bad?
The component publishes a transform between frames that nothing else uses (and whose
leading `/` tf2 rejects on lookup), while the frames that were meant stay unconnected.

## Example
```xml
<launch>
  <node_container pkg="rclcpp_components" exec="component_container" name="tf_container"
                  namespace="">
    <composable_node pkg="tf2_ros" plugin="tf2_ros::StaticTransformBroadcasterNode"
                     name="laser_tf">
      <param name="translation.z" value="0.2"/>
    </composable_node>
  </node_container>
</launch>
```

## Use instead
```xml
<launch>
  <node_container pkg="rclcpp_components" exec="component_container" name="tf_container"
                  namespace="">
    <composable_node pkg="tf2_ros" plugin="tf2_ros::StaticTransformBroadcasterNode"
                     name="laser_tf">
      <param name="translation.z" value="0.2"/>
      <param name="frame_id" value="base_link"/>
      <param name="child_frame_id" value="laser"/>
    </composable_node>
  </node_container>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import ArgIssue, ArgIssueKind
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "component_default_frames"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR


def message(issue: ArgIssue) -> str | None:
    """The diagnostic for ``issue``, or None when it is another rule's kind."""
    if issue.kind is not ArgIssueKind.DEFAULT_FRAMES:
        return None
    parent, child = issue.others
    return (
        f"no {' or '.join(issue.words)} parameter: the component publishes "
        f"'{parent}' -> '{child}' (its defaults are '/frame' and '/child')"
    )


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        for issue in transform.arg_issues:
            text = message(issue)
            if text is not None:
                yield finding_at(transform, text)
