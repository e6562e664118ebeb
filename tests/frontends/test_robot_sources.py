"""robot_description sources in ROS 1 and ROS 2 launch files (XML, YAML, Python)."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import DescriptionKind

WS = Path(__file__).resolve().parent.parent / "fixtures" / "robot_ws"
XACRO = "$(find demo_description)/urdf/robot.urdf.xacro"
RSP1 = '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'


def tree(tmp_path: Path, name: str, text: str, args: dict[str, str] | None = None
         ) -> LaunchTree:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    options = LintOptions(args=args or {}, package_paths=(str(WS),))
    return lint_paths([str(path)], options).trees[0]


@pytest.mark.parametrize("command", [
    f"$(find xacro)/xacro --inorder {XACRO} use_lidar:=false",
    f"$(find xacro)/xacro.py {XACRO} use_lidar:=false",
    f"xacro {XACRO} use_lidar:=false",
])
def test_ros1_xacro_command(tmp_path: Path, command: str) -> None:
    found = tree(tmp_path, "a.launch", f'<launch><param name="robot_description" '
                 f'command="{command}"/>{RSP1}</launch>')
    (source,) = found.descriptions
    assert source.kind is DescriptionKind.XACRO and source.args == (("use_lidar", "false"),)
    assert "sonar" in {j.child for j in found.joints}


@pytest.mark.parametrize("remap, ns, read", [
    ('<remap from="robot_description" to="zed_description"/>', "zed", True),
    ('<remap from="robot_description" to="/zed/zed_description"/>', "", True),
    ("", "zed", False),  # no remap: robot_state_publisher reads robot_description
    ('<remap from="robot_description" to="zed_description"/>', "other", False),
])
def test_ros1_description_read_through_a_remap(tmp_path: Path, remap: str, ns: str,
                                               read: bool) -> None:
    # precision trial 3, zed-ros-wrapper zed_camera.launch.xml: the description is the
    # parameter <camera>_description, which robot_state_publisher reads by a remap.
    node = ('<node pkg="robot_state_publisher" type="robot_state_publisher" '
            f'name="zed_state_publisher">{remap}</node>')
    text = (f'<launch><group ns="zed"><param name="zed_description" command="xacro {XACRO}"/>'
            f'</group><group ns="{ns}">{node}</group></launch>' if ns else
            f'<launch><group ns="zed"><param name="zed_description" command="xacro {XACRO}"/>'
            f'</group>{node}</launch>')
    found = tree(tmp_path, "a.launch", text)
    assert bool(found.joints) is read and len(found.descriptions) == int(read)


def test_ros1_arg_left_open_is_an_unknown_xacro_arg(tmp_path: Path) -> None:
    found = tree(tmp_path, "a.launch", f'<launch><arg name="l"/><param name="robot_description" '
                 f'command="xacro {XACRO} use_lidar:=$(arg l)"/>{RSP1}</launch>')
    (source,) = found.descriptions
    assert source.args == (("use_lidar", None),)
    lidar = [j for j in found.joints if j.child in ("laser", "sonar")]
    assert len(lidar) == 2 and lidar[0].condition.excludes(lidar[1].condition)


def test_ros1_textfile_and_literal(tmp_path: Path) -> None:
    text = (f'<launch><param name="robot_description" textfile="$(find demo_description)/urdf/'
            f'plain.urdf"/><group ns="two"><param name="robot_description" value="&lt;robot '
            f'name=\'x\'&gt;&lt;joint name=\'k\' type=\'fixed\'&gt;&lt;parent link=\'a\'/&gt;'
            f'&lt;child link=\'b\'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/></group>{RSP1}</launch>')
    found = tree(tmp_path, "a.launch", text)
    assert [s.kind for s in found.descriptions] == [DescriptionKind.FILE, DescriptionKind.LITERAL]
    assert [(j.parent, j.child) for j in found.joints] == [("base_link", "gps"), ("a", "b")]


def test_ros1_param_inside_the_state_publisher(tmp_path: Path) -> None:
    found = tree(tmp_path, "a.launch", '<launch><node pkg="robot_state_publisher" '
                 'type="robot_state_publisher" name="rsp"><param name="robot_description" '
                 f'command="xacro {XACRO}"/></node></launch>')
    assert len(found.joints) == 8


def test_ros2_xml_command(tmp_path: Path) -> None:
    text = ('<launch><node pkg="robot_state_publisher" exec="robot_state_publisher">'
            '<param name="robot_description" value="$(command \'xacro $(find-pkg-share '
            'demo_description)/urdf/robot.urdf.xacro use_lidar:=false\')"/></node></launch>')
    found = tree(tmp_path, "a.launch.xml", text)
    assert "sonar" in {j.child for j in found.joints}


LET_COMMAND = ('<launch><let name="desc" value="$(command \'{exe} $(find-pkg-share '
               'demo_description)/urdf/robot.urdf.xacro use_lidar:=false\')"/>{between}'
               '<node pkg="robot_state_publisher" exec="robot_state_publisher">'
               '<param name="robot_description" value="$(var desc)"/></node></launch>')


@pytest.mark.parametrize("exe", ["xacro", "$(find-exec xacro)"])
def test_ros2_xml_description_from_a_let_of_a_command(tmp_path: Path, exe: str) -> None:
    # precision trial 3, ros2_control_demos example_2/example_17: the command is run by a
    # <let> and the description given as $(var robot_description); it was "not read".
    found = tree(tmp_path, "a.launch.xml", LET_COMMAND.format(exe=exe, between=""))
    (source,) = found.descriptions
    assert source.kind is DescriptionKind.XACRO and source.args == (("use_lidar", "false"),)
    assert "sonar" in {j.child for j in found.joints}


@pytest.mark.parametrize("between", [
    '<let name="desc" value="&lt;robot name=\'r\'/&gt;"/>',  # set again: not the command
    '<arg name="c"/><let name="desc" if="$(var c)" value="y"/>',  # may be set again
])
def test_ros2_xml_let_set_again_is_not_the_command(tmp_path: Path, between: str) -> None:
    found = tree(tmp_path, "a.launch.xml", LET_COMMAND.format(exe="xacro", between=between))
    assert "sonar" not in {j.child for j in found.joints}


def test_ros2_yaml_command(tmp_path: Path) -> None:
    text = ("launch:\n- node:\n    pkg: robot_state_publisher\n    exec: robot_state_publisher\n"
            "    param:\n    - name: robot_description\n      value: \"$(command 'xacro "
            "$(find-pkg-share demo_description)/urdf/robot.urdf.xacro')\"\n")
    found = tree(tmp_path, "a.launch.yaml", text)
    assert "laser" in {j.child for j in found.joints}


def test_ros2_python_command_with_launch_configuration() -> None:
    options = LintOptions(package_paths=(str(WS),))
    path = WS / "src" / "demo_ros2" / "launch" / "bringup.launch.py"
    found = lint_paths([str(path)], options).trees[0]
    (source,) = found.descriptions
    assert source.args == (("use_lidar", "false"),)
    assert {"sonar", "arm_link"} <= {j.child for j in found.joints}
    assert not any(j.child == "laser" for j in found.joints)


@pytest.mark.parametrize("read", [
    "description = open(urdf).read()",
    "with open(urdf, 'r') as handle:\n        description = handle.read()",
])
def test_ros2_python_urdf_file_read(tmp_path: Path, read: str) -> None:
    text = f'''import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    urdf = os.path.join(get_package_share_directory("demo_description"), "urdf", "plain.urdf")
    {read}
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{{"robot_description": description}}]),
    ])
'''
    found = tree(tmp_path, "a.launch.py", text)
    (source,) = found.descriptions
    assert source.kind is DescriptionKind.FILE
    assert [(j.parent, j.child) for j in found.joints] == [("base_link", "gps")]
    assert not found.problems


def test_ros2_xml_file_content(tmp_path: Path) -> None:
    text = ('<launch><node pkg="robot_state_publisher" exec="robot_state_publisher">'
            '<param name="robot_description" value="$(file-content $(find-pkg-share '
            'demo_description)/urdf/plain.urdf)"/></node></launch>')
    found = tree(tmp_path, "a.launch.xml", text)
    assert [(j.parent, j.child) for j in found.joints] == [("base_link", "gps")]


SDF = ('<sdf version="1.6"><model name="vehicle"><link name="chassis"/><link name="wheel"/>'
       '<joint name="axle" type="revolute"><parent>chassis</parent><child>wheel</child>'
       '</joint></model></sdf>')


@pytest.mark.parametrize(("model", "sdf"), [("model.sdf", True), ("model.urdf", False)])
def test_an_sdf_description_is_said_unread(tmp_path: Path, model: str, sdf: bool) -> None:
    # precision trial, gazebosim/ros_gz: sdf_parser.launch.py gives robot_state_publisher
    # an SDF model (read through sdformat_urdf); its joints were silently none.
    (tmp_path / model).write_text(
        SDF if sdf else '<robot name="r"><link name="a"/><link name="b"/><joint name="j" '
                        'type="fixed"><parent link="a"/><child link="b"/></joint></robot>')
    text = ('<launch><node pkg="robot_state_publisher" exec="robot_state_publisher">'
            f'<param name="robot_description" value="$(file-content $(dirname)/{model})"/>'
            '</node></launch>')
    found = tree(tmp_path, "a.launch.xml", text)
    said = [p.message for p in found.problems if "is SDF" in p.message]
    assert len(said) == int(sdf)
    assert [(j.parent, j.child) for j in found.joints] == ([] if sdf else [("a", "b")])


def test_an_unknown_description_value_is_said_once(tmp_path: Path) -> None:
    # A robot_state_publisher given a value only launch knows has a robot the linter does
    # not read: said, so that the tree does not look like one without a description.
    text = '''from launch import LaunchDescription
from launch_ros.actions import Node
import helpers


def generate_launch_description():
    description = helpers.urdf()
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"robot_description": description}]),
        Node(package="controller_manager", executable="ros2_control_node",
             parameters=[{"robot_description": description}]),
    ])
'''
    found = tree(tmp_path, "a.launch.py", text)
    said = [p.message for p in found.problems if p.message.startswith("robot description")]
    assert said == ["robot description not read: line 7: calls 'helpers.urdf', which the "
                    "linter does not model"]
    assert found.joints == ()


@pytest.mark.parametrize("text", ["toxml()", "toprettyxml(indent='  ')"])
def test_ros2_python_xacro_process_file(tmp_path: Path, text: str) -> None:
    # precision trial, gazebosim/ros_gz joint_states.launch.py: xacro.process_file(path)
    # .toxml() (45 calls in the corpus) was an unknown description.
    launch = f'''import os
import xacro
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    path = os.path.join(get_package_share_directory("demo_description"), "urdf",
                        "robot.urdf.xacro")
    document = xacro.process_file(path, mappings={{"use_lidar": "false"}})
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{{"robot_description": document.{text}}}]),
    ])
'''
    found = tree(tmp_path, "a.launch.py", launch)
    (source,) = found.descriptions
    assert source.kind is DescriptionKind.XACRO and source.args == (("use_lidar", "false"),)
    assert "sonar" in {j.child for j in found.joints}
    unknown = launch.replace('mappings={"use_lidar": "false"}', "mappings=helpers.m()")
    found = tree(tmp_path, "b.launch.py", unknown)
    assert found.joints == ()


XACRO_PARSE = '''import os
import xacro
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    path = os.path.join(get_package_share_directory("demo_description"), "urdf",
                        "robot.urdf.xacro")
    doc = xacro.parse(open(path))
    PROCESS
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"robot_description": doc.toxml()}]),
    ])
'''


@pytest.mark.parametrize("process", [
    'xacro.process_doc(doc, mappings={"use_lidar": "false"})',
    'expand(doc)\ndef expand(d):\n    xacro.process_doc(d, mappings={"use_lidar": "false"})',
])
def test_ros2_python_xacro_parse_then_process_doc(tmp_path: Path, process: str) -> None:
    # precision trial 3, gazebo_ros2_control demos: doc = xacro.parse(open(path));
    # xacro.process_doc(doc); doc.toxml() (30 corpus files) was an unknown description.
    if process.startswith("expand"):  # the document expanded by a helper of the file
        helper = process.split("\n", 1)[1]
        launch = XACRO_PARSE.replace("    PROCESS", "    expand(doc)").replace(
            "def generate_launch_description", helper + "\n\n\ndef generate_launch_description")
    else:
        launch = XACRO_PARSE.replace("PROCESS", process)
    found = tree(tmp_path, "a.launch.py", launch)
    (source,) = found.descriptions
    assert source.kind is DescriptionKind.XACRO and source.args == (("use_lidar", "false"),)
    assert "sonar" in {j.child for j in found.joints}


def test_ros2_python_xacro_parse_without_process_doc_is_unread(tmp_path: Path) -> None:
    # Without process_doc the document is the raw xacro text: never read as the robot.
    found = tree(tmp_path, "a.launch.py", XACRO_PARSE.replace("    PROCESS\n", ""))
    assert found.joints == ()


RSP_ARGUMENT = """import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    urdf = os.path.join(os.path.dirname(__file__), 'robot.urdf')
    return LaunchDescription([Node(package='robot_state_publisher',
                                   executable='robot_state_publisher',
                                   {given}arguments=[urdf])])
"""
URDF_FILE = ('<robot name="r"><link name="base"/><link name="scan"/>'
             '<joint name="j" type="fixed"><parent link="base"/><child link="scan"/></joint>'
             '</robot>\n')


def test_ros2_urdf_file_given_as_robot_state_publishers_argument(tmp_path: Path) -> None:
    # Crystal to Eloquent (navigation2#452's turtlebot3), still a fallback on Rolling:
    # without a robot_description parameter the first argument is the URDF file.
    (tmp_path / "robot.urdf").write_text(URDF_FILE, encoding="utf-8")
    found = tree(tmp_path, "a.launch.py", RSP_ARGUMENT.format(given=""))
    (source,) = found.descriptions
    assert source.kind is DescriptionKind.FILE
    assert "scan" in {j.child for j in found.joints}


def test_ros2_robot_description_parameter_wins_over_the_argument(tmp_path: Path) -> None:
    (tmp_path / "robot.urdf").write_text(URDF_FILE, encoding="utf-8")
    given = "parameters=[{'robot_description': '<robot name=\"other\"/>'}],\n" + " " * 35
    found = tree(tmp_path, "a.launch.py", RSP_ARGUMENT.format(given=given))
    assert "scan" not in {j.child for j in found.joints}
