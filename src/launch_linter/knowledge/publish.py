"""What a launched node publishes and looks up, by its knowledge-base entry and the
parameters the launch files give it."""

from __future__ import annotations

import re

from launch_linter.knowledge import PLACEHOLDER, EdgeSpec, Entry
from launch_linter.model.record import Record, _set
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord

MAX_TEMPLATE_DEPTH = 4
_TRUE = ("true", "1", "yes", "on")
_FALSE = ("false", "0", "no", "off", "")


class PublishedEdge(Record):
    """An edge a node publishes: frames None when unknown; ``spec`` is the entry's edge."""

    parent: str | None
    child: str | None
    role: str
    spec: EdgeSpec

    __slots__ = ("parent", "child", "role", "spec")

    def __init__(self, parent: str | None, child: str | None, role: str, spec: EdgeSpec) -> None:
        _set(self, "parent", parent)
        _set(self, "child", child)
        _set(self, "role", role)
        _set(self, "spec", spec)

    @property
    def signature(self) -> tuple[str, str] | None:
        if self.parent is None or self.child is None:
            return None
        return (self.parent, self.child)


def truth(text: str | None) -> bool | None:
    """A parameter's value as a condition: booleans, and numbers (a period of 0 turns
    publishing off); None when unknown or neither."""
    if text is None:
        return None
    word = text.strip().lower()
    if word in _TRUE:
        return True
    if word in _FALSE:
        return False
    try:
        return float(word) != 0.0
    except ValueError:
        return None


def _text(value: object) -> str | None:
    if value is None:
        return None
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


class Parameters:
    """The value of each parameter of ``entry`` for ``node``: as given, else the entry's
    default when every parameter source of the node was read, else unknown (None)."""

    def __init__(self, entry: Entry, node: NodeRecord, assume: bool = False,
                 distro: str | None = None) -> None:
        self.entry = entry
        self.node = node
        self.assume = assume
        """Whether defaults stand for parameters that an unread file may set."""
        self.distro = distro
        """The target distribution (``--ros-distro``), None when not given."""

    def value(self, name: str, depth: int = 0) -> str | None:
        given = self.node.given(name)
        if given is not None:
            return None if given == UNKNOWN_VALUE else given
        if self.entry.parameters_elsewhere:
            return None
        if self.node.unread and (not self.assume or name in self.entry.unsure_defaults):
            return None
        default = _text(self.entry.default(name))
        if default is None or depth >= MAX_TEMPLATE_DEPTH:
            return default if default is None or "{" not in default else None
        return self.fill(default, depth + 1)

    def fill(self, template: str, depth: int = 0) -> str | None:
        """``template`` with each ``{param}`` replaced; None when one is unknown."""
        unknown = False

        def replace(match: re.Match[str]) -> str:
            nonlocal unknown
            value = self.value(match.group(1), depth)
            if value is None:
                unknown = True
                return ""
            return value

        filled = PLACEHOLDER.sub(replace, template)
        return None if unknown else filled

    def holds(self, condition: str) -> bool | None:
        """Whether one ``when`` condition holds (None: unknown): ``p``, ``!p``, ``a==b``,
        ``p=text``, ``a|b``."""
        if condition.startswith("!"):
            inner = self.holds(condition[1:])
            return None if inner is None else not inner
        if "==" in condition:
            left, right = condition.split("==", 1)
            a, b = self.value(left), self.value(right)
            return None if a is None or b is None else a == b
        if "=" in condition:
            # ``p=text``: the parameter's value is that text (a device type).
            name, text = condition.split("=", 1)
            value = self.value(name)
            return None if value is None else value == text
        if "|" in condition:
            values = [truth(self.value(name)) for name in condition.split("|")]
            if any(v is True for v in values):
                return True
            return None if any(v is None for v in values) else False
        return truth(self.value(condition))

    def prefix(self) -> str | None:
        """The text put before every published frame ('' for none; None when unknown)."""
        spec = self.entry.prefix
        if spec is None:
            return ""
        if spec.enabled_by is not None:
            enabled = truth(self.value(spec.enabled_by))
            if enabled is None:
                return None
            if not enabled:
                return ""
        prefix = self.value(spec.param)
        if prefix == "" and (spec.empty_means_namespace
                             or self.distro in spec.namespace_when_empty_in):
            prefix = self.node.namespace
        if prefix is None:
            return None
        if not prefix.endswith("/"):
            prefix += "/"
        return prefix.lstrip("/")


def published(entry: Entry, node: NodeRecord, assume: bool = False,
              distro: str | None = None) -> tuple[list[PublishedEdge], list[EdgeSpec]]:
    """The edges ``node`` publishes (frames None where unknown), and the edges it may
    publish: those whose conditions are unknown. With ``assume``, the entry's defaults
    stand for parameters that an unread parameter file may set; ``distro``: the target
    distribution, where the prefix depends on it."""
    if not has_input(entry, node):
        return [], []
    params = Parameters(entry, node, assume, distro)
    prefix = params.prefix()
    sure: list[PublishedEdge] = []
    maybe: list[EdgeSpec] = []
    for spec in entry.publishes:
        states = [params.holds(c) for c in spec.when]
        if any(s is False for s in states):
            continue
        if any(s is None for s in states):
            maybe.append(spec)
            continue
        parent, child = _frame(params.fill(spec.parent)), _frame(params.fill(spec.child))
        if prefix is None:
            parent = child = None
        elif prefix:
            parent = None if parent is None else prefix + parent
            child = None if child is None else prefix + child
        sure.append(PublishedEdge(parent, child, spec.role, spec))
    return sure, maybe


def _is_input(pattern: str, name: str) -> bool:
    if pattern.endswith("#"):
        stem = pattern[:-1]
        return name.startswith(stem) and name[len(stem):].isdigit()
    return name == pattern


def has_input(entry: Entry, node: NodeRecord) -> bool:
    """False when the node provably lacks the input it needs before publishing (every
    parameter source read, none of ``entry.inputs`` set): robot_localization's filter
    publishes nothing before its first measurement, and it measures only the topics its
    ``odom0``, ``imu0``... parameters name."""
    if not entry.inputs or node.unread or entry.parameters_elsewhere:
        return True
    return any(_is_input(pattern, key) for key, _ in node.params for pattern in entry.inputs)


def _frame(text: str | None) -> str | None:
    """A frame id as tf compares it (one leading ``/`` dropped, as for launch edges)."""
    if text is None or not text.strip("/"):
        return None
    return text[1:] if text.startswith("/") else text


def listed_parameters(entry: Entry, node: NodeRecord) -> list[str]:
    """The parameters of ``node`` that name frames through a list (``looks_up_listed``):
    for each parameter given that is named like a list pattern, each whitespace-separated
    item of its value names a sub-namespace beside it, whose frame parameter is one
    (``global_costmap/observation_sources: scan`` names
    ``global_costmap/scan/sensor_frame``)."""
    separator = "." if node.ros == 2 else "/"
    out: dict[str, None] = {}  # ordered and without repeats: a list may be long
    for pattern, frame in entry.looks_up_listed:
        wanted = pattern.split("/")
        for name, value in node.params:
            parts = name.split(separator)
            if value == UNKNOWN_VALUE or len(parts) != len(wanted) or not all(
                    w in ("*", p) for w, p in zip(wanted, parts)):
                continue
            for item in value.split():
                out[separator.join([*parts[:-1], item, frame])] = None
    return list(out)


def lookup_templates(entry: Entry, node: NodeRecord) -> tuple[str, ...]:
    """The frames ``node`` looks up, as templates: the entry's ``looks_up`` and one
    ``{param}`` per parameter a list names (:func:`listed_parameters`)."""
    return entry.looks_up + tuple("{" + name + "}" for name in listed_parameters(entry, node))


def frames_named(entry: Entry, node: NodeRecord, templates: tuple[str, ...],
                 assume: bool = False) -> list[tuple[str, str]]:
    """The known frames that ``templates`` (``looks_up``, ``camera_frames``) name, as
    written, each with the parameter that names it (or the template)."""
    params = Parameters(entry, node, assume)
    out: list[tuple[str, str]] = []
    for template in templates:
        frame = params.fill(template)
        if frame:
            names = PLACEHOLDER.findall(template)
            out.append((frame, names[0] if len(names) == 1 else template))
    return out
