"""A node given a parameter value its release does not accept.

## What it does
Reports a node's (or a ros2_control controller's) parameter whose value the node's
release for the target distribution does not accept, from the knowledge base of accepted
values (`knowledge/param_values.json`, each set read from the node's source in each
branch): nav2 AMCL's `robot_model_type` (`differential`/`omnidirectional` until
Galactic, the motion-model plugin classes `nav2_amcl::DifferentialMotionModel`/
`nav2_amcl::OmniMotionModel` from Humble on), a nav2 costmap layer's `plugin` that
nav2_costmap_2d does not declare in that release, the controller type
`joint_state_controller/JointStateController` after Foxy, and values AMCL (ROS 1 and 2)
silently replaces (`odom_model_type`, `laser_model_type`). It reports at the line that
sets the value. The parameters are read from the launch file, its parameter files, and
the parameter file a known launch file of an installed package is given (nav2_bringup's
`params_file` reaches AMCL).

Error when the distribution is known (`--ros-distro`, the `ros-distro` key, `ROS_DISTRO`
or the files) and the node refuses the value: it stops or fails to configure. Info when
the distribution is not known (naming the releases that refuse it), and for a value the
node replaces by a default of its own (it runs, on another model than the one named).

## Why is this bad?
A node that refuses its configuration does not come up, and whatever it publishes is
missing: AMCL on Humble given `robot_model_type: differential` cannot load its motion
model and never publishes `map -> odom` ("everyone going to Humble has their TurtleBot3
Nav2 example broken", ROBOTIS-GIT/turtlebot3#916); a costmap whose layer class does not
exist fails to configure, and its server with it.

## Example
```yaml
launch:
  - node:
      pkg: nav2_amcl
      exec: amcl
      name: amcl
      param:
        - name: robot_model_type
          value: differential
```

## Use instead
```yaml
launch:
  - node:
      pkg: nav2_amcl
      exec: amcl
      name: amcl
      param:
        - name: robot_model_type
          value: nav2_amcl::DifferentialMotionModel
```

## Known problems
A value set under another name by a remapping, or by a parameter file the linter cannot
read, is not checked. Where other packages may add values (pluginlib classes), only the
values of the node's own package (its class prefix) and the names other releases used
are known to be refused. A source checkout of another release in the workspace may
accept what the distribution's release refuses.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge.values import ValueFact
from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS, describe
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import finding_at_node, finding_at_param, program_of

ID = "param_value_refused"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.yaml"
EXAMPLE_DISTRO = "humble"
MAX_SHOWN = 4


def _distro_of(context: RuleContext, ros: int | None) -> str | None:
    distro = context.distro
    if (ros == 1 and distro in ROS1_DISTROS) or (ros == 2 and distro in ROS2_DISTROS):
        return distro
    return None


def _values(node: NodeRecord, facts: list[ValueFact]) -> list[tuple[str, str]]:
    """The node's parameters that some fact names, each with the value it is given last."""
    if node.kind == "controller":
        return [] if node.plugin is None else [("type", node.plugin)]
    names = [name for name in dict.fromkeys(key for key, _ in node.params)
             if any(fact.names(name) for fact in facts)]
    return [(name, node.given(name) or UNKNOWN_VALUE) for name in names]


def _accepted(fact: ValueFact) -> str:
    shown = ", ".join(fact.accepts[:MAX_SHOWN])
    more = f" and {len(fact.accepts) - MAX_SHOWN} more" if len(fact.accepts) > MAX_SHOWN else ""
    if not shown:
        return ""
    return f" (it accepts {shown}{more}{'' if fact.closed else ' and other plugins'})"


def _finding(node: NodeRecord, name: str, message: str,
             severity: Severity | None) -> Finding:
    found = (finding_at_node(node, message) if node.kind == "controller"
             else finding_at_param(node, name, message))
    return Finding(found.path, found.line, found.column, found.message, node=found.node,
                   related=found.related, severity=severity)


def check(context: RuleContext) -> Iterator[Finding]:
    knowledge = context.knowledge.values
    if not knowledge.values:
        return
    for node in context.tree.nodes:
        if node.kind not in ("node", "controller"):
            continue
        facts = knowledge.facts_for(node.ros, node.package, node.executable, node.plugin,
                                    node.kind == "controller")
        if not facts:
            continue
        distro = _distro_of(context, node.ros)
        for name, value in _values(node, facts):
            if value == UNKNOWN_VALUE:
                continue
            relevant = [f for f in facts if f.names(name)]
            program = program_of(node)
            if distro is not None:
                fact = next((f for f in relevant if distro in f.distros), None)
                if fact is None or not fact.refused(value):
                    continue
                release = f"{program}'s release for {distro.capitalize()}"
                if fact.outcome == "falls_back":
                    yield _finding(node, name, (
                        f"{release} does not know {name} '{value}'{_accepted(fact)} and uses "
                        f"'{fact.fallback}' instead: {fact.effect}"), Severity.INFO)
                else:
                    yield _finding(node, name, (
                        f"{release} does not accept {name} '{value}'{_accepted(fact)}: "
                        f"{fact.effect}"), None)
                continue
            refusing = [f for f in relevant if f.refused(value)]
            if not refusing:
                continue
            distros = tuple(d for f in refusing for d in f.distros)
            yield _finding(node, name, (
                f"{program} does not accept {name} '{value}' in {describe(distros)}"
                f"{_accepted(refusing[-1])}: {refusing[-1].effect}; set --ros-distro to "
                f"decide"), Severity.INFO)
