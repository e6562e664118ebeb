"""The ROS 1 loader's tags other than ``<node>`` and ``<include>``: ``<group>``,
``<arg>``, ``<param>``, ``<rosparam>``, ``<remap>``, ``<env>``, ``<machine>``."""

from __future__ import annotations

import os

from launch_linter.frontends.param_syntax import yaml_file_syntax_error, yaml_syntax_error
from launch_linter.frontends.params import (
    parse_yaml,
    read_yaml_file_placed,
    ros1_params_keyed,
)
from launch_linter.frontends.robot.sources import (
    DESCRIPTION_PARAM,
    from_ros1_param,
    is_description_name,
    params_from_yaml,
)
from launch_linter.frontends.ros1_base import (
    _MACHINE_ATTRS,
    _MACHINE_OLD_ATTRS,
    _ROSPARAM_ATTRS,
    MAX_NESTING,
    Ros1Base,
    _Context,
)
from launch_linter.frontends.ros1_checks import (
    _checkable_path,
    _conjoin,
    _is_int,
    _is_positive_number,
    _param_value_problem,
    _reasons,
    rosparam_body_problem,
)
from launch_linter.frontends.ros1_names import (
    _canonical_name,
    _is_legal_name,
    make_global_ns,
    ns_join,
)
from launch_linter.frontends.ros1_root_args import undeclared_root_arg
from launch_linter.model.record import replace
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.model.transform import ALWAYS, Condition
from launch_linter.resolve import reads
from launch_linter.resolve.substitution import SubstitutionError, resolve
from launch_linter.resolve.value import Hole, Value, resolved_text, text_of
from launch_linter.resolve.xml_safe import Element, line_starts

MAX_OTHER_DESCRIPTIONS = 256
"""Parameters of other names kept as possible descriptions (bounded per tree)."""
MAX_YAML_BODIES = 64
"""``<rosparam>`` texts whose documents a tree keeps for its node to read (a node's are
read right after its children are judged)."""
_PARAM_SOURCES = ("textfile", "binfile", "command")
_PARAM_SOURCE_NAMES = frozenset(_PARAM_SOURCES)
"""Where a ``<param>`` takes its value from, other than ``value``, in roslaunch's order."""
NODELET = ("nodelet", "nodelet")
NODELET_ARGS_UNKNOWN = "nodelet (arguments not resolved)"
"""The program of a ``nodelet`` node whose arguments the linter cannot read: unknown."""


def nodelet_loaded(args: str | None) -> str | None:
    """What a ``nodelet`` node runs, by its arguments (nodelet's ``nodelet.cpp``): None
    for ``manager`` (a container that publishes nothing itself), the nodelet type
    (``pkg/Class``) for ``load TYPE MANAGER`` and ``standalone TYPE``, else unknown
    (nodelet noetic-devel c7973f0 ``nodelet/src/nodelet.cpp`` 106-136, 316-383)."""
    words = args.split() if args is not None else []
    if words and words[0] == "manager":
        return None
    if len(words) >= {"load": 3, "standalone": 2}.get(words[0] if words else "", 9):
        return words[1]
    return NODELET_ARGS_UNKNOWN


def _loads_values(attrib: dict[str, str]) -> bool:
    """Whether a ``<rosparam>`` loads a document's values as parameters: a literal
    ``load`` command without a ``param`` to put it under."""
    return (attrib.get("command") or "load") == "load" and "param" not in attrib


class Ros1Tags(Ros1Base):
    """The tags of a launch file, walked in order as roslaunch does."""

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
            self._error(context, element, f"<{element.tag}> tag has an empty 'ns' attribute",
                        attribute="ns")
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
        conditional = bool(condition.literals)  # not ``always``: a property call per arg
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
        # Resolved in roslaunch's order (name, value, default, doc); a text without "$" is
        # its own value, without the calls of ``_required``/``_resolve`` (most args).
        name_text = attrib.get("name")
        literal_name = name_text is not None and "$" not in name_text
        name_value = (((name_text,) if name_text else ()) if literal_name
                      else self._required(element, "name", context))
        value_text = attrib.get("value")
        value = (None if value_text is None
                 else self._substitute(value_text, element, "value", context, None)
                 if "$" in value_text else (value_text,) if value_text else ())
        default_text = attrib.get("default")
        default = (None if default_text is None
                   else self._substitute(default_text, element, "default", context, None)
                   if "$" in default_text else (default_text,) if default_text else ())
        doc = attrib.get("doc")
        if doc is not None and "$" in doc:
            self._substitute(doc, element, "doc", context, None)
        if name_value is None:
            return
        if value is not None and default is not None:
            self._error(context, element, "<arg> tag must have one and only one of value/default.")
        name = name_text if literal_name else resolved_text(name_value)
        if name is None:
            self._report("unresolved", context.filename, element,
                         f"arg name {text_of(name_value)!r} cannot be resolved; the arg is ignored")
            return
        for text in (value_text, default_text):
            if text is not None and "$(" in text:
                source = self._env_in_text(text)
                if source is not None:
                    self._env_args[name] = source
        written = value if value is not None else default
        if written is not None and not (
                len(written) == 1 and type(written[0]) is str and written[0]):
            # A value of one non-empty text is no blank default (``_note_blank`` would
            # return at once): most args skip the call.
            self._note_blank(context, element, name, value, default)
        self._declare(context, element, name, value, default, condition)

    def _note_blank(self, context: _Context, element: Element, name: str,
                    value: Value | None, default: Value | None) -> None:
        """Remember an arg that is empty because a root file's default is: declared with
        ``default=""`` in the root (whose command line could set it), or set empty from
        such an arg (a default that reads it, an include passing it on)."""
        written = value if value is not None else default
        if written is None or resolved_text(written) != "":
            return
        origin = self._blank_arg_in(element.attrib.get("value" if value is not None
                                                       else "default", ""))
        if origin is not None:
            self._blank_args[name] = origin
        elif (value is None and element.attrib.get("default") == "" and context.open_args
              and context.include_args is None and name not in context.args):
            self._blank_args[name] = name

    def _param(self, element: Element, context: _Context,
               anon: dict[str, str] | None = None) -> None:
        attrib = element.attrib
        condition = ALWAYS
        if "if" in attrib or "unless" in attrib:
            found = self._condition(element, context, anon)
            if found is None:
                return
            condition = found
        value_text = attrib.get("value")
        written = (None if value_text is None
                   else self._substitute(value_text, element, "value", context, anon)
                   if "$" in value_text else (value_text,) if value_text else ())
        if anon is not None and written is not None and "anon" not in (value_text or ""):
            # Without an anonymous name the value is the same in any anonymous-name table.
            self._child_values[element] = written
        count = int(written is not None)
        sources: dict[str, Value] = {}
        if not _PARAM_SOURCE_NAMES.isdisjoint(attrib):  # most have a value only
            for key in _PARAM_SOURCES:
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
        described = False
        if DESCRIPTION_PARAM in name_text and is_description_name(resolved_text(name_value)):
            if written is not None:
                sources["value"] = written
            self._description(element, context, _conjoin(context.condition, condition), sources)
            described = True
        elif "/" in name_text and anon is None:
            # ``<param name="hector_mapping/pub_map_odom_transform" .../>`` beside the node.
            full = resolved_text(name_value)
            text = None if written is None else resolved_text(written)
            if full is not None:
                always = _conjoin(context.condition, condition).always
                self.node_params.append((full, text if text is not None and always
                                         else UNKNOWN_VALUE))
        elif ("tf_prefix" in name_text and name_text.strip() in ("tf_prefix", "~tf_prefix")
              and anon is None):
            # robot_state_publisher finds tf_prefix by searchParam, from its namespace up.
            text = None if written is None else resolved_text(written)
            scope = None if context.ns_unresolved else context.ns
            self.tf_prefixes.append((scope, UNKNOWN_VALUE if text is None else text))
        if sources and not described and anon is None and not context.ns_unresolved:
            # A command or file under another name: a description if a robot_state_publisher
            # reads it by a remap of robot_description (known once the tree is read).
            full = resolved_text(name_value)
            if full:
                self._other_description(element, context, _conjoin(context.condition, condition),
                                        sources, ns_join(context.ns, full))
        param_type = attrib.get("type")
        if written is not None and param_type is not None:
            value = resolved_text(written)
            problem = (None if value is None
                       else _param_value_problem(value.strip(), param_type or "auto"))
            if problem is not None:
                self._error(context, element, f"Invalid <param> tag: {problem}",
                            attribute="value")

    def _description(self, element: Element, context: _Context, condition: Condition,
                     values: dict[str, Value]) -> None:
        source = from_ros1_param(values, self._display(context.filename), element.line,
                                 element.column, condition, os.path.dirname(context.filename),
                                 element.attrib.get("command", ""))
        if source is not None:
            namespace = None if context.ns_unresolved else context.ns
            self.descriptions.append(replace(source, namespace=namespace))

    def _other_description(self, element: Element, context: _Context, condition: Condition,
                           values: dict[str, Value], name: str) -> None:
        if len(self.other_descriptions) >= MAX_OTHER_DESCRIPTIONS:
            return
        source = from_ros1_param(values, self._display(context.filename), element.line,
                                 element.column, condition, os.path.dirname(context.filename))
        if source is not None:
            self.other_descriptions.append((name, source))

    def _frame_node(self, element: Element, context: _Context, present: Condition,
                    name: str | None, package: str, executable: str,
                    namespace: str | None, args: Value | None = None) -> None:
        """Keep a launched node with the parameters it is given inside its element
        (``<param>``, ``<rosparam>`` text and files); the knowledge base tells which of
        them matter. A ``nodelet`` node is the nodelet its arguments load. ``present``:
        the node's presence condition (its context's and its own, conjoined)."""
        params: list[tuple[str, str]] = []
        unread: list[str] = []
        lines: list[tuple[str, str, int, int]] = []
        path = self._display(context.filename)
        for sub in element.children:
            if sub.tag == "param":
                key = sub.attrib.get("name")
                if not key:
                    continue
                value = sub.attrib.get("value")
                known: str | None = value
                if value is None:
                    known = None
                elif "$" in value:
                    # Anonymous names are left alone: resolving one here would renumber.
                    # A value ``_param`` resolved already is not resolved again.
                    resolved = self._child_values.get(sub)
                    known = None if "$(anon" in value else resolved_text(
                        resolved if resolved is not None else self._resolve_text(
                            value, sub, "value", context, dict(context.anon)))
                key = key.lstrip("~")
                params.append((key, UNKNOWN_VALUE if known is None else known))
                lines.append((key, path, sub.line, sub.column))
            elif sub.tag == "rosparam":
                found, why, places = self._rosparam_values(sub, context)
                params.extend(found)
                lines.extend((key, *place) for (key, _), place in zip(found, places))
                if why:
                    unread.append(why)
        plugin = (nodelet_loaded(None if args is None else resolved_text(args))
                  if (package, executable) == NODELET else None)
        self.nodes.append(NodeRecord(
            path, element.line, element.column, package,
            executable, name, tuple(params), present,
            plugin=plugin, unread=tuple(unread), namespace=namespace, ros=1,
            param_lines=tuple(lines),
        ))

    def _rosparam_values(self, element: Element, context: _Context
                         ) -> tuple[list[tuple[str, str]], str | None, list[tuple[str, int, int]]]:
        """The parameters a ``<rosparam>`` loads (its text or its file, under its ``ns``),
        why they are not read when they are not, and where each is written (a file's key;
        the ``<rosparam>`` element for its text)."""
        attrib = element.attrib
        if not _loads_values(attrib):
            return [], None, []
        ns_text = attrib.get("ns", "")
        if "$" in ns_text:
            ns_text = resolved_text(self._resolve_text(ns_text, element, "ns", context,
                                                       dict(context.anon))) or ""
        here = (self._display(context.filename), element.line, element.column)
        file_text = attrib.get("file")
        if file_text is not None:
            path = resolved_text(self._resolve_text(file_text, element, "file", context,
                                                    dict(context.anon)))
            if path is None:
                return [], f"parameter file {file_text!r} is not resolved", []
            document, why, keys = read_yaml_file_placed(path)
            shown = self._display(path)
        elif element.text and "$(" not in element.text:
            document, why = self._yaml_body(element.text)
            keys, shown = {}, ""
            if why is not None:
                # Without PyYAML, flat ``key: value`` lines are still read.
                found = params_from_yaml(element.text)
                return found, why, [here] * len(found)
        else:
            return [], None if not element.text else "<rosparam> text with substitutions", []
        if why is not None:
            return [], why, []
        params, places = [], []
        substituted = attrib.get("subst_value", "false")
        if "$" in substituted:
            substituted = resolved_text(self._resolve_text(
                substituted, element, "subst_value", context, dict(context.anon))) or ""
        for key, value, at in ros1_params_keyed(document, ns_text):
            if "$(" in value and substituted.strip().lower() != "false":
                value = self._substituted(value, substituted, context)
            params.append((key, value))
            line_column = keys.get(at)
            places.append(here if line_column is None
                          else (shown, line_column[0], line_column[1]))
        return params, None, places

    def _yaml_body(self, text: str) -> tuple[object, str | None]:
        """``parse_yaml(text)``, once per text in a tree: a node's ``<rosparam>`` text is
        judged (:meth:`_rosparam`) and then read (:meth:`_frame_node`)."""
        read = self._yaml_bodies.get(text)
        if read is None:
            if len(self._yaml_bodies) >= MAX_YAML_BODIES:  # the documents are not kept
                self._yaml_bodies.clear()
            read = self._yaml_bodies[text] = parse_yaml(text)
        return read

    def _body_syntax_error(self, element: Element, text: str) -> str | None:
        """``yaml_syntax_error`` of a ``<rosparam>`` text (``text``, as resolved); a text
        that :meth:`_rosparam_values` reads is parsed once for both: one that reads as a
        document composes, so only a failure is judged again."""
        if (text == element.text and "$(" not in text and _loads_values(element.attrib)
                and self._yaml_body(text)[1] is None):
            return None
        return yaml_syntax_error(text)

    def _substituted(self, value: str, substituted: str, context: _Context) -> str:
        """A value of a ``<rosparam>`` file as roslaunch loads it under ``subst_value``
        (``substituted``, the attribute's value, '' when unresolved): its substitutions
        resolved when the attribute is true, else (or when one cannot be resolved)
        unknown."""
        if substituted.strip().lower() != "true":
            return UNKNOWN_VALUE
        try:
            text = resolved_text(resolve(value, self._scope(context, None)))
        except SubstitutionError:
            return UNKNOWN_VALUE
        return UNKNOWN_VALUE if text is None else text

    def _rosparam(self, element: Element, context: _Context,
                  anon: dict[str, str] | None = None) -> None:
        if self._condition(element, context, anon) is None:
            return
        if anon is None:
            # Beside the nodes: ``NODE/param`` names reach a node by its name.
            found, why, _ = self._rosparam_values(element, context)
            self.node_params.extend(found)
            if why:
                self.params_unread.append(why)
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
        ) and not reads.is_file(file_text):
            self._error(context, element,
                        f"error loading <rosparam> tag: file does not exist "
                        f"[{self._quoted(file_text)}]", attribute="file")
        elif file_text and (command_text or "load") == "load" and not substitute:
            # loader.py's load_rosparam: yaml.safe_load of the file, and a MarkedYAMLError
            # is "file ... contains invalid YAML" (with subst_value the text parsed is
            # another one, so it is judged only without).
            invalid = yaml_file_syntax_error(file_text) if reads.is_file(file_text) else None
            if invalid is not None:
                self._error(context, element,
                            f"error loading <rosparam> tag: file {self._quoted(file_text)} "
                            f"contains invalid YAML: {invalid}")
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
            invalid = None if text is None else self._body_syntax_error(element, text)
            problem = (f"Error within YAML block: {invalid}" if invalid is not None
                       else None if text is None else rosparam_body_problem(text, has_param))
            if problem is not None:
                self._error(context, element, f"error loading <rosparam> tag: {problem}")

    def _undeclared_at_root(self, name: str, filename: str, chain: tuple[str, ...]) -> None:
        """An arg the root declares nowhere, read under no undecided condition in the root
        or in a file it includes passing all args (see :mod:`.ros1_root_args`)."""
        element, seen = self._element, self._condition_seen
        if (element is None or self.options.study_errors or self._in_undecided_node
                or (seen is not None and seen[0] is element and not seen[1])
                or (chain[0], "\x00" + name) in self._missing_reported
                or self._root_may_declare(name)):
            return
        self._missing_reported.add((chain[0], "\x00" + name))
        if filename == chain[0] and self._root_lines is None:
            self._root_lines = line_starts(self._root_data)
        site = self._included_at.get(chain[1]) if len(chain) > 1 else None
        problem = undeclared_root_arg(name, filename, chain[0], self._display, element,
                                      self._label, (self._root_data, self._root_lines or []),
                                      site)
        if problem is not None:
            self.problems.append(problem)

    def _remap(self, element: Element, context: _Context) -> None:
        if self._condition(element, context) is None:
            return
        ends = (self._required(element, "from", context), self._required(element, "to", context))
        for value in ends:
            text = None if value is None else resolved_text(value)
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
                                                            anon)))
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

    # -- defined by a subclass, further on ---------------------------------------------------
    def _include(self, element: Element, context: _Context) -> None:
        """Defined by :class:`.ros1.Ros1Loader`."""
        raise NotImplementedError

    def _node(self, element: Element, context: _Context, is_test: bool = False) -> None:
        """Defined by :class:`.ros1.Ros1Loader`."""
        raise NotImplementedError
