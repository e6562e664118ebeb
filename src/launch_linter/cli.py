"""The ``launch-linter`` command: assembles the subcommands' parsers and dispatches.

Each subcommand module owns its arguments (``add_parser``) and its handler (``run``);
exit statuses and :class:`UsageError` live in the leaf module ``commands.common``.
"""

from __future__ import annotations

import argparse
import gc
import os
import sys
from collections.abc import Callable, Sequence
from types import ModuleType

from launch_linter import __version__
from launch_linter.commands.common import EXIT_OK, EXIT_USAGE, UsageError, check_numbers

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any

CORE_COMMANDS = ("check", "transforms", "rules", "explain")
"""The core commands, in help order; their modules (which import the engine) are
imported only when a parser is built for them, so ``--version`` alone imports none."""

_EDGE_PACKAGES = (
    "launch_linter.mining",
    "launch_linter.generate",
    "launch_linter.evaluation",
    "launch_linter.graph",
    "launch_linter.server",
)


def _edge_commands() -> list[ModuleType]:
    """The commands of the edge packages, in help order. The standalone linter carries
    only the core, so there these packages are absent and their commands with them."""
    try:
        from launch_linter.evaluation import commands as evaluate
        from launch_linter.generate import commands as generate
        from launch_linter.graph import commands as graph
        from launch_linter.mining import commands as mine
        from launch_linter.server import commands as server
    except ModuleNotFoundError as exc:
        if exc.name is None or not exc.name.startswith(_EDGE_PACKAGES):
            raise
        return []
    return [mine, generate, evaluate, graph, server]


def _core_commands(only: str | None = None) -> list[ModuleType]:
    """The core commands' modules in help order (``only``: that command's alone, the
    others' modules are start-up time for nothing)."""
    return [_core_command(name) for name in CORE_COMMANDS if only is None or name == only]


def _core_command(name: str) -> ModuleType:
    # Each import written out (not importlib): the standalone linter's embedding follows
    # the imports it reads (generate/embed.py).
    if name == "check":
        from launch_linter.commands import check

        return check
    if name == "transforms":
        from launch_linter.commands import transforms

        return transforms
    if name == "rules":
        from launch_linter.commands import rules

        return rules
    from launch_linter.commands import explain

    return explain


def _named_command(argv: Sequence[str]) -> str | None:
    """The core command that ``argv`` names, if any."""
    words = [a for a in argv if not a.startswith("-")]
    return words[0] if words and words[0] in CORE_COMMANDS else None


def _core_only(argv: Sequence[str] | None) -> bool:
    """Whether the command line names a core command (or asks only for the version): then
    the edge commands' parsers, and the libraries their modules import, are not needed,
    which is most of the start-up time of a ``check``."""
    args = list(sys.argv[1:] if argv is None else argv)
    return args == ["--version"] or _named_command(args) is not None


class HelpFormatter(argparse.HelpFormatter):
    """argparse's own, which measures the terminal only when it formats something.

    ``add_argument`` makes a formatter for every argument, only to check its metavar, and
    measuring the terminal imports ``shutil`` (with its compression modules): a tenth of
    the start-up of a run answered by the results cache, which prints no help."""

    def __init__(self, prog: str, *args: Any, **kwargs: Any) -> None:
        self._arguments = (prog, args, kwargs)

    def __getattr__(self, name: str) -> Any:
        # Called only for an attribute not set yet: the base class's, which it sets as it
        # starts (measuring the terminal), so it starts now.
        if name.startswith("__") or "_prog" in self.__dict__:
            raise AttributeError(name)
        prog, args, kwargs = self.__dict__["_arguments"]
        super().__init__(prog, *args, **kwargs)
        return getattr(self, name)


class ArgumentParser(argparse.ArgumentParser):
    """A parser, and its subcommands' parsers, with :class:`HelpFormatter` by default."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", HelpFormatter)
        super().__init__(*args, **kwargs)


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The parser for ``argv``: that of the core command it names (the others' parsers
    are start-up time for nothing), else every command's."""
    parser = ArgumentParser(
        prog="launch-linter",
        description="Find mistakes in the static transforms of ROS launch files.",
    )
    parser.add_argument("--version", action="version", version=f"launch-linter {__version__}")
    # ``prog`` given (the usage argparse would format from the parser, which has no
    # positional argument before the command): formatting it measures the terminal.
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", prog=parser.prog)
    if argv is not None and _core_only(argv):
        # The named command's parser alone; none for ``--version``, which argparse prints
        # before any command is read.
        named = _named_command(argv)
        commands = [] if named is None else _core_commands(named)
    else:
        commands = [*_core_commands(), *_edge_commands()]
    for module in commands:
        module.add_parser(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser(sys.argv[1:] if argv is None else argv)
    ns = parser.parse_args(argv)
    if ns.command is None:
        parser.print_help()
        return EXIT_USAGE
    handler: Callable[[argparse.Namespace], int] = ns.handler
    try:
        check_numbers(vars(ns))
        return handler(ns)
    except UsageError as exc:
        sys.stderr.write(f"launch-linter: error: {exc}\n")
        return EXIT_USAGE
    except BrokenPipeError:
        return EXIT_OK
    except KeyboardInterrupt:
        sys.stderr.write("launch-linter: interrupted\n")
        return EXIT_USAGE
    except Exception as exc:  # the contract: an internal failure is exit 2, never exit 1
        if os.environ.get("LAUNCH_LINTER_DEBUG"):
            raise
        sys.stderr.write(
            f"launch-linter: internal error: {type(exc).__name__}: {exc}\n"
            "(set LAUNCH_LINTER_DEBUG=1 for the traceback, and please report it)\n"
        )
        return EXIT_USAGE


def tune_collector() -> None:
    """Let the garbage collector run far less often during a run of the command.

    What a run allocates lives as long as the run (modules, parsers, beliefs) or as long as
    one file, and reference counting frees a file's trees (ROS 1 XML leaves no reference
    cycles at all), so the collector's frequent young-generation passes find almost
    nothing and its full passes re-scan everything imported. Freezing what exists after
    start-up and collecting the young generation every 50,000 allocations instead of 700
    saves about a tenth of ``check``'s CPU on the corpus. Only the console command does
    this: :func:`main` is also called by programs and tests that keep their own settings.
    """
    gc.freeze()
    gc.set_threshold(50_000, 20, 20)


def entry() -> int:
    """The ``launch-linter`` console command."""
    tune_collector()
    return main()
