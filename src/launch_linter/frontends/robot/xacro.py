"""xacro, expanded without running anything.

The real ``xacro`` evaluates ``${...}`` with Python's ``eval`` and can read any file; robot
descriptions are untrusted input to the linter, so this expander follows xacro's in-order
processing tag by tag but evaluates expressions with :mod:`launch_linter.resolve.safe_eval`
and reads only the files the description includes, through the bounded XML reader.

Supported: what docs/robot.md lists (properties, args, ``$(find)``/``$(env)``, includes,
macros with defaults and blocks, conditionals, ``xacro:call``/``element``/``attribute``).

What cannot be known becomes *unknown* rather than an error: an attribute keeps a reason
(``ExpandedNode.unknown``); a conditional whose value is unknown keeps its content, marked with
the condition text (``ExpandedNode.conditions``). Problems are :class:`XacroProblem` records;
bounds on files, include depth, macro depth, elements made and total work end the expansion with
a problem, never a hang.
"""

from __future__ import annotations

import os
import typing
from collections.abc import Callable, Mapping

from launch_linter.frontends.robot.xacro_data import Symbols, yaml_loader
from launch_linter.frontends.robot.xacro_globals import dunder_refusal, undefined_name
from launch_linter.frontends.robot.xacro_macros import (
    ParamArg,
    macro_params,
    never_inserted,
    params_read_as_args,
)
from launch_linter.frontends.robot.xacro_unexpanded import lexed, unprefixed_call
from launch_linter.frontends.robot.xacro_values import (
    _GLOB,
    _MATH_PREFIX,
    _PREFIX,
    _TOKEN,
    _WHOLE_EXPRESSION,
    DROPPED,
    KEPT,
    MALFORMED,
    MAX_FILES,
    MAX_INCLUDE_DEPTH,
    MAX_MACRO_DEPTH,
    MAX_OUTPUT_CHARS,
    MAX_OUTPUT_ELEMENTS,
    MAX_TEXT,
    MAX_WORK,
    PARAM_AS_ARG,
    PLUGIN_TEXT_TAGS,
    REFUSED,
    UNEXPANDED,
    UNKNOWN,
    ExpandedNode,
    Expansion,
    XacroProblem,
    _Abort,
    _Block,
    _boolean,
    _Macro,
    _Mismatch,
    _Placed,
    _Property,
    _Refused,
    _Table,
    _Unknown,
    expression_error,
    extension,
    legacy_tag,
    legacy_tags,
    valid_name,
)
from launch_linter.model.budget import Budget, BudgetExceeded
from launch_linter.resolve import reads
from launch_linter.resolve.safe_eval import (
    EvalError,
    EvalScope,
    EvalUndefined,
    evaluate,
    evaluate_value,
)
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml, read_launch_bytes


class XacroExpander:
    """Expands one description file; make a new one per (file, args)."""

    def __init__(
        self,
        args: Mapping[str, str | None],
        find: Callable[[str], str | None],
        env: Mapping[str, str] | None = None,
        locate: Callable[[str], str | None] | None = None,
        budget: Budget | None = None,
        display: Callable[[str], str] | None = None,
    ) -> None:
        self.args: dict[str, str | None] = dict(args)
        """xacro args; None is an arg given with a value the linter does not know."""
        self.display: Callable[[str], str] = display or str
        """How a message shows a path it quotes (the run's; by default as it is)."""
        self.find = find
        self.locate = locate
        """Where a missing file is installed from (a share path to its source file)."""
        self.env = dict(env or {})
        self._legacy = legacy_tags(self.env)
        """Whether unprefixed xacro tags are read (the target distribution's xacro)."""
        self.budget = budget
        """The launch tree's budget, charged with every unit of work besides MAX_WORK."""
        self._args_read: set[str] = set()
        self._env_read: set[str] = {"ROS_DISTRO"}
        self._cut_by_budget = False
        self._open = False
        """Whether something not followed could have defined a property (an unknown or
        kept problem so far): then a name nothing defines is unknown, not refused."""
        self.problems: list[XacroProblem] = []
        self.files: list[str] = []
        self._include_stack: list[str] = []
        self._macro_depth = 0
        self._work = self._made = 0
        self._resolving: list[str] = []
        self._path, self._line = "", 1
        self._produced = 0
        """Characters of attribute text made (a property copied 100,000 times passed 1 GB)."""
        self._parsed: dict[str, Element | None] = {}
        """Each file parsed once, however often it is included (the tree is only read)."""
        self._defines_macros = False
        self._yaml_files: dict[str, tuple[object, int] | _Unknown] = {}
        self._load_yaml: object | None = None
        self._call_site: tuple[str, int, int] | None = None
        self._include_site: tuple[str, int, int] | None = None
        self._param_args: dict[str, dict[tuple[int, int], list[ParamArg]]] = {}
        """Per file: its macros' parameters read as ``$(arg)``, by the macro's position."""
        self._arg_lines: dict[tuple[str, int, str], int] = {}
        self._dunder_defined: dict[str, tuple[str, int]] = {}
        """(file, element line, arg) of such a use -> the use's own line."""

    # -- entry -------------------------------------------------------------------------
    def expand(self, path: str, data: bytes | None = None) -> Expansion:
        """Expand the file ``path``, or ``data`` as if it were that file."""
        absolute = os.path.abspath(path)
        root: ExpandedNode | None = None
        try:
            element = self._read(absolute, None, data)
            if element is not None:
                root = self._node(element, absolute, ())
                self._include_stack.append(absolute)
                table = _Table()
                # xacro evaluates the root's own attributes first, before any xacro:arg
                # of the document is declared.
                self._attributes(element, root, table)
                self._children(element.children, absolute, table, root, ())
        except _Abort as stop:
            self.problems.append(XacroProblem(stop.path, stop.line, stop.message, True,
                                              stop.kind or UNKNOWN))
            root = None
        except RecursionError:
            self.problems.append(XacroProblem(
                self._path or absolute, self._line, "description nested too deeply", True))
            root = None
        return Expansion(root, self.problems, self.files, self._defines_macros,
                         frozenset(self._args_read), frozenset(self._env_read),
                         self._cut_by_budget)

    # -- bounds and problems -------------------------------------------------------------
    def _charge(self, units: int = 1) -> None:
        self._work += units
        if self._work > MAX_WORK:
            raise _Abort(f"expansion needs more than {MAX_WORK:,} steps; stopped",
                         self._path, self._line)
        if self.budget is not None:
            try:
                self.budget.step(units)
            except BudgetExceeded as exc:
                self._cut_by_budget = True
                raise _Abort(exc.message, self._path, self._line) from None

    def _problem(self, path: str, line: int, message: str, kind: str = UNKNOWN,
                 conditions: tuple[str, ...] = (), name: str | None = None,
                 own: bool = False) -> None:
        self._open = self._open or kind in (UNKNOWN, KEPT)
        if len(self.problems) < 1000:
            self.problems.append(XacroProblem(path, line, message, False, kind, conditions,
                                              name, own))

    def _refusal(self, path: str, line: int, message: str, refused: _Refused,
                 conditions: tuple[str, ...]) -> None:
        # An undeclared arg that is a macro's parameter is placed at the use's own line.
        arg = refused.arg
        at = line if arg is None else self._arg_lines.get((path, line, arg), line)
        # A call not matching its macro is xacro's stop whatever was left unread before
        # the definition; with the problems capped, nothing after the cap is known.
        own = isinstance(refused, _Mismatch) and len(self.problems) < 1000 and all(
            p.kind != UNKNOWN for p in self.problems[refused.seen:])
        if isinstance(refused, _Placed):  # a fault of another place: said there
            path, at, message = refused.path, refused.line, refused.detail
        self._problem(path, at, message, REFUSED, conditions, arg, own)

    def _read(self, absolute: str, at: tuple[str, int] | None,
              data: bytes | None = None) -> Element | None:
        where = at or (absolute, 1)
        if absolute not in self.files:
            if len(self.files) >= MAX_FILES:
                raise _Abort(f"description reads more than {MAX_FILES} files", *where)
            self.files.append(absolute)
        if absolute in self._parsed:
            return self._parsed[absolute]
        self._parsed[absolute] = root = self._parse(absolute, at, where, data)
        return root

    def _parse(self, absolute: str, at: tuple[str, int] | None,
               where: tuple[str, int], data: bytes | None) -> Element | None:
        try:
            data = read_launch_bytes(absolute) if data is None else data
        except OSError as exc:
            if at is None:
                raise _Abort(f"cannot read the file: {exc.strerror or exc}", *where) from None
            self._problem(where[0], where[1], f"cannot read included file "
                          f"{self.display(absolute)}: {exc.strerror or exc}")
            return None
        try:
            root = parse_xml(data, PLUGIN_TEXT_TAGS, all_text=True).root  # see _children
            self._param_args[absolute] = params_read_as_args(data, self._legacy)
            return root
        except XmlError as exc:  # xacro's minidom stops on a malformed file (ExpatError)
            if at is None:  # placed at the file and line: no need to name them
                raise _Abort(f"{MALFORMED}: {exc.message}", absolute, exc.line,
                             REFUSED if exc.malformed else None) from None
            message = f"{self.display(absolute)}:{exc.line}: {MALFORMED}: {exc.message}"
            if exc.malformed:
                raise _Placed(message, absolute, exc.line,
                              f"{MALFORMED}: {exc.message}") from None
            raise _Unknown(message) from None

    # -- text substitution -------------------------------------------------------------
    def evaluate_text(self, text: str, table: _Table) -> str:
        """xacro's ``eval_text``; raises :class:`_Unknown` for what cannot be known."""
        if "$" not in text:
            return text
        self._charge()
        text, dropped = lexed(text, self.env.get("ROS_DISTRO"))
        if dropped is not None:
            self._problem(self._path, self._line, dropped, UNEXPANDED)
        parts: list[str] = []
        position = 0
        size = 0  # of the parts so far (summing them per token was quadratic)
        for match in _TOKEN.finditer(text):
            parts.append(text[position:match.start()])
            position = match.end()
            token = match.group()
            if token in ("$${", "$$("):
                parts.append(token[1:])
            elif token.startswith("${"):
                parts.append(self._expression(self._inner(token[2:-1], table), table))
            else:
                inner = token[2:-1]
                if "${" in inner:
                    inner = self.evaluate_text(inner, table)
                parts.append(extension(inner.strip(), self.args, self.find, self.env,
                                       self._args_read, self._env_read,
                                       lambda source: self._expression(source, table)))
            size += len(parts[-2]) + len(parts[-1])
            if size > MAX_TEXT:
                raise _Abort(f"a value longer than {MAX_TEXT:,} characters", self._path,
                             self._line)
        parts.append(text[position:])
        return "".join(parts)

    def _inner(self, source: str, table: _Table) -> str:
        # xacro substitutes the $(...) inside an expression first:
        # ${load_yaml('$(find pkg)/config/x.yaml')}
        return self.evaluate_text(source, table) if "$(" in source else source

    def _expression(self, source: str, table: _Table, as_text: bool = True) -> typing.Any:
        source = _MATH_PREFIX.sub("", source.strip())
        self._charge(len(source) + 1)
        refused = dunder_refusal(source, self.env.get("ROS_DISTRO"), self._dunder_defined)
        if refused is not None:
            raise refused
        scope = EvalScope(args=Symbols(self, table), env={}, find=lambda _: None,
                          anon=lambda name: name, dirname=None)
        try:
            return evaluate(source, scope) if as_text else evaluate_value(source, scope)
        except _Unknown:
            raise
        except EvalUndefined as exc:
            raise undefined_name(f"${{{source}}}: {exc.reason}", exc.name,
                                 self._open or self._legacy) from None
        except EvalError as exc:
            raise expression_error(source, exc.reason) from None

    def property_value(self, name: str, table: _Table, prop: _Property) -> str | None:
        if prop.block is not None:
            raise _Unknown(f"block property '{name}' used as a value")
        if prop.text is None:
            if prop.reason is not None:
                raise _Unknown(prop.reason)
            return prop.value
        if name in self._resolving:
            chain = " -> ".join([*self._resolving, name])
            prop.text, prop.reason = None, f"circular property definition: {chain}"
            raise _Unknown(prop.reason)
        self._resolving.append(name)
        try:
            prop.value, prop.data = self._text_or_data(prop.text, table)
        except _Unknown as unknown:
            prop.reason = unknown.reason
            raise
        finally:
            prop.text = None
            self._resolving.pop()
        return prop.value

    def _text_or_data(self, text: str, table: _Table) -> tuple[str | None, object]:
        """A text that is one ``${...}`` keeps a dict or list value, as xacro keeps the
        value of such a text (``${load_yaml(...)}``); anything else is text."""
        if not _WHOLE_EXPRESSION.match(text):
            return self.evaluate_text(text, table), None
        value = self._expression(self._inner(text[2:-1], table), table, as_text=False)
        if isinstance(value, (dict, list)):
            return None, value
        if len(str(value)) > MAX_TEXT:
            raise _Abort(f"a value longer than {MAX_TEXT:,} characters", self._path, self._line)
        return str(value), None

    def yaml_loader(self) -> object:
        if self._load_yaml is None:
            self._load_yaml = yaml_loader(lambda: self._path, self._charge, self._yaml_files)
        return self._load_yaml

    # -- elements ----------------------------------------------------------------------
    def _node(self, element: Element, path: str, conditions: tuple[str, ...],
              tag: str | None = None) -> ExpandedNode:
        self._made += 1
        if self._made > MAX_OUTPUT_ELEMENTS:
            raise _Abort(f"expansion makes more than {MAX_OUTPUT_ELEMENTS:,} elements", path,
                         element.line)
        made = ExpandedNode(tag or element.tag, path, element.line, element.column, conditions)
        made.call, made.included = self._call_site, self._include_site
        return made

    def _attributes(self, element: Element, node: ExpandedNode, table: _Table) -> None:
        for name, text in element.attrib.items():
            if name.startswith(_PREFIX) or name.startswith("xmlns"):
                continue
            try:
                value = node.attrib[name] = self.evaluate_text(text, table)
                self._produced += len(value)
                if self._produced > MAX_OUTPUT_CHARS:
                    raise _Abort(f"expansion produces more than {MAX_OUTPUT_CHARS:,} "
                                 "characters of attribute text", node.path, node.line)
            except _Unknown as unknown:
                node.attrib[name] = text
                node.unknown[name] = unknown.reason
                if isinstance(unknown, _Refused):
                    self._refusal(node.path, node.line, f"{name}={text!r}: {unknown.reason}",
                                  unknown, node.conditions)

    def _children(self, elements: list[Element], path: str, table: _Table,
                  out: ExpandedNode, conditions: tuple[str, ...]) -> None:
        for element in elements:
            self._charge()
            self._path, self._line = path, element.line
            tag = element.tag
            if not tag.startswith(_PREFIX) and legacy_tag(element, table):
                if self._legacy:
                    tag = _PREFIX + tag
                elif unprefixed_call(element, table):
                    self._problem(path, element.line, f"<{tag}>", UNEXPANDED, conditions, tag)
                # A legacy xacro (distribution not given) would define names here.
                self._open = self._open or "ROS_DISTRO" not in self.env
            if not tag.startswith(_PREFIX):
                node = self._node(element, path, conditions)
                self._attributes(element, node, table)
                if element.text.strip():  # every text node (ros/xacro 7045754, eval_all)
                    try:
                        node.text = self.evaluate_text(element.text.strip(), table)
                    except _Unknown as unknown:  # xacro evaluates text as it does attributes
                        node.text = None
                        if isinstance(unknown, _Refused):
                            self._refusal(path, element.line, f"<{tag}>: {unknown.reason}",
                                          unknown, conditions)
                out.children.append(node)
                self._children(element.children, path, table, node, conditions)
                continue
            try:
                self._directive(element, tag[len(_PREFIX):], path, table, out, conditions)
            except _Refused as refused:
                self._refusal(path, element.line, f"<{tag}>: {refused.reason}", refused,
                              conditions)
            except _Unknown as unknown:
                self._problem(path, element.line, f"<{tag}>: {unknown.reason}", UNKNOWN,
                              conditions)

    def _directive(self, element: Element, what: str, path: str, table: _Table,
                   out: ExpandedNode, conditions: tuple[str, ...]) -> None:
        attrib = element.attrib
        if what == "property":
            self._property(element, path, table)
        elif what == "arg":
            name = attrib.get("name", "")
            self._args_read.add(name)
            if name not in self.args:
                default = attrib.get("default")
                try:
                    self.args[name] = (None if default is None
                                       else self.evaluate_text(default, table))
                except _Unknown:
                    self.args[name] = None
                    raise
        elif what == "macro":
            self._define_macro(element, path, table)
        elif what == "include":
            self._include(element, path, table, out, conditions)
        elif what in ("if", "unless"):
            text = attrib.get("value", "")
            try:
                keep: bool | None = _boolean(self.evaluate_text(text, table))
            except _Refused:
                raise
            except _Unknown as unknown:
                self._problem(path, element.line,
                              f"<xacro:{what} value={text!r}>: {unknown.reason}; "
                              "its content is kept as conditional", KEPT, conditions)
                keep = None
            if keep is None:
                mark = text if what == "if" else "!" + text
                self._children(element.children, path, table, out, (*conditions, mark))
            elif keep == (what == "if"):
                self._children(element.children, path, table, out, conditions)
        elif what == "insert_block":
            self._insert_block(element, path, table, out, conditions)
        elif what == "element":
            name = self.evaluate_text(attrib.get("xacro:name", ""), table)
            if not name:
                raise _Unknown("xacro:element: empty name")
            node = self._node(element, path, conditions, name)
            self._attributes(element, node, table)
            out.children.append(node)
            self._children(element.children, path, table, node, conditions)
        elif what == "attribute":
            name = self.evaluate_text(attrib.get("name", ""), table)
            try:
                out.attrib[name] = self.evaluate_text(attrib.get("value", ""), table)
            except _Unknown as unknown:
                out.attrib[name] = attrib.get("value", "")
                out.unknown[name] = unknown.reason
        elif what == "call":
            # <xacro:call macro="${name}" .../>: the macro named by the (evaluated)
            # attribute, called with the other attributes and the children.
            called = Element(element.tag, {k: v for k, v in attrib.items() if k != "macro"},
                             element.line, element.column)
            called.children = element.children
            self._call(called, self.evaluate_text(attrib.get("macro", ""), table), path,
                       table, out, conditions)
        else:
            self._call(element, what, path, table, out, conditions)

    def _property(self, element: Element, path: str, table: _Table) -> None:
        attrib = element.attrib
        name = self.evaluate_text(attrib.get("name", ""), table)
        if not valid_name(name):
            raise _Refused(f"property names must be valid Python identifiers: {name!r}")
        if name.startswith("__"):  # xacro takes it, but refuses any expression reading it
            self._dunder_defined.setdefault(name, (path, element.line))
        target = table
        scope = attrib.get("scope")
        if scope == "parent" and table.parent is not None:
            target = table.parent
        elif scope == "global":
            while target.parent is not None:
                target = target.parent
        if "default" in attrib and table.find_property(name) is not None:
            return
        text = attrib.get("value", attrib.get("default"))
        if text is None:
            target.properties[name] = _Property(None, None, block=(element, path))
            return
        prop = _Property(text, None)
        if attrib.get("lazy_eval", "true").lower() in ("false", "0") or target is not table:
            # A property set in another scope is evaluated here, where its names are seen.
            prop = self._evaluated(text, table)
        target.properties[name] = prop

    def _define_macro(self, element: Element, path: str, table: _Table) -> None:
        name = element.attrib.get("name", "")
        if name.startswith(_PREFIX):
            name = name[len(_PREFIX):]
        params, defaults = macro_params(element.attrib.get("params", ""))
        table.macros[name] = _Macro(params, defaults, element, path, seen=len(self.problems))
        self._defines_macros = True
        for param in never_inserted(element, params, self._legacy, self._charge):
            self._problem(path, element.line, f"block parameter '{param}' of macro "
                          f"'{name}' is never inserted (no <xacro:insert_block "
                          f"name=\"{param.lstrip('*')}\"/>)", DROPPED)
        # Found once per file, at the outermost macro (a nested one is defined only
        # while its outer macro is called).
        for use in self._param_args.get(path, {}).pop((element.line, element.column), ()):
            self._arg_lines.setdefault((path, use.element_line, use.name), use.line)
            self._problem(path, use.line, f"macro '{use.macro}'", PARAM_AS_ARG,
                          name=use.name)

    def _include(self, element: Element, path: str, table: _Table, out: ExpandedNode,
                 conditions: tuple[str, ...]) -> None:
        namespace = self.evaluate_text(element.attrib["ns"], table) if (
            "ns" in element.attrib) else None
        filename = self.evaluate_text(element.attrib.get("filename", ""), table)
        if _GLOB.search(filename):
            raise _Unknown(f"include pattern {filename!r} is not followed")
        target = os.path.normpath(os.path.join(os.path.dirname(path), filename))
        if target in self._include_stack:
            chain = [os.path.basename(p) for p in [*self._include_stack, target]]
            raise _Abort(f"include cycle: {' -> '.join(chain)}", path, element.line)
        if len(self._include_stack) >= MAX_INCLUDE_DEPTH:
            raise _Abort(f"includes nested deeper than {MAX_INCLUDE_DEPTH}", path, element.line)
        if not reads.exists(target):  # a FIFO or device is read, and said to be one
            installed = self.locate(target) if self.locate is not None else None
            if installed is not None:
                target = installed
            elif element.attrib.get("optional", "").lower() in ("true", "1"):
                return
            else:
                raise _Unknown(f"included file {self.display(target)} not found")
        included = self._read(target, (path, element.line))
        if included is None:
            return
        self._include_stack.append(target)
        outer_site = self._include_site  # in a macro, elements keep their call's include
        self._include_site = outer_site if self._call_site else (path, element.line, element.column)
        # With ns=, the file's macros are called as ns.name and its properties read as
        # ${ns.x} (xacro gives the file a table of its own, reached through the namespace).
        inner = table if namespace is None else _Table(table)
        try:
            self._children(included.children, target, inner, out, conditions)
        finally:
            self._include_stack.pop()
            self._include_site = outer_site
        if namespace is not None:
            for name, macro in inner.macros.items():
                table.macros[f"{namespace}.{name}"] = _Macro(
                    macro.params, macro.defaults, macro.body, macro.path, macro.scope or inner,
                    macro.seen)
            table.properties[namespace] = _Property(None, None, namespace=inner)

    def _insert_block(self, element: Element, path: str, table: _Table, out: ExpandedNode,
                      conditions: tuple[str, ...]) -> None:
        name = self.evaluate_text(element.attrib.get("name", ""), table)
        block = table.find_block(name)
        if block is None:
            found = table.find_property(name)
            if found is None or found[1].block is None:
                raise _Refused(f"undefined block '{name}'")
            block_element, block_path = found[1].block
            self._children(block_element.children, block_path, table, out, conditions)
            return
        # xacro evaluates a block in the caller's scope, before the macro body sees it.
        if block.content_only:
            self._children(block.element.children, block.path, block.scope, out, conditions)
        else:
            self._children([block.element], block.path, block.scope, out, conditions)

    def _call(self, element: Element, name: str, path: str, table: _Table,
              out: ExpandedNode, conditions: tuple[str, ...]) -> None:
        macro = table.find_macro(name)
        if macro is None:
            raise _Refused(f"unknown macro '{name}'")
        if self._macro_depth >= MAX_MACRO_DEPTH:
            raise _Abort(f"macros nested deeper than {MAX_MACRO_DEPTH} (recursive macro?)",
                         path, element.line)
        scoped = _Table(table if macro.scope is None else macro.scope)
        params = list(macro.params)
        for attribute, text in element.attrib.items():
            if attribute not in params:
                raise _Mismatch(f"invalid parameter '{attribute}' of macro '{name}'", macro.seen)
            params.remove(attribute)
            scoped.properties[attribute] = self._evaluated(text, table)
        blocks = list(element.children)
        for param in [p for p in params if p.startswith("*")]:
            if not blocks:
                raise _Mismatch(f"not enough blocks for macro '{name}'", macro.seen)
            params.remove(param)
            content_only = param.startswith("**")
            scoped.blocks[param.lstrip("*")] = _Block(blocks.pop(0), path, content_only, table)
        if blocks:
            raise _Mismatch(f"unused block <{blocks[0].tag}> in call of macro '{name}'",
                            macro.seen)
        for param in list(params):
            if param not in macro.defaults:
                continue
            forward, default = macro.defaults[param]
            params.remove(param)
            if forward is not None:
                found = table.find_property(forward)
                if found is not None:
                    value = _Property(None, None, namespace=found[1].namespace)
                    try:
                        value.value = self.property_value(forward, found[0], found[1])
                        value.data = found[1].data
                    except _Unknown as unknown:
                        value.reason = unknown.reason
                    scoped.properties[param] = value
                    continue
                if default is None:
                    raise _Refused(f"undefined property to forward: {forward}")
            scoped.properties[param] = self._evaluated(default or "", table)
        if params:
            raise _Mismatch(f"undefined parameters [{','.join(params)}] of macro '{name}'",
                            macro.seen)
        self._macro_depth += 1
        outermost = self._call_site is None
        if outermost:
            self._call_site = (path, element.line, element.column)
        try:
            self._children(macro.body.children, macro.path, scoped, out, conditions)
        finally:
            self._macro_depth -= 1
            if outermost:
                self._call_site = None

    def _evaluated(self, text: str, table: _Table) -> _Property:
        try:
            value, data = self._text_or_data(text, table)
            return _Property(None, value, data=data)
        except _Refused:
            raise  # evaluated at once, as xacro's eval_text in handle_macro_call: it stops
        except _Unknown as unknown:
            return _Property(None, None, unknown.reason)


def expand(path: str, args: Mapping[str, str | None], find: Callable[[str], str | None],
           env: Mapping[str, str] | None = None, data: bytes | None = None,
           locate: Callable[[str], str | None] | None = None, budget: Budget | None = None,
           display: Callable[[str], str] | None = None) -> Expansion:
    """Expand the xacro (or plain URDF) file ``path`` with ``args`` (``name:=value``);
    ``data`` is expanded as if it were that file (text linted by ``lint_text``); ``locate``
    maps an included path that is not there to the file installed there; ``budget``: the
    launch tree's, besides the expansion's own bounds; ``display`` shows a quoted path."""
    return XacroExpander(args, find, env, locate, budget, display).expand(path, data)


__all__ = [
    "MAX_FILES", "MAX_INCLUDE_DEPTH", "MAX_MACRO_DEPTH", "MAX_OUTPUT_ELEMENTS", "MAX_TEXT",
    "MAX_WORK", "ExpandedNode", "Expansion", "XacroExpander", "XacroProblem", "expand",
]
