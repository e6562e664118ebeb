"""The real-fault benchmark (tests/faults): faults users reported in public Q&A and issue
threads, each copied small with its fixed version. A case passes when a warning or error
lands on the fault's line (or its other publisher's) and the fixed version gives no
warning or error. Cases the linter cannot find yet are xfail with the reason, so the rate
stays visible (scripts/fault_rate.py prints it per class). Cases with ``holdout: true``
were collected after the rules and chosen before the linter ran on them; their ids start
with ``holdout-`` and scripts/fault_rate.py reports their rate apart."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "tests" / "faults"
CLASSES = {"two_publishers", "static_on_owned_edge", "node_second_parent", "frame_param",
           "multi_robot", "use_sim_time", "optical_frame", "camera_publish_tf_vs_urdf",
           "static_vs_urdf", "urdf_structure", "undeclared_launch_arg",
           "static_transform_args", "launch_schema", "missing_publisher"}


def _runner() -> ModuleType:
    spec = importlib.util.spec_from_file_location("fault_rate", ROOT / "scripts" / "fault_rate.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["fault_rate"] = module
    spec.loader.exec_module(module)
    return module


RUNNER = _runner()
FOLDERS = RUNNER.case_folders()


def _param(folder: Path) -> object:
    case = json.loads((folder / "case.json").read_text(encoding="utf-8"))
    marks = []
    if case.get("expected_miss"):
        marks.append(pytest.mark.xfail(reason=case["expected_miss"], strict=True))
    name = f"holdout-{folder.name}" if case.get("holdout") else folder.name
    return pytest.param(folder, id=name, marks=marks)


def _is_holdout(folder: Path) -> bool:
    return bool(json.loads((folder / "case.json").read_text(encoding="utf-8")).get("holdout"))


def test_there_are_enough_cases_and_each_is_complete() -> None:
    assert sum(not _is_holdout(folder) for folder in FOLDERS) >= 30
    assert sum(_is_holdout(folder) for folder in FOLDERS) >= 14
    for folder in FOLDERS:
        case = json.loads((folder / "case.json").read_text(encoding="utf-8"))
        assert case.get("holdout", False) in (True, False), folder
        assert case["source"].startswith("https://"), folder
        assert case["class"] in CLASSES, folder
        assert case["locations"] and case["rule"], folder
        entry = case["entry"]
        assert (folder / "fault" / entry).is_file(), folder
        assert (folder / "fixed" / case.get("fixed_entry", entry)).is_file(), folder
        for location in case["locations"]:
            lines = (folder / "fault" / location["file"]).read_text(encoding="utf-8")
            assert 1 <= location["line"] <= len(lines.splitlines()), (folder, location)


@pytest.mark.parametrize("folder", [_param(folder) for folder in FOLDERS])
def test_fault_is_reported_at_its_line_and_fixed_version_is_silent(folder: Path) -> None:
    outcome = RUNNER.run_case(folder)
    assert outcome.found, f"{folder.name}: no warning/error at the fault's line"
    assert not outcome.fixed_loud, f"{folder.name}: fixed version reports {outcome.fixed_loud}"
