"""``launch-linter generate``: write a standalone linter for the chosen beliefs."""

from __future__ import annotations

import argparse
import os
import shlex
import stat
import sys

from launch_linter import __version__
from launch_linter.beliefs_files import BeliefsNotFound, load_beliefs
from launch_linter.commands.common import EXIT_OK, UsageError
from launch_linter.model.beliefs import BELIEF_CLASSES


def _classes(given: list[str] | None) -> tuple[str, ...]:
    if not given:
        return BELIEF_CLASSES
    names = {c.strip() for value in given for c in value.split(",") if c.strip()}
    unknown = sorted(names - set(BELIEF_CLASSES))
    if unknown:
        raise UsageError(
            f"unknown belief class(es): {', '.join(unknown)} "
            f"(choose from {', '.join(BELIEF_CLASSES)})"
        )
    return tuple(c for c in BELIEF_CLASSES if c in names)


def generate_command(beliefs: str, min_z: float, classes: tuple[str, ...]) -> str:
    """The command line that generates the same file (the output name does not matter)."""
    words = ["launch-linter", "generate", "--beliefs", beliefs, "--min-z", repr(min_z)]
    if classes != BELIEF_CLASSES:
        for cls in classes:
            words.extend(("--class", cls))
    return shlex.join(words)


def generate_text(beliefs_spec: str, min_z: float, classes: tuple[str, ...]) -> str:
    """The standalone linter for these beliefs, from the installed package's source."""
    # Imported here: the renderer needs Jinja2, which no other command loads.
    from launch_linter.generate import embed, render

    try:
        beliefs = load_beliefs(beliefs_spec, min_z)
    except BeliefsNotFound as exc:
        raise UsageError(str(exc)) from None
    try:
        embedding = embed.collect(embed.package_root())
        options = render.RenderOptions(
            beliefs_source=beliefs_spec,
            min_z=min_z,
            classes=classes,
            version=__version__,
            command=generate_command(beliefs_spec, min_z, classes),
        )
        return render.render(beliefs, embedding, options)
    except (embed.EmbedError, render.RenderError) as exc:
        raise UsageError(str(exc)) from None


def _write(path: str, text: str) -> None:
    with open(path, "w", encoding="utf-8", newline="\n") as handle:
        handle.write(text)
    mode = os.stat(path).st_mode
    # Executable for whoever may read it, as the shebang line intends.
    readable = mode & (stat.S_IRUSR | stat.S_IRGRP | stat.S_IROTH)
    os.chmod(path, mode | (readable >> 2))


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    generate = subparsers.add_parser("generate", help="render a standalone linter from beliefs")
    generate.add_argument("--beliefs", default="bundled")
    generate.add_argument("--min-z", type=float, default=1.0)
    generate.add_argument("--class", dest="classes", action="append", metavar="CLASS")
    generate.add_argument("-o", "--output", required=True, metavar="FILE.py")
    generate.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    classes = _classes(ns.classes)
    if ns.min_z != ns.min_z:  # NaN would select nothing and mean nothing
        raise UsageError("--min-z must be a number")
    text = generate_text(ns.beliefs, ns.min_z, classes)
    try:
        _write(ns.output, text)
    except OSError as exc:
        raise UsageError(f"cannot write {ns.output}: {exc.strerror or exc}") from None
    sys.stderr.write(
        f"wrote {ns.output}: {len(text.encode('utf-8')):,} bytes, "
        f"launch-linter {__version__}, beliefs {ns.beliefs} (z >= {ns.min_z:g})\n"
    )
    return EXIT_OK
