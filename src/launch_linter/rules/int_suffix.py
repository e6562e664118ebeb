"""A gap in a series of names or frames that end in an integer.

## What it does
In each file, groups the static transforms' node names by stem (the name without its
trailing integer), and does the same, separately, for parent frames and for child frames.
When a stem has at least two distinct suffixes and fewer integers are missing between the
smallest and the largest than are present, the missing ones are reported: `tf1`, `tf1`,
`tf3` reports `tf2`. Sparse series such as AprilTag ids (`tag_8`, `tag_17`, `tag_26`) are
not reported, and different stems are never pooled (`cam1` and `laser3` say nothing about
`cam2`).

## Why is this bad?
Numbered sensors, wheels and markers are usually declared as a block copied line by line.
A missing number often means a line was lost, or a copy kept its old number (two `tf1`,
no `tf2`), so one device has no transform or two transforms.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="sonar_tf1"
        args="0.2 0.1 0 0.5 0 0 base_link sonar1"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="sonar_tf3"
        args="0.2 -0.1 0 -0.5 0 0 base_link sonar3"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="sonar_tf1"
        args="0.2 0.1 0 0.5 0 0 base_link sonar1"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="sonar_tf2"
        args="0.2 -0.1 0 -0.5 0 0 base_link sonar2"/>
</launch>
```

## Known problems
A series can skip a number on purpose (a removed sensor); a name built from an unresolved
substitution that starts with the stem makes the stem's series unknown, and it is not
reported.
"""
from __future__ import annotations

import re
from collections.abc import Callable, Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import Record, _set
from launch_linter.model.transform import Field, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at, transforms_by_file

ID = "int_suffix"
CATEGORY = Category.MAY_SEMANTIC
SEVERITY = Severity.INFO

# At most 18 digits: a longer run is no numbering anybody wrote by hand, and Python refuses
# to read an integer of more than 4,300 digits (and reads long ones in quadratic time).
_SUFFIXED = re.compile(r"^(?P<stem>.*\D)(?P<number>\d{1,18})$")
# Our stand-in for $(anon id) numbers anonymous names itself; those numbers mean nothing.
_SYNTHETIC_STEM = "_anon"
MAX_LISTED = 6


class _Kind(Record):
    label: str
    field: Field
    value: Callable[[StaticTransform], str | None]

    __slots__ = ("label", "field", "value")

    def __init__(
        self,
        label: str,
        field: Field,
        value: Callable[[StaticTransform], str | None],
    ) -> None:
        _set(self, "label", label)
        _set(self, "field", field)
        _set(self, "value", value)


KINDS = (
    _Kind("node names", Field.NAME, lambda t: t.name),
    _Kind("parent frames", Field.PARENT, lambda t: t.parent),
    _Kind("child frames", Field.CHILD, lambda t: t.child),
)


def _spell(stem: str, number: int, width: int) -> str:
    return f"{stem}{number:0{width}d}"


def _listed(values: list[str]) -> str:
    if len(values) <= MAX_LISTED:
        return ", ".join(values)
    return ", ".join(values[: MAX_LISTED - 1]) + f", ... {values[-1]}"


def _series(
    transforms: list[StaticTransform], kind: _Kind
) -> dict[str, dict[int, tuple[str, StaticTransform]]]:
    """stem -> suffix -> (spelling, first transform), over resolved values."""
    series: dict[str, dict[int, tuple[str, StaticTransform]]] = {}
    for transform in transforms:
        value = kind.value(transform)
        # Most values do not end in a digit: no pattern to try (isdigit() holds for every
        # character \d matches).
        if value is None or not value[-1:].isdigit() or transform.is_unresolved(kind.field):
            continue
        match = _SUFFIXED.match(value)
        if match is None or match["stem"].endswith(_SYNTHETIC_STEM):
            continue
        numbers = series.setdefault(match["stem"], {})
        numbers.setdefault(int(match["number"]), (value, transform))
    return series


def _unresolved_values(transforms: list[StaticTransform], kind: _Kind) -> list[str]:
    """Written values that are not resolved: any stem they start with is unknown."""
    return [
        value
        for t in transforms
        if t.is_unresolved(kind.field) and (value := kind.value(t)) is not None
    ]


def check(context: RuleContext) -> Iterator[Finding]:
    for transforms in context.shared(transforms_by_file).values():
        if len(transforms) < 2:
            continue  # a series has two numbers at least
        for kind in KINDS:
            blocked = _unresolved_values(transforms, kind)
            for stem, numbers in _series(transforms, kind).items():
                if len(numbers) < 2 or any(text.startswith(stem) for text in blocked):
                    continue
                present = sorted(numbers)
                # Counted before the gap is listed: "frame_1" and "frame_999999999" must not
                # make a range of a billion numbers.
                gaps = present[-1] - present[0] + 1 - len(present)
                if not gaps or gaps >= len(present):
                    continue
                missing = sorted(set(range(present[0], present[-1] + 1)) - set(present))
                spellings = [numbers[n][0] for n in present]
                width = min(len(s) - len(stem) for s in spellings)
                padded = any(s[len(stem)] == "0" and len(s) > len(stem) + 1 for s in spellings)
                gap = [_spell(stem, n, width if padded else 0) for n in missing]
                after = min(n for n in present if n > missing[0])
                before = max(n for n in present if n < missing[0])
                yield finding_at(numbers[after][1],
                    f"{kind.label} {_listed(spellings)} skip {_listed(gap)}: "
                    f"a transform of the series may be missing or misnumbered",
                    (numbers[before][1],),
                )
