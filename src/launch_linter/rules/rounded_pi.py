"""An angle written as π or a fraction of it rounded to a few decimals (`1.57`, `3.14`).

## What it does
Reports a URDF joint `rpy` or a static transform's yaw, pitch or roll that is a multiple
of π/4 (π/4, π/2, 3π/4, π, …, 2π, either sign) rounded or truncated to the decimals it
was written with, when that is at least 1e-4 rad off: `1.57`, `-3.14`, `0.785`, `1.571`.
The message gives the error in radians and in millimetres at 1 m and at the child's
farthest own child frame (how far the misplaced points are). A warning when the child is a
sensor's frame (its name holds `laser`, `scan`, `lidar`, `camera`, `cam`, `optical`,
`depth`, `sonar`, `radar`, `imu`, …) and the error is 5e-4 rad or more (two decimals:
0.5 mm at 1 m and more) and no other angle of the transform is written coarser (`4.7 -1
3.14`: a rough orientation, whose rounding of π is below its own precision); info
otherwise (three decimals, a frame that places a part or a robot, a rough orientation)
from 1e-4 rad. `1.5708` (4e-6 rad) and values
computed by xacro (`${pi/2}`) are not reported. A value that rounds π/2 at
neither its rounding nor its truncation (`1.5712`) is a measured angle and not reported.

## Why is this bad?
The frame is turned by slightly less (or more) than the quarter or half turn meant, and
everything seen through it is off by the error times the distance: `1.57` is 8e-4 rad off
π/2, 0.8 mm at 1 m and 8 mm at 10 m for a lidar; `3.14` is 1.6 mm at 1 m. tf has no
tolerance for it, so point clouds of two sensors disagree and a camera's optical frame is
skewed. The exact value costs nothing.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0.2 0 0.1 1.57 0 0 base_link laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0.2 0 0.1 1.5707963 0 0 base_link laser"/>
</launch>
```
"""
from __future__ import annotations

import math
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.model.transform import RotationKind
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._tree import Edge, finding_on, written_edges

ID = "rounded_pi"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
WARNING_FROM = 5e-4
"""Radians off from which the rounding of a sensor's frame is a warning (two decimals of
π/2: 0.8 mm at 1 m)."""
SENSOR_PARTS = ("laser", "scan", "lidar", "lrf", "velodyne", "ouster", "hokuyo", "camera",
                "cam", "optical", "depth", "rgb", "kinect", "realsense", "sonar",
                "radar", "imu")
"""Parts of a frame name that make it a sensor's: what it measures is misplaced by the
error times the range (a frame that only places a part or a robot is info)."""
REPORTED_FROM = 1e-4
"""Radians off from which it is reported at all (info below ``WARNING_FROM``)."""
MAX_DECIMALS = 6
_NAMES = {1: "π/4", 2: "π/2", 3: "3π/4", 4: "π", 5: "5π/4", 6: "3π/2", 7: "7π/4", 8: "2π"}


def rounded_pi(value: float) -> tuple[str, float] | None:
    """(the fraction of π meant, radians off) when ``value`` is a multiple of π/4 rounded
    or truncated to the decimals it is written with (Python's shortest spelling of it)."""
    if not math.isfinite(value) or not 0 < abs(value) < 2.25 * math.pi:
        return None
    quarters = round(abs(value) / (math.pi / 4))
    if not 1 <= quarters <= 8:
        return None
    meant = quarters * math.pi / 4
    off = abs(abs(value) - meant)
    if off < REPORTED_FROM:
        return None
    decimals = _decimals(value)
    if not 2 <= decimals <= MAX_DECIMALS:
        return None
    scale = 10 ** decimals
    rounded = round(meant * scale) / scale
    truncated = math.floor(meant * scale) / scale
    if abs(value) not in (rounded, truncated):
        return None
    sign = "-" if value < 0 else ""
    return sign + _NAMES[quarters], off


def rounded_meaning(value: float) -> float:
    """The multiple of π/4 that ``value`` rounds."""
    return math.copysign(round(abs(value) / (math.pi / 4)) * math.pi / 4, value)


def _decimals(value: float) -> int:
    """The decimals ``value`` is written with (Python's shortest spelling; 0 for an
    integer, and more than any bound for an exponent)."""
    written = repr(abs(value))
    if "e" in written:
        return 99
    return len(written.split(".", 1)[1].rstrip("0")) if "." in written else 0


def _angles(edge: Edge) -> list[tuple[str, float]]:
    if edge.joint is not None and edge.joint.rpy is not None:
        return list(zip(("roll", "pitch", "yaw"), edge.joint.rpy))
    transform = edge.transform
    if transform is not None and transform.rotation is not None \
            and transform.rotation.kind is RotationKind.YPR:
        return list(zip(("yaw", "pitch", "roll"), transform.rotation.values))
    return []


def _farthest_child(edge: Edge, by_parent: dict[str, list[Edge]]) -> tuple[str, float] | None:
    """The child's own child frame farthest from it, from the same kind of source (the
    same description for a URDF joint), so that the message is the same in every tree."""
    best: tuple[str, float] | None = None
    for other in by_parent.get(edge.child, ()):
        if other.translation is None:
            continue
        if (other.joint is None) != (edge.joint is None):
            continue
        if other.joint is not None and edge.joint is not None \
                and other.joint.source.file != edge.joint.source.file:
            continue
        distance = math.sqrt(sum(v * v for v in other.translation))
        if best is None or distance > best[1]:
            best = (other.child, distance)
    return best


def check(context: RuleContext) -> Iterator[Finding]:
    edges = written_edges(context)
    by_parent: dict[str, list[Edge]] | None = None
    for edge in edges:
        found = [(name, value, rounded) for name, value in _angles(edge)
                 if (rounded := rounded_pi(value)) is not None]
        if not found:
            continue
        worst = max(off for _, _, (_, off) in found)
        parts = [f"{name} {value!r} is {meant} rounded ({off:.1e} rad off)"
                 for name, value, (meant, off) in found]
        at_one_metre = f"{worst * 1000:.2f} mm at 1 m"
        if by_parent is None:  # built once, when the first rounded angle is found
            by_parent = {}
            for other in edges:
                by_parent.setdefault(other.parent, []).append(other)
        farthest = _farthest_child(edge, by_parent)
        if farthest is not None and farthest[1] > 0:
            at_one_metre += (f", {worst * farthest[1] * 1000:.2f} mm at '{farthest[0]}' "
                             f"({farthest[1]:.3g} m from '{edge.child}')")
        meant = found[0][2][0].lstrip("-").replace("π", "pi")
        exact = (f"${{{meant}}}" if edge.joint is not None
                 else f"{rounded_meaning(found[0][1]):.7f}")
        finding = finding_on(
            edge,
            f"{'; '.join(parts)}: frame '{edge.child}' is turned off the "
            f"{'angle' if len(found) == 1 else 'angles'} meant, which misplaces what it "
            f"carries by {at_one_metre}; write π to full precision (e.g. {exact})",
        )
        if edge.joint is not None and edge.joint.defined is not None:
            # The angle is typed in the macro that made the joint: shown there (where
            # --fix edits it), with the call as the related place.
            path, line, column = edge.joint.defined
            finding = replace(finding, path=path, line=line, column=column,
                              related=(edge.location,))
        sensor = any(part in edge.child.lower() for part in SENSOR_PARTS)
        coarse = any(_decimals(value) < 2 for _, value in _angles(edge) if value != 0)
        warn = sensor and worst >= WARNING_FROM and not coarse
        yield replace(finding, severity=None if warn else Severity.INFO)
