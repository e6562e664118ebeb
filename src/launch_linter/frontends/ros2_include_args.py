"""ROS 2 include arguments that the included description never uses.

``IncludeLaunchDescription`` sets every launch argument it is given as a launch
configuration and runs the included description; nothing checks that the description
declares or reads it (ROS 1's roslaunch refuses such an include: ``unused args``). An
argument that no action of the included file, nor of the files it includes, declares or
reads changes nothing: usually a switch the included file does not have (or no longer has,
or spells differently). :class:`ArgumentWatch` follows the includes as ``ros2_run`` runs
them: every launch configuration read (``$(var)``, ``LaunchConfiguration``, an
``OpaqueFunction``'s ``context.launch_configurations``), declared or set, the actions
not run (a false condition: read statically), and every configuration the files' text
names (a ``LaunchConfiguration`` handed to a function the linter does not model). Anything
it cannot see (an include not followed or skipped, an ``OpaqueFunction`` not run, a
configuration name not literal, launch arguments not known, a parameter file loaded with
``allow_substs`` that cannot be read, or any given in Python, where ``allow_substs`` is
not kept) makes the include's arguments unknown: never reported; so does a file
chosen by a launch configuration (``$(var vehicle_model)_launch``: its arguments are an
interface that other files fill).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Callable

from launch_linter.frontends.ros2_actions import (
    Action,
    DeclareArg,
    Deferred,
    Include,
    ParamsFile,
    SetVar,
    Unfollowed,
    Where,
)
from launch_linter.frontends.ros2_declared import Declarations
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.resolve.ros2_substitution import Call, Text
from launch_linter.resolve.xml_safe import read_regular_file

RULE = "ros2_unused_include_arg"
MISSPELT = "ros2_include_arg_misspelt"
MAX_SUGGESTION_CANDIDATES = 500
MAX_PARAMETER_FILE_BYTES = 512 * 1024
"""What is read of a parameter file for its ``$(var)`` (its parser reads as much)."""
MAX_SUGGESTED_NAMES = 32
"""Bounds of the "did you mean": the declared names one reported argument is compared
with, and the reported arguments that get one (each comparison costs)."""


PYTHON_MENTIONS = re.compile(
    r"LaunchConfiguration(?:Equals|NotEquals)?\(\s*(?:variable_name\s*=\s*)?"
    r"(?:'([^'\\\n]*)'|\"([^\"\\\n]*)\"|(?=[^\s'\"]))"
    r"|launch_configurations\s*(?:\[|\.get\(|\.__getitem__\()\s*"
    r"(?:'([^'\\\n]*)'|\"([^\"\\\n]*)\")")
"""A configuration a Python launch file names: ``LaunchConfiguration('x')`` (also
``...Equals``, ``...NotEquals``) or ``context.launch_configurations['x']`` / ``.get('x')``;
no group matched: a name that is not a string literal."""
CONTEXT_READS = re.compile(r"launch_configurations\s*(?:\[|\.get\(|\.__getitem__\()\s*['\"]")
XML_MENTIONS = re.compile(r"\$\(var\s+(?:([^\s)$]+)|(?=\$))")
"""``$(var x)`` in XML or YAML launch text; no group matched: ``$(var $(...))``."""
ENTRY_POINT = re.compile(r"^[ \t]*def generate_launch_description\b", re.M)


def _decorated_entry(text: str) -> bool:
    """Whether a ``generate_launch_description`` stands under a decorator (the line
    before it starts with ``@``): one look back per definition, linear in the text."""
    for match in ENTRY_POINT.finditer(text):
        before = text.rfind("\n", 0, max(match.start() - 1, 0))
        if text[before + 1:match.start()].lstrip().startswith("@"):
            return True
    return False


class _Watch:
    """One include being run: its arguments and what its files use."""

    __slots__ = ("include", "target", "passed", "used", "declared", "unknown", "openings")

    def __init__(self, include: Include, target: str, passed: dict[str, tuple[int, int]],
                 openings: int) -> None:
        self.include = include
        self.target = target
        self.passed = passed
        """Each argument name given, with where it is given (line, column; 0, 0 when the
        front-end does not know: the include's place)."""
        self.used: set[str] = set()
        self.declared: set[str] = set()
        self.unknown = False
        self.openings = openings


class ArgumentWatch:
    """The includes being run (innermost last) and, per include argument, whether any
    run of the include used it."""

    def __init__(self, declarations: Declarations) -> None:
        self._declarations = declarations
        self._open: list[_Watch] = []
        self._unused: dict[tuple[str, int, int, str], tuple[_Unused, bool]] = {}
        """Per include place and argument: what to report and whether every run of that
        include left the argument unused."""

    # -- what the runner tells ------------------------------------------------------------
    def read(self, name: str | None) -> None:
        """A launch configuration read (``None``: a name the linter could not resolve)."""
        if not self._open:
            return
        if name is None:
            self._open[-1].unknown = True
        else:
            self._open[-1].used.add(name)

    def declares(self, action: Action) -> None:
        """An action met in an included file, run or not: declaring or setting a
        configuration counts as using the argument of that name."""
        if not self._open or not isinstance(action, (DeclareArg, SetVar)):
            return
        name = _literal(action.name)
        if name is None:
            self._open[-1].unknown = True
        else:
            self._open[-1].declared.add(name)

    def skipped(self, action: Action) -> None:
        """An action a false condition skips: its substitutions are not performed, but
        what it would read is the description's own; an include or ``OpaqueFunction`` in it
        is unseen."""
        if self._open:
            watch = self._open[-1]
            watch.unknown = _static_reads(action, watch.used) or watch.unknown

    def file_read(self, data: bytes, python: bool) -> None:
        """A file an include being watched reads: every configuration its text names
        counts as read, where launch would perform it or not (a ``LaunchConfiguration``
        handed to a function the linter does not model, ``RewrittenYaml``'s
        ``root_key``); a name it cannot read (not a literal) makes the include unknown."""
        if not self._open:
            return
        watch = self._open[-1]
        if not any(open_watch.passed for open_watch in self._open):
            return  # nothing to judge in it or around it (decoding costs)
        text = data.decode("utf-8", "replace")
        found = PYTHON_MENTIONS if python else XML_MENTIONS
        for match in found.finditer(text):
            name = next((g for g in match.groups() if g is not None), None)
            if name is None:
                watch.unknown = True
            else:
                watch.used.add(name)
        if python and text.count("launch_configurations") > len(CONTEXT_READS.findall(text)):
            watch.unknown = True  # the launch context's configurations, read otherwise
        if python and _decorated_entry(text):
            # A decorator around generate_launch_description may declare arguments
            # (beluga's @with_launch_arguments(...)): what it declares is not read.
            watch.unknown = True
        if python and "allow_substs" in text:
            # A parameter file whose $(var) launch performs, given in Python (where the
            # linter does not keep allow_substs): not read.
            watch.unknown = True

    def parameter_file(self, path: str | None) -> None:
        """A parameter file loaded with ``allow_substs`` (XML, YAML) by a node of the
        include being watched: the ``$(var x)`` in it are reads; a file that cannot be
        read (or a path not resolved) makes the include unknown."""
        if not self._open or not any(open_watch.passed for open_watch in self._open):
            return
        watch = self._open[-1]
        try:
            data = b"" if path is None else read_regular_file(path, MAX_PARAMETER_FILE_BYTES)
        except OSError:
            path = None
        if path is None:
            watch.unknown = True
            return
        for match in XML_MENTIONS.finditer(data.decode("utf-8", "replace")):
            if match.group(1) is None:
                watch.unknown = True
            else:
                watch.used.add(match.group(1))

    def start(self, include: Include, target: str, passed: dict[str, tuple[int, int]]
              ) -> None:
        """``include`` is about to run ``target`` with the arguments ``passed``. When a
        launch configuration chooses the file (``$(var vehicle_model)_launch``), the
        arguments are an interface that other files fill: not judged."""
        chooser: set[str] = set()
        if _static_reads(include.path, chooser) or chooser:
            passed = {}
        self._open.append(_Watch(include, target, passed, self._declarations.openings))

    def finish(self, shown: Callable[[str], str]) -> None:
        """The include started last has run: judge its arguments, and hand what its
        files used to the include around it."""
        watch = self._open.pop()
        if self._declarations.openings != watch.openings:
            watch.unknown = True  # something in it was not followed
        if self._open:
            outer = self._open[-1]
            outer.used.update(watch.used)
            outer.declared.update(watch.declared)
            outer.unknown = outer.unknown or watch.unknown
        where = watch.include.where
        for name, (line, column) in watch.passed.items():
            key = (where.path, where.line, where.column, name)
            unused = name not in watch.used and name not in watch.declared
            earlier = self._unused.get(key)
            if earlier is not None:
                # One include run again (a file included twice): unused only if every run
                # left it unused, and seen whole only if every run was.
                earlier[0].unknown = earlier[0].unknown or watch.unknown
                self._unused[key] = (earlier[0], earlier[1] and unused)
                continue
            place = Location(shown(where.path), line or where.line, column or where.column)
            self._unused[key] = (_Unused(name, place, Location(place.path, where.line,
                                                               where.column),
                                         shown(watch.target), watch.declared,
                                         watch.unknown), unused)

    def abandon(self) -> None:
        """The run stopped midway (the work budget ran out): nothing open is judged."""
        self._open.clear()

    def problems(self) -> list[Problem]:
        """The arguments no run used: misspelt when a declared name is spelt alike (even
        where some of the include is unseen: its files declare the other spelling), else
        unused where every run was seen whole. Close names are looked for in the first
        ``MAX_SUGGESTED_NAMES`` arguments only (each comparison costs)."""
        found: list[Problem] = []
        compared = 0
        for fact, unused in self._unused.values():
            if not unused:
                continue
            close = None
            if compared < MAX_SUGGESTED_NAMES and fact.declared:
                compared += 1
                close = fact.close_name()
            if close is not None:
                found.append(fact.misspelt(close))
            elif not fact.unknown:
                found.append(fact.problem())
        return found


class _Unused:
    """An include argument no run of the include used."""

    __slots__ = ("name", "place", "include", "target", "declared", "unknown")

    def __init__(self, name: str, place: Location, include: Location, target: str,
                 declared: set[str], unknown: bool) -> None:
        self.name = name
        self.place = place
        self.include = include
        self.target = target
        self.declared = declared
        """What the included files declare (for a "did you mean")."""
        self.unknown = unknown
        """Whether some of what the include runs is unseen (it may read the argument)."""

    def close_name(self) -> str | None:
        """A name the included files declare that is spelt like this one (difflib's ratio
        of 0.8 or more), or that is this one with a word joined by ``_`` (``params`` and
        ``params_file``), else None."""
        # Imported here: difflib is needed only for an argument nothing uses.
        import difflib

        candidates = sorted(self.declared)[:MAX_SUGGESTION_CANDIDATES]
        close = difflib.get_close_matches(self.name, candidates, 1, 0.8)
        if close:
            return close[0]
        extended = [name for name in candidates if _one_word_apart(self.name, name)]
        return extended[0] if len(extended) == 1 else None

    def misspelt(self, close: str) -> Problem:
        message = (f"launch argument '{self.name}' is passed to {self.target}, which declares "
                   f"'{close}' and neither declares nor reads '{self.name}': ROS 2 launch "
                   f"sets it as a configuration nothing reads, and '{close}' keeps its "
                   f"default; pass '{close}'")
        return Problem(MISSPELT, self.place.path, self.place.line, self.place.column,
                       message, None, (self.include,))

    def problem(self) -> Problem:
        message = (f"launch argument '{self.name}' is passed to {self.target}, which neither "
                   f"declares nor reads it (nor do the files it includes): ROS 2 launch "
                   f"ignores it without a word: declare it there and use it, or stop "
                   f"passing it")
        return Problem(RULE, self.place.path, self.place.line, self.place.column, message,
                       None, (self.include,))


def _one_word_apart(name: str, other: str) -> bool:
    """Whether one name is the other with one more word joined by ``_`` before or after
    it (``params``, ``params_file``; ``frame``, ``base_frame``)."""
    short, long = sorted((name, other), key=len)
    if not short or len(long) == len(short):
        return False
    if long.startswith(short + "_"):
        rest = long[len(short) + 1:]
    elif long.endswith("_" + short):
        rest = long[:-len(short) - 1]
    else:
        return False
    return bool(rest) and "_" not in rest


def _literal(subs: tuple[object, ...]) -> str | None:
    if all(isinstance(sub, Text) for sub in subs):
        return "".join(sub.text for sub in subs if isinstance(sub, Text))
    return None


def _static_reads(action: object, used: set[str]) -> bool:
    """Add to ``used`` the configurations ``action`` (an action or substitutions) would
    read if it ran; True when it holds something whose reads cannot be seen (an include,
    an ``OpaqueFunction``, something not followed, a configuration name not literal).
    Iterative: the action's depth is the input's."""
    unseen = False
    stack: list[object] = [action]
    while stack:
        item = stack.pop()
        if isinstance(item, (Include, Deferred, Unfollowed)) or (
                isinstance(item, ParamsFile) and item.substitutions):
            unseen = True
        elif isinstance(item, Call):
            if item.name == "var" and item.args:
                name = _literal(item.args[0])
                if name is None:
                    unseen = True
                else:
                    used.add(name)
            stack.extend(item.args)
        elif isinstance(item, (tuple, list)):
            stack.extend(item)
        elif dataclasses.is_dataclass(item) and not isinstance(item, (type, Where)):
            stack.extend(getattr(item, f.name) for f in dataclasses.fields(item))
    return unseen
