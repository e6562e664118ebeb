"""ROS 2 launch XML (and, through :class:`Entity`, YAML) to launch actions.

``launch_xml`` and ``launch_yaml`` both turn a file into "entities" (a type name,
attributes, nested entity lists and children) that the actions' own ``parse`` methods
read; :func:`actions_of` does the same for the tags that matter to static transforms:
``arg``, ``let``, ``set_env``/``unset_env``, ``push_ros_namespace``, ``group``,
``include``, ``timer``, ``node``, ``node_container``, ``load_composable_node``. Tag
names are compared with ``-`` read as ``_`` (both spellings are in use). Other tags do not
start static transforms and are skipped.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from launch_linter.frontends.ros2_actions import (
    Action,
    Component,
    DeclareArg,
    FileRead,
    Group,
    Include,
    LoadComponents,
    Params,
    ParamsFile,
    ParamsUnknown,
    Predicate,
    Problem,
    PushNamespace,
    RunNode,
    SetEnv,
    SetVar,
    Uses,
    Where,
    may_rename,
    ros2_control,
    ros2_run,
    shell_reads_as_words,
)
from launch_linter.frontends.ros2_schema import SchemaEntity, check_launch
from launch_linter.model.launch import may_hold_directive
from launch_linter.model.transform import LaunchFormat
from launch_linter.resolve.ros2_substitution import (
    Call,
    CommandLineError,
    Opaque,
    Subs,
    SubstitutionSyntaxError,
    Text,
    first_refusal,
    parse,
    split_command_line,
    written,
)
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml


@dataclass
class Entity:
    """One launch entity, whichever the file format."""

    tag: str
    line: int
    column: int
    attrs: dict[str, str] = field(default_factory=dict)
    lists: dict[str, list[Entity]] = field(default_factory=dict)
    """Attributes that hold entities (``param``, ``arg`` of an include, ...)."""
    children: list[Entity] = field(default_factory=list)
    """Nested actions (of ``launch``, ``group``, ``timer``)."""
    other_keys: list[str] = field(default_factory=list)
    """YAML keys written but kept neither as attributes nor as nested entities (a null
    value, a list of scalars, a mapping): the schema check still sees their names."""


def _placed(subs: Subs, at: tuple[int, int]) -> Subs:
    """``subs`` with each ``$(var)`` marked as written at ``at`` (line, column); the
    parser bounds the nesting (``MAX_NESTING``)."""
    return tuple(
        Call(sub.name, tuple(_placed(arg, at) for arg in sub.args), sub.written,
             at if sub.name == "var" else sub.at) if isinstance(sub, Call) else sub
        for sub in subs)


def normalise_tag(tag: str) -> str:
    return tag.replace("-", "_")


class _Reader:
    def __init__(self, path: str) -> None:
        self.path = path
        self.problems: list[Problem] = []
        self.parsed: dict[str, tuple[Subs, str | None]] = {}
        """Each attribute text parsed once (``$(var use_sim_time)`` recurs in a file), with
        why launch refuses it, if it does."""
        self.refused: set[tuple[int, str]] = set()
        """(entity, attribute) whose refusal is reported: each is read more than once."""

    def where(self, entity: Entity) -> Where:
        return Where(self.path, entity.line, entity.column)

    def report(self, rule: str, entity: Entity, message: str) -> None:
        self.problems.append(Problem(rule, entity.line, entity.column, message))

    def subs(self, entity: Entity, attribute: str) -> Subs | None:
        """The attribute's substitutions. What launch's parser refuses (bad syntax, an
        unknown substitution, a wrong argument count) is reported at the entity that
        carries it, once, and stands as an opaque piece: launch refuses it while it parses
        the file, not when the enclosing action runs."""
        text = entity.attrs.get(attribute)
        if text is None:
            return None
        known = self.parsed.get(text)
        if known is None:
            try:
                subs = parse(text)
                refusal = first_refusal(subs)
            except SubstitutionSyntaxError as exc:
                subs, refusal = (), f"{exc}"
            if refusal is not None:
                subs = (Opaque(text, f"not a valid substitution: {refusal}"),)
            known = self.parsed[text] = (subs, refusal)
        subs, refusal = known
        if refusal is not None and (id(entity), attribute) not in self.refused:
            self.refused.add((id(entity), attribute))
            self.report("roslaunch_error", entity, f"{attribute}: {refusal}")
        if "$(var" in text:
            # A read launch finds unset is reported at the entity that writes it (a
            # <param> of a <node>), as the syntax faults above.
            return _placed(subs, (entity.line, entity.column))
        return subs

    def required(self, entity: Entity, attribute: str) -> Subs | None:
        value = self.subs(entity, attribute)
        if value is None:
            self.report(
                "roslaunch_error", entity,
                f"<{entity.tag}> is missing the required attribute '{attribute}'",
            )
        return value

    def predicate(self, entity: Entity) -> Predicate | None:
        if_value, unless_value = self.subs(entity, "if"), self.subs(entity, "unless")
        if if_value is not None and unless_value is not None:
            self.report("roslaunch_error", entity, "'if' and 'unless' cannot both be given")
        if if_value is not None:
            return Predicate(True, if_value)
        if unless_value is not None:
            return Predicate(False, unless_value)
        return None

    def performed(self, entity: Entity) -> tuple[Subs, ...]:
        """Every attribute of ``entity`` and of the entities nested in it (parameters,
        remappings, composable nodes) but its conditions: the substitutions launch performs
        when the action runs."""
        found: list[Subs] = []
        pending = [entity]
        while pending:
            current = pending.pop()
            for attribute in current.attrs:
                if attribute not in ("if", "unless"):
                    value = self.subs(current, attribute)
                    if value is not None and any(not isinstance(s, Text) for s in value):
                        found.append(value)
            pending.extend(item for items in current.lists.values() for item in items)
        return tuple(found)

    def actions(self, entities: list[Entity]) -> tuple[Action, ...]:
        out: list[Action] = []
        for entity in entities:
            action = self.action(entity)
            if action is not None:
                out.append(action)
        return tuple(out)

    def action(self, entity: Entity) -> Action | None:
        tag = normalise_tag(entity.tag)
        where, condition = self.where(entity), self.predicate(entity)
        if tag == "arg":
            name = self.required(entity, "name")
            if name is None:
                return None
            return DeclareArg(where, condition, name, self.subs(entity, "default"))
        if tag == "let":
            name, value = self.required(entity, "name"), self.required(entity, "value")
            if name is None or value is None:
                return None
            return SetVar(where, condition, name, value)
        if tag in ("set_env", "unset_env"):
            name = self.required(entity, "name")
            value = self.required(entity, "value") if tag == "set_env" else None
            if name is None or (tag == "set_env" and value is None):
                return None
            return SetEnv(where, condition, name, value)
        if tag == "push_ros_namespace":
            namespace = self.required(entity, "namespace")
            return None if namespace is None else PushNamespace(where, condition, namespace)
        if tag in ("group", "timer"):
            children = self.actions(entity.children)
            if tag == "timer":
                # A timer runs its actions later in the same context: an unscoped group.
                return Group(where, condition, children, scoped=False)
            return Group(
                where, condition, children,
                scoped=self.subs(entity, "scoped") or True,
                forwarding=self.subs(entity, "forwarding") or True,
            )
        if tag == "include":
            return self.include(entity, where, condition)
        if tag == "node":
            return self.node(entity, where, condition)
        if tag == "executable":
            return self.executable(entity, where, condition)
        if tag in ("node_container", "load_composable_node"):
            components = tuple(
                self.component(child) for child in entity.lists.get("composable_node", [])
            )
            return LoadComponents(where, condition, components, self.performed(entity))
        # Any other action (<set_parameter>, <set_remap>, <log>, an extension's tag) still
        # performs its substitutions when it runs.
        uses = self.performed(entity)
        if tag == "set_parameter":
            name, value = self.subs(entity, "name"), self.subs(entity, "value")
            if name is not None and value is not None:
                return Uses(where, condition, uses, (name, value))
        return Uses(where, condition, uses) if uses or condition is not None else None

    def include(self, entity: Entity, where: Where, condition: Predicate | None
                ) -> Include | None:
        path = self.required(entity, "file")
        if path is None:
            return None
        args: list[tuple[Subs, Subs]] = []
        places: list[tuple[int, int]] = []
        for arg in entity.lists.get("arg", []):
            name, value = self.required(arg, "name"), self.required(arg, "value")
            if name is not None and value is not None:
                args.append((name, value))
                places.append((arg.line, arg.column))
        return Include(where, condition, path, tuple(args), arg_places=tuple(places))

    def node(self, entity: Entity, where: Where, condition: Predicate | None) -> RunNode | None:
        executable = self.subs(entity, "exec")
        if executable is None:
            hint = " (ROS 2 calls ROS 1's 'type' 'exec')" if "type" in entity.attrs else ""
            self.report(
                "roslaunch_error", entity,
                f"<node> is missing the required attribute 'exec'{hint}",
            )
            return None
        args = self.subs(entity, "args")
        try:
            arguments = () if args is None else tuple(split_command_line(args))
        except CommandLineError as exc:
            self.report("parse_error", entity,
                        f"args: {exc}: launch's command-line parser (shlex) refuses it, "
                        f"and with it the whole file")
            return None
        return RunNode(
            where=where,
            condition=condition,
            package=self.subs(entity, "pkg"),
            executable=executable,
            name=self.subs(entity, "name") or self.subs(entity, "node-name"),
            namespace=self.subs(entity, "namespace"),
            arguments=arguments,
            args_written=entity.attrs.get("args", ""),
            parameters=self.params(entity.lists.get("param", [])),
            uses=self.performed(entity),
            may_rename=may_rename([entity.attrs.get("args", ""),
                                   entity.attrs.get("ros_args", "")]),
            remappings=self.remappings(entity.lists.get("remap", [])),
        )

    def remappings(self, remaps: list[Entity]) -> tuple[tuple[Subs, Subs], ...] | None:
        """``<remap from= to=>`` pairs (YAML ``remap:``); None when one is incomplete."""
        pairs: list[tuple[Subs, Subs]] = []
        for remap in remaps:
            source, target = self.subs(remap, "from"), self.subs(remap, "to")
            if source is None or target is None:
                return None
            pairs.append((source, target))
        return tuple(pairs)

    def executable(self, entity: Entity, where: Where, condition: Predicate | None
                   ) -> RunNode | Uses | None:
        """``<executable cmd="ros2 run PKG EXEC ARGS">`` starts that node."""
        cmd = self.required(entity, "cmd")
        if cmd is None:
            return None
        shell = (entity.attrs.get("shell") or "").strip().lower() == "true"
        if shell and not shell_reads_as_words(written(cmd)):
            return Uses(where, condition, self.performed(entity))
        try:
            items = split_command_line(cmd)
        except CommandLineError as exc:
            self.report("parse_error", entity,
                        f"cmd: {exc}: launch's command-line parser (shlex) refuses it, "
                        f"and with it the whole file")
            return None
        run = ros2_run(items)
        if run is None:
            return Uses(where, condition, self.performed(entity), controls=ros2_control(items))
        package, executable, arguments = run
        return RunNode(
            where=where, condition=condition, package=package, executable=executable,
            name=None, namespace=None, arguments=arguments,
            args_written=entity.attrs.get("cmd", ""), pushed_namespace=False,
            uses=self.performed(entity),
        )

    def component(self, entity: Entity) -> Component:
        return Component(
            where=self.where(entity),
            condition=self.predicate(entity),
            package=self.subs(entity, "pkg"),
            plugin=self.required(entity, "plugin") or (),
            name=self.subs(entity, "name"),
            namespace=self.subs(entity, "namespace"),
            parameters=self.params(entity.lists.get("param", [])),
        )

    def params(self, entities: list[Entity]) -> tuple[Params | ParamsFile | ParamsUnknown, ...]:
        out: list[Params | ParamsFile | ParamsUnknown] = []
        for entity in entities:
            if "from" in entity.attrs:
                substitutions = entity.attrs.get("allow_substs", "false").strip().lower()
                out.append(ParamsFile(self.subs(entity, "from") or (), substitutions != "false"))
                continue
            items: list[tuple[str, Subs]] = []
            places: list[Where | None] = []
            self.param_items(entity, "", items, places)
            out.append(Params(tuple(items), tuple(places)))
        return tuple(out)

    def param_items(self, entity: Entity, prefix: str, items: list[tuple[str, Subs]],
                    places: list[Where | None]) -> None:
        name = entity.attrs.get("name")
        if name is None:
            self.report("roslaunch_error", entity, "<param> needs a 'name' or 'from' attribute")
            return
        nested = entity.lists.get("param", [])
        if nested:
            for child in nested:
                self.param_items(child, f"{prefix}{name}.", items, places)
            return
        value = self.subs(entity, "value")
        if value is not None:
            items.append((prefix + name, value))
            places.append(self.where(entity))


def _schema_entity(entity: Entity, xml: bool) -> SchemaEntity:
    if xml:
        # An XML entity's children are its nested tags, in order, whatever they are.
        nested = entity.children
    else:
        # YAML nests entities as list-valued keys, and actions under ``children``.
        nested = [item for items in entity.lists.values() for item in items]
        nested.extend(entity.children)
    names = (*entity.attrs, *entity.other_keys)
    return SchemaEntity(
        entity.tag, entity.line, entity.column, tuple(dict.fromkeys(names)),
        tuple([_schema_entity(child, xml) for child in nested]),
    )


def schema_problems(root: Entity, launch_format: str) -> tuple[Problem, ...]:
    """What launch's front-end refuses under ``root`` (``ros2_schema`` problems), and the
    actions it may not know (``unresolved``)."""
    xml = launch_format == "xml"
    children = tuple(_schema_entity(child, xml) for child in root.children)
    return tuple(
        Problem("ros2_schema" if found.refused else "unresolved", found.line, found.column,
                found.message)
        for found in check_launch(children, launch_format)
    )


def actions_of(path: str, root: Entity, launch_format: str = "xml"
               ) -> tuple[tuple[Action, ...] | None, tuple[Problem, ...]]:
    """The actions of a ``launch`` root entity read from ``path``, and the problems seen.

    The actions are None when launch refuses the file (a ``ros2_schema`` problem): it
    starts none of its nodes, so none of its transforms are published.
    """
    schema = schema_problems(root, launch_format)
    reader = _Reader(path)
    actions = reader.actions(root.children)
    # An attribute read twice (by its action, then with everything the action performs)
    # reports its mistake once.
    problems = tuple(dict.fromkeys((*schema, *reader.problems)))
    if any(problem.rule in ("ros2_schema", "parse_error") for problem in problems):
        return None, problems
    return actions, problems


def _entity(element: Element) -> Entity:
    entity = Entity(element.tag, element.line, element.column, dict(element.attrib))
    for child in element.children:
        entity.children.append(_entity(child))
        entity.lists.setdefault(normalise_tag(child.tag), []).append(entity.children[-1])
    return entity


def read_xml(path: str, data: bytes) -> FileRead:
    """Read a ROS 2 launch XML file (``path`` absolute, ``data`` its bytes)."""
    try:
        # Comments and element lines serve only suppression directives.
        document = parse_xml(data, directives=may_hold_directive(data))
    except XmlError as exc:
        message = f"not well-formed XML: {exc.message}"
        problem = Problem("parse_error", exc.line, exc.column, message)
        return FileRead(LaunchFormat.ROS2_XML, None, problems=(problem,))
    comments = tuple(document.comments)
    lines = tuple(document.element_lines)
    if document.root.tag != "launch":
        problem = Problem(
            "parse_error", document.root.line, document.root.column,
            f"root element is <{document.root.tag}>, not <launch>",
        )
        return FileRead(LaunchFormat.ROS2_XML, None, comments, lines, (problem,))
    actions, problems = actions_of(path, _entity(document.root), "xml")
    return FileRead(LaunchFormat.ROS2_XML, actions, comments, lines, problems)
