#!/usr/bin/env python3
"""How long the language server takes from a change to its diagnostics.

    python benchmarks/bench_server.py [--changes 20] [WORKSPACE FILE ...]

It starts ``launch-linter server`` as an editor would (a subprocess over stdio, driven by
pygls' own client; needs the lsp extra), opens the workspace (default: a copy of the
repository's ``examples/`` and of the robot workspace of the tests) and, for each file (by
default every launch file, URDF and xacro of it), sends ``--changes`` full-text changes
(alternately the file with a blank line added and as it was) and times each from sending
``didChange`` to the publication of that file's diagnostics: the latency a user sees, with
the JSON-RPC round trip and the re-lint of every entry point that reads the file. It prints
the median and the worst per file and over all. The target is about 300 ms.
"""

from __future__ import annotations

import argparse
import asyncio
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

from lsprotocol import types as lsp
from pygls.lsp.client import BaseLanguageClient

ROOT = Path(__file__).resolve().parent.parent
SUFFIXES = (".launch", ".launch.xml", ".launch.py", ".urdf", ".xacro")


def default_workspace(into: Path) -> Path:
    shutil.copytree(ROOT / "examples", into / "examples")
    shutil.copytree(ROOT / "tests" / "fixtures" / "robot_ws" / "src" / "demo_bringup",
                    into / "src" / "demo_bringup")
    shutil.copytree(ROOT / "tests" / "fixtures" / "robot_ws" / "src" / "demo_description",
                    into / "src" / "demo_description")
    return into


async def measure(workspace: Path, files: list[Path], changes: int) -> dict[str, list[float]]:
    client = BaseLanguageClient("bench-server", "1")
    published: dict[str, asyncio.Event] = {}

    @client.feature(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    def on_diagnostics(params: lsp.PublishDiagnosticsParams) -> None:
        if params.uri in published:
            published[params.uri].set()

    await client.start_io(sys.executable, "-m", "launch_linter", "server")
    await client.initialize_async(lsp.InitializeParams(
        capabilities=lsp.ClientCapabilities(), root_uri=workspace.as_uri(),
        workspace_folders=[lsp.WorkspaceFolder(uri=workspace.as_uri(), name="bench")]))
    client.initialized(lsp.InitializedParams())
    times: dict[str, list[float]] = {}
    for path in files:
        uri, text = path.as_uri(), path.read_text()
        published[uri] = asyncio.Event()
        client.text_document_did_open(lsp.DidOpenTextDocumentParams(
            text_document=lsp.TextDocumentItem(uri=uri, language_id="xml", version=1,
                                               text=text)))
        await asyncio.wait_for(published[uri].wait(), 60)
        for version in range(2, changes + 2):
            published[uri].clear()
            start = time.perf_counter()
            client.text_document_did_change(lsp.DidChangeTextDocumentParams(
                text_document=lsp.VersionedTextDocumentIdentifier(uri=uri, version=version),
                content_changes=[lsp.TextDocumentContentChangeEvent_Type2(
                    text=text + "\n" if version % 2 == 0 else text)]))
            await asyncio.wait_for(published[uri].wait(), 60)
            times.setdefault(str(path.relative_to(workspace)), []).append(
                time.perf_counter() - start)
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return times


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--changes", type=int, default=20)
    parser.add_argument("workspace", nargs="?", help="a folder (default: examples + fixtures)")
    parser.add_argument("files", nargs="*", help="files in it to edit (default: all)")
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        workspace = (Path(options.workspace) if options.workspace
                     else default_workspace(Path(scratch))).resolve()
        files = [workspace / f for f in options.files] or sorted(
            p for p in workspace.rglob("*") if p.name.endswith(SUFFIXES))
        times = asyncio.run(measure(workspace, files, options.changes))
    every = [t for series in times.values() for t in series]
    for name, series in times.items():
        print(f"{name:60s} median {statistics.median(series) * 1000:7.1f} ms"
              f"   worst {max(series) * 1000:7.1f} ms")
    print(f"{'all ' + str(len(every)) + ' changes':60s} median "
          f"{statistics.median(every) * 1000:7.1f} ms   worst {max(every) * 1000:7.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
