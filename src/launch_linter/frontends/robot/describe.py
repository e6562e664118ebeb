"""From the ``robot_description`` a launch file gives to the URDF joints it publishes.

Front-ends record :class:`DescriptionSource`s (where, which file, which xacro args) and
:class:`NodeRecord`s; :func:`attach_robot` expands each description once per run (the
:class:`RobotCache` keys expansions by file, args and package roots) and adds its joints
to the tree, so rules see launch static transforms and URDF joints together.
"""

from __future__ import annotations

import os
import re
import typing
from collections.abc import Callable, Hashable, Mapping, Sequence

from launch_linter.frontends.robot.alternatives import alternatives
from launch_linter.frontends.robot.sim_control import simulated_controllers
from launch_linter.frontends.robot.xacro_ignored import ignored_args
from launch_linter.frontends.robot.xacro_order import legacy_order_refusal
from launch_linter.frontends.robot.xacro_values import (
    FAULT_KINDS,
    KEPT,
    MALFORMED,
    REFUSED,
    TF_PREFIX_PARAM,
    UNKNOWN,
)
from launch_linter.model.budget import Budget
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.included import through_include
from launch_linter.model.launch import LaunchTree
from launch_linter.model.paths import shown_in_text
from launch_linter.model.record import replace
from launch_linter.model.robot import (
    UNKNOWN_VALUE,
    DescriptionFault,
    DescriptionKind,
    DescriptionSource,
    FaultKind,
    NodeRecord,
    RobotJoint,
    RobotModel,
    spawns_into_simulator,
)
from launch_linter.resolve import reads
from launch_linter.resolve.value import (
    Value,
    blocker,
    environment_variable,
    holes,
    why_unresolved,
)
from launch_linter.workspace.packages import PackageIndex

if typing.TYPE_CHECKING:
    from launch_linter.frontends.robot.xacro import Expansion
    from launch_linter.frontends.robot.xacro_values import XacroProblem

RSP_PACKAGE = "robot_state_publisher"
_XACRO_NAMED = re.compile(
    r"""(?:name\s*=\s*)?['"]xacro(?:\.py)?['"]|^\$\(find-exec\s+xacro(?:\.py)?\)$""")
"""An unresolved word that names xacro: ``FindExecutable(name='xacro')`` (Python) or
``$(find-exec xacro)`` (XML, YAML)."""
MAX_DESCRIPTIONS_PER_TREE = 50
MAX_EXPANSIONS_PER_FILE = 64
"""Expansions of one file kept with different args (a run's memory stays bounded)."""

# Aliases are evaluated at run time: typing's spelling keeps them working on Python 3.8.
Word = typing.Tuple[str, bool]
"""A command word and whether it is fully resolved."""


_ABSENT = "\0absent"
"""What a relevance key holds for an arg or variable that was not given."""

_Given = typing.Tuple[typing.Tuple[str, typing.Optional[str]], ...]


def _relevant(given: Mapping[str, str | None], names: frozenset[str]) -> _Given:
    return tuple(sorted((name, given.get(name, _ABSENT)) for name in names))


class RobotCache:
    """Expansions made in one run, each computed once per (file, package roots, the given
    args and environment variables the expansion looked up) and reused by every
    description that gives the same values for those names: twelve descriptions of one
    costly xacro, differing only in args it never reads, cost one expansion."""

    def __init__(self) -> None:
        self._expansions: dict[Hashable, list[tuple[_Given, _Given, Expansion,
                                                     reads.ReadLog]]] = {}
        self.included: dict[Hashable, tuple[frozenset[str], reads.ReadLog]] = {}
        """Package folder -> the description file names its descriptions include (with
        what scanning them read: ``reads.remembered``)."""

    def expansion(self, file: str, args: tuple[tuple[str, str | None], ...],
                  packages: PackageIndex, env: dict[str, str],
                  budget: Budget | None = None,
                  display: Callable[[str], str] | None = None) -> Expansion:
        """The expansion of ``file`` with ``args``: computed under ``budget`` (the launch
        tree's) unless an earlier one read the same values; one stopped by a tree's budget
        after other work of that tree is not kept (a tree with budget left expands it
        again). ``display`` (how messages show paths) is the run's, the same for every
        use."""
        given = dict(args)
        found = self._expansions.setdefault((file, packages.key), [])
        for args_read, env_read, expansion, log in found:
            if (all(given.get(name, _ABSENT) == value for name, value in args_read)
                    and all(env.get(name, _ABSENT) == value for name, value in env_read)):
                # Every launch file that uses the expansion depends on the files it read.
                reads.depend_on(log)
                return expansion
        # Imported when a description is first expanded: xacro (with its interpreter
        # of ${} expressions) is a third of the start-up of a run that meets none.
        from launch_linter.frontends.robot.xacro import expand

        # Begun with a tree's whole budget, an expansion stopped by it would be stopped in
        # any tree (on a slow machine five seconds come before its own step bound).
        fresh = budget is None or budget.steps == 0
        with reads.recording() as log:
            expansion = expand(file, given, packages.find, env,
                               locate=lambda path: packages.locate(path).path, budget=budget,
                               display=display)
        kept = fresh or not expansion.cut_by_budget
        if kept and len(found) < MAX_EXPANSIONS_PER_FILE:
            found.append((_relevant(given, expansion.args_read),
                          _relevant(env, expansion.env_read), expansion, log))
        reads.depend_on(log)
        return expansion

    def __len__(self) -> int:
        return sum(len(found) for found in self._expansions.values())


XacroCall = typing.Tuple[
    typing.Optional[str], typing.Tuple[typing.Tuple[str, typing.Optional[str]], ...],
    typing.Optional[str], bool,
]


def _xacro_word(words: Sequence[Word]) -> int | None:
    """Which of the first words names xacro (``xacro``, ``$(find xacro)/xacro``, the
    first ``xacro`` of ``rosrun xacro xacro``); None when ``words`` do not run xacro."""
    for index, (text, resolved) in enumerate(words[:4]):
        base = text.rstrip("/").rsplit("/", 1)[-1].strip("'\"")
        named = not resolved and _XACRO_NAMED.search(text) is not None
        if base in ("xacro", "xacro.py") or named:
            return index
    return None


def _xacro_words_start(words: Sequence[Word]) -> int | None:
    """Where the words given to xacro begin; None when ``words`` do not run xacro."""
    index = _xacro_word(words)
    if index is None:
        return None
    if index + 1 < len(words) and words[index + 1][0] in ("xacro", "xacro.py"):
        return index + 2
    return index + 1


_RUNNERS = frozenset({"xacro", "xacro.py", "rosrun", "python", "python2", "python3"})
"""Programs that run xacro without changing its environment."""


def xacro_wrapper(words: Sequence[Word]) -> str | None:
    """The first word of a command that runs xacro through another program (a script that
    sources a configuration first, ``env X=1``), when there is one: that program may set
    the environment variables xacro reads."""
    index = _xacro_word(words)
    if not index:  # xacro itself first, or no xacro
        return None
    first = words[0][0].rstrip("/").rsplit("/", 1)[-1].strip("'\"")
    return None if first in _RUNNERS else words[0][0]


def xacro_options(words: Sequence[Word]) -> tuple[str, ...]:
    """The option words (``--inorder``, ``-i``, ``--legacy``, ...) of a xacro call."""
    start = _xacro_words_start(words)
    if start is None:
        return ()
    return tuple(text for text, resolved in words[start:]
                 if resolved and text.startswith("-") and ":=" not in text)


def xacro_command(words: Sequence[Word], command: Value = ()) -> XacroCall | None:
    """``(file, args, reason, open_args)`` when ``words`` (of the value ``command``) run
    xacro (``xacro``, ``xacro.py``, ``$(find xacro)/xacro``, ``rosrun xacro xacro``,
    ``--inorder`` and other options skipped); None when the command is not xacro. ``file``
    is None when unresolved, and ``reason`` names what blocks it; ``open_args`` is true
    when an unresolved word may give more args."""
    start = _xacro_words_start(words)
    if start is None:
        return None
    file: str | None = None
    reason: str | None = None
    seen_file = False
    args: list[tuple[str, str | None]] = []
    open_args = False
    skip = False
    for text, resolved in words[start:]:
        if skip:
            skip = False
            continue
        if text in ("-o", "--output"):
            skip = True
            continue
        if text.startswith("-"):
            continue
        if ":=" in text:
            name, _, value = text.partition(":=")
            args.append((name, value if resolved else None))
            continue
        if seen_file and not resolved:
            open_args = True
        if not seen_file:
            seen_file = True
            if resolved:
                file = text
            else:
                reason = _unresolved_file(text, command)
    if not seen_file:
        reason = "the xacro command names no file"
    return file, tuple(args), reason, open_args


def _unresolved_file(text: str, command: Value) -> str:
    """Why the description file ``text`` (a word of ``command``) is unknown: the first
    unknown that really blocks it (an environment variable behind a launch argument's
    default, say), not only the substitution written in the command."""
    inside = tuple(hole for hole in holes(command) if hole.text in text)
    if not inside:
        return f"the description file {text!r} is not resolved"
    if text not in {hole.text for hole in inside} and all(
            environment_variable(hole) for hole in inside):
        # Known text around environment variables: the variables are what blocks it.
        return "the description file depends on " + "; ".join(
            f"{hole.text}: {hole.reason}" for hole in inside)
    shown = shown_in_text(text, min(text.find(hole.text) for hole in inside))
    if all(blocker(hole)[0] == hole.text for hole in inside):
        return (f"the description file {shown!r} is not resolved: "
                f"{why_unresolved(inside, quoted=True)}")
    return f"the description file depends on {why_unresolved(inside)}"


def literal_kind(text: str) -> bool:
    """Whether a parameter value is a URDF written in place."""
    return "<robot" in text[:4096]


def attach_robot(tree: LaunchTree, packages: PackageIndex, cache: RobotCache | None,
                 display: Callable[[str], str], env: dict[str, str],
                 sites: Mapping[str, Location] | None = None,
                 tf_prefixes: Sequence[tuple[str | None, str]] = ()) -> LaunchTree:
    """The tree with the joints of the descriptions that a robot_state_publisher of the
    tree publishes (in ROS 1 a ``robot_description`` parameter without one is not
    published by this tree), and an ``unresolved`` diagnostic per problem; one about a
    description an included file gives names that file's include (``sites``: each
    included file's first include, by the file's shown path; ``tf_prefixes``: the ROS 1
    ``tf_prefix`` parameters set in a namespace, which simulated plugins find)."""
    if not tree.descriptions:
        return tree
    publishes = any(node.package == RSP_PACKAGE for node in tree.nodes)
    cache = cache if cache is not None else RobotCache()
    if not publishes:
        return _refusals(tree, packages, cache, display, env)
    # The expansions a tree needs share one budget; a reused expansion costs nothing.
    budget = Budget()
    joints: list[RobotJoint] = []
    robots: list[RobotModel] = []
    problems_found: list[Problem] = []
    # Several nodes given one description (robot_state_publisher, the controller manager,
    # a spawner) make one message per cause, not one per node.
    reported: set[tuple[object, ...]] = set()
    for source in tree.descriptions[:MAX_DESCRIPTIONS_PER_TREE]:
        same = (source.kind, source.file, source.args, source.text, source.reason)
        first = same not in reported
        reported.add(same)
        chosen, said = [source], None
        if source.file is None and source.open_file is not None:
            chosen, said = alternatives(source, display)
            if chosen and first:
                problems_found.append(_unresolved(source, f"robot description: {said}"))
        if source.file is None and source.kind is not DescriptionKind.LITERAL and not (
                source.open_file and chosen):
            if first:
                problems_found.append(_unresolved(source, f"robot description not read: "
                                                  f"{source.reason or 'unknown file'}"
                                                  + (f"; {said}" if said else "")))
            continue
        for each in chosen:
            robot, unresolved = read_description(each, packages, cache, display, env,
                                                 budget=budget)
            if first:
                problems_found.extend(unresolved)
            if robot is not None:
                joints.extend(robot.joints)
                robots.append(robot)
    if sites:
        problems_found = [problem if problem.path not in sites
                          else through_include(problem, sites[problem.path])
                          for problem in problems_found]
    plugins = simulated_plugins(tree.nodes, robots, SearchedPrefixes(tf_prefixes), display)
    return replace(tree, joints=tuple(joints), robots=tuple(robots),
                   problems=tree.problems + tuple(problems_found),
                   nodes=tree.nodes + tuple(plugins))


def _refusals(tree: LaunchTree, packages: PackageIndex, cache: RobotCache,
              display: Callable[[str], str], env: dict[str, str]) -> LaunchTree:
    """A tree with descriptions but no robot_state_publisher (a spawner's only, say):
    roslaunch still runs each ``<param command="xacro ...">`` when it loads the file and
    stops when xacro fails, so a description xacro refuses is kept, without joints or
    plugins (nothing publishes or spawns it), for ``xacro_error``; nothing else is said."""
    budget = Budget()
    refused: list[RobotModel] = []
    for source in tree.descriptions[:MAX_DESCRIPTIONS_PER_TREE]:
        if source.kind is not DescriptionKind.XACRO or source.file is None:
            continue
        robot, _ = read_description(source, packages, cache, display, env, budget=budget)
        if robot is not None and any(f.kind is FaultKind.REFUSED and f.proven
                                     for f in robot.faults):
            refused.append(replace(robot, joints=(), plugins=()))
    return replace(tree, robots=tuple(refused)) if refused else tree


def simulated_plugins(nodes: Sequence[NodeRecord], robots: Sequence[RobotModel],
                      tf_prefixes: SearchedPrefixes | None = None,
                      display: Callable[[str], str] | None = None) -> list[NodeRecord]:
    """The Gazebo plugins of the descriptions, when the tree spawns a description into a
    simulator (a description only published by robot_state_publisher, as on the real
    robot, runs no plugin). Each runs under its description's condition and, when every
    spawner is conditional, the first spawner's; a ros2_control plugin's controller
    parameter files give its controllers (``display`` shows their paths). A ROS 1 plugin
    gets its robot namespace and the ``tf_prefix`` found from there (``tf_prefixes``:
    those set in a namespace)."""
    prefixes = tf_prefixes if tf_prefixes is not None else SearchedPrefixes(())
    spawners = [n for n in nodes if spawns_into_simulator(n)]
    if not spawners:
        return []
    ros = next((n.ros for n in nodes if n.ros is not None), None)
    condition = (spawners[0].condition if all(not s.condition.always for s in spawners)
                 else None)
    out: list[NodeRecord] = []
    for robot in robots:
        for plugin in robot.plugins:
            plugin = replace(plugin, ros=ros if ros is not None else plugin.ros,
                             condition=plugin.condition if condition is None
                             else plugin.condition & condition)
            if plugin.ros == 1:
                plugin = _ros1_robot_namespace(plugin, robot.source, spawners, prefixes)
            plugin, controllers = simulated_controllers(plugin, display)
            out.append(plugin)
            out.extend(controllers)
    return out


def _ros1_robot_namespace(plugin: NodeRecord, source: DescriptionSource,
                          spawners: Sequence[NodeRecord],
                          tf_prefixes: SearchedPrefixes) -> NodeRecord:
    """A ROS 1 plugin with the namespace its node handle runs in and the ``tf_prefix``
    gazebo_plugins find there (``tf::getPrefixParam``, a ``searchParam``): its own
    ``<robotNamespace>``, else the one ``spawn_model`` writes into it (``-robot_namespace``,
    by default the spawner's namespace, where it reads the description parameter by its
    relative name). Unknown (no prefix assumed) when no spawner runs in the namespace of
    the description's parameter."""
    namespace: str | None = plugin.namespace
    if plugin.given("robotNamespace") is None:
        namespace = None
        if source.namespace is not None:
            here = source.namespace.strip("/")
            if any(s.namespace is not None and s.namespace.strip("/") == here
                   for s in spawners if s.package == "gazebo_ros"):
                namespace = "/" + here
    prefix = UNKNOWN_VALUE if namespace is None else tf_prefixes.find(namespace)
    return replace(plugin, namespace=namespace, params=(*plugin.params, (TF_PREFIX_PARAM, prefix)))


def searched_tf_prefix(namespace: str, tf_prefixes: Sequence[tuple[str | None, str]]
                       ) -> str:
    """The ``tf_prefix`` that ``searchParam`` finds from ``namespace`` up
    (:class:`SearchedPrefixes`, for one lookup)."""
    return SearchedPrefixes(tf_prefixes).find(namespace)


class SearchedPrefixes:
    """The ``tf_prefix`` parameters set in namespaces, indexed for ``searchParam``
    (``tf::getPrefixParam`` and robot_state_publisher): from a namespace up, the one set in
    the closest enclosing namespace, the last one set there; ``UNKNOWN_VALUE`` when one
    whose namespace is unresolved could be it, '' when none is set. A lookup walks the
    namespace's own levels, not every parameter."""

    def __init__(self, tf_prefixes: Sequence[tuple[str | None, str]]) -> None:
        self.unknown = any(scope is None for scope, _ in tf_prefixes)
        self.by_scope = {scope.strip("/"): value for scope, value in tf_prefixes
                         if scope is not None}

    def __bool__(self) -> bool:
        return self.unknown or bool(self.by_scope)

    def find(self, namespace: str) -> str:
        if self.unknown:
            return UNKNOWN_VALUE
        inside = namespace.strip("/")
        parts = inside.split("/") if inside else []
        for end in range(len(parts), -1, -1):
            found = self.by_scope.get("/".join(parts[:end]))
            if found is not None:
                return found
        return ""


def read_description(source: DescriptionSource, packages: PackageIndex, cache: RobotCache,
                     display: Callable[[str], str], env: dict[str, str],
                     standalone: bool = False, budget: Budget | None = None,
                     ) -> tuple[RobotModel | None, list[Problem]]:
    """The expanded description ``source`` gives (None when it cannot be read), and an
    ``unresolved`` diagnostic per problem of the expansion that is not a fault of its own;
    ``budget``: the launch tree's (a new one when the description is linted alone)."""
    budget = budget if budget is not None else Budget()
    # Imported here, as xacro is in RobotCache: only trees that publish a robot need it.
    from launch_linter.frontends.robot.urdf import (
        elements_of,
        joints_of,
        literal_root,
        plugins_of,
    )

    problems_found: list[Problem] = []
    defines_macros = False
    files: list[str] = []
    env_read: frozenset[str] = frozenset()
    if source.kind is DescriptionKind.LITERAL or source.file is None:
        root, problems = literal_root(source.text or "", source.path, source.line,
                                      own_lines=standalone)
    elif source.text is not None:
        # A description linted as text (``lint_text``): expanded, not kept in the cache.
        from launch_linter.frontends.robot.xacro import expand

        expansion = expand(source.file, dict(source.args), packages.find, env,
                           source.text.encode("utf-8"),
                           lambda path: packages.locate(path).path, budget, display)
        root, problems, files = expansion.root, expansion.problems, expansion.files
        defines_macros, env_read = expansion.defines_macros, expansion.env_read
    else:
        # A share path (FindPackageShare/$(find) of a ROS 2 package) is read from the
        # source file its install rules name; one nobody can prove absent stays unknown.
        located = packages.locate(source.file, near=source.near,
                                  ros_version=1 if source.near is not None else None)
        if located.path is None and not located.absent:
            return None, [_unresolved(source, f"robot description {display(source.file)} "
                                              f"not read: {located.reason}")]
        if located.path is None and _xacro_source(source):
            return _absent(source, display(source.file), located.reason), []
        args = source.args if source.kind is DescriptionKind.XACRO else ()
        expansion = cache.expansion(located.path or os.path.abspath(source.file), args,
                                    packages, env, budget, display)
        root, problems, files = expansion.root, expansion.problems, expansion.files
        defines_macros, env_read = expansion.defines_macros, expansion.env_read
    if source.kind is not DescriptionKind.XACRO:
        # Read as text (cat, textfile, open().read()): urdfdom parses it, not xacro's
        # minidom, and takes some of what expat refuses (space before the declaration).
        problems = [replace(p, kind=UNKNOWN) if p.fatal and p.kind == REFUSED else p
                    for p in problems]
    # A description read as text (textfile=, cat, open().read()) is never run through
    # xacro: its <xacro:...> elements are ones urdfdom skips, not calls xacro refuses.
    faults = (_faults(problems, source, display) + legacy_order_refusal(
        files, env, source.xacro_options, display)
        if source.kind is DescriptionKind.XACRO else ())
    proven = {(f.path, f.line, f.message) for f in faults if f.proven}
    followed_up = [p for p in _causes(problems)
                   if (display(p.path), p.line, p.message) not in proven]
    for problem in followed_up[:20]:
            where = display(problem.path)
            problems_found.append(Problem(
                "unresolved", source.path, source.line, source.column,
                f"robot description {where}:{problem.line}: {problem.message}"
                + ("; its joints are not read" if problem.fatal else ""),
            ))
    if root is None:
        # A file xacro refuses to read at all (not well-formed) stops the command as any
        # other refusal: kept, without joints, for ``xacro_error``.
        refused = tuple(f for f in faults if f.kind is FaultKind.REFUSED and f.proven)
        return (RobotModel(source, (), (), False, refused, False, standalone, ())
                if refused else None), problems_found
    if root.tag == "sdf":
        # ROS 2's robot_state_publisher reads SDF through the sdformat_urdf parser plugin
        # (gz-sim demos do); the linter reads URDF only, so the joints are unknown, not none.
        where = display(source.file) if source.file is not None else "(text)"
        problems_found.append(_unresolved(
            source, f"robot description {where} is SDF (<sdf> root, which "
                    f"robot_state_publisher reads through the sdformat_urdf plugin); "
                    f"its joints are not read"))
    found = joints_of(root, source, display, source.condition, bool(env.get("ROS_DISTRO")))
    plugins = plugins_of(root, display, source.condition, None)
    # After something not followed (an include not read, an unknown xacro arg), a joint's
    # unknown parent or origin may only follow from it: that is the cause already said.
    unknown = [j for j in found if j.reasons] if _all_followed(problems) else []
    for joint in unknown[:20]:
        problems_found.append(Problem(
            "unresolved", joint.path, joint.line, joint.column,
            f"URDF joint '{joint.name}' (robot_description at {source.path}:"
            f"{source.line}): {', '.join(joint.unresolved)} not known: "
            f"{'; '.join(joint.reasons)[:300]}",
        ))
    elements, names_known = elements_of(root, display, source.condition)
    followed = all(p.kind in (KEPT, *FAULT_KINDS) and p.kind != REFUSED for p in problems)
    # Variables read as unset that the wrapper may set: what they decide is not known.
    wrapped = sorted(n for n in env_read if n not in env and n != "ROS_DISTRO") if (
        source.wrapper) else []
    if wrapped:
        problems_found.append(_unresolved(source, (
            f"robot description: the command runs xacro through "
            f"{os.path.basename(source.wrapper or '')}, which may "
            f"set {', '.join(wrapped[:5])}; the links and joints they decide are not known")))
    # A description linted as text (an editor's buffer) is not on disk as it is read.
    ignored = (ignored_args(source, files, followed, packages.find) if source.text is None
               else ())
    robot = RobotModel(source, tuple(elements), tuple(found),
                       names_known and followed and not wrapped,
                       faults, defines_macros, standalone, tuple(plugins), ignored)
    return robot, problems_found


def _xacro_source(source: DescriptionSource) -> bool:
    """Whether ``source`` runs xacro on a file written as a xacro source (``*.xacro``):
    only such a file is never made by the build (``xacro_add_files`` writes its output
    without the ``.xacro``, xacro's ``cmake/xacro-extras.cmake.em``)."""
    return (source.kind is DescriptionKind.XACRO and source.file is not None
            and ".xacro" in os.path.basename(source.file))


def _absent(source: DescriptionSource, shown: str, reason: str) -> RobotModel:
    """The robot of a xacro call whose file is provably absent: xacro stops at once
    ("No such file or directory"), so the launch file's command fails; the fault is
    placed at the launch file's line that names the file."""
    fault = DescriptionFault(source.path, source.line, FaultKind.REFUSED,
                             f"no such file {shown}"
                             + ("" if reason == "not found" else f": {reason}"))
    return RobotModel(source, (), (), False, (fault,), False, False, ())


_FOLLOWED = (KEPT, *FAULT_KINDS)
"""Problem kinds after which the expansion goes on as the real xacro's would."""


def _faults(problems: Sequence[XacroProblem], source: DescriptionSource,
            display: Callable[[str], str]) -> tuple[DescriptionFault, ...]:
    """The problems that are faults of the source itself (xacro refuses or drops), each
    proven unless something before it was not followed (an include not read, an
    unsupported directive: what looks undefined may be defined there)."""
    out: list[DescriptionFault] = []
    followed = True
    for problem in problems:
        if problem.kind in FAULT_KINDS:
            # A block never inserted, a parameter read as an arg and a file not well-formed
            # are read from the macro or the file alone: nothing hides them.
            # A call not matching a macro defined after everything not followed is
            # xacro's stop whatever those held (XacroProblem.own).
            proven = problem.kind != REFUSED or MALFORMED in problem.message or problem.own or (
                followed and not (source.open_args and "$(arg " in problem.message))
            out.append(DescriptionFault(display(problem.path), problem.line,
                                        FaultKind(problem.kind), problem.message, proven,
                                        problem.conditions, problem.name))
        # A refusal stops the real xacro; what comes after it is checked as if it did not.
        followed = followed and problem.kind in _FOLLOWED
    return tuple(out)


_TAG = re.compile(r"^<[^>]*>: ")
"""The element a xacro problem names first (``<xacro:include>: ``)."""


def _causes(problems: Sequence[XacroProblem]) -> list[XacroProblem]:
    """The problems that are causes of their own: after an include not read (or another
    thing not followed) a refusal such as "unknown macro" may only follow from it, so it
    is not a cause of its own (nor a fault: see :func:`_faults`)."""
    out: list[XacroProblem] = []
    said: set[str] = set()
    followed = True
    for problem in problems:
        # One cause written in several places (the same package not found by two
        # includes) is said at the first.
        said_as = _TAG.sub("", problem.message, count=1)
        own = (followed or problem.kind != REFUSED or MALFORMED in problem.message
               or problem.own)
        if own and said_as not in said:
            out.append(problem)
            said.add(said_as)
        followed = followed and problem.kind in _FOLLOWED
    return out


def _all_followed(problems: Sequence[XacroProblem]) -> bool:
    return all(problem.kind in _FOLLOWED for problem in problems)


def _unresolved(source: DescriptionSource, message: str) -> Problem:
    return Problem("unresolved", source.path, source.line, source.column, message)


def robot_nodes(nodes: Sequence[NodeRecord]) -> list[NodeRecord]:
    return [n for n in nodes if n.package == RSP_PACKAGE]
