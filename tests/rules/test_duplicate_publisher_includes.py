"""duplicate_publisher: one launch line run twice through two different includes (two
robot_state_publishers with one description, an EKF started by two includes), and two
robot_state_publishers of one namespace with one description; what the linter reads twice
by itself (a loop, a helper function, exclusive branches) is never reported."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.model.diagnostic import Diagnostic, Location, Severity

RULE = "duplicate_publisher"
URDF = ("<robot name='r'><link name='base_link'/><link name='laser'/>"
        "<joint name='j' type='fixed'><parent link='base_link'/><child link='laser'/>"
        "</joint></robot>")
HEADER = ("import os\n"
          "from launch import LaunchDescription\n"
          "from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription\n"
          "from launch.conditions import IfCondition, UnlessCondition\n"
          "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
          "from launch.substitutions import LaunchConfiguration\n"
          "from launch_ros.actions import Node\n"
          "HERE = os.path.dirname(__file__)\n")
RSP = ("def generate_launch_description():\n"
       "    return LaunchDescription([\n"
       "        DeclareLaunchArgument('namespace', default_value=''),\n"
       "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
       "             namespace=LaunchConfiguration('namespace'),\n"
       "             parameters=[{'robot_description': open(os.path.join(HERE, 'r.urdf'))"
       ".read()}]),\n"
       "    ])\n")
RSP_LINE = HEADER.count("\n") + 4


def include(name: str, extra: str = "") -> str:
    return (f"IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(HERE, "
            f"'{name}')){extra})")


def write(folder: Path, files: dict[str, str]) -> Path:
    (folder / "r.urdf").write_text(URDF)
    (folder / "rsp.launch.py").write_text(HEADER + RSP)
    for name, text in files.items():
        (folder / name).write_text(text)
    return folder / "main.launch.py"


def found(root: Path) -> list[Diagnostic]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return list(lint_paths([str(root)], options).diagnostics)


def entry(*actions: str) -> str:
    body = "".join(f"        {a},\n" for a in actions)
    return HEADER + ("def generate_launch_description():\n"
                     f"    return LaunchDescription([\n{body}    ])\n")


def test_one_file_included_by_two_include_lines_is_two_publishers(tmp_path: Path) -> None:
    """husarion_ugv_ros#640: spawn and controller launch files both include the file
    that starts robot_state_publisher: reported at the second include line."""
    root = write(tmp_path, {
        "spawn.launch.py": entry(include("rsp.launch.py")),
        "control.launch.py": entry(include("rsp.launch.py")),
        "main.launch.py": entry(include("spawn.launch.py"), include("control.launch.py")),
    })
    [finding] = found(root)
    site = HEADER.count("\n") + 3  # the include line in entry()
    assert (Path(finding.path).name, finding.line, finding.severity) == (
        "control.launch.py", site, Severity.ERROR)
    assert [(Path(r.path).name, r.line) for r in finding.related] == [
        ("spawn.launch.py", site), ("rsp.launch.py", RSP_LINE)]
    assert "runs twice" in finding.message and "'base_link' -> 'laser'" in finding.message


def test_the_fix_including_it_once_is_silent(tmp_path: Path) -> None:
    root = write(tmp_path, {
        "spawn.launch.py": entry(include("rsp.launch.py")),
        "control.launch.py": entry(
            "DeclareLaunchArgument('publish_robot_state', default_value='true')",
            include("rsp.launch.py", ", condition=IfCondition(LaunchConfiguration("
                                     "'publish_robot_state'))")),
        "main.launch.py": entry(include("spawn.launch.py"), include(
            "control.launch.py", ", launch_arguments={'publish_robot_state': 'false'}.items()")),
    })
    assert found(root) == []


def test_one_include_run_twice_by_the_reading_is_silent(tmp_path: Path) -> None:
    """A loop runs one include line twice with one include chain, which the linter cannot
    tell from one run read twice: silent. A helper function called from two places makes
    two includes (each call is where the include is made): reported at the second call."""
    looped = HEADER + ("def generate_launch_description():\n"
                       f"    return LaunchDescription([{include('rsp.launch.py')} "
                       "for _ in range(2)])\n")
    assert found(write(tmp_path, {"main.launch.py": looped})) == []
    helper = HEADER + ("def robot():\n"
                       f"    return {include('rsp.launch.py')}\n"
                       "def generate_launch_description():\n"
                       "    return LaunchDescription([robot(),\n"
                       "                              robot()])\n")
    [finding] = found(write(tmp_path, {"main.launch.py": helper}))
    assert finding.line == HEADER.count("\n") + 5


def test_exclusive_includes_and_other_namespaces_are_silent(tmp_path: Path) -> None:
    use = "LaunchConfiguration('sim')"
    exclusive = entry("DeclareLaunchArgument('sim', default_value='true')",
                      include("rsp.launch.py", f", condition=IfCondition({use})"),
                      include("rsp.launch.py", f", condition=UnlessCondition({use})"))
    assert found(write(tmp_path, {"main.launch.py": exclusive})) == []
    apart = entry(*(include("rsp.launch.py", f", launch_arguments={{'namespace': '{n}'}}"
                            ".items()") for n in ("r1", "r2")))
    # Robots told apart by namespace are robot_frame_collision's.
    assert found(write(tmp_path, {"main.launch.py": apart})) == []


def test_an_undecided_include_condition_is_info(tmp_path: Path) -> None:
    root = write(tmp_path, {"main.launch.py": entry(
        "DeclareLaunchArgument('rviz')",
        include("rsp.launch.py"),
        include("rsp.launch.py", ", condition=IfCondition(LaunchConfiguration('rviz'))"))})
    [finding] = found(root)
    assert finding.severity is Severity.INFO
    assert "not proven: whether both includes run depends on" in finding.message


def test_two_publishers_of_one_description_in_one_namespace(tmp_path: Path) -> None:
    node = ("Node(package='robot_state_publisher', executable='robot_state_publisher',"
            " parameters=[{'robot_description': open(os.path.join(HERE, 'r.urdf')).read()"
            "%s}])")
    root = write(tmp_path, {"main.launch.py": entry(node % "", node % "")})
    [finding] = found(root)
    assert finding.line == HEADER.count("\n") + 4 and finding.severity is Severity.ERROR
    assert finding.related == (Location(finding.path, finding.line - 1, 9),)
    prefixed = entry(node % "", node % ", 'frame_prefix': 'other/'")
    assert found(write(tmp_path, {"main.launch.py": prefixed})) == []


def test_a_known_node_started_by_two_includes(tmp_path: Path) -> None:
    """mecanum_ws_v2's shape: one EKF file included by two launch files."""
    (tmp_path / "ekf.launch.py").write_text(HEADER + (
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='robot_localization', "
        "executable='ekf_node', parameters=[{'world_frame': 'odom', 'odom0': 'odom'}])])\n"))
    root = write(tmp_path, {
        "a.launch.py": entry(include("ekf.launch.py")),
        "main.launch.py": entry(include("a.launch.py"), include("ekf.launch.py")),
    })
    [finding] = found(root)
    assert (Path(finding.path).name, finding.severity) == ("main.launch.py", Severity.ERROR)
    assert "one launch line run twice: by this include" in finding.message
