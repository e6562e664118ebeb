"""sim_time_mismatch: ROS 2 nodes on wall time beside a simulator (fault, then fixed)."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "sim_time_mismatch"


def run(tmp_path: Path, name: str, text: str) -> list[tuple[str, int]]:
    path = tmp_path / name
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.rule, d.line) for d in lint_paths([str(path)], options).diagnostics]


PY = ("from launch import LaunchDescription\n"
      "from launch.actions import DeclareLaunchArgument, GroupAction\n"
      "from launch.conditions import IfCondition, UnlessCondition\n"
      "from launch.substitutions import LaunchConfiguration\n"
      "from launch_ros.actions import Node, SetParameter\n"
      "def generate_launch_description():\n"
      "    sim = LaunchConfiguration('use_sim_time')\n"
      "    return LaunchDescription([\n"
      "        DeclareLaunchArgument('use_sim_time', default_value='{default}'),\n"
      "        Node(package='gazebo_ros', executable='spawn_entity.py',\n"
      "             arguments=['-topic', 'robot_description', '-entity', 'r']),\n"
      "        Node(package='robot_localization', executable='ekf_node',\n"
      "             parameters=[{{'use_sim_time': sim}}]),\n"
      "        Node(package='slam_toolbox', executable='async_slam_toolbox_node'{slam}),\n"
      "        Node(package='robot_state_publisher', executable='robot_state_publisher'),\n"
      "    ])\n")


def test_nodes_on_wall_time_beside_a_spawned_robot(tmp_path: Path) -> None:
    fault = PY.format(default="false", slam="")
    # The EKF given false: at the dictionary key; slam_toolbox given nothing: at its Node.
    assert run(tmp_path, "sim.launch.py", fault) == [(RULE, 13), (RULE, 14)]
    fixed = PY.format(default="true", slam=", parameters=[{'use_sim_time': sim}]")
    assert run(tmp_path, "sim.launch.py", fixed) == []


def test_set_parameter_gives_sim_time_to_the_nodes_after_it(tmp_path: Path) -> None:
    text = PY.format(default="true", slam="").replace(
        "        Node(package='gazebo_ros'", "        SetParameter(name='use_sim_time', "
        "value=True),\n        Node(package='gazebo_ros'")
    assert run(tmp_path, "sim.launch.py", text) == []


def test_no_simulator_unknown_values_and_exclusive_branches_are_silent(
        tmp_path: Path) -> None:
    no_sim = PY.format(default="false", slam="").replace("gazebo_ros", "demo")
    assert run(tmp_path, "real.launch.py", no_sim) == []
    unknown = PY.format(default="false", slam="").replace(
        "default_value='false'", "default_value=os.environ['SIM']").replace(
        "from launch import", "import os\nfrom launch import")
    assert run(tmp_path, "env.launch.py", unknown) == [(RULE, 15)]
    branches = ('<launch><arg name="sim" default="true"/>\n'
                '<node if="$(var sim)" pkg="ros_gz_sim" exec="create" args="-topic x"/>\n'
                '<node unless="$(var sim)" pkg="nav2_amcl" exec="amcl"/>\n'
                '<node if="$(var sim)" pkg="nav2_amcl" exec="amcl">'
                '<param name="use_sim_time" value="$(var sim)"/></node>\n</launch>\n')
    assert run(tmp_path, "b.launch.xml", branches) == []


def test_ros1_is_left_out(tmp_path: Path) -> None:
    ros1 = ('<launch><node pkg="gazebo_ros" type="spawn_model" name="s" args="-urdf"/>'
            '<node pkg="amcl" type="amcl" name="amcl"/></launch>')
    assert run(tmp_path, "a.launch", ros1) == []


JSP = ("from launch import LaunchDescription\n"
       "from launch_ros.actions import Node\n"
       "def generate_launch_description():\n"
       "    return LaunchDescription([\n"
       "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
       "             parameters=[{{'use_sim_time': {rsp}}}]),\n"
       "        Node(package='joint_state_publisher', executable='joint_state_publisher'"
       "{jsp}),\n"
       "    ])\n")


def test_a_node_on_sim_time_is_a_clock_source_and_joint_states_reach_tf(
        tmp_path: Path) -> None:
    """create3_sim#203: robot_state_publisher on simulated time, joint_state_publisher on
    wall time: the wheels' transforms carry wall-clock stamps."""
    fault = JSP.format(rsp="True", jsp="")
    assert run(tmp_path, "d.launch.py", fault) == [(RULE, 7)]
    fixed = JSP.format(rsp="True", jsp=", parameters=[{'use_sim_time': True}]")
    assert run(tmp_path, "d.launch.py", fixed) == []
    # Both on wall time: nothing says a clock runs; without robot_state_publisher the
    # joint states reach no transform.
    assert run(tmp_path, "d.launch.py", JSP.format(rsp="False", jsp="")) == []
    alone = fault.replace("robot_state_publisher", "demo_nodes_cpp")
    assert run(tmp_path, "d.launch.py", alone) == []


def test_a_controller_spawner_stamps_nothing(tmp_path: Path) -> None:
    """controller_manager's spawner only asks the manager (in the simulator) to load a
    controller: its own clock reaches no stamp."""
    text = JSP.format(rsp="True", jsp="").replace(
        "package='joint_state_publisher', executable='joint_state_publisher'",
        "package='controller_manager', executable='spawner', arguments=['joint_broad']")
    assert run(tmp_path, "d.launch.py", text) == []
    manager = text.replace("executable='spawner'", "executable='ros2_control_node'")
    assert run(tmp_path, "d.launch.py", manager) == [(RULE, 7)]


def test_two_nodes_given_contradicting_clocks_are_said_to_disagree(
        tmp_path: Path) -> None:
    """bumperbot's real-robot launch gives ros2_control_node use_sim_time false while an
    included controller launch defaults to true: which one is wrong is not known, that
    they disagree is."""
    text = JSP.format(rsp="True", jsp=", parameters=[{'use_sim_time': False}]")
    path = tmp_path / "d.launch.py"
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(path)], options).diagnostics
    assert found.line == 7 and "is given use_sim_time false" in found.message
    assert "give both the same use_sim_time" in found.message


def test_rviz_looks_up_at_its_own_clock(tmp_path: Path) -> None:
    """navigation2#4274: rviz2 without use_sim_time beside a spawned robot."""
    text = ('<launch><node pkg="gazebo_ros" exec="spawn_entity.py" args="-topic x"/>\n'
            '<node pkg="rviz2" exec="rviz2" name="rviz2"{}/>\n</launch>\n')
    assert run(tmp_path, "v.launch.xml", text.format("")) == [(RULE, 2)]
    fixed = text.format('><param name="use_sim_time" value="true"/></node')
    assert run(tmp_path, "v.launch.xml", fixed.replace('/>\n</launch>', '>\n</launch>')
               ) == []


OVERRIDE = ("import os\n"
            "from launch import LaunchDescription\n"
            "from launch.substitutions import LaunchConfiguration\n"
            "from launch_ros.actions import Node\n"
            "def generate_launch_description():\n"
            "    sim = LaunchConfiguration('use_sim_time', default='true')\n"
            "    ekf = os.path.join(os.path.dirname(__file__), 'ekf.yaml')\n"
            "    return LaunchDescription([\n"
            "        Node(package='slam_toolbox', executable='async_slam_toolbox_node',\n"
            "             parameters=[{{'use_sim_time': sim}}]),\n"
            "        Node(package='robot_localization', executable='ekf_node',\n"
            "             name='ekf_filter_node',\n"
            "             parameters=[{params}]),\n"
            "    ])\n")


def test_a_parameter_file_listed_after_the_argument_overrides_it(tmp_path: Path) -> None:
    """roverrobotics_ros2#19: launch_ros passes each entry of parameters= in order (a
    dictionary as a parameter file of its own) and the last setting wins: the file's
    false after the argument's true. Reported at the file's key, the node and the
    overridden true as related."""
    (tmp_path / "ekf.yaml").write_text(
        "ekf_filter_node:\n  ros__parameters:\n    frequency: 30.0\n    use_sim_time: false\n")
    fault = OVERRIDE.format(params="{'use_sim_time': sim}, ekf")
    (tmp_path / "o.launch.py").write_text(fault)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    [found] = lint_paths([str(tmp_path / "o.launch.py")], options).diagnostics
    assert (Path(found.path).name, found.line) == ("ekf.yaml", 4)
    assert "o.launch.py:13 is overridden by this later setting" in found.message
    assert [(Path(r.path).name, r.line) for r in found.related] == [
        ("o.launch.py", 11), ("o.launch.py", 9), ("o.launch.py", 13)]
    # The argument after the file: it wins, both nodes on simulated time.
    assert run(tmp_path, "o.launch.py", OVERRIDE.format(params="ekf, {'use_sim_time': sim}")) \
        == []


def test_a_node_whose_parameters_switch_every_edge_off_sends_no_stamp(
        tmp_path: Path) -> None:
    """imu_filter_madgwick given publish_tf false sends no transform and looks none up: it
    stamps its IMU messages with the input's stamps (imu_tools humble c8a27cd,
    imu_filter_ros.cpp 398-415 publish only under publish_tf), so its wall clock reaches
    no tf (samples8: three such findings judged false). With its default it sends
    fixed_frame -> the IMU's frame at its own clock's time."""
    text = ('<launch><node pkg="gazebo_ros" exec="spawn_entity.py" args="-topic x"/>\n'
            '<node pkg="imu_filter_madgwick" exec="imu_filter_madgwick_node">'
            '{}</node>\n</launch>\n')
    assert run(tmp_path, "m.launch.xml", text.format("")) == [(RULE, 2)]
    off = text.format('<param name="publish_tf" value="false"/>')
    assert run(tmp_path, "m.launch.xml", off) == []


NAV2 = ("import os\nfrom launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch_ros.actions import Node\n"
        "from ament_index_python.packages import get_package_share_directory\n"
        "def generate_launch_description():\n"
        "    d = os.path.join(get_package_share_directory('nav2_bringup'), 'launch')\n"
        "    f = os.path.join(os.path.dirname(__file__), 'nav.yaml')\n"
        "    return LaunchDescription([\n"
        "        Node(package='gazebo_ros', executable='spawn_entity.py',\n"
        "             arguments=['-topic', 'robot_description', '-entity', 'r']),\n"
        "        IncludeLaunchDescription(\n"
        "            PythonLaunchDescriptionSource([d, '/bringup_launch.py']),\n"
        "            launch_arguments={{'params_file': f{more}}}.items())])\n")


def test_nav2_bringup_may_rewrite_the_files_use_sim_time_to_its_argument(
        tmp_path: Path) -> None:
    # Up to Humble RewrittenYaml sets the file's use_sim_time to the argument; from Iron
    # the file's value overrides SetParameter: the distribution decides, not judged.
    (tmp_path / "nav.yaml").write_text("amcl:\n  ros__parameters:\n    use_sim_time: False\n")
    given = NAV2.format(more=", 'use_sim_time': 'true'")
    assert run(tmp_path, "a.launch.py", given) == []
    # Not given: the argument's default 'false' agrees with the file in every distribution.
    assert run(tmp_path, "a.launch.py", NAV2.format(more="")) == [(RULE, 3)]
    # A file without the key: nothing is rewritten (Foxy and Humble leave it unset).
    (tmp_path / "nav.yaml").write_text("amcl:\n  ros__parameters:\n    alpha1: 0.2\n")
    assert run(tmp_path, "a.launch.py", given) == [(RULE, 13)]


INCLUDED = ("from launch import LaunchDescription\n"
            "from launch.actions import DeclareLaunchArgument\n"
            "from launch.conditions import IfCondition, UnlessCondition\n"
            "from launch.substitutions import LaunchConfiguration\n"
            "from launch_ros.actions import Node\n"
            "def generate_launch_description():\n"
            "    ns = LaunchConfiguration('use_namespace')\n"
            "    return LaunchDescription([\n"
            "        DeclareLaunchArgument('use_namespace', default_value='false'),\n"
            "        Node(condition=UnlessCondition(ns), package='rviz2', executable='rviz2'),\n"
            "        Node(condition=IfCondition(ns), package='rviz2', executable='rviz2',\n"
            "             namespace='tb1')])\n")
HANDLER = ("import os\nfrom launch import LaunchDescription\n"
           "from launch.actions import IncludeLaunchDescription, RegisterEventHandler\n"
           "from launch.event_handlers import OnProcessExit\n"
           "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
           "from launch_ros.actions import Node\n"
           "def generate_launch_description():\n"
           "    spawn = Node(package='gazebo_ros', executable='spawn_entity.py',\n"
           "                 arguments=['-topic', 'robot_description', '-entity', 'r'])\n"
           "    rviz = IncludeLaunchDescription(PythonLaunchDescriptionSource(\n"
           "        os.path.join(os.path.dirname(__file__), 'rviz.launch.py')),\n"
           "        launch_arguments={'use_namespace': 'True'}.items())\n"
           "    return LaunchDescription([spawn, RegisterEventHandler(\n"
           "        OnProcessExit(target_action=spawn, on_exit=[rviz]))])\n")


def test_an_include_in_an_event_handler_keeps_its_arguments_inside(tmp_path: Path) -> None:
    """samples9, turtlebot3_multi_robot's template: nav2's rviz_launch.py included from an
    OnProcessExit handler with use_namespace 'True': only the namespaced rviz2 runs."""
    (tmp_path / "rviz.launch.py").write_text(INCLUDED)
    path = tmp_path / "sim.launch.py"
    path.write_text(HANDLER)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(path)], options).diagnostics
    assert [(Path(d.path).name, d.line) for d in found] == [("rviz.launch.py", 11)]
