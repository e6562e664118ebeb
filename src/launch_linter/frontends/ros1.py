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

from launch_linter.decode import decode_ros1, is_number
from launch_linter.frontends.record import (
    Command,
    Reading,
    Site,
    transform_record,
    unresolved_message,
)
from launch_linter.frontends.robot.describe import RSP_PACKAGE
from launch_linter.frontends.robot.sources import DESCRIPTION_PARAM
from launch_linter.frontends.ros1_base import (
    _NODE_LATE_ATTRS,
    _NODE_LATE_NAMES,
    MAX_FILES_PER_TREE,
    MAX_INCLUDE_DEPTH,
    MAX_NESTING,
    STATIC_TF_TYPE,
    TF_PACKAGES,
    LoadOptions,
    _Context,
    include_call,
    relative_to_cwd,
)
from launch_linter.frontends.ros1_checks import (
    _conjoin,
    _single_command,
    _test_limit_problems,
    rosparam_body_problem,
    yaml_root_kind,
)
from launch_linter.frontends.ros1_names import _COLLAPSE_SLASHES, make_global_ns, ns_join
from launch_linter.frontends.ros1_tags import Ros1Tags
from launch_linter.frontends.tokens import split_args
from launch_linter.frontends.xml_dialect import is_ros2_xml
from launch_linter.model.diagnostic import Location
from launch_linter.model.launch import LaunchTree
from launch_linter.model.transform import ALWAYS, DECODED_FIELDS, ArgForm, Condition, Field
from launch_linter.resolve import reads
from launch_linter.resolve.value import (
    Value,
    holes,
    is_resolved,
    resolved_text,
    shown_value,
    text_of,
    why_unresolved,
)
from launch_linter.resolve.xml_safe import Element, read_launch_bytes

MAX_SAME_NAME = 64
"""Nodes of one resolved name kept for comparison (a hostile file repeating one name
costs a bounded look-up per node)."""


class Ros1Loader(Ros1Tags):
    """Loads one root file (and its includes) into a :class:`LaunchTree`."""

    def _node(self, element: Element, context: _Context, is_test: bool = False) -> None:
        """``<node>`` (or ``<test>``): every attribute is resolved in roslaunch's order;
        static transform publishers become :class:`StaticTransform` records."""
        attrib = element.attrib
        condition = (self._condition(element, context) if "if" in attrib or "unless" in attrib
                     else ALWAYS)
        if condition is None:
            return
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
            name_text = None if name_value is None else resolved_text(name_value)
        else:
            name_value, name_text = self._required_text(element, "name", context)
        namespace = self._namespace(element, context)
        # <param>/<rosparam> children resolve in a copy of the node's context taken here.
        param_anon = dict(context.anon) if element.children else None
        if "clear_params" in attrib:
            name = text_of(name_value) if name_value is not None else None
            self._clear_params(element, context, needs_ns=False, node_name=name)
        package, package_text = self._required_text(element, "pkg", context)
        node_type, type_text = self._required_text(element, "type", context)
        late_names = _NODE_LATE_NAMES.intersection(attrib)
        if len(late_names) == 1:  # most often ``output`` alone: no order to keep
            (late_name,) = late_names
            late = {late_name: self._resolve_text(attrib[late_name], element, late_name, context)}
        else:
            late = self._present(element, _NODE_LATE_ATTRS, context) if late_names else {}
        if element.children:
            outer, self._in_undecided_node = (self._in_undecided_node,
                                              self._in_undecided_node or not condition.always)
            self._node_children(element, context, param_anon or {}, dict(context.anon))
            self._in_undecided_node = outer
        if namespace is None:
            return
        ns, ns_unresolved = namespace
        if len(late) > ("args" in late):
            self._validate_node(element, context, late)
        if name_text and "/" in name_text:
            self._error(context, element, f"node name cannot contain a namespace: {name_text}")
        if package_text is not None and not package_text.strip():
            self._error(context, element, "package must be non-empty")
        if type_text is not None and not type_text.strip():
            self._error(context, element, "type must be non-empty")
        if "//" in ns:
            ns = _COLLAPSE_SLASHES.sub("/", ns)
        present = _conjoin(context.condition, condition)
        if not is_test and name_text and not ns_unresolved:
            self._register_name(element, context, name_text, ns, present)
        if package_text is not None and type_text is not None:
            self._frame_node(element, context, present, name_text, package_text, type_text,
                             None if ns_unresolved else ns, late.get("args"))
            if package_text == RSP_PACKAGE and not ns_unresolved:
                self._description_remap(element, context, ns)
        if is_test or package is None or node_type is None:
            return
        if type_text is not None and type_text != STATIC_TF_TYPE:
            return
        if package_text is not None and package_text not in TF_PACKAGES:
            return
        if type_text is None and package_text is None:
            return
        self._transform(element, context, present, name_value or (), ns, ns_unresolved,
                        package, node_type, late.get("args", ()))

    def _required_text(self, element: Element, attribute: str,
                       context: _Context) -> tuple[Value | None, str | None]:
        """:meth:`_required`'s value and its text; a literal (most names, packages and
        types) is its own text, without a call."""
        written = element.attrib.get(attribute)
        if written is not None and "$" not in written:
            return ((written,) if written else ()), written
        value = self._required(element, attribute, context)
        return value, None if value is None else resolved_text(value)

    def _description_remap(self, element: Element, context: _Context, ns: str) -> None:
        """``<remap from="robot_description" to="X"/>`` in a robot_state_publisher: it reads
        its description from the parameter X (resolved in the node's namespace)."""
        for sub in element.children:
            if sub.tag.lower() != "remap" or self._condition(sub, context) is None:
                continue
            source, target = (self._resolve(sub, end, context) for end in ("from", "to"))
            source_text = None if source is None else resolved_text(source)
            target_text = None if target is None else resolved_text(target)
            if target_text and source_text in (DESCRIPTION_PARAM, "/" + DESCRIPTION_PARAM):
                self.remapped_descriptions.append(ns_join(ns, target_text))

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
        # Most nodes have neither: no call for an absent one.
        required = ("required" in late
                    and self._check_bool(context, element, late["required"], "required"))
        respawn = ("respawn" in late
                   and self._check_bool(context, element, late["respawn"], "respawn"))
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
                       namespace: str, condition: Condition) -> None:
        """roslaunch refuses two nodes with the same resolved name in one launch tree;
        two under conditions that exclude each other (``if="$(arg a)"`` and
        ``unless="$(arg a)"``) are never launched together."""
        resolved_name = ns_join(namespace, name)
        earlier = self.node_names.get(resolved_name)
        if earlier is None:  # most names: no earlier node to compare with
            self.node_names[resolved_name] = [(context.filename, element, condition)]
            return
        first = next((e for e in earlier if not e[2].excludes(condition)), None)
        if len(earlier) < MAX_SAME_NAME:
            earlier.append((context.filename, element, condition))
        if first is None:
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
            reasons = why_unresolved(file_value, quoted=True)
            self._report("unresolved", context.filename, element,
                         f"include file {shown_value(file_value)!r} not followed: {reasons}")
            return
        absolute = self._locate(path, context.filename)
        if absolute is None:
            located = self.options.packages.locate(
                path if os.path.isabs(path) else os.path.join(
                    os.path.dirname(context.filename), path),
                near=os.path.dirname(context.filename), ros_version=1)
            if located.path is None and not located.absent and not self.options.study_errors:
                self._report("unresolved", context.filename, element,
                             f"include file {self._quoted(path)!r} not followed: "
                             f"{located.reason}")
                return
            if located.path is None:
                self._error(context, element,
                            f"included file not found: {self._quoted(path)}", attribute="file")
                return
            absolute = located.path
        call = include_call(absolute, child.args)
        if call in context.calls:
            # roslaunch would recurse for ever only if the file comes back with the same
            # argument values under a condition that held: a recursion that changes its
            # arguments ends when its condition turns false (followed below, to the depth
            # bound), and one whose values or condition are unknown may end too.
            cycle = " -> ".join(self._display(p) for p in (*context.chain, absolute))
            if child.condition.always and all(is_resolved(v) for v in child.args.values()):
                self._error(context, element, f"include cycle: {cycle}")
            else:
                self._report("unresolved", context.filename, element,
                             f"include of {self._display(absolute)} repeats with the same "
                             f"unknown argument values or condition ({cycle}); not followed")
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
                        f"cannot read included file {self._quoted(path)}: "
                        f"{exc.strerror or exc}")
            return
        self.budget.produce(len(data))
        if is_ros2_xml(data):
            # The package found is the ROS 2 version of one a ROS 1 environment has (a
            # migrated repository keeps its old ROS 1 tests): roslaunch would open the ROS 1
            # package's file, which the workspace does not hold.
            self._report("unresolved", context.filename, element,
                         f"include of {self._display(absolute)} not followed: it is ROS 2 "
                         f"launch XML, which roslaunch does not read (the package found is "
                         f"built for ROS 2; a ROS 1 environment has its own)")
            return
        root = self._parse(absolute, data)
        if root is None:
            return
        self._path = absolute
        child.filename = absolute
        child.scope = child.side_scope = None
        child.chain = (*context.chain, absolute)
        child.calls = (*context.calls, call)
        child.included_from = (self._display(context.filename), element.line)
        site = self._included_at[absolute] = Location(child.included_from[0], element.line,
                                                      element.column)
        self.include_sites.setdefault(self._display(absolute), site)
        self._launch_conditions(root, child)
        self._walk(root.children, child)
        self._path = context.filename
        if not pass_all:
            unused = [name for name in args_passed if name not in child.arg_names]
            if unused:
                self._error(context, element,
                            f"unused args [{', '.join(unused)}] for include of "
                            f"[{self._quoted(path)}]")

    @staticmethod
    def _locate(path: str, including_file: str) -> str | None:
        # roslaunch opens a relative path from the working directory; a linter run from
        # elsewhere also tries the including file's folder, which is what authors mean.
        candidates = [path] if os.path.isabs(path) else [
            os.path.abspath(path), os.path.join(os.path.dirname(including_file), path)
        ]
        for candidate in candidates:
            if reads.is_file(candidate):
                return os.path.abspath(candidate)
        # A folder, device or FIFO of that name is found, so that reading it says what it is.
        for candidate in candidates:
            if reads.exists(candidate):
                return os.path.abspath(candidate)
        return None

    def _transform(self, element: Element, context: _Context, present: Condition,
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
        site = Site(self._display(context.filename), element.line, element.column,
                    self.root_display, context.included_from, present)
        command = Command(name, namespace,
                          text_of(package) if package_text is None else package_text,
                          text_of(node_type) if type_text is None else type_text,
                          element.attrib.get("args") or "", text_of(args_value), words.words)
        if known:
            reading = Reading(form, decoded.parent, decoded.child, decoded.translation,
                              decoded.rotation, decoded.period_ms, arity_issue, number_issues)
        else:
            reading = Reading(form, arity_issue=arity_issue, number_issues=number_issues)
        transform = transform_record(site, command, reading, unresolved, reasons)
        self.transforms.append(transform)
        if transform.unresolved:
            self._report("unresolved", context.filename, element,
                         unresolved_message(transform), node=name)


def load_ros1(path: str, options: LoadOptions, data: bytes | None = None) -> LaunchTree:
    """Load ``path`` (or ``data`` standing for it) into a :class:`LaunchTree`."""
    return Ros1Loader(options).load(path, data)


__all__ = [
    "MAX_FILES_PER_TREE",
    "MAX_INCLUDE_DEPTH",
    "MAX_NESTING",
    "STATIC_TF_TYPE",
    "TF_PACKAGES",
    "LoadOptions",
    "Ros1Loader",
    "load_ros1",
    "make_global_ns",
    "ns_join",
    "relative_to_cwd",
    "rosparam_body_problem",
    "yaml_root_kind",
]
