"""ROS 1 launch XML to static transforms, with roslaunch's loading rules.

The walk follows ``roslaunch.xmlloader`` tag by tag: the same tags, the same attributes
resolved in the same order and in the same context (which matters for ``$(anon)``
numbering and for the errors roslaunch raises), ``<arg>`` scoping (groups copy, includes
see only what is passed), ``if``/``unless``, namespaces and ``<include>``. Where
roslaunch would stop with an error we record a ``roslaunch_error`` diagnostic and go on;
where a value cannot be known statically it becomes a hole, and the transform stays in
the output marked unresolved, with its presence condition. Nothing is executed or read
on behalf of the launch file except the files it includes.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field

from launch_linter.decode import decode_ros1, is_number
from launch_linter.frontends.robot.describe import RobotCache
from launch_linter.frontends.robot.sources import (
    DESCRIPTION_PARAM,
    FRAME_NODE_PACKAGES,
    FRAME_PARAMS,
    from_ros1_param,
    is_description_name,
    params_from_yaml,
    with_node_params,
)
from launch_linter.frontends.tokens import split_args
from launch_linter.model.budget import Budget, BudgetExceeded
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.launch import Comment, FileStatus, LaunchTree, holds_directive
from launch_linter.model.robot import UNKNOWN_VALUE, DescriptionSource, NodeRecord
from launch_linter.model.transform import (
    ALWAYS,
    DECODED_FIELDS,
    ArgForm,
    Condition,
    ConditionLiteral,
    Field,
    StaticTransform,
)
from launch_linter.resolve.packages import PackageIndex
from launch_linter.resolve.substitution import (
    SubstitutionError,
    SubstitutionScope,
    resolve,
    to_bool,
)
from launch_linter.resolve.value import Hole, Value, holes, resolved_text, text_of
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml, read_launch_bytes

STATIC_TF_TYPE = "static_transform_publisher"
TF_PACKAGES = ("tf", "tf2_ros")
MAX_INCLUDE_DEPTH = 32
MAX_NESTING = 100
"""Most ``<group>``/``<include>`` levels followed, all files of a tree together."""
MAX_FILES_PER_TREE = 2_000

_NAME_LEGAL = re.compile(r"[~/A-Za-z][\w/]*\Z")
_COLLAPSE_SLASHES = re.compile("//+")

# Attributes roslaunch resolves for each tag, in its order (after ``if``/``unless``).
_ARG_ATTRS = ("name", "value", "default", "doc")
_NODE_LATE_ATTRS = ("machine", "args", "output", "respawn", "respawn_delay", "cwd",
                    "launch-prefix", "required")
_PARAM_VALUE_ATTRS = ("value", "textfile", "binfile", "command")
_ROSPARAM_ATTRS = ("command", "ns", "file", "param", "subst_value")
_MACHINE_OLD_ATTRS = ("ros-root", "ros-package-path", "ros-ip", "ros-hostname")
_MACHINE_ATTRS = ("env-loader", "ssh-port", "user", "password", "default", "timeout")
_UNCHECKED_PARAM_TYPES = ("str", "string", "auto", "yaml")
"""The ``<param>`` types whose values roslaunch takes as they are (YAML is not checked)."""


def relative_to_cwd(path: str) -> str:
    """``os.path.relpath(path)``, quicker for the usual case of a path below the cwd."""
    folder = os.getcwd()
    if path.startswith(folder) and path[len(folder):len(folder) + 1] == os.sep:
        return os.path.normpath(path[len(folder) + 1:])
    return os.path.relpath(path)


_VALUE_ERRORS = ("Invalid <param> tag", "included file not found", "<group> tag has an empty",
                 "<node> tag has an empty", "cannot turn")
"""Errors about a value that may come from the environment (a syntax error never does)."""
_ENV_REFERENCE = re.compile(r"\$\((optenv|env|arg)\s+([^\s)]+)")
"""``$(optenv NAME ...)``, ``$(env NAME)``, ``$(arg NAME)`` in attribute text."""


@dataclass(frozen=True, slots=True)
class LoadOptions:
    """What the command line tells the loader."""

    args: Mapping[str, str] = field(default_factory=dict)
    env: Mapping[str, str] = field(default_factory=dict)
    packages: PackageIndex = field(default_factory=lambda: PackageIndex([]))
    display_path: Callable[[str], str] = relative_to_cwd
    study_errors: bool = False
    """True (the ``study`` profile): report as ``roslaunch_error``, as the study counted
    them, what the default reports as ``unresolved`` info because the file alone cannot
    decide it: an error whose cause depends on the environment (``$(optenv)``/``$(env)``
    not given with ``--env``, a ``~`` path in ROS 2)."""
    ros_version: int | None = None
    """1 or 2 to read an XML root file as that ROS's launch XML; None: by its content."""
    robots: RobotCache | None = None
    """Robot descriptions expanded in this run (None: a new cache per tree)."""


class _AnonNames:
    """roslaunch's anonymous names, made stable: ``id_anon<N>``, N counted per root."""

    def __init__(self) -> None:
        self.count = 0

    def make(self, table: dict[str, str], anon_id: str) -> str:
        if anon_id not in table:
            self.count += 1
            table[anon_id] = f"{anon_id}_anon{self.count}"
        return table[anon_id]


class _Context:
    """roslaunch's ``LoaderContext``, plus what static resolution needs to know."""

    __slots__ = ("anon", "arg_names", "args", "chain", "condition", "depth", "filename",
                 "include_args", "included_from", "ns", "ns_unresolved", "open_args",
                 "pass_all_args", "scope", "side_scope")

    def __init__(self, ns: str, filename: str, args: dict[str, Value], open_args: bool) -> None:
        self.ns = ns
        self.ns_unresolved = ""
        """Why the namespace is unknown (the blocking substitutions); empty when known."""
        self.filename = filename
        self.args = args
        self.open_args = open_args
        """Whether args the linter does not know may be set (the root's command line)."""
        self.arg_names: dict[str, bool] = {}
        """Args declared here; the value says whether under an unresolved condition."""
        self.anon: dict[str, str] = {}
        self.condition = ALWAYS
        self.chain: tuple[str, ...] = (filename,)
        self.included_from: tuple[str, int] | None = None
        self.pass_all_args = False
        self.include_args: dict[str, Value] | None = None
        self.depth = 0
        self.scope: SubstitutionScope | None = None
        """Made on first use; it reads ``args`` and ``anon`` live, so only a change of
        file or of those dicts themselves resets it."""
        self.side_scope: tuple[dict[str, str], SubstitutionScope] | None = None
        """The last scope made for another anonymous-name table (a node's children)."""

    def copy(self) -> _Context:
        """A child context: roslaunch deep-copies args and anonymous names."""
        child = _Context(self.ns, self.filename, dict(self.args), self.open_args)
        child.ns_unresolved = self.ns_unresolved
        child.arg_names = dict(self.arg_names)
        child.anon = dict(self.anon)
        child.condition = self.condition
        child.chain = self.chain
        child.included_from = self.included_from
        child.pass_all_args = self.pass_all_args
        child.include_args = self.include_args
        child.depth = self.depth
        return child


def make_global_ns(ns: str) -> str:
    if ns.startswith("~"):
        raise ValueError(f"cannot turn [{ns}] into a global name")
    if not ns.startswith("/"):
        ns = "/" + ns
    return ns if ns.endswith("/") else ns + "/"


def ns_join(ns: str, name: str) -> str:
    if name.startswith(("/", "~")):
        return name
    if ns == "~":
        return "~" + name
    if not ns:
        return name
    return ns + name if ns.endswith("/") else ns + "/" + name


def _is_legal_name(name: str) -> bool:
    """rosgraph's ``is_legal_name`` (the empty name is legal)."""
    return name == "" or (_NAME_LEGAL.match(name) is not None and "//" not in name)


def _canonical_name(name: str) -> str:
    if not name or name == "/" or ("//" not in name and name[-1] != "/"):
        return name
    canonical = "/".join(x for x in name.split("/") if x)
    return "/" + canonical if name.startswith("/") else canonical


def _bool_attribute(value: str, label: str) -> str | None:
    """roslaunch's strict booleans (``respawn``, ``required`` …): the error, if any."""
    if value.lower() in ("true", "false"):
        return None
    if not value:
        return f"bool value for {label} must be non-empty"
    return f"invalid bool value for {label}: {value}"



class Ros1Loader:
    """Loads one root file (and its includes) into a :class:`LaunchTree`."""

    def __init__(self, options: LoadOptions) -> None:
        self.options = options
        self.transforms: list[StaticTransform] = []
        self.problems: list[Problem] = []
        self.files: list[str] = []
        self.comments: list[Comment] = []
        self.element_lines: list[tuple[str, int]] = []
        self.descriptions: list[DescriptionSource] = []
        self.nodes: list[NodeRecord] = []
        self.node_params: list[tuple[str, str]] = []
        """Frame parameters set beside a node (``NODE/param``): full name, value."""
        self.anon = _AnonNames()
        self.root_display = ""
        self.node_names: dict[str, tuple[str, Element]] = {}
        """Resolved node name -> (file, element) of its first node."""
        self._displays: dict[str, str] = {}
        self._missing_reported: set[tuple[str, str]] = set()
        self._element: Element | None = None
        self._env_args: dict[str, str] = {}
        """Args whose value comes from the environment -> the substitution it comes from."""
        """The element whose attribute is being resolved (for errors found meanwhile)."""
        self.budget = Budget()
        self._path = ""
        """The file being walked (where the budget ran out, if it does)."""

    # -- diagnostics -------------------------------------------------------------------
    def _report(
        self, rule: str, path: str, element: Element | None, message: str,
        node: str | None = None, related: tuple[Location, ...] = (),
    ) -> None:
        line, column = (element.line, element.column) if element else (1, 1)
        self.problems.append(
            Problem(rule, self._display(path), line, column, message, node, related)
        )

    def _error(self, context: _Context, element: Element | None, message: str) -> None:
        source = (
            None if element is None or self.options.study_errors
            or not message.startswith(_VALUE_ERRORS) else self._env_source(element)
        )
        if source is not None:
            self._report("unresolved", context.filename, element,
                         f"{message}, but the value depends on the environment ({source}): "
                         f"not checked (give it with --env)")
            return
        self._report("roslaunch_error", context.filename, element, message)

    def _env_source(self, element: Element) -> str | None:
        """The environment substitution (or home path) one of the element's attributes
        depends on, directly or through an ``$(arg)``; None when there is none."""
        for text in element.attrib.values():
            found = self._env_in_text(text)
            if found is not None:
                return found
        return None

    def _env_in_text(self, text: str) -> str | None:
        # A leading "~" is a private name here, not a home directory: roslaunch expands no
        # "~" in paths, and $(env HOME) without --env is already unresolved.
        if "$(" not in text:
            return None
        for match in _ENV_REFERENCE.finditer(text):
            command, name = match.group(1), match.group(2)
            if command == "arg":
                if name in self._env_args:
                    return self._env_args[name]
            elif name not in self.options.env:
                return f"$({command} {name})"
        return None

    def _display(self, path: str) -> str:
        shown = self._displays.get(path)
        if shown is None:
            shown = self._displays[path] = self.options.display_path(path)
        return shown

    # -- entry -------------------------------------------------------------------------
    def load(self, path: str, data: bytes | None = None) -> LaunchTree:
        absolute = os.path.abspath(path)
        self.root_display = self._display(absolute)
        if data is None:
            try:
                data = read_launch_bytes(absolute)
            except OSError as exc:
                self._report("parse_error", absolute, None,
                             f"cannot read file: {exc.strerror or exc}")
                return self._tree(FileStatus.UNREADABLE)
        root = self._parse(absolute, data)
        if root is None:
            return self._tree(FileStatus.PARSE_ERROR)
        context = _Context(self._root_namespace(), absolute, self._command_line_args(), True)
        self._path = absolute
        try:
            self._launch_conditions(root, context)
            self._walk(root.children, context)
        except RecursionError:
            # MAX_NESTING keeps real files far from this; it is the last line of defence.
            self._report("unresolved", absolute, root,
                         "launch tree nested too deeply to follow; the rest is not read")
        except BudgetExceeded as exc:
            self._report("unresolved", self._path, self._element or root,
                         f"work budget of this launch tree exhausted ({exc.reason}); "
                         "the rest is not read")
        return self._tree(FileStatus.OK)

    def _tree(self, status: FileStatus) -> LaunchTree:
        return LaunchTree(
            root=self.root_display,
            status=status,
            transforms=tuple(self.transforms),
            problems=tuple(self.problems),
            files=tuple(self.files),
            comments=tuple(self.comments),
            element_lines=tuple(self.element_lines),
            descriptions=tuple(self.descriptions),
            nodes=tuple(with_node_params(self.nodes, self.node_params)),
        )

    def _command_line_args(self) -> dict[str, Value]:
        """``NAME:=VALUE`` arguments as rosgraph's ``load_mappings`` keeps them: names and
        values stripped, empty ones and ``_private`` parameter assignments dropped."""
        args: dict[str, Value] = {}
        for name, value in self.options.args.items():
            name, value = name.strip(), value.strip()
            if not name or not value:
                continue
            if len(name) > 1 and name[0] == "_" and name[1] != "_":
                continue
            args[name] = (value,)
        return args

    def _root_namespace(self) -> str:
        ns = self.options.args.get("__ns") or self.options.env.get("ROS_NAMESPACE") or "/"
        try:
            return make_global_ns(ns)
        except ValueError:
            return "/"

    def _parse(self, absolute: str, data: bytes) -> Element | None:
        display = self._display(absolute)
        if display not in self.files:
            self.files.append(display)
        try:
            document = parse_xml(data, text_tags=("rosparam",), collect=("launch",))
        except XmlError as exc:
            self.problems.append(Problem(
                "parse_error", display, exc.line, exc.column,
                f"not well-formed XML: {exc.message}",
            ))
            return None
        if document.comments and holds_directive(document.comments):
            self.comments += [Comment(display, line, text) for line, text in document.comments]
            self.element_lines += [(display, line) for line in document.element_lines]
        # roslaunch takes the one <launch> element of the document, wherever it is.
        launches = document.collected
        if len(launches) != 1:
            where = document.root if not launches else launches[1]
            message = (
                f"no <launch> element (the root element is <{document.root.tag}>)"
                if not launches else "more than one <launch> element"
            )
            self.problems.append(Problem("parse_error", display, where.line, where.column, message))
            return None
        return launches[0]

    def _launch_conditions(self, launch: Element, context: _Context) -> None:
        """roslaunch evaluates ``if``/``unless`` on ``<launch>`` and ignores the outcome;
        it fails on a value that is not a boolean and crashes on a substitution there."""
        if_text, unless_text = launch.get("if"), launch.get("unless")
        if if_text is not None and unless_text is not None:
            self._error(context, launch, "cannot set both 'if' and 'unless' on the same tag")
            return
        text = if_text if if_text is not None else unless_text
        if text is None:
            return
        if "$" in text:
            self._error(context, launch,
                        "roslaunch cannot resolve substitutions in if/unless of <launch>")
            return
        try:
            to_bool((text,))
        except ValueError as exc:
            self._error(context, launch, str(exc))

    # -- substitution helpers ---------------------------------------------------------
    def _scope(self, context: _Context, anon: dict[str, str] | None) -> SubstitutionScope:
        if anon is None or anon is context.anon:
            if context.scope is None:
                context.scope = self._new_scope(context, context.anon)
            return context.scope
        side = context.side_scope
        if side is None or side[0] is not anon:
            side = context.side_scope = (anon, self._new_scope(context, anon))
        return side[1]

    def _new_scope(self, context: _Context, anon: dict[str, str]) -> SubstitutionScope:
        # The scope is kept in the context, so what it holds must not lead back to the
        # context: a reference cycle would leave the whole load to the garbage collector.
        filename, open_args = context.filename, context.open_args

        def missing(name: str) -> str:
            if open_args:
                return f"arg '{name}' is not set (give it with --arg {name}:=VALUE)"
            # Only the args passed to an included file exist there: roslaunch fails.
            message = (f"included file [{self._display(filename)}] requires the "
                       f"'{name}' arg to be set")
            if (filename, name) not in self._missing_reported:
                self._missing_reported.add((filename, name))
                self._report("roslaunch_error", filename, self._element, message)
            return message

        return SubstitutionScope(
            args=context.args,
            env=self.options.env,
            find=self.options.packages.find,
            anon=lambda anon_id: self.anon.make(anon, anon_id),
            filename=filename,
            missing_arg=missing,
            budget=self.budget,
        )

    def _resolve_text(self, text: str, element: Element, label: str, context: _Context,
                      anon: dict[str, str] | None = None) -> Value:
        if "$" not in text:
            return (text,) if text else ()
        return self._substitute(text, element, label, context, anon)

    def _substitute(self, text: str, element: Element, label: str, context: _Context,
                    anon: dict[str, str] | None) -> Value:
        self._element = element
        scope = context.scope if anon is None else None
        try:
            return resolve(text, scope or self._scope(context, anon))
        except SubstitutionError as exc:
            self._error(context, element, f"<{element.tag}> {label}: {exc}")
            return (Hole(text, str(exc)),)

    def _resolve(self, element: Element, attribute: str, context: _Context,
                 anon: dict[str, str] | None = None) -> Value | None:
        """The attribute's value (None when absent); roslaunch errors become holes."""
        text = element.attrib.get(attribute)
        if text is None:
            return None
        if "$" not in text:
            return (text,) if text else ()
        return self._substitute(text, element, attribute, context, anon)

    def _resolve_all(self, element: Element, attributes: Iterable[str], context: _Context,
                     anon: dict[str, str] | None = None) -> list[Value | None]:
        return [self._resolve(element, a, context, anon) for a in attributes]

    def _present(self, element: Element, attributes: Iterable[str], context: _Context,
                 anon: dict[str, str] | None = None) -> dict[str, Value]:
        """The values of those of ``attributes`` that ``element`` has, resolved in order."""
        attrib = element.attrib
        found: dict[str, Value] = {}
        for attribute in attributes:
            text = attrib.get(attribute)
            if text is not None:
                found[attribute] = (
                    ((text,) if text else ()) if "$" not in text
                    else self._substitute(text, element, attribute, context, anon)
                )
        return found

    def _required(self, element: Element, attribute: str, context: _Context,
                  anon: dict[str, str] | None = None) -> Value | None:
        text = element.attrib.get(attribute)
        if text is None:
            self._error(context, element,
                        f"<{element.tag}> tag is missing required attribute: '{attribute}'")
            return None
        if "$" not in text:
            return (text,) if text else ()
        return self._substitute(text, element, attribute, context, anon)

    def _condition(self, element: Element, context: _Context,
                   anon: dict[str, str] | None = None) -> Condition | None:
        """The extra presence condition of ``element``; None when it is skipped."""
        attrib = element.attrib
        if "if" not in attrib and "unless" not in attrib:
            return ALWAYS
        if_value = self._resolve(element, "if", context, anon)
        unless_value = self._resolve(element, "unless", context, anon)
        if if_value is not None and unless_value is not None:
            self._error(context, element, "cannot set both 'if' and 'unless' on the same tag")
        positive = if_value is not None
        value = if_value if if_value is not None else unless_value
        assert value is not None
        try:
            truth = to_bool(value)
        except ValueError as exc:
            self._error(context, element, f"{'if' if positive else 'unless'}: {exc}")
            truth = None
        if truth is None:
            return Condition((ConditionLiteral(text_of(value), positive),))
        return ALWAYS if truth == positive else None

    def _check_bool(self, context: _Context, element: Element, value: Value | None,
                    label: str) -> bool | None:
        """A strict boolean attribute: its value, or None when absent, unknown or bad."""
        text = resolved_text(value) if value is not None else None
        if text is None:
            return None
        problem = _bool_attribute(text, label)
        if problem is not None:
            self._error(context, element, problem)
            return None
        return text.lower() == "true"

    # -- tags --------------------------------------------------------------------------
    def _walk(self, elements: list[Element], context: _Context) -> None:
        step = self.budget.step
        for element in elements:
            step()
            self._element = element
            tag = element.tag
            if tag == "node":
                self._node(element, context)
            elif tag == "arg":
                self._arg(element, context)
            elif tag == "group":
                self._group(element, context)
            elif tag == "include":
                self._include(element, context)
            elif tag == "param":
                self._param(element, context)
            elif tag == "rosparam":
                self._rosparam(element, context)
            elif tag == "remap":
                self._remap(element, context)
            elif tag == "env":
                self._env(element, context)
            elif tag == "machine":
                self._machine(element, context)
            elif tag == "test":
                self._node(element, context, is_test=True)

    def _namespace(self, element: Element, context: _Context) -> tuple[str, str] | None:
        """The namespace inside ``element`` and why it is unresolved ("" when it is not);
        None when roslaunch refuses it (``~`` names)."""
        if "ns" not in element.attrib:
            return context.ns, context.ns_unresolved
        ns_value = self._resolve(element, "ns", context) or ()
        ns = text_of(ns_value)
        if not ns:
            self._error(context, element, f"<{element.tag}> tag has an empty 'ns' attribute")
            return context.ns, context.ns_unresolved
        try:
            joined = make_global_ns(ns if ns.startswith("/") else ns_join(context.ns, ns))
        except ValueError as exc:
            self._error(context, element, str(exc))
            return None
        return joined, context.ns_unresolved or _reasons(ns_value)

    def _child_namespace(self, element: Element, context: _Context) -> _Context | None:
        """roslaunch's ``_ns_clear_params_attr`` up to the new context (``clear_params``,
        resolved afterwards in the parent, is :meth:`_clear_params`)."""
        namespace = self._namespace(element, context)
        if namespace is None:
            return None
        child = context.copy()
        child.ns, child.ns_unresolved = namespace
        return child

    def _clear_params(self, element: Element, context: _Context, needs_ns: bool,
                      node_name: str | None = None) -> None:
        value = self._resolve(element, "clear_params", context)
        if value is None or not text_of(value):
            return
        if self._check_bool(context, element, value, "clear_params"):
            if needs_ns and element.get("ns") is None:
                self._error(context, element,
                            "'ns' attribute must be set in order to use 'clear_params'")
            elif not needs_ns and not node_name:
                self._error(context, element,
                            f"<{element.tag}> tag must have a 'name' attribute to use "
                            f"'clear_params' attribute")

    def _nested(self, element: Element, context: _Context) -> bool:
        """Whether one more level of nesting may be followed."""
        if context.depth < MAX_NESTING:
            return True
        self._report("unresolved", context.filename, element,
                     f"<{element.tag}> nested deeper than {MAX_NESTING} levels; not followed")
        return False

    def _group(self, element: Element, context: _Context) -> None:
        condition = self._condition(element, context)
        if condition is None or not self._nested(element, context):
            return
        child = self._child_namespace(element, context)
        self._clear_params(element, context, needs_ns=True)
        if child is None:
            return
        child.condition = _conjoin(context.condition, condition)
        child.depth += 1
        self._walk(element.children, child)

    def _declare(self, context: _Context, element: Element | None, name: str,
                 value: Value | None, default: Value | None, condition: Condition) -> None:
        """roslaunch's ``LoaderContext.add_arg``; a declaration under an unresolved
        condition may or may not happen, so what it would set becomes a hole."""
        conditional = not condition.always
        earlier = context.arg_names.get(name)
        if earlier is None:
            context.arg_names[name] = conditional
        elif conditional or earlier:
            context.arg_names[name] = True
        elif not context.pass_all_args and element is not None:
            self._error(context, element, f"arg '{name}' has already been declared")
        target = context.args if context.include_args is None else context.include_args
        if conditional:
            new = value if value is not None else default if name not in target else None
            if new is not None and target.get(name) != new:
                target[name] = (Hole(
                    f"$(arg {name})",
                    f"arg '{name}' is set under an unresolved condition ({condition.describe()})",
                ),)
            return
        if value is not None:
            if name in target and not context.pass_all_args and not earlier:
                if element is not None:
                    self._error(context, element,
                                f"cannot override arg '{name}', which has already been set")
                return
            target[name] = value
        elif default is not None and name not in target:
            target[name] = default

    def _arg(self, element: Element, context: _Context) -> None:
        attrib = element.attrib
        condition = (
            self._condition(element, context) if "if" in attrib or "unless" in attrib
            else ALWAYS
        )
        if condition is None:
            return
        name_value = self._required(element, "name", context)
        value = self._resolve(element, "value", context)
        default = self._resolve(element, "default", context)
        doc = attrib.get("doc")
        if doc is not None and "$" in doc:
            self._substitute(doc, element, "doc", context, None)
        if name_value is None:
            return
        if value is not None and default is not None:
            self._error(context, element, "<arg> tag must have one and only one of value/default.")
        name = resolved_text(name_value)
        if name is None:
            self._report("unresolved", context.filename, element,
                         f"arg name {text_of(name_value)!r} cannot be resolved; the arg is ignored")
            return
        for key in ("value", "default"):
            source = self._env_in_text(attrib.get(key, ""))
            if source is not None:
                self._env_args[name] = source
        self._declare(context, element, name, value, default, condition)

    def _param(self, element: Element, context: _Context,
               anon: dict[str, str] | None = None) -> None:
        attrib = element.attrib
        condition = ALWAYS
        if "if" in attrib or "unless" in attrib:
            found = self._condition(element, context, anon)
            if found is None:
                return
            condition = found
        written = self._resolve(element, "value", context, anon)
        count = int(written is not None)
        sources: dict[str, Value] = {}
        for key in ("textfile", "binfile", "command"):
            text = attrib.get(key)
            if text is not None:
                count += 1
                sources[key] = (self._substitute(text, element, key, context, anon)
                                if "$" in text else (text,))
        if count != 1:
            self._error(context, element,
                        "<param> tag must have one and only one of value/textfile/binfile.")
        name_text = attrib.get("name")
        if name_text is None:
            self._error(context, element, "<param> tag is missing required attribute: 'name'")
            return
        name_value = ((name_text.strip(),) if "$" not in name_text
                      else self._substitute(name_text.strip(), element, "name", context, anon))
        if DESCRIPTION_PARAM in name_text and is_description_name(resolved_text(name_value)):
            if written is not None:
                sources["value"] = written
            self._description(element, context, _conjoin(context.condition, condition), sources)
        elif "/" in name_text and name_text.rsplit("/", 1)[-1] in FRAME_PARAMS and anon is None:
            # ``<param name="hector_mapping/pub_map_odom_transform" .../>`` beside the node.
            full = resolved_text(name_value)
            text = None if written is None else resolved_text(written)
            if full is not None:
                always = _conjoin(context.condition, condition).always
                self.node_params.append((full, text if text is not None and always
                                         else UNKNOWN_VALUE))
        param_type = attrib.get("type")
        if written is not None and param_type is not None:
            value = resolved_text(written)
            problem = (None if value is None
                       else _param_value_problem(value.strip(), param_type or "auto"))
            if problem is not None:
                self._error(context, element, f"Invalid <param> tag: {problem}")

    def _description(self, element: Element, context: _Context, condition: Condition,
                     values: dict[str, Value]) -> None:
        source = from_ros1_param(values, self._display(context.filename), element.line,
                                 element.column, condition, os.path.dirname(context.filename))
        if source is not None:
            self.descriptions.append(source)

    def _frame_node(self, element: Element, context: _Context, condition: Condition,
                    name: str | None, package: str, executable: str) -> None:
        """Keep a node that publishes tf or owns a frame, with its frame params."""
        params: list[tuple[str, str]] = []
        for sub in element.children:
            if sub.tag == "param":
                key, value = sub.attrib.get("name"), sub.attrib.get("value")
                if not key or value is None or key.rsplit("/", 1)[-1] not in FRAME_PARAMS:
                    continue
                known: str | None = value
                if "$" in value:
                    # Anonymous names are left alone: resolving one here would renumber.
                    known = None if "$(anon" in value else resolved_text(self._resolve_text(
                        value, sub, "value", context, dict(context.anon)))
                params.append((key, UNKNOWN_VALUE if known is None else known))
            elif sub.tag == "rosparam" and sub.text:
                params.extend(params_from_yaml(sub.text))
        self.nodes.append(NodeRecord(
            self._display(context.filename), element.line, element.column, package,
            executable, name, tuple(params), _conjoin(context.condition, condition),
        ))

    def _rosparam(self, element: Element, context: _Context,
                  anon: dict[str, str] | None = None) -> None:
        if self._condition(element, context, anon) is None:
            return
        command, _ns, file, _param, subst = self._resolve_all(element, _ROSPARAM_ATTRS, context,
                                                              anon)
        substitute = self._check_bool(context, element, subst, "subst_value")
        command_text = resolved_text(command) if command is not None else "load"
        if command_text is not None and (command_text or "load") not in ("load", "dump", "delete"):
            self._error(context, element, "command must be 'load', 'dump', or 'delete'")
        if file is not None and command_text == "delete":
            self._error(context, element, "'file' attribute is invalid with 'delete' command.")
        file_text = None if file is None else resolved_text(file)
        if file is not None and (command_text or "load") == "load" and file_text is not None and (
            file_text == "" or _checkable_path(element.attrib.get("file", ""), file_text)
        ) and not os.path.isfile(file_text):
            self._error(context, element,
                        f"error loading <rosparam> tag: file does not exist [{file_text}]")
        body: Value | None = (element.text,) if element.text else ()
        if substitute:
            body = self._resolve_text(element.text, element, "text", context, anon)
        if file is None and (command_text or "load") == "load" and body is not None:
            text = resolved_text(body)
            # An unresolved param=/ns= may well be set: only a certain absence counts.
            has_param = any(
                value is not None and (resolved_text(value) is None or bool(text_of(value)))
                for value in (_param, _ns)
            )
            problem = None if text is None else rosparam_body_problem(text, has_param)
            if problem is not None:
                self._error(context, element, f"error loading <rosparam> tag: {problem}")

    def _remap(self, element: Element, context: _Context) -> None:
        if self._condition(element, context) is None:
            return
        ends = [self._required(element, a, context) for a in ("from", "to")]
        texts = [resolved_text(v) if v is not None else None for v in ends]
        for text in texts:
            if text is None:
                continue
            name = _canonical_name(text)
            if not name:
                self._error(context, element, "remap from/to attributes cannot be empty")
            elif not _is_legal_name(name):
                self._error(context, element, f"remap [{name}] is not a valid ROS name")

    def _env(self, element: Element, context: _Context,
             anon: dict[str, str] | None = None) -> None:
        if self._condition(element, context, anon) is None:
            return
        name = self._required(element, "name", context, anon)
        self._required(element, "value", context, anon)
        if name is not None and resolved_text(name) == "":
            self._error(context, element, "Invalid <env> tag: 'name' attribute must be non-empty")

    def _machine(self, element: Element, context: _Context) -> None:
        if self._condition(element, context) is None:
            return
        # roslaunch resolves the rest of a <machine> in a copy of the context.
        anon = dict(context.anon)
        old = self._resolve_all(element, _MACHINE_OLD_ATTRS, context, anon)
        if any(v for v in old):
            self._error(context, element,
                        "<machine>: ros-* attributes are not supported since ROS Fuerte")
        self._required(element, "name", context, anon)
        self._required(element, "address", context, anon)
        values = dict(zip(_MACHINE_ATTRS, self._resolve_all(element, _MACHINE_ATTRS, context,
                                                            anon), strict=True))
        default = values["default"]
        default_text = resolved_text(default) if default is not None else "false"
        if default_text is not None and (default_text or "false").lower() not in (
            "true", "false", "never"
        ):
            self._error(context, element, f"Invalid value for 'attribute': {default_text}")
        port = values["ssh-port"]
        port_text = resolved_text(port) if port is not None else None
        if port_text is not None and not _is_int(port_text or "22"):
            self._error(context, element, f"invalid ssh-port: {port_text}")
        if any(child.tag == "env" for child in element.children):
            self._error(context, element, "<machine>: <env> tag is not supported since ROS Fuerte")
        timeout = values["timeout"]
        timeout_text = resolved_text(timeout) if timeout is not None else None
        if timeout_text is not None and not _is_positive_number(timeout_text):
            self._error(context, element, f"'timeout' be a positive number: [{timeout_text}]")

    def _node(self, element: Element, context: _Context, is_test: bool = False) -> None:
        """``<node>`` (or ``<test>``): every attribute is resolved in roslaunch's order;
        static transform publishers become :class:`StaticTransform` records."""
        condition = self._condition(element, context)
        if condition is None:
            return
        attrib = element.attrib
        if is_test:
            for attribute in ("respawn", "respawn_delay", "output"):
                if attribute in attrib:
                    self._error(context, element,
                                f"<test> tags cannot have '{attribute}' attribute")
            name_value = self._resolve(element, "name", context)
            test_name = self._required(element, "test-name", context)
            limits = self._present(element, ("time-limit", "retry"), context)
            for message in _test_limit_problems(limits):
                self._error(context, element, f"Invalid <node> tag: {message}")
            if not (name_value and text_of(name_value)):
                name_value = test_name
        else:
            name_value = self._required(element, "name", context)
        namespace = self._namespace(element, context)
        # <param>/<rosparam> children resolve in a copy of the node's context taken here.
        param_anon = dict(context.anon) if element.children else None
        if "clear_params" in attrib:
            name = text_of(name_value) if name_value is not None else None
            self._clear_params(element, context, needs_ns=False, node_name=name)
        package = self._required(element, "pkg", context)
        node_type = self._required(element, "type", context)
        late = self._present(element, _NODE_LATE_ATTRS, context)
        if element.children:
            self._node_children(element, context, param_anon or {}, dict(context.anon))
        if namespace is None:
            return
        ns, ns_unresolved = namespace
        if len(late) > ("args" in late):
            self._validate_node(element, context, late)
        name_text = None if name_value is None else resolved_text(name_value)
        package_text = None if package is None else resolved_text(package)
        type_text = None if node_type is None else resolved_text(node_type)
        if name_text and "/" in name_text:
            self._error(context, element, f"node name cannot contain a namespace: {name_text}")
        if package_text is not None and not package_text.strip():
            self._error(context, element, "package must be non-empty")
        if type_text is not None and not type_text.strip():
            self._error(context, element, "type must be non-empty")
        if "//" in ns:
            ns = _COLLAPSE_SLASHES.sub("/", ns)
        if not is_test and name_text and not ns_unresolved:
            self._register_name(element, context, name_text, ns)
        if package_text in FRAME_NODE_PACKAGES and type_text is not None:
            self._frame_node(element, context, condition, name_text, package_text, type_text)
        if is_test or package is None or node_type is None:
            return
        if type_text is not None and type_text != STATIC_TF_TYPE:
            return
        if package_text is not None and package_text not in TF_PACKAGES:
            return
        if type_text is None and package_text is None:
            return
        self._transform(element, context, condition, name_value or (), ns, ns_unresolved,
                        package, node_type, late.get("args", ()))

    def _node_children(self, element: Element, context: _Context, param_anon: dict[str, str],
                       env_anon: dict[str, str]) -> None:
        for sub in element.children:
            sub_tag = sub.tag.lower()
            if sub_tag == "remap":
                self._remap(sub, context)
            elif sub_tag == "param":
                self._param(sub, context, param_anon)
            elif sub_tag == "rosparam":
                self._rosparam(sub, context, param_anon)
            elif sub_tag == "env":
                self._env(sub, context, env_anon)

    def _validate_node(self, element: Element, context: _Context,
                       late: dict[str, Value]) -> None:
        """What roslaunch's ``Node`` constructor and ``_node_tag`` refuse in the optional
        attributes."""
        required = self._check_bool(context, element, late.get("required"), "required")
        respawn = self._check_bool(context, element, late.get("respawn"), "respawn")
        if required and respawn:
            self._error(context, element, "respawn and required cannot both be set to true")
        delay = late.get("respawn_delay")
        delay_text = resolved_text(delay) if delay is not None else None
        if delay_text is not None:
            try:
                float(delay_text)
            except ValueError:
                self._error(context, element,
                            f"invalid float value for respawn_delay: {delay_text}")
        output = late.get("output")
        output_text = resolved_text(output) if output is not None else None
        if output_text is not None and output_text not in ("log", "screen"):
            self._error(context, element, "output must be one of 'log', 'screen'")
        cwd = late.get("cwd")
        cwd_text = resolved_text(cwd) if cwd is not None else None
        if cwd_text is not None and cwd_text not in ("ROS_HOME", "ros_home", "node"):
            self._error(context, element, "cwd must be one of 'ROS_HOME', 'node'")

    def _register_name(self, element: Element, context: _Context, name: str,
                       namespace: str) -> None:
        """roslaunch refuses two nodes with the same resolved name in one launch tree."""
        resolved_name = ns_join(namespace, name)
        first = self.node_names.get(resolved_name)
        if first is None:
            self.node_names[resolved_name] = (context.filename, element)
            return
        where = Location(self._display(first[0]), first[1].line, first[1].column)
        self._report(
            "roslaunch_error", context.filename, element,
            f"roslaunch file contains multiple nodes named [{resolved_name}]",
            node=name, related=(where,),
        )

    def _include(self, element: Element, context: _Context) -> None:
        condition = self._condition(element, context)
        if condition is None:
            return
        file_value = self._required(element, "file", context)
        pass_all = bool(self._check_bool(
            context, element, self._resolve(element, "pass_all_args", context), "pass_all_args"
        ))
        child = self._child_namespace(element, context)
        self._clear_params(element, context, needs_ns=True)
        if child is None or file_value is None or not self._nested(element, context):
            return
        child.condition = _conjoin(context.condition, condition)
        child.depth += 1
        child.arg_names = {}
        child.include_args = {}
        if pass_all:
            for name, value in context.args.items():
                self._declare(child, None, name, value, None, ALWAYS)
            child.pass_all_args = True
        for sub in element.children:
            sub_tag = sub.tag.lower()
            if sub_tag == "arg":
                self._arg(sub, child)
            elif sub_tag == "env":
                self._env(sub, child)
        passed = child.include_args
        for name in child.arg_names:
            if name not in passed:
                self._error(context, element, f"include args must have declared values ({name})")
        args_passed = list(passed)
        child.args, child.include_args, child.arg_names, child.anon = dict(passed), None, {}, {}
        child.scope = child.side_scope = None
        child.open_args = pass_all and context.open_args
        self._follow_include(element, context, child, file_value, args_passed, pass_all)

    def _follow_include(self, element: Element, context: _Context, child: _Context,
                        file_value: Value, args_passed: list[str], pass_all: bool) -> None:
        path = resolved_text(file_value)
        if path is None:
            reasons = "; ".join(f"{h.text}: {h.reason}" for h in holes(file_value))
            self._report("unresolved", context.filename, element,
                         f"include file {text_of(file_value)!r} not followed: {reasons}")
            return
        absolute = self._locate(path, context.filename)
        if absolute is None:
            self._error(context, element, f"included file not found: {path}")
            return
        if absolute in context.chain:
            cycle = " -> ".join(self._display(p) for p in (*context.chain, absolute))
            self._error(context, element, f"include cycle: {cycle}")
            return
        if len(context.chain) >= MAX_INCLUDE_DEPTH or len(self.files) >= MAX_FILES_PER_TREE:
            self._report("unresolved", context.filename, element,
                         f"includes nested deeper than {MAX_INCLUDE_DEPTH} levels or more than "
                         f"{MAX_FILES_PER_TREE} files in the tree; not followed")
            return
        try:
            data = read_launch_bytes(absolute)
        except OSError as exc:
            self._error(context, element,
                        f"cannot read included file {path}: {exc.strerror or exc}")
            return
        self.budget.produce(len(data))
        root = self._parse(absolute, data)
        if root is None:
            return
        self._path = absolute
        child.filename = absolute
        child.scope = child.side_scope = None
        child.chain = (*context.chain, absolute)
        child.included_from = (self._display(context.filename), element.line)
        self._launch_conditions(root, child)
        self._walk(root.children, child)
        self._path = context.filename
        if not pass_all:
            unused = [name for name in args_passed if name not in child.arg_names]
            if unused:
                self._error(context, element,
                            f"unused args [{', '.join(unused)}] for include of [{path}]")

    @staticmethod
    def _locate(path: str, including_file: str) -> str | None:
        # roslaunch opens a relative path from the working directory; a linter run from
        # elsewhere also tries the including file's folder, which is what authors mean.
        candidates = [path] if os.path.isabs(path) else [
            os.path.abspath(path), os.path.join(os.path.dirname(including_file), path)
        ]
        for candidate in candidates:
            if os.path.isfile(candidate):
                return os.path.abspath(candidate)
        # A folder, device or FIFO of that name is found, so that reading it says what it is.
        for candidate in candidates:
            if os.path.exists(candidate):
                return os.path.abspath(candidate)
        return None

    def _transform(self, element: Element, context: _Context, condition: Condition,
                   name_value: Value, namespace: str, ns_unresolved: str, package: Value,
                   node_type: Value, args_value: Value) -> None:
        package_text, type_text = resolved_text(package), resolved_text(node_type)
        name_text = resolved_text(name_value)
        name = name_text or text_of(name_value) or None
        words = split_args(args_value)
        unresolved: set[Field] = set()
        if name_text is None or name is None:
            unresolved.add(Field.NAME)
        if ns_unresolved:
            unresolved.add(Field.NAMESPACE)
        if package_text is None:
            unresolved.add(Field.PACKAGE)
        if type_text is None:
            unresolved.add(Field.EXECUTABLE)
        decode_package = package_text or (
            "tf" if len(words.words) in (9, 10) and is_number(words.words[-1]) else "tf2_ros"
        )
        decoded = decode_ros1(decode_package, words.words)
        arity_issue = decoded.arity_issue
        form = decoded.form
        if words.unresolved:
            indices = words.unresolved
            # A hole is taken for one word (typically a frame from an arg) while that gives
            # a form the program accepts; a hole that stands for the whole value (an
            # $(eval) or a refused text) may hold any number of words.
            if (decoded.form in (ArgForm.INVALID, ArgForm.PARAM) or decoded.arity_issue
                    or any(not _single_command(h.text) for h in words.holes)):
                unresolved.add(Field.ARITY)
                arity_issue, form = None, ArgForm.UNKNOWN
            if form is ArgForm.UNKNOWN:
                fields = dict.fromkeys(DECODED_FIELDS, True)
            else:
                rotation_end = 6 if form is ArgForm.YPR else 7
                fields = {
                    Field.TRANSLATION: any(i in indices for i in (0, 1, 2)),
                    Field.ROTATION: any(3 <= i < rotation_end for i in indices),
                    Field.PARENT: decoded.parent_index in indices,
                    Field.CHILD: decoded.child_index in indices,
                    Field.PERIOD_MS: decoded.period_ms is not None
                    and decoded.numeric_indices[-1] in indices,
                }
            unresolved.update(k for k, v in fields.items() if v)
        if words.unresolved or unresolved:
            number_issues = tuple(n for n in decoded.number_issues
                                  if n.index not in words.unresolved)
            all_holes = (*holes(name_value), *holes(args_value), *holes(package),
                         *holes(node_type))
            reasons = tuple(dict.fromkeys(f"{h.text}: {h.reason}" for h in all_holes))
            if ns_unresolved:
                reasons = (*reasons, f"namespace {namespace!r}: {ns_unresolved}")
        else:
            number_issues, reasons = decoded.number_issues, ()
        known = form is not ArgForm.UNKNOWN
        transform = StaticTransform(
            path=self._display(context.filename),
            line=element.line,
            column=element.column,
            root=self.root_display,
            included_from=context.included_from,
            name=name,
            namespace=namespace,
            package=text_of(package) if package_text is None else package_text,
            executable=text_of(node_type) if type_text is None else type_text,
            args_written=element.attrib.get("args") or "",
            args=text_of(args_value),
            tokens=words.words,
            parent_written=decoded.parent if known else None,
            child_written=decoded.child if known else None,
            translation=decoded.translation if known else None,
            rotation=decoded.rotation if known else None,
            period_ms=decoded.period_ms if known else None,
            form=form,
            arity_issue=arity_issue,
            number_issues=number_issues,
            condition=_conjoin(context.condition, condition),
            unresolved=frozenset(unresolved),
            unresolved_reasons=reasons,
        )
        self.transforms.append(transform)
        if transform.unresolved:
            self._report(
                "unresolved", context.filename, element,
                f"cannot resolve {', '.join(transform.unresolved_names)} statically"
                + (f": {'; '.join(reasons)}" if reasons else ""),
                node=name,
            )


def _reasons(value: Value) -> str:
    """The substitutions that leave ``value`` unresolved, with why; "" when resolved."""
    return "; ".join(f"{h.text}: {h.reason}" for h in holes(value))


def _single_command(text: str) -> bool:
    """Whether ``text`` is one ``$(arg …)``-like substitution, not an ``$(eval)``."""
    return (text.startswith("$(") and text.endswith(")") and text.count("$(") == 1
            and not text.startswith("$(eval "))


def _conjoin(outer: Condition, inner: Condition) -> Condition:
    return outer if inner.always else inner if outer.always else outer & inner


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


def load_ros1(path: str, options: LoadOptions, data: bytes | None = None) -> LaunchTree:
    """Load ``path`` (or ``data`` standing for it) into a :class:`LaunchTree`."""
    return Ros1Loader(options).load(path, data)
