"""Text reached through an include names the include that reached it.

A file included with other arguments elsewhere can say something else at the same line, so
a diagnostic about an included file's text (ROS 1 XML, ROS 2 XML, YAML and Python alike)
says which include gave it its values, once: its message ends with ``(included from
FILE:LINE)`` and the include's place is its last related location. The report formats
read it back with :func:`included_from` (JSON ``included_from``, SARIF's related location
"included from here"); the message stays the one sentence a text report prints.
"""

from __future__ import annotations

from launch_linter.model.diagnostic import Location, Problem


def note(site: Location) -> str:
    """The words a message about included text ends with."""
    return f" (included from {site.path}:{site.line})"


def through_include(problem: Problem, site: Location) -> Problem:
    """``problem`` (about an included file's text) naming the include ``site``."""
    return Problem(problem.rule, problem.path, problem.line, problem.column,
                   problem.message + note(site), problem.node, (*problem.related, site))


def included_from(message: str, related: tuple[Location, ...]) -> Location | None:
    """The include a diagnostic's text was reached through (see :func:`through_include`),
    None for text of the file linted itself."""
    if not related or not message.endswith(note(related[-1])):
        return None
    return related[-1]


def cause(message: str, related: tuple[Location, ...]) -> str:
    """The message without the include it names: the same cause reached from two roots
    (a file linted alone and included, or included by two roots) is one finding."""
    site = included_from(message, related)
    return message if site is None else message[: -len(note(site))]
