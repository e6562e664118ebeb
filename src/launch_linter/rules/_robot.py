"""What the URDF structure rules share: the descriptions of a tree and how a message says
what robot_state_publisher does with a description urdfdom refuses."""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Location, Severity
from launch_linter.model.robot import FaultKind, RobotElement, RobotModel
from launch_linter.rules._api import Finding, RuleContext


def robots_of(context: RuleContext) -> tuple[RobotModel, ...]:
    return context.tree.robots


def refused(urdfdom_says: str) -> str:
    """The consequence of a description urdfdom refuses, quoting urdfdom's words (one
    message whether a launch file loads it or it is linted on its own, so that the two
    are one finding)."""
    return (f"urdfdom refuses the description (\"{urdfdom_says}\"): robot_state_publisher "
            f"stops at start-up and publishes none of its frames, and check_urdf fails")


def judged(robot: RobotModel) -> bool:
    """Whether the structure of ``robot`` is what robot_state_publisher would get: not
    when xacro refuses the source (there is no description at all then)."""
    return not any(f.kind is FaultKind.REFUSED for f in robot.faults)


def level(robot: RobotModel) -> Severity | None:
    """A structure fault is an error in a description a launch file loads; in a file
    linted on its own with its default args (which its users may override) a warning."""
    return Severity.WARNING if robot.standalone else None


def first_by_name(elements: Iterable[RobotElement]) -> dict[str, RobotElement]:
    """Each name's first element (urdfdom keeps links and joints by name)."""
    out: dict[str, RobotElement] = {}
    for element in elements:
        if element.name is not None:
            out.setdefault(element.name, element)
    return out


def where(element: RobotElement, seen_from: RobotElement) -> str:
    if element.path == seen_from.path:
        return f"line {element.line}"
    return f"{element.path}:{element.line}"


def finding_at(robot: RobotModel, element: RobotElement, message: str,
               related: Iterable[RobotElement] = ()) -> Finding:
    return Finding(element.path, element.line, element.column, message, element.name,
                   tuple(Location(r.path, r.line, r.column) for r in related),
                   severity=level(robot))


def written_place(element: RobotElement, seen: set[tuple[str, int, int]]
                  ) -> tuple[tuple[str, int, int], tuple[Location, ...]] | None:
    """Where to show ``element``: where a xacro macro wrote it, the call as related, or
    where it stands; None when that place was shown already (each call of a macro writes
    the same element again)."""
    place = element.defined or (element.path, element.line, element.column)
    if place in seen:
        return None
    seen.add(place)
    related = (() if element.defined is None
               else (Location(element.path, element.line, element.column),))
    return place, related


def close_names(name: str, known: list[str]) -> list[str]:
    """Up to three names of ``known`` close to ``name`` (a likely misspelling)."""
    # Imported here: difflib is needed only for a description with a name it lacks.
    import difflib

    return difflib.get_close_matches(name, known, n=3, cutoff=0.6)


def defined_phrase(close: list[str]) -> str:
    """`` (defined: 'a', 'b')`` for the close names a message offers, empty for none."""
    if not close:
        return ""
    return " (defined: " + ", ".join(f"'{n}'" for n in close) + ")"
