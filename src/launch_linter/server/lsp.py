"""The language server over stdio (pygls; the ``lsp`` extra): diagnostics, fixes, hover.

Diagnostics follow every change of an open launch file, URDF or xacro (unsaved text): the
document's own lint if it is a launch file, and that of every entry point that includes or
loads it. Code actions are the findings' fixes (safe ones preferred, unsafe ones labelled).
Hover on a frame shows its parent chain and who publishes it. See docs/editors.md.
"""

from __future__ import annotations

import os
from typing import Any

from lsprotocol import types as lsp
from pygls.server import LanguageServer
from pygls.uris import from_fs_path, to_fs_path

from launch_linter import __version__
from launch_linter.model.diagnostic import Applicability, Diagnostic, Severity
from launch_linter.server.session import CONFIG_NAMES, Session

SEVERITIES = {
    Severity.ERROR: lsp.DiagnosticSeverity.Error,
    Severity.WARNING: lsp.DiagnosticSeverity.Warning,
    Severity.INFO: lsp.DiagnosticSeverity.Information,
}
SOURCE = "launch-linter"


def utf16_length(text: str) -> int:
    return len(text.encode("utf-16-le")) // 2


class Positions:
    """LSP positions (0-based lines, UTF-16 characters) in one document's text."""

    def __init__(self, text: str) -> None:
        self.lines = text.split("\n")
        self.data = text.encode("utf-8", "surrogateescape")

    def of_column(self, line: int, column: int) -> lsp.Position:
        """``line`` and ``column`` 1-based, the column counted in characters."""
        index = min(max(line - 1, 0), len(self.lines) - 1)
        prefix = self.lines[index][: max(column - 1, 0)]
        return lsp.Position(line=index, character=utf16_length(prefix))

    def of_byte(self, offset: int) -> lsp.Position:
        before = self.data[:offset]
        line = before.count(b"\n")
        start = before.rfind(b"\n") + 1
        text = before[start:].decode("utf-8", "surrogateescape")
        return lsp.Position(line=line, character=utf16_length(text))

    def finding_range(self, diagnostic: Diagnostic) -> lsp.Range:
        """From the finding's column to the end of the line's text (the element it names
        starts there)."""
        start = self.of_column(diagnostic.line, diagnostic.column)
        text = self.lines[start.line] if start.line < len(self.lines) else ""
        end = lsp.Position(line=start.line, character=utf16_length(text.rstrip()))
        if (end.character, end.line) <= (start.character, start.line):
            end = lsp.Position(line=start.line, character=start.character + 1)
        return lsp.Range(start=start, end=end)


def overlaps(a: lsp.Range, b: lsp.Range) -> bool:
    return a.start.line <= b.end.line and b.start.line <= a.end.line


def text_of(path: str, session: Session) -> str:
    if path in session.texts:
        return session.texts[path]
    try:
        with open(path, encoding="utf-8", errors="surrogateescape") as handle:
            return handle.read()
    except OSError:
        return ""


def to_lsp(diagnostic: Diagnostic, positions: Positions) -> lsp.Diagnostic:
    fix = diagnostic.fix
    data: dict[str, Any] = {}
    if fix is not None and fix.edits:
        data["fix"] = fix.applicability.value
    return lsp.Diagnostic(
        range=positions.finding_range(diagnostic),
        message=diagnostic.message,
        severity=SEVERITIES[diagnostic.severity],
        code=diagnostic.rule,
        source=SOURCE,
        data=data or None,
    )


class LaunchLinterServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__("launch-linter", __version__)
        self.session = Session([])

    def publish(self, paths: set[str]) -> None:
        for path in sorted(paths):
            positions = Positions(text_of(path, self.session))
            self.publish_diagnostics(
                from_fs_path(path),
                [to_lsp(d, positions) for d in self.session.diagnostics(path)],
            )

    def code_actions(self, path: str, wanted: lsp.Range) -> list[lsp.CodeAction]:
        positions = Positions(text_of(path, self.session))
        actions = []
        for diagnostic in self.session.diagnostics(path):
            fix = diagnostic.fix
            if fix is None or not fix.edits:
                continue
            changes: dict[str, list[lsp.TextEdit]] = {}
            for edit in fix.edits:
                where = Positions(text_of(os.path.realpath(edit.path), self.session))
                changes.setdefault(from_fs_path(os.path.realpath(edit.path)), []).append(
                    lsp.TextEdit(range=lsp.Range(start=where.of_byte(edit.start),
                                                 end=where.of_byte(edit.end)),
                                 new_text=edit.content))
            # offered where the finding is shown or where its edits are (the words to fix
            # may sit lines below the element's start)
            places = [positions.finding_range(diagnostic)] + [
                e.range for e in changes.get(from_fs_path(path), [])]
            if not any(overlaps(place, wanted) for place in places):
                continue
            safe = fix.applicability is Applicability.SAFE
            actions.append(lsp.CodeAction(
                title=f"{fix.message} [{diagnostic.rule}]" + ("" if safe else " (unsafe fix)"),
                kind=lsp.CodeActionKind.QuickFix,
                diagnostics=[to_lsp(diagnostic, positions)],
                is_preferred=safe,
                edit=lsp.WorkspaceEdit(changes=changes),
            ))
        return actions


server = LaunchLinterServer()


def _path(uri: str) -> str:
    return os.path.realpath(to_fs_path(uri) or uri)


@server.feature(lsp.INITIALIZED)
def initialized(ls: LaunchLinterServer, params: lsp.InitializedParams) -> None:
    folders = [to_fs_path(f.uri) for f in ls.workspace.folders.values()]
    if not folders and ls.workspace.root_path:
        folders = [ls.workspace.root_path]
    ls.session = Session([f for f in folders if f])
    ls.session.index()


@server.feature(lsp.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: LaunchLinterServer, params: lsp.DidOpenTextDocumentParams) -> None:
    path = _path(params.text_document.uri)
    ls.publish(ls.session.update(path, params.text_document.text) | {path})


@server.feature(lsp.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: LaunchLinterServer, params: lsp.DidChangeTextDocumentParams) -> None:
    document = ls.workspace.get_text_document(params.text_document.uri)
    path = _path(params.text_document.uri)
    ls.publish(ls.session.update(path, document.source) | {path})


@server.feature(lsp.TEXT_DOCUMENT_DID_SAVE)
def did_save(ls: LaunchLinterServer, params: lsp.DidSaveTextDocumentParams) -> None:
    path = _path(params.text_document.uri)
    if os.path.basename(path) in CONFIG_NAMES:
        ls.session.forget_configuration()
        ls.publish(ls.session.relint(set(ls.session.findings)))


@server.feature(lsp.TEXT_DOCUMENT_DID_CLOSE)
def did_close(ls: LaunchLinterServer, params: lsp.DidCloseTextDocumentParams) -> None:
    ls.session.close(_path(params.text_document.uri))


@server.feature(
    lsp.TEXT_DOCUMENT_CODE_ACTION,
    lsp.CodeActionOptions(code_action_kinds=[lsp.CodeActionKind.QuickFix]),
)
def code_action(ls: LaunchLinterServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
    return ls.code_actions(_path(params.text_document.uri), params.range)


@server.feature(lsp.TEXT_DOCUMENT_HOVER)
def hover(ls: LaunchLinterServer, params: lsp.HoverParams) -> lsp.Hover | None:
    path = _path(params.text_document.uri)
    # the hover counts characters; UTF-16 units differ only past the BMP, rare in frames
    text = ls.session.hover(path, params.position.line, params.position.character)
    if text is None:
        return None
    return lsp.Hover(contents=lsp.MarkupContent(kind=lsp.MarkupKind.Markdown, value=text))


def serve() -> None:
    server.start_io()
