"""The differential scripts' own pieces (the full runs need roslaunch, ros_comm and a
``launch`` virtual environment; see docs/agreement.md)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parent.parent


def _script(name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(name, ROOT / "scripts" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def test_ros_comm_selects_test_launch_files_and_input_refusals(tmp_path: Path) -> None:
    script = _script("differential_ros_comm")
    (tmp_path / "pkg" / "test").mkdir(parents=True)
    (tmp_path / "pkg" / "test" / "a.xml").write_text("<launch/>\n")
    (tmp_path / "pkg" / "test" / "package.xml").write_text("<launch/>\n")
    (tmp_path / "pkg" / "test" / "b.xml").write_text("<robot/>\n")
    (tmp_path / "pkg" / "launch").mkdir()
    (tmp_path / "pkg" / "launch" / "c.launch").write_text("<launch/>\n")
    assert script.test_launch_files(str(tmp_path)) == [str(tmp_path / "pkg" / "test" / "a.xml")]
    assert script._wants_input({"error": "[x] requires the 'base' arg to be set"})
    assert script._wants_input({"error_type": "ResourceNotFound", "error": "roslib"})
    assert not script._wants_input({"error": "<node> tag is missing required attribute"})


def test_probe_every_node_is_local_to_the_objects_it_replaces() -> None:
    script = _script("differential_ros_comm")
    every_type = script._EveryType("static_transform_publisher")
    assert (every_type != "talker") is False  # the loader tests with !=
    assert "anything" in script._EveryPackage(("tf",))


def test_ros2_probes_and_our_side() -> None:
    script = _script("differential_ros2_launch")
    probes = {probe_id: text for probe_id, _, text in script.schema_probes()}
    assert script.ours("xml", probes["group/accepted"])[0] is False
    assert script.ours("xml", probes["group/misspelled"])[0] is True
    refused, cmds, _ = script.ours("xml", '<launch><executable cmd=" $(var a) b"/></launch>')
    assert (refused, cmds) == (False, [["", "$(var a)", "b"]])
    assert script.ours("xml", "<launch><executable cmd=\"a 'b\"/></launch>")[0] is True
    assert len(script.random_cmdlines(1, 5)) == 5
