"""The library API under the command line: discover files, load trees, run rules."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterable, Sequence

from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Diagnostic, Problem, Severity
from launch_linter.model.distro import uses_flags
from launch_linter.model.included import cause
from launch_linter.model.launch import FileRecord, FileStatus, LaunchTree
from launch_linter.model.paths import shown_path
from launch_linter.model.record import Record, _set
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import StaticTransform
from launch_linter.resolve import reads
from launch_linter.results_cache import ResultsCache, lint_with_cache
from launch_linter.rules._catalog import CATALOG, CATEGORY_OF, RULE_IDS
from launch_linter.rules._profiles import STUDY_SEVERITY
from launch_linter.suppressions import (
    UNUSED_ID,
    PathIgnore,
    apply_suppressions,
    ignored_by_path,
)
from launch_linter.workspace.discovery import (
    MAX_DISCOVERED_FILES,
    Exclusions,
    InputFile,
    discover,
)
from launch_linter.workspace.environment import built_beside

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Dict, Optional, Tuple

    # Imported where a file is linted: a run the results cache answers reads no launch
    # file and runs no rule (front-ends, rules, knowledge, packages: a third of start-up).
    from launch_linter.frontends import python_trees
    from launch_linter.frontends.robot.describe import RobotCache
    from launch_linter.frontends.ros1 import LoadOptions
    from launch_linter.knowledge import KnowledgeBase
    from launch_linter.results_cache import Linted
    from launch_linter.rules import Rule
    from launch_linter.rules._api import Finding
    from launch_linter.workspace.discovery import Ignored
    from launch_linter.workspace.environment import Place
    from launch_linter.workspace.packages import PackageIndex

__all__ = [
    "AUTO_JOBS",
    "MAX_DISCOVERED_FILES",
    "Exclusions",
    "InputFile",
    "LintOptions",
    "LintResult",
    "auto_jobs",
    "discover",
    "lint_bytes",
    "lint_files",
    "lint_paths",
    "lint_text",
]

AUTO_JOBS = 0
FILES_PER_JOB = 300
"""A worker must have this many files to pay for itself: a file costs about half a
millisecond, a worker's start and the results it sends back tens of milliseconds."""


class LintOptions(Record):
    """How to resolve launch files and which rules to run."""

    args: dict[str, str]
    env: dict[str, str]
    package_paths: tuple[str, ...] | None
    """``$(find)`` roots; None means the enclosing workspace of each linted file."""
    environment: tuple[Place, ...]
    """Package places of a sourced environment (``workspace.environment``), searched
    after the roots and the workspace's own ``install/``/``devel/``."""
    select: frozenset[str] | None
    ignore: frozenset[str]
    severity: dict[str, Severity]
    beliefs: BeliefSet
    jobs: int
    """Worker processes; ``AUTO_JOBS`` (0) lets ``auto_jobs`` choose from the file count."""
    per_path_ignores: tuple[PathIgnore, ...]
    profile: str
    """``default`` or ``study`` (the study's checks and severities, for ``evaluate``)."""
    ros: int | None
    """1 or 2: read every XML launch file as that ROS's (``--ros``); None: the nearest
    ``package.xml`` decides for ``*.xml`` files, else their content."""
    ros_distro: str | None
    """Target ROS distribution (lower case), for the rules and fixes that depend on it;
    None: from evidence in the files, else unknown."""
    knowledge: KnowledgeBase | None
    """The knowledge base of tf publishers; None: the bundled one."""

    __slots__ = (
        "args", "env", "package_paths", "environment", "select", "ignore", "severity", "beliefs",
        "jobs", "per_path_ignores", "profile", "ros", "ros_distro", "knowledge",
    )

    def __init__(
        self,
        args: dict[str, str] | None = None,
        env: dict[str, str] | None = None,
        package_paths: tuple[str, ...] | None = None,
        environment: tuple[Place, ...] = (),
        select: frozenset[str] | None = None,
        ignore: frozenset[str] = frozenset(),
        severity: dict[str, Severity] | None = None,
        beliefs: BeliefSet | None = None,
        jobs: int = 1,
        per_path_ignores: tuple[PathIgnore, ...] = (),
        profile: str = "default",
        ros: int | None = None,
        ros_distro: str | None = None,
        knowledge: KnowledgeBase | None = None,
    ) -> None:
        _set(self, "args", {} if args is None else args)
        _set(self, "env", {} if env is None else env)
        _set(self, "package_paths", package_paths)
        _set(self, "environment", environment)
        _set(self, "select", select)
        _set(self, "ignore", ignore)
        _set(self, "severity", {} if severity is None else severity)
        _set(self, "beliefs", BeliefSet.empty() if beliefs is None else beliefs)
        _set(self, "jobs", jobs)
        _set(self, "per_path_ignores", per_path_ignores)
        _set(self, "profile", profile)
        _set(self, "ros", ros)
        _set(self, "ros_distro", ros_distro)
        _set(self, "knowledge", knowledge)


class LintResult(Record):
    files: tuple[FileRecord, ...]
    trees: tuple[LaunchTree, ...]
    """Empty when the run was asked not to keep them (``keep_trees=False``)."""
    diagnostics: tuple[Diagnostic, ...]

    __slots__ = ("files", "trees", "diagnostics")

    def __init__(
        self,
        files: tuple[FileRecord, ...],
        trees: tuple[LaunchTree, ...],
        diagnostics: tuple[Diagnostic, ...],
    ) -> None:
        _set(self, "files", files)
        _set(self, "trees", trees)
        _set(self, "diagnostics", diagnostics)

    @property
    def transforms(self) -> tuple[StaticTransform, ...]:
        return tuple(t for tree in self.trees for t in tree.transforms)

    @property
    def joints(self) -> tuple[tuple[str, RobotJoint], ...]:
        """(root, joint) for every URDF joint a tree's robot_state_publisher publishes."""
        return tuple((tree.root, j) for tree in self.trees for j in tree.joints)


def _display_function(item: InputFile) -> object:
    def display(path: str) -> str:
        return item.display if os.path.abspath(path) == item.path else shown_path(path)

    return display


def selected_rules(options: LintOptions) -> tuple[Rule, ...]:
    from launch_linter.rules import RULES

    selected = selected_ids(options)
    return tuple(r for r in RULES if r.id in selected)


def selected_ids(options: LintOptions) -> frozenset[str]:
    """The ids of the rules ``options`` select (no rule module needed)."""
    return frozenset(
        rule_id
        for rule_id, category in CATALOG
        if (options.select is None or rule_id in options.select
            or category.value in options.select)
        and rule_id not in options.ignore
        and category.value not in options.ignore
    )


PACKAGE_DECIDES_SUFFIXES = (".xml",)
"""XML launch files whose ROS version the enclosing package decides (``*.launch.xml``,
``*_launch.xml``, ``*.xml`` with a ``<launch>`` root). ``*.launch`` stays decided by its
content: ROS 1 files left in migrated ament packages are common."""


if TYPE_CHECKING:
    Packages = Dict[Tuple[str, ...], Tuple[PackageIndex, reads.ReadLog]]
    """Package indexes by roots, and by folder (see ``load_options_for``)."""


def ros_version_for(path: str, options: LintOptions, index: PackageIndex) -> int | None:
    """``--ros`` if given; else, for ``*.xml`` files, the nearest package's build type
    (its manifest parsed once per index, which the install layout reads too)."""
    if options.ros is not None:
        return options.ros
    if not path.lower().endswith(PACKAGE_DECIDES_SUFFIXES):
        return None
    return index.ros_version_of(path)


def load_options_for(
    item: InputFile, options: LintOptions, cache: Packages,
    robots: RobotCache | None = None,
) -> LoadOptions:
    """How to load ``item``. ``cache`` (package indexes, each with its manifests' ROS
    versions) and ``robots`` are shared by the files of one run, so each is worked out
    once (and each file depends on what working it out read: ``reads.remembered``)."""
    from launch_linter.workspace.packages import default_package_roots

    if options.package_paths is not None:
        index = _package_index(tuple(options.package_paths), cache, options.environment)
    else:
        # default_package_roots walks up the folders of a file (to / outside a package):
        # done once per folder (the real one, for a symbolic link), whose index the cache
        # keeps under ("", folder), a key that no tuple of roots (absolute paths) can equal.
        path = os.path.realpath(item.path) if os.path.islink(item.path) else item.path
        index = reads.remembered(
            cache, ("", os.path.dirname(path)),
            lambda: _package_index(tuple(default_package_roots(path)), cache,
                                   options.environment))
    # The target distribution is the ROS_DISTRO of the machine that runs the files.
    distro = {"ROS_DISTRO": options.ros_distro} if options.ros_distro else {}
    from launch_linter.frontends.ros1 import LoadOptions

    return LoadOptions(
        args=options.args,
        env={**distro, **options.env},
        packages=index,
        display_path=_display_function(item),  # type: ignore[arg-type]
        study_errors=options.profile == "study",
        ros_version=ros_version_for(item.path, options, index),
        robots=robots,
        knowledge=options.knowledge,
    )


def _package_index(roots: tuple[str, ...], cache: Packages,
                   environment: tuple[Place, ...] = ()) -> PackageIndex:
    """The index of ``roots``, then their workspace's build output, then ``environment``
    (the order of ``workspace.environment``)."""
    from launch_linter.workspace.packages import PackageIndex

    places = (*built_beside(roots), *environment)
    key = (*roots, *(f"{kind}:{folder}" for kind, folder in places))
    return reads.remembered(cache, key, lambda: PackageIndex(list(roots), places))


def check_tree(tree: LaunchTree, rules: Iterable[Rule], options: LintOptions) -> list[Diagnostic]:
    """Run ``rules`` on one tree; each finding becomes a diagnostic stamped by its rule."""
    from launch_linter.knowledge import bundled
    from launch_linter.rules import RuleContext
    from launch_linter.rules._tree import with_macro_definitions
    from launch_linter.rules.description_never_loaded import at_info_if_never_loaded

    context = RuleContext(tree, options.beliefs, options.profile, target_distro(tree, options),
                          options.knowledge if options.knowledge is not None else bundled())
    found = at_info_if_never_loaded(tree, [(rule, f) for rule in rules
                                           for f in rule.check(context)])
    return with_macro_definitions(tree, [_stamp(rule, f, options) for rule, f in found])


def target_distro(tree: LaunchTree, options: LintOptions) -> str | None:
    """The distribution given, else Foxy when a file uses Foxy-era Node keywords (unless
    the tree's ROS 2 static_transform_publisher flags, Humble's, contradict them), else
    None."""
    if options.ros_distro:
        return options.ros_distro
    if any(p.rule == "ros2_removed_keyword" for p in tree.problems) and not any(
        t.ros_version == 2 and uses_flags(t.tokens) for t in tree.transforms
    ):
        return "foxy"
    return None


def _stamp(rule: Rule, finding: Finding, options: LintOptions) -> Diagnostic:
    # The one place where a rule's id, category and severity meet its findings, and where
    # the configuration's and command line's severity overrides apply. The study profile
    # gives a finding at the rule's default level the study's level for that rule.
    override = options.severity.get(rule.id)
    if override is None and options.profile == "study" and finding.severity is None:
        override = STUDY_SEVERITY.get(rule.id)
    return rule.diagnostic(finding, override)


def _file_record(item: InputFile, tree: LaunchTree) -> FileRecord:
    own = sum(1 for t in tree.transforms if t.path == item.display)
    return FileRecord(item.display, tree.status, own)


def finish_diagnostics(
    trees: Sequence[LaunchTree], diagnostics: Iterable[Diagnostic], options: LintOptions
) -> tuple[Diagnostic, ...]:
    """Apply inline suppressions and per-path ignores to the rules' diagnostics, and sort."""
    ran = selected_ids(options)
    kept, unused = apply_suppressions(
        trees,
        diagnostics,
        known={rule_id: category.value for rule_id, category in CATEGORY_OF.items()},
        ran=ran,
        report_unused=UNUSED_ID in ran,
    )
    stamped = []
    if unused:  # the rules themselves (their modules) only when a directive went unused
        from launch_linter.rules import RULES_BY_ID
        from launch_linter.rules._api import finding_of

        stamped = [_stamp(RULES_BY_ID[UNUSED_ID], finding_of(u), options) for u in unused]
    out = [
        d
        for d in (*kept, *stamped)
        if not ignored_by_path(d, options.per_path_ignores)
    ]
    return tuple(sorted(out, key=lambda d: d.sort_key))


if TYPE_CHECKING:
    Recorded = Tuple[Linted, Optional[reads.ReadLog]]
    """A file linted (its tree, None when not kept and there is no directive; its record
    and diagnostics) and, when asked, the log of what linting it read."""


def _directives_only(tree: LaunchTree) -> LaunchTree | None:
    """What suppressions need of a tree (its comments and element lines), if anything."""
    if not tree.comments:
        return None
    return LaunchTree(tree.root, tree.status, (), (), tree.files,
                      comments=tree.comments, element_lines=tree.element_lines)


REPORT_HINT = "please report it, with the file, at the project's issue tracker"


def internal_error_tree(item: InputFile, what: str, line: int = 1) -> LaunchTree:
    """The tree of a file the linter failed on: its status and one problem saying so."""
    message = f"internal error while linting this file ({what}); {REPORT_HINT}"
    problem = Problem("parse_error", item.display, line, 1, message[:MAX_INTERNAL_MESSAGE])
    return LaunchTree(item.display, FileStatus.INTERNAL_ERROR, (), (problem,), (item.display,))


def _internal_error(item: InputFile, what: str, line: int = 1) -> Linted:
    """A failed file as linted: its problem stated as a diagnostic whatever was selected."""
    from launch_linter.rules import RULES_BY_ID
    from launch_linter.rules._api import finding_of

    tree = internal_error_tree(item, what, line)
    rule = RULES_BY_ID["parse_error"]
    found = [rule.diagnostic(finding_of(p)) for p in tree.problems]
    return tree, _file_record(item, tree), found


MAX_INTERNAL_MESSAGE = 500


def _lint_one(item: InputFile, options: LintOptions, rules: Sequence[Rule],
              cache: Packages, robots: RobotCache | None = None) -> Linted:
    """One file, isolated: an unexpected exception costs this file only."""
    from launch_linter.frontends import python_trees
    from launch_linter.frontends.dispatch import load_tree

    try:
        # The fixes are located while the front-end's Python syntax trees are at hand, so
        # that no file is parsed twice (and the results cache keeps them located).
        with python_trees.keeping() as trees:
            tree = load_tree(item.path, load_options_for(item, options, cache, robots))
            found = check_tree(tree, rules, options)
        located = _with_located_fixes(found, options.ros_distro, trees=trees)
        return tree, _file_record(item, tree), list(located)
    except (KeyboardInterrupt, SystemExit):
        raise
    except BaseException as exc:  # one bad file never loses a run
        return _internal_error(item, f"{type(exc).__name__}: {exc}", _line_of(exc, item.path))


def _line_of(exc: BaseException, path: str) -> int:
    """The line of ``path`` being worked on when ``exc`` was raised, if the trace says."""
    trace = exc.__traceback__
    line = 1
    while trace is not None:
        if trace.tb_frame.f_code.co_filename == path:
            line = trace.tb_lineno
        trace = trace.tb_next
    return line


def _lint_chunk(
    items: Sequence[InputFile],
    options: LintOptions,
    cache: Packages,
    keep_trees: bool = True,
    record: bool = False,
) -> list[Recorded]:
    """Lint ``items``; with ``record``, each with the log of what linting it read."""
    rules = selected_rules(options)
    # One cache per chunk: a description included by many launch files is expanded once.
    from launch_linter.frontends.robot.describe import RobotCache

    robots = RobotCache()
    out: list[Recorded] = []
    for item in items:
        log = None
        if record:
            with reads.recording() as log:
                tree, found_record, found = _lint_one(item, options, rules, cache, robots)
        else:
            tree, found_record, found = _lint_one(item, options, rules, cache, robots)
        # Without the trees a run's memory stays flat: each is dropped once its rules ran.
        kept = tree if keep_trees or tree is None else _directives_only(tree)
        out.append(((kept, found_record, found), log))
    return out


_worker_packages: Packages = {}
"""Package indexes of one worker process, so that its chunks share each ``$(find)`` crawl."""


def _lint_chunk_in_worker(
    items: Sequence[InputFile], options: LintOptions, keep_trees: bool, record: bool,
    unsaved: dict[str, bytes] | None = None,
) -> list[Recorded]:
    if not unsaved:
        return _lint_chunk(items, options, _worker_packages, keep_trees, record)
    from launch_linter.resolve.xml_safe import unsaved_texts

    with unsaved_texts(unsaved):
        return _lint_chunk(items, options, _worker_packages, keep_trees, record)


def auto_jobs(files: int) -> int:
    """Workers for ``files`` files: one per ``FILES_PER_JOB`` files, at most one per CPU
    this process may use that other work (the load average) leaves free; at least one."""
    try:
        cpus = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not on every platform
        cpus = os.cpu_count() or 1
    try:
        busy = os.getloadavg()[0]
    except (AttributeError, OSError):
        busy = 0.0
    free = int(cpus - busy + 0.5)
    return max(1, min(cpus, free, files // FILES_PER_JOB))


def _lint_parallel(
    inputs: Sequence[InputFile], options: LintOptions, jobs: int, keep_trees: bool,
    record: bool = False,
) -> list[Recorded]:
    # Imported here: the process pool (with multiprocessing and logging) costs start-up
    # time that a serial run does not need.
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    from launch_linter.resolve.xml_safe import held_unsaved

    unsaved = held_unsaved()  # the texts --diff has fixed, not on disk
    # Several chunks per worker balance uneven files; results are put back in input order,
    # so the result is the serial one.
    size = max(1, -(-len(inputs) // (jobs * 4)))
    chunks = [inputs[i : i + size] for i in range(0, len(inputs), size)]
    results: list[list[Recorded] | None] = [None] * len(chunks)
    with ProcessPoolExecutor(max_workers=min(jobs, len(chunks))) as pool:
        futures = [pool.submit(_lint_chunk_in_worker, chunk, options, keep_trees, record,
                               unsaved)
                   for chunk in chunks]
        for index, future in enumerate(futures):
            with contextlib.suppress(BrokenProcessPool):
                results[index] = future.result()
    # A worker that died (killed, out of memory, a crash in C code) breaks the pool and
    # takes the unfinished chunks with it: their files are tried again one by one.
    lost = [item for index, chunk in enumerate(chunks) if results[index] is None
            for item in chunk]
    retried = _lint_alone(lost, options, keep_trees, record) if lost else {}
    out: list[Recorded] = []
    for index, chunk in enumerate(chunks):
        result = results[index]
        out.extend(result if result is not None else [retried[item.path] for item in chunk])
    return out


def _lint_alone(
    items: Sequence[InputFile], options: LintOptions, keep_trees: bool, record: bool
) -> dict[str, Recorded]:
    """Each file in a one-worker pool, in order, so that the file being linted when the
    worker dies is the one that killed it: it is reported, the files after it go on."""
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    from launch_linter.resolve.xml_safe import held_unsaved

    unsaved = held_unsaved()
    out: dict[str, Recorded] = {}
    remaining = list(items)
    while remaining:
        again: list[InputFile] = []
        with ProcessPoolExecutor(max_workers=1) as pool:
            futures = [pool.submit(_lint_chunk_in_worker, [item], options, keep_trees,
                                       record, unsaved)
                       for item in remaining]
            for position, item in enumerate(remaining):
                future = futures[position]
                try:
                    out[item.path] = future.result()[0]
                except BrokenProcessPool:
                    out[item.path] = (
                        _internal_error(item, "the worker process linting it died"), None)
                    again = remaining[position + 1:]
                    break
        remaining = again
    return out


def _with_located_fixes(
    diagnostics: Sequence[Diagnostic], distro: str | None,
    sources: dict[str, bytes] | None = None, trees: python_trees.Trees | None = None,
) -> tuple[Diagnostic, ...]:
    """``fix.with_located_fixes``, imported only when a finding carries a fix not located
    yet: locating edits is start-up time a run without one never needs."""
    if all(d.fix is None or d.fix.edits for d in diagnostics):
        return tuple(diagnostics)
    from launch_linter.fix import with_located_fixes

    return with_located_fixes(diagnostics, distro, sources, trees)


def lint_files(
    inputs: Sequence[InputFile], options: LintOptions, keep_trees: bool = True,
    cache: ResultsCache | None = None,
) -> LintResult:
    """Lint ``inputs``; with ``keep_trees=False`` the result has no trees (``check`` needs
    only the records and diagnostics, and memory then stays flat with the file count).

    ``cache``: reuse the results it holds that still hold, and put the others in it (its
    ``save`` is the caller's); used only with ``keep_trees=False``, as it keeps no trees.
    The result is the same as without it."""
    record = cache is not None and not keep_trees

    def lint(items: list[InputFile]) -> list[Recorded]:
        # Jobs are chosen for the files that are linted, not those the cache answers.
        jobs = options.jobs if options.jobs != AUTO_JOBS else auto_jobs(len(items))
        if jobs > 1 and len(items) > 1:
            return _lint_parallel(items, options, jobs, keep_trees, record)
        return _lint_chunk(items, options, {}, keep_trees, record)

    linted = lint_with_cache(inputs, cache if record else None, lint)
    trees = tuple(tree for tree, _, _ in linted if tree is not None)
    records = tuple(record for _, record, _ in linted)
    unique = _deduplicated(found for _, _, found in linted)
    # The per-file lists go before the findings are finished and their fixes located, so
    # that the peak memory of a large run holds each finding in one list, not in several.
    del linted
    finished = finish_diagnostics(trees, unique, options)
    return LintResult(
        records, trees if keep_trees else (), _with_located_fixes(finished, options.ros_distro)
    )


def _deduplicated(found: Iterable[list[Diagnostic]]) -> list[Diagnostic]:
    """The findings of every file, each once: a file linted on its own and also included
    by another input is reported once (the same place, rule and message found from two
    roots, or under two spellings of its path, is one finding, at the highest level any
    root gives it: a xacro file linted alone and loaded by a launch file). The include a
    message about included text names does not make another cause: the finding of the
    file linted alone is kept, else the first include's."""
    diagnostics: dict[tuple[object, ...], Diagnostic] = {}
    real: dict[str, str] = {}
    for diagnostics_of_file in found:
        for diagnostic in diagnostics_of_file:
            where = real.get(diagnostic.path)
            if where is None:
                where = real[diagnostic.path] = os.path.realpath(diagnostic.path)
            text = cause(diagnostic.message, diagnostic.related)
            key = (where, diagnostic.line, diagnostic.column, diagnostic.rule, text)
            known = diagnostics.setdefault(key, diagnostic)
            rank, known_rank = diagnostic.severity.rank, known.severity.rank
            if rank > known_rank or (rank == known_rank and text == diagnostic.message
                                     and known.message != text):
                diagnostics[key] = diagnostic
    return list(diagnostics.values())


def lint_paths(
    paths: Sequence[str],
    options: LintOptions | None = None,
    exclusions: Exclusions | None = None,
    ignored: Ignored | None = None,
    keep_trees: bool = True,
    cache: ResultsCache | None = None,
) -> LintResult:
    """Lint files and folders; every input file appears once in ``files``.

    ``exclusions`` are the folder-walk exclusions (default: VCS and hidden folders) and
    ``ignored`` an extra predicate on paths found in folders (the CLI's ``.gitignore``);
    ``keep_trees=False`` drops each file's tree once its rules ran, and ``cache`` reuses
    results (see ``lint_files``)."""
    if cache is None or keep_trees:
        inputs = discover(paths, exclusions, ignored)
    else:
        inputs = cache.discovered([list(paths), exclusions or Exclusions(), ignored is not None],
                                  lambda: discover(paths, exclusions, ignored))
    return lint_files(inputs, options or LintOptions(), keep_trees, cache)


def lint_text(
    text: str, path: str = "<string>.launch", options: LintOptions | None = None
) -> LintResult:
    """Lint launch-file text as if it were the file ``path`` (which need not exist)."""
    return lint_bytes(text.encode("utf-8"), path, options)


def lint_bytes(
    data: bytes, path: str = "<string>.launch", options: LintOptions | None = None
) -> LintResult:
    """Lint a launch file's bytes as if they were the file ``path`` (which need not
    exist): read in the encoding they declare, fixes located in these very bytes."""
    options = options or LintOptions()
    item = InputFile(os.path.abspath(path), path)
    load = load_options_for(item, options, {})
    from launch_linter.frontends import python_trees
    from launch_linter.frontends.dispatch import load_tree

    with python_trees.keeping() as trees:
        tree = load_tree(item.path, load, data)
    found = check_tree(tree, selected_rules(options), options)
    diagnostics = _with_located_fixes(
        finish_diagnostics((tree,), found, options), options.ros_distro, {path: data}, trees,
    )
    return LintResult((_file_record(item, tree),), (tree,), diagnostics)


def rule_ids() -> tuple[str, ...]:
    return RULE_IDS
