"""``launch-linter server``: the language server over standard input and output."""

from __future__ import annotations

import argparse

from launch_linter.commands.common import EXIT_OK, UsageError

INSTALL_HINT = "the language server needs the lsp extra: pip install 'launch-linter[lsp]'"


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    server = subparsers.add_parser(
        "server", help="language server for editors (stdio; needs the lsp extra)"
    )
    server.add_argument("--stdio", action="store_true", help="talk over stdio (the default)")
    server.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    try:
        # pygls is the lsp extra's: imported only when the server runs
        from launch_linter.server.lsp import serve
    except ModuleNotFoundError as exc:
        if exc.name is not None and exc.name.split(".")[0] in ("pygls", "lsprotocol"):
            raise UsageError(INSTALL_HINT) from None
        raise
    serve()
    return EXIT_OK
