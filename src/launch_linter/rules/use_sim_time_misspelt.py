"""A node given a misspelt `use_sim_time` (`use_sime_time`, `use_simtime`): it stays on wall time.

## What it does
Reports a parameter given to a ROS 2 node whose name is one or two letters away from
`use_sim_time` (`use_sime_time`, `use_sim_tim`, `use_simtime`, `Use_sim_time`) and that
does not contain `use_sim_time` itself (`use_sim_timestep` is another parameter), unless
its value is false. It reports at the line that sets it, the node related.

## Why is this bad?
The clock a node runs on is chosen by the parameter `use_sim_time` alone (rclcpp's
`TimeSource`, rclpy's; ROS 1's global `/use_sim_time`), and parameter names are matched
exactly: a misspelt name is a parameter no node reads, so the node keeps wall time while
the file says it should follow the simulator's `/clock`. Its transforms and lookups are
then about fifty years away from the simulated ones ("Lookup would require extrapolation
into the future"), and nothing reports the typo (lbr-stack/lbr_fri_ros2_stack#4: move_group
given `use_sime_time`, "the trajectory obtained from moveit will not be executed through
gazebo (due to time synchronization)").

## Example
```xml
<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="robot_state_publisher">
    <param name="use_sime_time" value="true"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="robot_state_publisher">
    <param name="use_sim_time" value="true"/>
  </node>
</launch>
```

## Known problems
A node that declares a parameter of such a name itself is reported too (none was seen
among launch files; one node in public code declares `use_sim_times`, which the rule
leaves out as it contains `use_sim_time`). ROS 1 is left out: there the clock is the one
global `/use_sim_time`, which a node's private parameter does not set even when spelt
right. Judged sample (docs/evaluation/batch5_ros2.jsonl): every node parameter of such a
name in public code found by searching for the misspellings (`use_sime_time`,
`use_sim_tim`, `use_simtime`) and in the corpus, 5 in 5 repositories, all typos.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import UNKNOWN_VALUE
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import finding_at_param, program_of

ID = "use_sim_time_misspelt"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.xml"

SIM_TIME = "use_sim_time"
_FALSE = ("false", "False", "FALSE", "0")


def near_miss(name: str) -> bool:
    """One or two edits (a letter added, left out or changed) away from ``use_sim_time``
    and not containing it (compared in lower case: rclcpp's names are case-sensitive)."""
    lowered = name.lower()
    if SIM_TIME in lowered and lowered != SIM_TIME:
        return False
    if name == SIM_TIME or abs(len(lowered) - len(SIM_TIME)) > 2:
        return False
    return _distance(lowered, SIM_TIME) <= 2


def _distance(a: str, b: str) -> int:
    """Levenshtein distance; both strings are short (within 2 of ``use_sim_time``)."""
    row = list(range(len(b) + 1))
    for i, char_a in enumerate(a, 1):
        previous, row[0] = row[:], i
        for j, char_b in enumerate(b, 1):
            row[j] = min(previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (char_a != char_b))
    return row[-1]


def check(context: RuleContext) -> Iterator[Finding]:
    for node in context.tree.nodes:
        if node.kind != "node" or node.ros != 2:
            continue
        seen: set[str] = set()
        for key, _ in node.params:
            name = key.replace("/", ".").rsplit(".", 1)[-1]
            if key in seen or not near_miss(name):
                continue
            seen.add(key)
            value = node.given(key)
            if value is None or value in _FALSE:
                continue
            shown = "" if value == UNKNOWN_VALUE else f" ({value})"
            yield finding_at_param(node, key, (
                f"{program_of(node)} is given '{key}'{shown}, not '{SIM_TIME}': no node "
                f"reads a parameter of that name, so this one stays on wall time while "
                f"the file means it to follow the simulated clock; write '{SIM_TIME}'"))
