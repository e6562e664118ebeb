"""What roslaunch checks in attribute and parameter values, and small helpers of the
ROS 1 loader on values and conditions."""

from __future__ import annotations

import os

from launch_linter.model.transform import Condition
from launch_linter.resolve.substitution import to_bool
from launch_linter.resolve.value import Value, holes, resolved_text

_UNCHECKED_PARAM_TYPES = ("str", "string", "auto", "yaml")
"""The ``<param>`` types whose values roslaunch takes as they are (YAML is not checked)."""


def _bool_attribute(value: str, label: str) -> str | None:
    """roslaunch's strict booleans (``respawn``, ``required`` …): the error, if any."""
    if value.lower() in ("true", "false"):
        return None
    if not value:
        return f"bool value for {label} must be non-empty"
    return f"invalid bool value for {label}: {value}"


def _reasons(value: Value) -> str:
    """The substitutions that leave ``value`` unresolved, with why; "" when resolved."""
    return "; ".join(f"{h.text}: {h.reason}" for h in holes(value))


def _single_command(text: str) -> bool:
    """Whether ``text`` is one ``$(arg …)``-like substitution, not an ``$(eval)``."""
    return (text.startswith("$(") and text.endswith(")") and text.count("$(") == 1
            and not text.startswith("$(eval "))


def _conjoin(outer: Condition, inner: Condition) -> Condition:
    # ``literals`` read directly (``always`` is a property: a call), for every node and
    # transform.
    return outer if not inner.literals else inner if not outer.literals else outer & inner


def _is_int(text: str) -> bool:
    try:
        int(text)
    except ValueError:
        return False
    return True


def _test_limit_problems(values: dict[str, Value]) -> list[str]:
    """What roslaunch's ``_test_attrs`` refuses: ``float(time-limit)`` must work and be
    positive, ``int(retry)`` must work (empty values are not checked)."""
    problems: list[str] = []
    limit = resolved_text(values["time-limit"]) if "time-limit" in values else None
    if limit:
        try:
            if float(limit) <= 0.0:
                problems.append("'time-limit' must be a positive number")
        except ValueError:
            problems.append(f"'time-limit' must be a number: [{limit}]")
    retry = resolved_text(values["retry"]) if "retry" in values else None
    if retry:
        try:
            int(retry)
        except ValueError:
            problems.append(f"'retry' must be a number: [{retry}]")
    return problems


def _checkable_path(written: str, path: str) -> bool:
    """Whether a missing file means the same on every machine: an absolute path found
    through ``$(find pkg)`` (the package exists) or ``$(dirname)``."""
    return os.path.isabs(path) and ("$(find " in written or "$(dirname)" in written)


def rosparam_body_problem(text: str, has_param: bool) -> str | None:
    """What roslaunch's ``load_rosparam`` refuses in a ``<rosparam>`` body: a YAML value
    that is not a mapping, without ``param=``."""
    if has_param or yaml_root_kind(text) != "other":
        return None
    return "'param' attribute must be set for non-dictionary values"


def yaml_root_kind(text: str) -> str | None:
    """Whether a YAML document's root is a ``mapping``, ``other`` (a sequence or a
    scalar), or None when that is not plain from its first lines (tags, anchors, block
    scalars, several documents, or nothing at all). Standard library only, and never a
    guess: the core does not depend on PyYAML, and a body it cannot classify is left
    alone."""
    lines = []
    for raw in text[:100_000].splitlines():
        stripped = raw.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if stripped.startswith(("%", "---", "...")):
            return None
        lines.append(raw)
    if not lines:
        return None  # empty: roslaunch takes it as {}
    first = lines[0].strip()
    if first[0] in "!&*|>?@`":
        return None
    if first.startswith("{"):
        return "mapping"
    if first.startswith("[") or first == "-" or first.startswith(("- ", "-\t")):
        return "other"
    key_end = _plain_key_end(first)
    if key_end is not None:
        return "mapping"
    if any(_plain_key_end(line.strip()) is not None for line in lines[1:]):
        return None  # not a plain single value: YAML may refuse it; leave it
    return "other"


def _plain_key_end(line: str) -> int | None:
    """Where a ``key:`` ends on a line (``: ``, ``:\t`` or ``:`` at its end, outside
    quotes), or None."""
    quote = ""
    index = 0
    if line[:1] in "'\"":
        quote = line[0]
        index = 1
        while index < len(line):
            if line[index] == quote:
                if quote == "'" and line[index + 1:index + 2] == "'":
                    index += 2
                    continue
                break
            index += 2 if quote == '"' and line[index] == "\\" else 1
        index += 1
        rest = line[index:].lstrip()
        return index if rest.startswith(":") and (rest == ":" or rest[1] in " \t") else None
    for index, char in enumerate(line):
        if char == "#" and index and line[index - 1] in " \t":
            return None
        if char == ":" and (index + 1 == len(line) or line[index + 1] in " \t"):
            return index
    return None


def _is_positive_number(text: str) -> bool:
    try:
        return float(text) > 0.0
    except ValueError:
        return False


def _param_value_problem(value: str, param_type: str) -> str | None:
    """What roslaunch's ``convert_value`` refuses (YAML is not checked)."""
    kind = param_type.lower().strip()
    if kind in _UNCHECKED_PARAM_TYPES:
        return None
    try:
        if kind == "int":
            int(value)
        elif kind == "double":
            float(value)
        elif kind in ("bool", "boolean"):
            to_bool((value,))
        else:
            return f"Unknown type '{kind}'"
    except ValueError as exc:
        return str(exc)
    return None
