"""The ROS 1 loader's foundation: options, the loader context, and reading, scoping and
resolving (substitutions, ``if``/``unless``, required attributes) as roslaunch does."""

from __future__ import annotations

import os
import re
import typing
import weakref
from collections.abc import Callable, Iterable, Mapping

from launch_linter.frontends.robot.describe import RobotCache
from launch_linter.frontends.robot.sources import with_node_params
from launch_linter.frontends.ros1_attributes import ignored_attributes, message
from launch_linter.frontends.ros1_checks import _bool_attribute
from launch_linter.frontends.ros1_names import make_global_ns
from launch_linter.frontends.ros1_root_args import declared_arg_names
from launch_linter.frontends.ros1_unused_args import unused_arg_problems
from launch_linter.model.budget import Budget, BudgetExceeded
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.included import through_include
from launch_linter.model.launch import (
    Comment,
    FileStatus,
    LaunchTree,
    holds_directive,
    may_hold_directive,
)
from launch_linter.model.paths import shown_path
from launch_linter.model.record import Record, _set, replace
from launch_linter.model.robot import DescriptionSource, NodeRecord
from launch_linter.model.transform import ALWAYS, Condition, ConditionLiteral, StaticTransform
from launch_linter.resolve.substitution import (
    SubstitutionError,
    SubstitutionScope,
    resolve,
    to_bool,
)
from launch_linter.resolve.value import Hole, Value, resolved_text, text_of
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml, read_launch_bytes
from launch_linter.workspace.launch_checks import only_parse_checked
from launch_linter.workspace.packages import PackageIndex

if typing.TYPE_CHECKING:
    from launch_linter.knowledge import KnowledgeBase

STATIC_TF_TYPE = "static_transform_publisher"
TF_PACKAGES = ("tf", "tf2_ros")
MAX_INCLUDE_DEPTH = 32
MAX_NESTING = 100
"""Most ``<group>``/``<include>`` levels followed, all files of a tree together."""
MAX_FILES_PER_TREE = 2_000

# Attributes roslaunch resolves for each tag, in its order (after ``if``/``unless``).
_ARG_ATTRS = ("name", "value", "default", "doc")
_NODE_LATE_ATTRS = ("machine", "args", "output", "respawn", "respawn_delay", "cwd",
                    "launch-prefix", "required")
_NODE_LATE_NAMES = frozenset(_NODE_LATE_ATTRS)
_PARAM_VALUE_ATTRS = ("value", "textfile", "binfile", "command")
_ROSPARAM_ATTRS = ("command", "ns", "file", "param", "subst_value")
_MACHINE_OLD_ATTRS = ("ros-root", "ros-package-path", "ros-ip", "ros-hostname")
_MACHINE_ATTRS = ("env-loader", "ssh-port", "user", "password", "default", "timeout")


def relative_to_cwd(path: str) -> str:
    """``shown_path(path)`` (relative under the cwd, absolute elsewhere), quicker for the
    usual case of a path below the cwd."""
    folder = os.getcwd()
    if path.startswith(folder) and path[len(folder):len(folder) + 1] == os.sep:
        return os.path.normpath(path[len(folder) + 1:])
    return shown_path(path)


_VALUE_ERRORS = ("Invalid <param> tag", "included file not found", "<group> tag has an empty",
                 "<node> tag has an empty", "cannot turn",
                 "error loading <rosparam> tag: file does not exist")
"""Errors about a value that may come from the environment or the command line (a syntax
error never does)."""
_ENV_REFERENCE = re.compile(r"\$\((optenv|env|arg)\s+([^\s)]+)")
"""``$(optenv NAME ...)``, ``$(env NAME)``, ``$(arg NAME)`` in attribute text."""


class LoadOptions(Record):
    """What the command line tells the loader."""

    args: Mapping[str, str]
    env: Mapping[str, str]
    packages: PackageIndex
    display_path: Callable[[str], str]
    study_errors: bool
    """True (the ``study`` profile): report as ``roslaunch_error``, as the study counted
    them, what the default reports as ``unresolved`` info because the file alone cannot
    decide it: an error whose cause depends on the environment (``$(optenv)``/``$(env)``
    not given with ``--env``, a ``~`` path in ROS 2)."""
    ros_version: int | None
    """1 or 2 to read an XML root file as that ROS's launch XML; None: by its content."""
    robots: RobotCache | None
    """Robot descriptions expanded in this run (None: a new cache per tree)."""
    knowledge: KnowledgeBase | None
    """The run's knowledge base (the configuration's files over the bundled one); None:
    the bundled one."""

    __slots__ = ("args", "env", "packages", "display_path", "study_errors", "ros_version",
                 "robots", "knowledge")

    def __init__(
        self,
        args: Mapping[str, str] | None = None,
        env: Mapping[str, str] | None = None,
        packages: PackageIndex | None = None,
        display_path: Callable[[str], str] = relative_to_cwd,
        study_errors: bool = False,
        ros_version: int | None = None,
        robots: RobotCache | None = None,
        knowledge: KnowledgeBase | None = None,
    ) -> None:
        _set(self, "args", {} if args is None else args)
        _set(self, "env", {} if env is None else env)
        _set(self, "packages", PackageIndex([]) if packages is None else packages)
        _set(self, "display_path", display_path)
        _set(self, "study_errors", study_errors)
        _set(self, "ros_version", ros_version)
        _set(self, "robots", robots)
        _set(self, "knowledge", knowledge)


class _AnonNames:
    """roslaunch's anonymous names, made stable: ``id_anon<N>``, N counted per root."""

    def __init__(self) -> None:
        self.count = 0

    def make(self, table: dict[str, str], anon_id: str) -> str:
        if anon_id not in table:
            self.count += 1
            table[anon_id] = f"{anon_id}_anon{self.count}"
        return table[anon_id]


IncludeCall = typing.Tuple[str, typing.Tuple[typing.Tuple[str, str], ...]]
"""A file and the values of the args it is given (as written where unresolved)."""


def include_call(path: str, args: dict[str, Value]) -> IncludeCall:
    if not args:  # every root file without --arg
        return path, ()
    return path, tuple(sorted((name, text_of(value)) for name, value in args.items()))


class _Context:
    """roslaunch's ``LoaderContext``, plus what static resolution needs to know."""

    __slots__ = ("anon", "arg_names", "args", "calls", "chain", "condition", "depth", "filename",
                 "include_args", "included_from", "ns", "ns_unresolved", "open_args",
                 "pass_all_args", "scope", "side_scope", "__weakref__")

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
        self.calls: tuple[IncludeCall, ...] = (include_call(filename, args),)
        """(file, argument values) of each include on the way here: a repeat is a cycle."""
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
        # Not through ``__init__``: the include call it would work out (sorting and joining
        # every arg) is the parent's, copied below.
        child = _Context.__new__(_Context)
        child.ns = self.ns
        child.filename = self.filename
        child.args = dict(self.args)
        child.open_args = self.open_args
        child.scope = None
        child.side_scope = None
        child.ns_unresolved = self.ns_unresolved
        child.arg_names = dict(self.arg_names)
        child.anon = dict(self.anon)
        child.condition = self.condition
        child.chain = self.chain
        child.calls = self.calls
        child.included_from = self.included_from
        child.pass_all_args = self.pass_all_args
        child.include_args = self.include_args
        child.depth = self.depth
        return child


class Ros1Base:
    """Reading, diagnostics, scopes and resolution of one root file's tree."""

    def __init__(self, options: LoadOptions) -> None:
        self.options = options
        self.transforms: list[StaticTransform] = []
        self.problems: list[Problem] = []
        # A file included many times reports each of its problems once: the same element
        # gives the same problem every time, and a hostile tree can repeat one 100,000 times.
        self._reported: set[tuple[object, ...]] = set()
        self._included_at: dict[str, Location] = {}
        """The include being walked for each included file (its place)."""
        self.include_sites: dict[str, Location] = {}
        """Each included file's first include, by the file's shown path."""
        self.files: list[str] = []
        self.comments: list[Comment] = []
        self.element_lines: list[tuple[str, int]] = []
        self.descriptions: list[DescriptionSource] = []
        self.other_descriptions: list[tuple[str, DescriptionSource]] = []
        """Descriptions in parameters of other names, with the full name: a
        robot_state_publisher reads one through ``<remap from="robot_description" to=...>``."""
        self.remapped_descriptions: list[str] = []
        """The full parameter names robot_state_publishers read their description from."""
        self.nodes: list[NodeRecord] = []
        self.node_params: list[tuple[str, str]] = []
        """Parameters set beside the nodes (``NODE/param``, ``<rosparam>`` files): full
        name, value."""
        self.tf_prefixes: list[tuple[str | None, str]] = []
        """``tf_prefix`` parameters set in a namespace (None: unresolved): value."""
        self.params_unread: list[str] = []
        """Why some parameters set beside the nodes could not be read."""
        self.anon = _AnonNames()
        self.root_display = ""
        self.node_names: dict[str, list[tuple[str, Element, Condition]]] = {}
        """Resolved node name -> (file, element, presence condition) of its nodes so far."""
        self._displays: dict[str, str] = {}
        self._missing_reported: set[tuple[str, str]] = set()
        # The root's text and declared args, the last if/unless judged (does it surely
        # hold?), a node's children under an undecided one, the attribute being resolved.
        self._root_data, self._root_lines = b"", typing.cast("list[int] | None", None)
        # The root's <launch> until its declared args are read (only for an arg it may
        # not declare, rare), then those names (None: one not literal, any name).
        self._root_launch: Element | None = None
        self._root_arg_names: frozenset[str] | None = None
        self._condition_seen: tuple[Element, bool] | None = None
        self._in_undecided_node, self._label = False, ""
        self._element: Element | None = None
        self._env_args: dict[str, str] = {}
        self._blank_args: dict[str, str] = {}
        """Args left at an empty default of the root file (directly or through other
        args) -> the root's arg whose default it is."""
        self._child_values: dict[Element, Value] = {}
        """The resolved ``value`` of each ``<param>`` inside a node whose text names no
        anonymous name: the node's record reads it again (see ``_frame_node``)."""
        self._yaml_bodies: dict[str, tuple[object, str | None]] = {}
        """``parse_yaml`` of the last ``<rosparam>`` texts: a node's is judged, then read."""
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
        problem = Problem(rule, self._display(path), line, column, message, node, related)
        # Once per cause and place in a tree: a file included twice says it once (an
        # unresolved value is one cause whichever node of the include it is in).
        key: tuple[object, ...] = (rule, problem.path, line, column, message) + (
            () if rule == "unresolved" else (node, related))
        if key in self._reported:
            return
        self._reported.add(key)
        site = self._included_at.get(path) if rule == "unresolved" else None
        self.problems.append(problem if site is None else through_include(problem, site))

    def _error(self, context: _Context, element: Element | None, message: str,
               attribute: str | None = None) -> None:
        """A roslaunch refusal; ``attribute`` names the attribute whose value it refuses
        (the one checked for the environment and for a root arg left at an empty
        default; every attribute of the element when it is not known)."""
        checkable = (element is not None and not self.options.study_errors
                     and message.startswith(_VALUE_ERRORS))
        source = None
        if checkable and element is not None:
            source = (self._env_source(element) if attribute is None
                      else self._env_in_text(element.attrib.get(attribute, "")))
        if source is not None:
            self._report("unresolved", context.filename, element,
                         f"{message}, but the value depends on the environment ({source}): "
                         f"not checked (give it with --env)")
            return
        blank = (self._blank_arg_in(element.attrib.get(attribute, ""))
                 if checkable and element is not None and attribute is not None else None)
        if blank is not None:
            # roslaunch refuses the root's own default here, so the file cannot have been
            # meant to run with it: like an arg without default, the command line gives it.
            self._report("unresolved", context.filename, element,
                         f"{message} with arg '{blank}' at its empty default, which the "
                         f"root file cannot run with, so the command line gives it: not "
                         f"checked (give it with --arg {blank}:=VALUE)")
            return
        self._report("roslaunch_error", context.filename, element, message)

    def _blank_arg_in(self, text: str) -> str | None:
        """The root arg left at its empty default that ``text`` reads, if any."""
        if "$(arg" not in text:
            return None
        for match in _ENV_REFERENCE.finditer(text):
            if match.group(1) == "arg" and match.group(2) in self._blank_args:
                return self._blank_args[match.group(2)]
        return None

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
        # Without an env-derived arg so far, only an ``$(env``/``$(optenv`` can answer: most
        # values (``$(arg x)``, ``$(find p)/...``) skip the pattern.
        if not self._env_args and "env" not in text:
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

    def _quoted(self, path: str) -> str:
        """A path a message quotes, shown as the report shows file paths (an empty
        one as it is)."""
        return self._display(path) if path else path

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
        self._root_data = data
        self._root_launch, self._root_arg_names = root, None
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
                         exc.message)
        tree = self._tree(FileStatus.OK)
        if tree.nodes and only_parse_checked(absolute, self.options.packages):
            tree = replace(tree, parse_check_only=True)
        return tree

    def _tree(self, status: FileStatus) -> LaunchTree:
        descriptions = self.descriptions
        if self.other_descriptions and self.remapped_descriptions:
            remapped = set(self.remapped_descriptions)
            descriptions = [*descriptions, *(
                source for name, source in self.other_descriptions if name in remapped)]
        return LaunchTree(
            root=self.root_display,
            status=status,
            transforms=tuple(self.transforms),
            problems=tuple(self.problems),
            files=tuple(self.files),
            comments=tuple(self.comments),
            element_lines=tuple(self.element_lines),
            descriptions=tuple(descriptions),
            nodes=tuple(with_node_params(self.nodes, self.node_params, self.params_unread,
                                          self.tf_prefixes)),
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
        first_read = display not in self.files
        if first_read:
            self.files.append(display)
        try:
            document = parse_xml(data, text_tags=("rosparam",), collect=("launch",),
                                 directives=may_hold_directive(data))
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
        if first_read:
            self.problems.extend(unused_arg_problems(display, launches[0], data))
            self._ignored_attributes(display, launches[0])
        return launches[0]

    def _root_may_declare(self, name: str) -> bool:
        """Whether the root file declares arg ``name`` or one whose name is not literal;
        its args are read at the first question, not for every root file."""
        if self._root_launch is not None:
            self._root_arg_names = declared_arg_names(self._root_launch)
            self._root_launch = None
        return self._root_arg_names is None or name in self._root_arg_names

    def _ignored_attributes(self, display: str, launch: Element) -> None:
        try:  # read before the walk (and its catch) starts for the root file
            found = list(ignored_attributes(launch, self.budget.step))
        except BudgetExceeded as exc:
            found = []
            self.problems.append(Problem("unresolved", display, 1, 1, exc.message))
        for parent, element, name, mistaken in found:
            self.problems.append(Problem("ros1_ignored_attribute", display, element.line,
                                         element.column, message(parent, element, name,
                                                                 mistaken)))

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
        filename, open_args, chain = context.filename, context.open_args, context.chain
        reading = weakref.ref(context)

        def missing(name: str) -> str:
            if open_args:
                read_in = reading()
                if read_in is not None and read_in.condition.always:
                    self._undeclared_at_root(name, filename, chain)
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
        self._label = label
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
            if attribute in attrib:  # a test, not a ``get`` call: most are absent
                text = attrib[attribute]
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
        self._condition_seen = (element, truth is not None)
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

    # -- defined by a subclass, further on ---------------------------------------------------
    def _walk(self, elements: list[Element], context: _Context) -> None:
        """Defined by :class:`.ros1_tags.Ros1Tags`."""
        raise NotImplementedError

    def _undeclared_at_root(self, name: str, filename: str, chain: tuple[str, ...]) -> None:
        """Defined by :class:`.ros1_tags.Ros1Tags`."""
        raise NotImplementedError
