"""The language server end to end: a real LSP client (pytest-lsp) talks to
``launch-linter server`` over stdio on a copy of the robot workspace fixture."""

from __future__ import annotations

import asyncio
import shutil
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

pytest.importorskip("pygls", reason="the language server needs the lsp extra")
pytest_lsp = pytest.importorskip("pytest_lsp", reason="pytest-lsp is a dev dependency")
from lsprotocol import types as lsp  # noqa: E402
from pytest_lsp import ClientServerConfig, LanguageClient  # noqa: E402

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "robot_ws"
SENSORS = "src/demo_bringup/launch/sensors.launch"
XACRO = "src/demo_description/urdf/robot.urdf.xacro"


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    shutil.copytree(FIXTURE, tmp_path / "ws")
    return (tmp_path / "ws").resolve()


@pytest_lsp.fixture(
    config=ClientServerConfig(server_command=[sys.executable, "-m", "launch_linter", "server"])
)
async def client(lsp_client: LanguageClient, workspace: Path):  # type: ignore[no-untyped-def]
    # no return annotation: pytest-lsp 0.4 calls issubclass() on every annotation, which
    # fails for typing.Any and generic aliases on Python 3.8
    await lsp_client.initialize_session(lsp.InitializeParams(
        capabilities=lsp.ClientCapabilities(),
        root_uri=workspace.as_uri(),
        workspace_folders=[lsp.WorkspaceFolder(uri=workspace.as_uri(), name="ws")],
    ))
    yield
    await lsp_client.shutdown_session()


async def opened(client: LanguageClient, path: Path) -> str:
    uri = path.as_uri()
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(
        text_document=lsp.TextDocumentItem(uri=uri, language_id="xml", version=1,
                                           text=path.read_text())))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    return uri


async def changed(client: LanguageClient, uri: str, text: str, version: int) -> None:
    client.text_document_did_change(lsp.DidChangeTextDocumentParams(
        text_document=lsp.VersionedTextDocumentIdentifier(uri=uri, version=version),
        content_changes=[lsp.TextDocumentContentChangeEvent_Type2(text=text)]))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)


async def eventually(check: Callable[[], bool], timeout: float = 20.0) -> None:
    """Publications come one per file, in no promised order: wait for the one asked."""
    for _ in range(int(timeout / 0.05)):
        if check():
            return
        await asyncio.sleep(0.05)
    assert check()


def codes(client: LanguageClient, uri: str) -> list[str]:
    return sorted(str(d.code) for d in client.diagnostics.get(uri, []))


@pytest.mark.asyncio
async def test_included_file_gets_the_entry_points_findings_as_it_is_edited(
        client: LanguageClient, workspace: Path) -> None:
    sensors = workspace / SENSORS
    uri = await opened(client, sensors)
    await eventually(lambda: "multiple_parents" in codes(client, uri))
    # the frame's second parent comes from the URDF that robot.launch (which includes this
    # file) loads: only the entry point's lint knows it
    assert "multiple_parents" in codes(client, uri)
    (finding,) = [d for d in client.diagnostics[uri] if d.code == "multiple_parents"]
    assert finding.severity == lsp.DiagnosticSeverity.Error and finding.range.start.line == 2

    text = sensors.read_text()
    await changed(client, uri, text.replace("base_footprint laser", "base_link laser_mount"), 2)
    await eventually(lambda: "multiple_parents" not in codes(client, uri))
    assert sensors.read_text() == text  # unsaved: nothing written


@pytest.mark.asyncio
async def test_code_actions_offer_safe_fixes_preferred_and_label_unsafe_ones(
        client: LanguageClient, workspace: Path) -> None:
    sensors = workspace / SENSORS
    uri = await opened(client, sensors)
    text = sensors.read_text().replace("0 0 0 base_footprint laser",
                                       "0 0 180 base_footprint /laser")
    await changed(client, uri, text, 2)
    await eventually(lambda: {"leading_slash", "rot_degrees"} <= set(codes(client, uri)))
    actions = await client.text_document_code_action_async(lsp.CodeActionParams(
        text_document=lsp.TextDocumentIdentifier(uri=uri),
        range=lsp.Range(start=lsp.Position(line=3, character=0),
                        end=lsp.Position(line=3, character=60)),
        context=lsp.CodeActionContext(diagnostics=client.diagnostics[uri])))
    assert actions is not None
    by_rule = {a.diagnostics[0].code: a for a in actions if isinstance(a, lsp.CodeAction)
               and a.diagnostics}
    safe, unsafe = by_rule["leading_slash"], by_rule["rot_degrees"]
    assert safe.is_preferred and "unsafe" not in safe.title
    assert not unsafe.is_preferred and "(unsafe fix)" in unsafe.title
    assert safe.edit is not None and safe.edit.changes is not None
    (edit,) = safe.edit.changes[uri]
    line = text.splitlines()[edit.range.start.line]
    assert line[edit.range.start.character:edit.range.end.character] == "/laser"
    assert edit.new_text == "laser"


@pytest.mark.asyncio
async def test_xacro_diagnostics_follow_unsaved_edits(
        client: LanguageClient, workspace: Path) -> None:
    xacro = workspace / XACRO
    uri = await opened(client, xacro)
    await eventually(lambda: "optical_frame_rotation" in codes(client, uri))
    text = xacro.read_text()
    fixed = text.replace('<child link="front_camera_ir_optical_frame"/>\n'
                         '    <origin xyz="0 0 0" rpy="0 0 0"/>',
                         '<child link="front_camera_ir_optical_frame"/>\n'
                         '    <origin xyz="0 0 0" rpy="${-pi/2} 0 ${-pi/2}"/>')
    assert fixed != text
    await changed(client, uri, fixed, 2)
    await eventually(lambda: "optical_frame_rotation" not in codes(client, uri))

    number, line = next((n, t) for n, t in enumerate(fixed.splitlines())
                        if 'name="laser"' in t)
    hover = await client.text_document_hover_async(lsp.HoverParams(
        text_document=lsp.TextDocumentIdentifier(uri=uri),
        position=lsp.Position(line=number, character=line.index('"laser"') + 2)))
    assert hover is not None and isinstance(hover.contents, lsp.MarkupContent)
    # the URDF's parent and the launch file's (the entry point's included sensors.launch)
    assert "2 publishers give it a parent" in hover.contents.value
    assert "robot_state_publisher: fixed joint 'laser_joint'" in hover.contents.value


@pytest.mark.asyncio
async def test_hover_shows_parent_chain_and_publishers(
        client: LanguageClient, workspace: Path) -> None:
    sensors = workspace / SENSORS
    uri = await opened(client, sensors)
    line = sensors.read_text().splitlines()[3]
    hover = await client.text_document_hover_async(lsp.HoverParams(
        text_document=lsp.TextDocumentIdentifier(uri=uri),
        position=lsp.Position(line=3, character=line.index("laser\"") + 2)))
    assert hover is not None and isinstance(hover.contents, lsp.MarkupContent)
    value = hover.contents.value
    assert "tf frame `laser`" in value and "`laser` → `base_footprint`" in value
    assert "static_transform_publisher 'laser_tf'" in value
    assert "robot_state_publisher: fixed joint 'laser_joint'" in value
    nothing = await client.text_document_hover_async(lsp.HoverParams(
        text_document=lsp.TextDocumentIdentifier(uri=uri),
        position=lsp.Position(line=0, character=2)))
    assert nothing is None
