"""The launch configurations of one ROS 2 tree: which names are declared or set, which are
read where unset, and what the loader did not follow before each read (``ros2_run`` tells
it as it runs the actions in launch's order). :meth:`Declarations.facts` gives the reads
that nothing in the tree declares, sets or passes: launch's "launch configuration 'x' does
not exist" (the rule ``ros2_undeclared_arg`` words them)."""

from __future__ import annotations

from collections.abc import Callable

from launch_linter.frontends.ros2_actions import Action, DeclareArg, SetVar, Where
from launch_linter.model.launch import UndeclaredUse
from launch_linter.resolve.ros2_substitution import Text, written
from launch_linter.workspace.mentions import named_by_another_file

MAX_SUGGESTED_NAMES = 32
MAX_SUGGESTION_CANDIDATES = 2_000
"""Bounds of the "did you mean" of undeclared launch configurations."""


class Declarations:
    def __init__(self) -> None:
        self.declared: set[str] = set()
        """Every launch configuration the tree declares or sets, wherever."""
        self.open: str | None = None
        """The first thing met so far that could set launch configurations the linter
        cannot see."""
        self.openings = 0
        """How many things met so far could set launch configurations the linter cannot
        see (an include's arguments it cannot judge when one is met inside it)."""
        self.unset: dict[tuple[str, int, int, str], tuple[bool, str | None]] = {}
        """Launch configurations read without a default where none was set, by place:
        whether under an undecided condition, and what was not followed before."""

    def opened(self, reason: str, rule: str = "unresolved") -> None:
        """Something not followed leaves the tree open; a rule's problem does not."""
        if rule != "unresolved":
            return
        self.openings += 1
        if self.open is None:
            self.open = reason

    def read_unset(self, name: str, where: Where, conditional: bool) -> None:
        """``name`` read without a default at ``where``, where it is not set."""
        key = (where.path, where.line, where.column, name)
        known = self.unset.get(key)
        if known is None:
            # What was not followed before the read: launch runs actions in order, so
            # nothing met later could have set it in time.
            self.unset[key] = (conditional, self.open)
        elif known[0] and not conditional:
            # One place (a LaunchConfiguration) performed by several actions: it fails
            # for sure when any of them runs for sure.
            self.unset[key] = (False, known[1])

    def declares(self, action: Action) -> None:
        """Note the configuration an action declares or sets, whether or not it runs:
        a declaration under a false condition is still the author's (it is the condition
        that leaves the configuration unset, and the linter does not judge that)."""
        if isinstance(action, (DeclareArg, SetVar)):
            if all(isinstance(sub, Text) for sub in action.name):
                self.declared.add(written(action.name))
            else:
                self.opened(f"line {action.where.line}: a configuration name is not literal")

    def facts(self, root: str, display: Callable[[str], str], root_display: str
              ) -> tuple[UndeclaredUse, ...]:
        """The configurations read where unset that nothing in the tree declares, sets or
        passes (a declared one without a default is the user's to give); ``root`` is the
        root file's absolute path."""
        found = [(key, conditional, opened) for key, (conditional, opened) in self.unset.items()
                 if key[3] not in self.declared]
        if not found:
            return ()
        # Imported here: difflib is needed only for a finding's "did you mean".
        import difflib

        includer = named_by_another_file(root)
        # A "did you mean" for the first names only, against the first declared ones:
        # each comparison costs, and a hostile file can hold thousands of both.
        declared = sorted(self.declared)[:MAX_SUGGESTION_CANDIDATES]
        similar: dict[str, str | None] = {}
        for name in dict.fromkeys(key[3] for key, _, _ in found):
            if len(similar) >= MAX_SUGGESTED_NAMES:
                break
            similar[name] = next(iter(difflib.get_close_matches(name, declared, 1, 0.8)), None)
        return tuple(
            UndeclaredUse(
                name, display(path), line, column, root_display, conditional, opened,
                None if includer is None else display(includer), similar.get(name),
            )
            for (path, line, column, name), conditional, opened in found
        )
