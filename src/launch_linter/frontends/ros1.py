"""ROS 1 launch XML to static transforms, with roslaunch's loading rules.

The walk follows ``roslaunch.xmlloader``: tags are processed in order, ``<arg>`` scoping
(groups copy, includes see only what is passed), ``if``/``unless``, namespaces and
``<include>``. Where roslaunch would stop with an error we record a ``roslaunch_error``
diagnostic and go on; where a value cannot be known statically it becomes a hole, and the
transform stays in the output marked unresolved, with its presence condition.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from launch_linter.decode import decode_ros1, is_number
from launch_linter.frontends.tokens import split_args
from launch_linter.frontends.xml_safe import MAX_BYTES, Element, XmlError, parse_xml
from launch_linter.model.diagnostic import Category, Diagnostic, Severity
from launch_linter.model.launch import Comment, FileStatus, LaunchTree
from launch_linter.model.transform import Condition, ConditionLiteral, StaticTransform
from launch_linter.resolve.packages import PackageIndex
from launch_linter.resolve.substitution import SubstitutionError, SubstitutionScope, resolve, to_bool
from launch_linter.resolve.value import Hole, Value, holes, is_resolved, resolved_text, text_of

STATIC_TF_TYPE = "static_transform_publisher"
TF_PACKAGES = ("tf", "tf2_ros")
MAX_INCLUDE_DEPTH = 32
MAX_FILES_PER_TREE = 2_000


@dataclass(frozen=True, slots=True)
class LoadOptions:
    """What the command line tells the loader."""

    args: Mapping[str, str] = field(default_factory=dict)
    env: Mapping[str, str] = field(default_factory=dict)
    packages: PackageIndex = field(default_factory=lambda: PackageIndex([]))
    display_path: Callable[[str], str] = os.path.relpath


class _AnonNames:
    """roslaunch's anonymous names, made stable: ``id_anon<N>``, N counted per root."""

    def __init__(self) -> None:
        self.count = 0

    def make(self, table: dict[str, str], anon_id: str) -> str:
        if anon_id not in table:
            self.count += 1
            table[anon_id] = f"{anon_id}_anon{self.count}"
        return table[anon_id]


@dataclass(slots=True)
class _Context:
    ns: str
    ns_unresolved: bool
    filename: str
    args: dict[str, Value]
    arg_names: list[str]
    anon: dict[str, str]
    condition: Condition
    chain: tuple[str, ...]
    included_from: tuple[str, int] | None
    pass_all_args: bool = False
    include_args: dict[str, Value] | None = None

    def copy(self) -> _Context:
        return _Context(
            self.ns, self.ns_unresolved, self.filename, dict(self.args), list(self.arg_names),
            dict(self.anon), self.condition, self.chain, self.included_from,
            self.pass_all_args, self.include_args,
        )


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


class Ros1Loader:
    """Loads one root file (and its includes) into a :class:`LaunchTree`."""

    def __init__(self, options: LoadOptions) -> None:
        self.options = options
        self.transforms: list[StaticTransform] = []
        self.diagnostics: list[Diagnostic] = []
        self.files: list[str] = []
        self.comments: list[Comment] = []
        self.element_lines: list[tuple[str, int]] = []
        self.anon = _AnonNames()
        self.root_display = ""

    # -- diagnostics -------------------------------------------------------------------
    def _report(
        self, rule: str, path: str, element: Element | None, message: str, node: str | None = None
    ) -> None:
        category, severity = {
            "parse_error": (Category.LAUNCH, Severity.ERROR),
            "roslaunch_error": (Category.LAUNCH, Severity.ERROR),
            "unresolved": (Category.LAUNCH, Severity.INFO),
        }[rule]
        line, column = (element.line, element.column) if element else (1, 1)
        self.diagnostics.append(
            Diagnostic(rule, category, severity, self._display(path), line, column, message, node)
        )

    def _display(self, path: str) -> str:
        return self.options.display_path(path)

    # -- entry -------------------------------------------------------------------------
    def load(self, path: str, data: bytes | None = None) -> LaunchTree:
        absolute = os.path.abspath(path)
        self.root_display = self._display(absolute)
        status = FileStatus.OK
        if data is None:
            try:
                data = _read(absolute)
            except OSError as exc:
                self._report("parse_error", absolute, None, f"cannot read file: {exc.strerror or exc}")
                return self._tree(FileStatus.UNREADABLE)
        root = self._parse(absolute, data, None)
        if root is None:
            status = FileStatus.PARSE_ERROR
        else:
            context = _Context(
                ns=self._root_namespace(),
                ns_unresolved=False,
                filename=absolute,
                args={k: (v,) if v else () for k, v in self.options.args.items() if not k.startswith("_")},
                arg_names=[],
                anon={},
                condition=Condition(),
                chain=(absolute,),
                included_from=None,
            )
            self._walk(root.children, context)
        return self._tree(status)

    def _tree(self, status: FileStatus) -> LaunchTree:
        return LaunchTree(
            root=self.root_display,
            status=status,
            transforms=tuple(self.transforms),
            diagnostics=tuple(self.diagnostics),
            files=tuple(self.files),
            comments=tuple(self.comments),
            element_lines=tuple(self.element_lines),
        )

    def _root_namespace(self) -> str:
        ns = self.options.args.get("__ns") or self.options.env.get("ROS_NAMESPACE") or "/"
        try:
            return make_global_ns(ns)
        except ValueError:
            return "/"

    def _parse(self, absolute: str, data: bytes, at: tuple[str, Element] | None) -> Element | None:
        display = self._display(absolute)
        if display not in self.files:
            self.files.append(display)
        try:
            document = parse_xml(data)
        except XmlError as exc:
            self.diagnostics.append(
                Diagnostic(
                    "parse_error", Category.LAUNCH, Severity.ERROR, display, exc.line, exc.column,
                    f"not well-formed XML: {exc.message}",
                )
            )
            return None
        self.comments.extend(Comment(display, line, text) for line, text in document.comments)
        self.element_lines.extend((display, line) for line in document.element_lines)
        if document.root.tag != "launch":
            self.diagnostics.append(
                Diagnostic(
                    "parse_error", Category.LAUNCH, Severity.ERROR, display, document.root.line,
                    document.root.column,
                    f"root element is <{document.root.tag}>, not <launch>",
                )
            )
            return None
        return document.root

    # -- substitution helpers ---------------------------------------------------------
    def _scope(self, context: _Context) -> SubstitutionScope:
        return SubstitutionScope(
            args=context.args,
            env=self.options.env,
            find=self.options.packages.find,
            anon=lambda anon_id: self.anon.make(context.anon, anon_id),
            filename=context.filename,
        )

    def _resolve(self, element: Element, attribute: str, context: _Context) -> Value | None:
        """The attribute's value (None when absent); roslaunch errors become holes."""
        text = element.get(attribute)
        if text is None:
            return None
        try:
            return resolve(text, self._scope(context))
        except SubstitutionError as exc:
            self._report("roslaunch_error", context.filename, element, f"{attribute}: {exc}")
            return (Hole(text, str(exc)),)

    def _condition(self, element: Element, context: _Context) -> Condition | None:
        """The extra presence condition of ``element``; None when it is skipped."""
        if_text, unless_text = element.get("if"), element.get("unless")
        if if_text is not None and unless_text is not None:
            self._report(
                "roslaunch_error", context.filename, element,
                "cannot set both 'if' and 'unless' on the same tag",
            )
        attribute = "if" if if_text is not None else "unless" if unless_text is not None else None
        if attribute is None:
            return Condition()
        value = self._resolve(element, attribute, context) or ()
        try:
            truth = to_bool(value)
        except ValueError as exc:
            self._report("roslaunch_error", context.filename, element, f"{attribute}: {exc}")
            truth = None
        if truth is None:
            return Condition((ConditionLiteral(text_of(value), attribute == "if"),))
        return Condition() if truth == (attribute == "if") else None

    # -- tags --------------------------------------------------------------------------
    def _walk(self, elements: list[Element], context: _Context) -> None:
        for element in elements:
            tag = element.tag
            if tag == "arg":
                self._arg(element, context)
            elif tag == "group":
                self._group(element, context)
            elif tag == "node":
                self._node(element, context.copy())
            elif tag == "include":
                self._include(element, context)

    def _child_namespace(self, element: Element, context: _Context, tag: str) -> _Context | None:
        child = context.copy()
        ns_value = self._resolve(element, "ns", context)
        if ns_value is None:
            return child
        ns = text_of(ns_value)
        if not ns:
            if tag == "group":
                self._report("roslaunch_error", context.filename, element,
                             "<group> tag has an empty 'ns' attribute")
            return child
        try:
            if ns.startswith("/"):
                child.ns = make_global_ns(ns)
            elif ns == "~" or ns.startswith("~"):
                raise ValueError(f"cannot turn [{ns}] into a global name")
            else:
                child.ns = make_global_ns(ns_join(context.ns, ns))
        except ValueError as exc:
            self._report("roslaunch_error", context.filename, element, str(exc))
            return None
        child.ns_unresolved = context.ns_unresolved or not is_resolved(ns_value)
        return child

    def _group(self, element: Element, context: _Context) -> None:
        condition = self._condition(element, context)
        if condition is None:
            return
        child = self._child_namespace(element, context, "group")
        if child is None:
            return
        child.condition = context.condition & condition
        self._walk(element.children, child)

    def _add_arg(self, context: _Context, element: Element | None, name: str,
                 value: Value | None, default: Value | None) -> None:
        if name in context.arg_names:
            if not context.pass_all_args and element is not None:
                self._report("roslaunch_error", context.filename, element,
                             f"arg '{name}' has already been declared")
        else:
            context.arg_names.append(name)
        target = context.args if context.include_args is None else context.include_args
        if value is not None:
            if name in target and not context.pass_all_args and element is not None:
                self._report("roslaunch_error", context.filename, element,
                             f"cannot override arg '{name}', which has already been set")
                return
            target[name] = value
        elif default is not None and name not in target:
            target[name] = default

    def _arg(self, element: Element, context: _Context) -> None:
        condition = self._condition(element, context)
        if condition is None:
            return
        name_value = self._resolve(element, "name", context)
        if name_value is None:
            self._report("roslaunch_error", context.filename, element,
                         "<arg> tag is missing required attribute: 'name'")
            return
        name = resolved_text(name_value)
        if name is None:
            self._report("unresolved", context.filename, element,
                         f"arg name {text_of(name_value)!r} cannot be resolved")
            return
        value = self._resolve(element, "value", context)
        default = self._resolve(element, "default", context)
        if value is not None and default is not None:
            self._report("roslaunch_error", context.filename, element,
                         "<arg> tag must have one and only one of value/default.")
        if not condition.always:
            hole = (Hole(f"$(arg {name})", f"arg '{name}' is set under an unresolved condition"),)
            value = hole if value is not None else None
            default = hole if default is not None else None
        self._add_arg(context, element, name, value, default)

    def _include(self, element: Element, context: _Context) -> None:
        condition = self._condition(element, context)
        if condition is None:
            return
        file_value = self._resolve(element, "file", context)
        if file_value is None:
            self._report("roslaunch_error", context.filename, element,
                         "<include> tag is missing required attribute: 'file'")
            return
        pass_all = False
        pass_value = self._resolve(element, "pass_all_args", context)
        if pass_value is not None:
            text = text_of(pass_value).lower()
            if text in ("true", "false"):
                pass_all = text == "true"
            else:
                self._report("roslaunch_error", context.filename, element,
                             f"invalid bool value for pass_all_args: {text_of(pass_value)}")
        child = self._child_namespace(element, context, "include")
        if child is None:
            return
        child.condition = context.condition & condition
        child.arg_names = []
        child.include_args = {}
        if pass_all:
            for name, value in context.args.items():
                self._add_arg(child, None, name, value, None)
            child.pass_all_args = True
        for sub in element.children:
            if sub.tag.lower() == "arg":
                self._arg(sub, child)
        passed = child.include_args or {}
        for name in child.arg_names:
            if name not in passed:
                self._report("roslaunch_error", context.filename, element,
                             f"include args must have declared values ({name})")
        args_passed = list(passed)
        child.args, child.include_args, child.arg_names, child.anon = dict(passed), None, [], {}

        path = resolved_text(file_value)
        if path is None:
            reasons = "; ".join(f"{h.text}: {h.reason}" for h in holes(file_value))
            self._report("unresolved", context.filename, element,
                         f"include file {text_of(file_value)!r} not followed: {reasons}")
            return
        absolute = self._locate(path, context.filename)
        if absolute is None:
            self._report("roslaunch_error", context.filename, element,
                         f"included file not found: {path}")
            return
        if absolute in context.chain:
            cycle = " -> ".join(self._display(p) for p in (*context.chain, absolute))
            self._report("roslaunch_error", context.filename, element, f"include cycle: {cycle}")
            return
        if len(context.chain) > MAX_INCLUDE_DEPTH or len(self.files) >= MAX_FILES_PER_TREE:
            self._report("roslaunch_error", context.filename, element,
                         f"includes nested deeper than {MAX_INCLUDE_DEPTH} levels; not followed")
            return
        try:
            data = _read(absolute)
        except OSError as exc:
            self._report("roslaunch_error", context.filename, element,
                         f"cannot read included file {path}: {exc.strerror or exc}")
            return
        root = self._parse(absolute, data, (context.filename, element))
        if root is None:
            return
        child.filename = absolute
        child.chain = (*context.chain, absolute)
        child.included_from = (self._display(context.filename), element.line)
        self._walk(root.children, child)
        if not pass_all:
            unused = [name for name in args_passed if name not in child.arg_names]
            if unused:
                self._report("roslaunch_error", context.filename, element,
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
        return None

    def _node(self, element: Element, context: _Context) -> None:
        condition = self._condition(element, context)
        if condition is None:
            return
        node_type = self._resolve(element, "type", context)
        package = self._resolve(element, "pkg", context)
        type_text = resolved_text(node_type) if node_type is not None else None
        package_text = resolved_text(package) if package is not None else None
        if node_type is None or package is None:
            return
        if type_text is not None and type_text != STATIC_TF_TYPE:
            return
        if package_text is not None and package_text not in TF_PACKAGES:
            return
        if type_text is None and package_text is None:
            return
        name_value = self._resolve(element, "name", context)
        if name_value is None:
            self._report("roslaunch_error", context.filename, element,
                         "<node> tag is missing required attribute: 'name'")
            name_value = ()
        name = text_of(name_value) or None
        if name is not None and is_resolved(name_value) and "/" in name:
            self._report("roslaunch_error", context.filename, element,
                         f"node name cannot contain a namespace: {name}")
        child = self._child_namespace(element, context, "node")
        if child is None:
            return
        namespace = child.ns.replace("//", "/")
        args_value = self._resolve(element, "args", context) or ()
        words = split_args(args_value)
        unresolved: list[str] = []
        if not is_resolved(name_value) or name is None:
            unresolved.append("name")
        if child.ns_unresolved:
            unresolved.append("namespace")
        if package_text is None:
            unresolved.append("package")
        if type_text is None:
            unresolved.append("executable")
        decode_package = package_text or (
            "tf" if len(words.words) in (9, 10) and is_number(words.words[-1]) else "tf2_ros"
        )
        decoded = decode_ros1(decode_package, words.words)
        arity_issue = decoded.arity_issue
        form = decoded.form
        if words.unresolved:
            indices = words.unresolved
            if decoded.form == "invalid" or decoded.arity_issue:
                unresolved.append("arity")
                arity_issue, form = None, "unknown"
            fields = {
                "translation": any(i in indices for i in (0, 1, 2)),
                "rotation": any(3 <= i < (6 if form == "ypr" else 7) for i in indices),
                "parent": decoded.parent_index in indices,
                "child": decoded.child_index in indices,
                "period_ms": decoded.period_ms is not None
                and decoded.numeric_indices[-1] in indices,
            }
            if form == "unknown":
                fields = dict.fromkeys(("translation", "rotation", "parent", "child"), True)
            unresolved.extend(k for k, v in fields.items() if v)
        number_issues = tuple(n for n in decoded.number_issues if n.index not in words.unresolved)
        all_holes = (*holes(name_value), *holes(args_value), *holes(package), *holes(node_type))
        reasons = tuple(dict.fromkeys(f"{h.text}: {h.reason}" for h in all_holes))
        transform = StaticTransform(
            path=self._display(context.filename),
            line=element.line,
            column=element.column,
            root=self.root_display,
            included_from=context.included_from,
            name=name,
            namespace=namespace,
            package=text_of(package),
            executable=text_of(node_type),
            args_written=element.get("args") or "",
            args=text_of(args_value),
            tokens=words.words,
            parent_written=None if form == "unknown" else decoded.parent,
            child_written=None if form == "unknown" else decoded.child,
            translation=None if form == "unknown" else decoded.translation,
            rotation=None if form == "unknown" else decoded.rotation,
            period_ms=None if form == "unknown" else decoded.period_ms,
            form=form,
            arity_issue=arity_issue,
            number_issues=number_issues,
            condition=context.condition & condition,
            unresolved=tuple(dict.fromkeys(unresolved)),
            unresolved_reasons=reasons,
        )
        self.transforms.append(transform)
        if transform.unresolved:
            self._report(
                "unresolved", context.filename, element,
                f"cannot resolve {', '.join(transform.unresolved)} statically"
                + (f": {'; '.join(reasons)}" if reasons else ""),
                node=name,
            )


def _read(path: str) -> bytes:
    with open(path, "rb") as handle:
        data = handle.read(MAX_BYTES + 1)
    return data


def load_ros1(path: str, options: LoadOptions, data: bytes | None = None) -> LaunchTree:
    """Load ``path`` (or ``data`` standing for it) into a :class:`LaunchTree`."""
    return Ros1Loader(options).load(path, data)
