"""A ROS 2 node given a parameter file whose path is empty or names no file.

## What it does
Reports a parameter file in a ROS 2 node's `parameters=[...]` (or `<param from=...>`)
whose path resolves to the empty text (a launch argument left at an empty default that
the includer does not give), or to a file that is provably absent: under a package found
in the linted paths no install rule provides it, or under the linted tree it is not
there. It reports at the substitution that gives the path (`LaunchConfiguration(...)`),
the node and the argument's declaration related. A path left empty by the *root* file's
own argument (usually given on the command line), or under a condition, is only
`unresolved`.

## Why is this bad?
launch_ros turns each path into a `pathlib.Path` and, when it is not a file, logs
"Parameter file path is not a file" and leaves it out of the node's command line
(launch_ros/actions/node.py `_perform_substitutions`, the same in every branch from foxy
to rolling; an empty path is the current folder). The node starts without any of the
file's parameters: on its defaults (frames, `publish_tf`), or it stops when it needs
them. chvmp/champ#103: the include left `links_map_path` and two others at `''`, and
`quadruped_controller_node` and `state_estimation_node` died ("No links config file
provided").

## Example
```python
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="champ_base", executable="state_estimation_node",
             parameters=[os.path.join(os.path.dirname(__file__), "link.yaml")]),
    ])
```

```yaml
/**:
  ros__parameters:
    base: base_link
```

## Use instead
```python
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="champ_base", executable="state_estimation_node",
             parameters=[os.path.join(os.path.dirname(__file__), "links.yaml")]),
    ])
```

```yaml
/**:
  ros__parameters:
    base: base_link
```

## Known problems
A relative path depends on the folder `ros2 launch` runs in and is not judged; a path
outside the linted paths and every package found is unknown, not absent. A ROS 1
`<rosparam file=...>` that is empty or missing is `roslaunch_error` (roslaunch refuses
the whole launch).
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_param_file_missing"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"
EXAMPLE_INCLUDED = "links.yaml"
"""The parameter file the documented example names (misspelt) and its fix names."""


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
