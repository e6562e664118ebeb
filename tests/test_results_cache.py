"""The results cache: reused while every file a root's lint read holds, and only then;
the output always that of ``--no-cache``."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from launch_linter import __version__, results_cache
from launch_linter.cli import main
from launch_linter.commands.options import NO_CACHE_VARIABLE
from launch_linter.engine import LintOptions, LintResult, lint_paths
from launch_linter.model.diagnostic import (
    Applicability,
    Belief,
    Category,
    Diagnostic,
    Edit,
    Fix,
    Location,
    Severity,
    TokenEdit,
)
from launch_linter.model.launch import Comment, FileRecord, FileStatus, LaunchTree
from launch_linter.model.record import replace
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import read_regular_file
from launch_linter.results_cache import ResultsCache

MANIFEST = """<package format="2"><name>{name}</name>
<buildtool_depend>catkin</buildtool_depend></package>
"""
SELF = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="self_tf"
        args="0 0 0 0 0 0 base_link base_link"/>
</launch>
"""
FILES = {
    "src/pkg/package.xml": MANIFEST.format(name="pkg"),
    # a.launch includes inc.launch through the package index; inc.launch is a root too.
    "src/pkg/launch/a.launch": '<launch><include file="$(find pkg)/launch/inc.launch"/>'
                               "</launch>\n",
    "src/pkg/launch/inc.launch": SELF,
    "src/pkg/launch/b.launch": SELF.replace("self_tf", "other_tf"),
    # c.launch publishes a xacro description and loads a parameter file.
    "src/pkg/launch/c.launch": """<launch>
  <param name="robot_description" command="xacro $(find pkg)/urdf/robot.urdf.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <rosparam command="load" file="$(find pkg)/config/params.yaml"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="arm_tf"
        args="0 0 0 0 0 0 base_link arm"/>
</launch>
""",
    "src/pkg/urdf/robot.urdf.xacro": """<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:include filename="parts.xacro"/>
  <link name="base_link"/>
  <xacro:arm/>
</robot>
""",
    "src/pkg/urdf/parts.xacro": """<robot xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:macro name="arm">
    <link name="arm"/>
    <joint name="j" type="fixed"><parent link="base_link"/><child link="arm"/></joint>
  </xacro:macro>
</robot>
""",
    "src/pkg/config/params.yaml": "rate: 10\n",
    "src/other/package.xml": MANIFEST.format(name="other"),
    "src/other/notes.txt": "not read by any lint\n",
}
OPTIONS = LintOptions()


@pytest.fixture
def workspace(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv(NO_CACHE_VARIABLE, raising=False)
    for name, text in FILES.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text, encoding="utf-8")
    return tmp_path


def lint(folder: Path, cache_folder: Path | None, options: LintOptions = OPTIONS,
         version: str = __version__) -> tuple[LintResult, ResultsCache | None]:
    cache = None if cache_folder is None else ResultsCache.open(
        str(cache_folder), version, options)
    result = lint_paths(["src"], options, keep_trees=False, cache=cache)
    if cache is not None:
        cache.save()
    return result, cache


def relinted(workspace: Path, options: LintOptions = OPTIONS, version: str = __version__,
             ) -> list[str]:
    """Lint with the cache; the roots linted again (names), after checking that the
    output is that of a run without the cache."""
    cached, cache = lint(workspace, workspace / "cache", options, version)
    plain, _ = lint(workspace, None, options)
    assert cached == plain
    assert cache is not None
    return sorted(os.path.basename(path) for path in cache.missed)


def edit(path: Path, old: str, new: str) -> None:
    path.write_text(path.read_text(encoding="utf-8").replace(old, new), encoding="utf-8")


ROOTS = ["a.launch", "b.launch", "c.launch", "inc.launch", "parts.xacro", "robot.urdf.xacro"]


def test_a_second_run_reuses_every_root(workspace: Path) -> None:
    assert relinted(workspace) == ROOTS
    assert relinted(workspace) == []


def test_results_from_worker_processes_are_kept(workspace: Path) -> None:
    assert relinted(workspace, replace(OPTIONS, jobs=2)) == ROOTS
    assert relinted(workspace) == []


def test_a_cache_kept_in_process_looks_at_the_files_again_each_run(workspace: Path) -> None:
    cache = ResultsCache.open(str(workspace / "cache"), __version__, OPTIONS)
    assert cache is not None
    first = lint_paths(["src"], OPTIONS, keep_trees=False, cache=cache)
    assert lint_paths(["src"], OPTIONS, keep_trees=False, cache=cache) == first
    edit(workspace / "src/pkg/launch/inc.launch", "base_link base_link", "base_link odom")
    cache.missed.clear()
    assert lint_paths(["src"], OPTIONS, keep_trees=False, cache=cache) == lint(workspace, None)[0]
    assert sorted(os.path.basename(p) for p in cache.missed) == ["a.launch", "inc.launch"]


def test_an_included_file_relints_the_roots_that_read_it(workspace: Path) -> None:
    relinted(workspace)
    edit(workspace / "src/pkg/launch/inc.launch", "base_link base_link", "base_link odom")
    assert relinted(workspace) == ["a.launch", "inc.launch"]


def test_a_change_of_the_same_size_is_seen_by_content(workspace: Path) -> None:
    relinted(workspace)
    target = workspace / "src/pkg/launch/b.launch"
    status = target.stat()
    edit(target, "base_link base_link", "base_link base_lin0")
    os.utime(target, ns=(status.st_atime_ns, status.st_mtime_ns))  # same size and time
    assert relinted(workspace) == ["b.launch"]


def test_a_settled_file_is_trusted_by_its_time_and_size(workspace: Path) -> None:
    settled = 1_500_000_000_000_000_000
    for path in workspace.rglob("*"):
        os.utime(path, ns=(settled, settled))
    relinted(workspace)
    target = workspace / "src/pkg/launch/b.launch"
    edit(target, "other_tf", "other_tg")
    os.utime(target, ns=(settled, settled + 1_000))
    assert relinted(workspace) == ["b.launch"]


def test_a_xacro_include_relints_its_description(workspace: Path) -> None:
    relinted(workspace)
    edit(workspace / "src/pkg/urdf/parts.xacro", 'name="arm"/>', 'name="arm2"/>')
    # The launch file that expands it; and each description, linted on its own, depends
    # on the files of its package that include it.
    assert relinted(workspace) == ["c.launch", "parts.xacro", "robot.urdf.xacro"]


def test_a_description_added_to_a_package_relints_its_descriptions(workspace: Path) -> None:
    relinted(workspace)
    (workspace / "src/pkg/urdf/other.urdf").write_text("<robot name='o'><link name='x'/></robot>")
    assert relinted(workspace) == ["other.urdf", "parts.xacro", "robot.urdf.xacro"]


def test_a_parameter_file_that_appears_or_goes(workspace: Path) -> None:
    relinted(workspace)
    (workspace / "src/pkg/config/params.yaml").unlink()
    assert relinted(workspace) == ["c.launch"]
    assert relinted(workspace) == []


def test_a_package_manifest_relints_the_roots_that_find_packages(workspace: Path) -> None:
    relinted(workspace)
    edit(workspace / "src/other/package.xml", "<name>other</name>", "<name>pkg</name>")
    # A description linted alone asks which package ships it (description_never_loaded).
    assert relinted(workspace) == ["a.launch", "c.launch", "robot.urdf.xacro"]


def test_a_new_package_folder_relints_the_roots_that_find_packages(workspace: Path) -> None:
    relinted(workspace)
    (workspace / "src/third").mkdir()
    (workspace / "src/third/package.xml").write_text(MANIFEST.format(name="third"))
    assert relinted(workspace) == ["a.launch", "c.launch", "robot.urdf.xacro"]


def test_an_unrelated_file_relints_nothing(workspace: Path) -> None:
    relinted(workspace)
    edit(workspace / "src/other/notes.txt", "not", "never")
    (workspace / "src/pkg/README.md").write_text("new\n")
    assert relinted(workspace) == []


def test_other_options_or_another_version_use_another_cache(workspace: Path) -> None:
    relinted(workspace)
    assert relinted(workspace, replace(OPTIONS, ignore=frozenset({"tf_self_loop"}))) == ROOTS
    assert relinted(workspace, replace(OPTIONS, jobs=2)) == []  # never changes a result
    assert relinted(workspace, version="99.0") == ROOTS


def test_a_corrupt_cache_is_ignored_and_rewritten(workspace: Path) -> None:
    relinted(workspace)
    (cache_file,) = (workspace / "cache").glob("results-*.json")
    document = json.loads(cache_file.read_text())
    first = sorted(document["entries"])[0]
    document["entries"][first]["result"][2] = [["not", "a", "diagnostic"]]
    cache_file.write_text(json.dumps(document))
    assert relinted(workspace) == [os.path.basename(first)]
    cache_file.write_text('{"format": [' * 100_000)
    assert relinted(workspace) == ROOTS
    assert json.loads(cache_file.read_text())["format"] == results_cache.FORMAT
    assert relinted(workspace) == []


def test_a_cache_that_cannot_be_written_is_silently_skipped(workspace: Path) -> None:
    blocker = workspace / "file"
    blocker.write_text("")
    result, cache = lint(workspace, blocker / "cache")
    assert cache is not None and len(cache.missed) == len(ROOTS)
    assert result == lint(workspace, None)[0]
    assert not (blocker / "cache").exists()


def test_check_writes_the_cache_folder_with_its_gitignore(
    workspace: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["check", "--no-cache", "--format", "json", "src"]) == 1
    plain = capsys.readouterr().out
    assert not (workspace / ".launch-linter-cache").exists()
    for _ in range(2):
        assert main(["check", "--format", "json", "src"]) == 1
        assert capsys.readouterr().out == plain
    assert (workspace / ".launch-linter-cache/.gitignore").read_text().endswith("*\n")
    (workspace / ".launch-linter.toml").write_text('cache-dir = "elsewhere"\n')
    assert main(["check", "--format", "json", "src"]) == 1
    assert capsys.readouterr().out == plain
    assert list((workspace / "elsewhere").glob("results-*.json"))


def test_fix_with_the_cache_relints_what_it_fixed(
    workspace: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = workspace / "src/pkg/launch/b.launch"
    edit(target, "0 0 0 0 0 0 base_link base_link", "0 0 0 0 0 0 1 base_link laser 100")
    main(["check", "src"])
    capsys.readouterr()
    main(["check", "--fix", "src"])
    capsys.readouterr()
    main(["check", "--no-cache", "--format", "json", "src"])
    plain = capsys.readouterr().out
    main(["check", "--format", "json", "src"])
    assert capsys.readouterr().out == plain


def test_reads_are_recorded_only_while_recording(tmp_path: Path) -> None:
    target = tmp_path / "f.yaml"
    target.write_text("a: 1\n")
    read_regular_file(str(target), 100)
    with reads.recording() as log:
        read_regular_file(str(target), 100)
        assert not reads.is_file(str(tmp_path / "missing"))
    assert log.stamps[str(target)][:2] == (reads.FILE, 5)
    assert log.stamps[str(target)][3] == reads.digest(b"a: 1\n")
    assert log.stamps[str(tmp_path / "missing")][0] == reads.ABSENT
    assert not log.is_unstable()


def test_a_value_shared_between_roots_is_a_dependency_of_each() -> None:
    store: dict[str, tuple[int, reads.ReadLog]] = {}
    logs = []
    for _ in range(2):
        with reads.recording() as log:
            reads.remembered(store, "k", lambda: reads.note_path("/nonexistent/x") or 1)
        logs.append(log)
    assert logs[0].groups == logs[1].groups == [store["k"][1]]
    assert "/nonexistent/x" in store["k"][1].stamps


def test_the_codec_knows_every_field() -> None:
    assert results_cache.codec_matches()


def test_a_result_survives_the_round_trip() -> None:
    fix = Fix(Applicability.UNSAFE, "m", ("a", "b"), (TokenEdit(0, 1, "x"),),
              (Edit("p", 1, 2, "y", "z"),), "humble")
    diagnostic = Diagnostic(
        "tf_self_loop", Category.TF, Severity.ERROR, "p.launch", 3, 4, "msg", "node",
        (Location("q.launch", 5, 6),), Belief("sig_implication", ("a", "b"), "c", 3, 1, 0.1),
        fix)
    tree = LaunchTree("p.launch", FileStatus.OK, (), (), ("p.launch", "q.launch"),
                      comments=(Comment("p.launch", 2, "launch-linter: disable=x"),),
                      element_lines=(("p.launch", 3),))
    linted = (tree, FileRecord("p.launch", FileStatus.OK, 1), [diagnostic])
    assert results_cache.decode_linted(
        json.loads(json.dumps(results_cache.encode_linted(linted)))) == linted


def checked(capsys: pytest.CaptureFixture[str]) -> list[str]:
    """``check`` with the cache and without: the same JSON; the files it lists."""
    main(["check", "--format", "json", "src"])
    cached = capsys.readouterr().out
    main(["check", "--no-cache", "--format", "json", "src"])
    assert capsys.readouterr().out == cached
    return sorted(os.path.basename(f["path"]) for f in json.loads(cached)["files"])


def test_the_folder_walk_is_reused_until_a_folder_or_ignore_file_changes(
    workspace: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (workspace / ".git").mkdir()
    assert checked(capsys) == ROOTS
    assert checked(capsys) == ROOTS
    (workspace / "src/pkg/launch/new.launch").write_text(SELF)
    assert checked(capsys) == sorted([*ROOTS, "new.launch"])
    (workspace / "src/pkg/config/robot.xml").write_text("<robot/>\n")
    assert checked(capsys) == sorted([*ROOTS, "new.launch"])
    (workspace / "src/pkg/config/robot.xml").write_text("<launch/>\n")  # found by content
    assert checked(capsys) == sorted([*ROOTS, "new.launch", "robot.xml"])
    (workspace / ".gitignore").write_text("new.launch\n")
    assert checked(capsys) == sorted([*ROOTS, "robot.xml"])
    (workspace / "src/pkg/launch/b.launch").unlink()
    assert checked(capsys) == sorted([*(r for r in ROOTS if r != "b.launch"), "robot.xml"])


def test_a_result_resting_on_unsaved_text_is_not_kept(tmp_path: Path) -> None:
    from launch_linter.resolve.xml_safe import read_launch_bytes, unsaved_texts

    target = tmp_path / "a.launch"
    target.write_text("<launch/>")
    with unsaved_texts({str(target): b"<launch></launch>"}), reads.recording() as log:
        assert read_launch_bytes(str(target)) == b"<launch></launch>"
    assert log.is_unstable()


def test_a_run_answered_by_the_cache_loads_no_front_end(workspace: Path) -> None:
    import subprocess
    import sys

    import launch_linter

    probe = ("import contextlib, io, sys\nfrom launch_linter.cli import main\n"
             "with contextlib.redirect_stdout(io.StringIO()):\n    main(['check', 'src'])\n"
             "print(sorted(m for m in sys.modules if m.startswith('launch_linter.frontends.')))")
    env = {k: v for k, v in os.environ.items() if k != NO_CACHE_VARIABLE}
    env["PYTHONPATH"] = str(Path(launch_linter.__file__).resolve().parents[1])
    loaded = [subprocess.run([sys.executable, "-c", probe], cwd=workspace, env=env, text=True,
                             capture_output=True, check=True).stdout for _ in range(2)]
    assert "launch_linter.frontends.ros1" in loaded[0]
    assert loaded[1].strip() == "[]"


def test_a_cached_run_keys_on_the_beliefs_file_without_decoding_it(
    workspace: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The bundled beliefs enter the run key as the digest of their file: a run the cache
    answers never decodes them (the JSON report's count is kept with the key), and a
    changed file is another key, whose count is that of the new file."""
    from launch_linter import beliefs_files
    from launch_linter.model.beliefs import BeliefSet

    tmp_data = workspace / "data"
    tmp_data.mkdir()
    bundled = Path(beliefs_files.data_folder()) / beliefs_files.BUNDLED
    document = json.loads(bundled.read_text(encoding="utf-8"))
    (tmp_data / beliefs_files.BUNDLED).write_text(json.dumps(document), encoding="utf-8")
    monkeypatch.setattr(beliefs_files, "data_folder", lambda: str(tmp_data))

    def count() -> int:
        assert main(["check", "--format", "json", "src"]) == 1
        return int(json.loads(capsys.readouterr().out)["beliefs"]["count"])

    first = count()
    assert first > 0
    with monkeypatch.context() as patched:
        def refuse(*args: object, **kwargs: object) -> BeliefSet:
            raise AssertionError("the beliefs were decoded")

        patched.setattr(BeliefSet, "from_json", staticmethod(refuse))
        assert count() == first  # answered by the cache: nothing decoded
        # A changed beliefs file is another run key: linted again, so decoded.
        document["beliefs"] = [*document["beliefs"][:-1],
                               dict(document["beliefs"][0], z=99.0, n=7)]
        (tmp_data / beliefs_files.BUNDLED).write_text(json.dumps(document), encoding="utf-8")
        patched.delenv("LAUNCH_LINTER_DEBUG", raising=False)
        assert main(["check", "--format", "json", "src"]) == 2  # an internal error
        assert "the beliefs were decoded" in capsys.readouterr().err
    assert count() == len(BeliefSet.from_json(document, "bundled", 1.0).beliefs)
    assert len(list((workspace / ".launch-linter-cache").glob("results-*.json"))) == 2


def test_stored_beliefs_are_keyed_by_their_origin_and_threshold() -> None:
    from launch_linter.beliefs_files import load_beliefs

    def key(beliefs: object) -> str:
        return results_cache.run_key(__version__, replace(OPTIONS, beliefs=beliefs), None, "/")

    bundled = load_beliefs("bundled", 1.0)
    assert bundled.origin is not None
    assert key(bundled) == key(load_beliefs("bundled", 1.0))
    assert key(bundled) != key(load_beliefs("bundled", 2.0))
    assert key(bundled) != key(load_beliefs("study", 1.0))
    # Decoding changes nothing the set says, nor its key.
    decoded = load_beliefs("bundled", 1.0)
    assert decoded.beliefs == bundled.beliefs and decoded.p0 == bundled.p0
    assert decoded == bundled and key(decoded) == key(bundled)
    assert decoded.count == len(decoded.beliefs)


def test_a_launch_file_named_by_a_new_file_is_linted_again(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from launch_linter.workspace import mentions

    monkeypatch.setattr(mentions, "_names_by_folder", {})  # kept per process otherwise
    (workspace / "src/ros2/launch").mkdir(parents=True)
    (workspace / "src/ros2/package.xml").write_text(
        '<package format="3"><name>ros2</name>\n'
        "<export><build_type>ament_cmake</build_type></export></package>\n")
    (workspace / "src/ros2/launch/inner.launch.xml").write_text(
        '<launch><node pkg="foo" exec="bar" name="$(var robot)"/></launch>\n')
    assert "inner.launch.xml" in relinted(workspace)
    mentions._names_by_folder.clear()
    assert relinted(workspace) == []
    (workspace / "src/ros2/launch/outer.launch.xml").write_text(
        '<launch><include file="$(dirname)/inner.launch.xml"/></launch>\n')
    mentions._names_by_folder.clear()
    assert relinted(workspace) == ["inner.launch.xml", "outer.launch.xml"]


def test_a_ros1_fragment_whose_includer_turns_ros2_is_linted_again(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A fragment only a ROS 1 file names depends on that file's dialect (its content)."""
    from launch_linter.workspace import mentions

    monkeypatch.setattr(mentions, "_names_by_folder", {})  # kept per process otherwise
    (workspace / "src/moveit/launch").mkdir(parents=True)
    (workspace / "src/moveit/package.xml").write_text(
        '<package format="3"><name>moveit</name>\n'
        "<export><build_type>ament_cmake</build_type></export></package>\n")
    (workspace / "src/moveit/launch/pipe.launch.xml").write_text(
        '<launch><node name="m" pkg="moveit" type="mover"/></launch>\n')
    includer = workspace / "src/moveit/launch/group.launch"
    includer.write_text('<launch><include file="$(dirname)/pipe.launch.xml"/></launch>\n')
    assert "pipe.launch.xml" in relinted(workspace)
    mentions._names_by_folder.clear()
    assert relinted(workspace) == []
    edit(includer, "<include", '<let name="x" value="1"/><include')
    mentions._names_by_folder.clear()
    assert relinted(workspace) == ["group.launch", "pipe.launch.xml"]


def test_install_rules_read_to_locate_an_include_relint_its_includer(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    inner = ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
             "def generate_launch_description():\n    return LaunchDescription([Node("
             "package='tf2_ros', executable='static_transform_publisher', arguments=["
             "'--frame-id', 'a', '--child-frame-id', 'b'])])\n")
    top = ("import os\nfrom ament_index_python.packages import get_package_share_directory\n"
           "from launch import LaunchDescription\nfrom launch.actions import "
           "IncludeLaunchDescription\nfrom launch.launch_description_sources import "
           "PythonLaunchDescriptionSource\ndef generate_launch_description():\n    path = "
           "os.path.join(get_package_share_directory('demo'), 'launch/inner.launch.py')\n"
           "    return LaunchDescription([IncludeLaunchDescription("
           "PythonLaunchDescriptionSource(path))])\n")
    files = {
        "src/demo/package.xml": '<package format="3"><name>demo</name><export><build_type>'
                                "ament_cmake</build_type></export></package>\n",
        "src/demo/CMakeLists.txt": "project(demo)\n"
                                   "install(DIRECTORY bringup/launch DESTINATION share/demo)\n",
        "src/demo/bringup/launch/inner.launch.py": inner,
        "src/demo/top.launch.py": top,
    }
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    assert "top.launch.py" in relinted(tmp_path)
    assert relinted(tmp_path) == []
    edit(tmp_path / "src/demo/CMakeLists.txt", "bringup/launch", "bringup/other")
    assert relinted(tmp_path) == ["top.launch.py"]


def test_a_parameter_file_read_relints_its_launch_file(workspace: Path) -> None:
    relinted(workspace)
    edit(workspace / "src/pkg/config/params.yaml", "rate: 10", "rate: 20")
    assert relinted(workspace) == ["c.launch"]
