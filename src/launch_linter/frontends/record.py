"""The static transform record, built one way by the ROS 1 and the ROS 2 front-ends.

A front-end knows three things about a ``static_transform_publisher`` node: where it is
declared (:class:`Site`), how it is written (:class:`Command`), and what its arguments
mean (:class:`Reading`): named tuples, made for each such node and read once (a frozen
dataclass costs a call per field to make). :func:`transform_record` puts them into the
:class:`~launch_linter.model.transform.StaticTransform` the rules read, and
:func:`unresolved_message` words the ``unresolved`` problem both front-ends report for it.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import NamedTuple

from launch_linter.model.transform import (
    ArgForm,
    ArgIssue,
    Condition,
    Field,
    LaunchFormat,
    NumberIssue,
    Rotation,
    StaticTransform,
)


class Site(NamedTuple):
    """Where a node is declared (the file as shown, line, column), the root file of its
    tree, the include that brought its file in, and its presence condition."""

    path: str
    line: int
    column: int
    root: str
    included_from: tuple[str, int] | None
    condition: Condition


class Command(NamedTuple):
    """The node as written: name and namespace, package and executable, and its arguments
    (as written, as text, and as the words the program receives)."""

    name: str | None
    namespace: str
    package: str
    executable: str
    args_written: str
    args: str
    tokens: tuple[str, ...]


class Reading(NamedTuple):
    """What the arguments mean: the frames and numbers the developer intended (None where
    unknown), the form, and how the package's program reads or refuses them."""

    form: ArgForm
    parent: str | None = None
    child: str | None = None
    translation: tuple[float, float, float] | None = None
    rotation: Rotation | None = None
    period_ms: float | None = None
    arity_issue: str | None = None
    number_issues: tuple[NumberIssue, ...] = ()
    arg_issues: tuple[ArgIssue, ...] = ()


def transform_record(site: Site, command: Command, reading: Reading,
                     unresolved: Iterable[Field], reasons: Iterable[str], *,
                     ros_version: int = 1,
                     launch_format: LaunchFormat = LaunchFormat.ROS1_XML) -> StaticTransform:
    """The record of one static transform publisher."""
    return StaticTransform(
        path=site.path,
        line=site.line,
        column=site.column,
        root=site.root,
        included_from=site.included_from,
        name=command.name,
        namespace=command.namespace,
        package=command.package,
        executable=command.executable,
        args_written=command.args_written,
        args=command.args,
        tokens=command.tokens,
        parent_written=reading.parent,
        child_written=reading.child,
        translation=reading.translation,
        rotation=reading.rotation,
        period_ms=reading.period_ms,
        form=reading.form,
        arity_issue=reading.arity_issue,
        number_issues=reading.number_issues,
        condition=site.condition,
        unresolved=frozenset(unresolved),
        unresolved_reasons=tuple(reasons),
        ros_version=ros_version,
        launch_format=launch_format,
        arg_issues=reading.arg_issues,
    )


def unresolved_message(transform: StaticTransform) -> str:
    """The ``unresolved`` problem of a transform with unresolved fields."""
    reasons = transform.unresolved_reasons
    return (f"cannot resolve {', '.join(transform.unresolved_names)} statically"
            + (f": {'; '.join(reasons)}" if reasons else ""))
