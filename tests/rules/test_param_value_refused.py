"""param_value_refused: a parameter value the node's release does not accept, from the
knowledge of accepted values (error with the distribution known, else info)."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "param_value_refused"

YAML_NODE = ("launch:\n"
             "  - node:\n"
             "      pkg: {pkg}\n"
             "      exec: {exe}\n"
             "      name: {name}\n"
             "      param:\n"
             "        - name: {param}\n"
             "          value: {value}\n")


def run(tmp_path: Path, text: str, distro: str | None, name: str = "a.launch.yaml",
        extra: dict[str, str] | None = None) -> list[tuple[str, int, str]]:
    for file, content in (extra or {}).items():
        (tmp_path / file).write_text(content)
    path = tmp_path / name
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro=distro)
    return [(Path(d.path).name, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


def amcl(value: str) -> str:
    return YAML_NODE.format(pkg="nav2_amcl", exe="amcl", name="amcl",
                            param="robot_model_type", value=value)


def test_a_refused_value_is_an_error_with_the_distribution_known(tmp_path: Path) -> None:
    assert run(tmp_path, amcl("differential"), "humble") == [("a.launch.yaml", 7, "error")]
    assert run(tmp_path, amcl("nav2_amcl::DifferentialMotionModel"), "galactic") == [
        ("a.launch.yaml", 7, "error")]


def test_an_accepted_value_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, amcl("nav2_amcl::DifferentialMotionModel"), "humble") == []
    assert run(tmp_path, amcl("differential"), "foxy") == []
    assert run(tmp_path, amcl("my_pkg::MyModel"), "jazzy") == []


def test_without_a_distribution_it_is_info(tmp_path: Path) -> None:
    assert run(tmp_path, amcl("differential"), None) == [("a.launch.yaml", 7, "info")]


def test_a_value_the_node_replaces_is_info(tmp_path: Path) -> None:
    launch = ('<launch>\n  <node pkg="amcl" type="amcl" name="amcl">\n'
              '    <param name="odom_model_type" value="differential"/>\n'
              '  </node>\n</launch>\n')
    assert run(tmp_path, launch, "noetic", "a.launch") == [("a.launch", 3, "info")]
    assert run(tmp_path, launch.replace("differential", "omni"), "noetic", "a.launch") == []


def test_a_costmap_layer_class_its_release_lacks(tmp_path: Path) -> None:
    params = ("controller_server:\n  ros__parameters:\n    use_sim_time: false\n"
              "local_costmap:\n  local_costmap:\n    ros__parameters:\n"
              "      plugins: [denoise]\n      denoise:\n        plugin: {cls}\n")
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    f = os.path.join(os.path.dirname(__file__), 'nav.yaml')\n"
              "    return LaunchDescription([Node(package='nav2_controller',\n"
              "        executable='controller_server', name='controller_server',\n"
              "        parameters=[f])])\n")
    layer = "nav2_costmap_2d::DenoiseLayer"
    found = run(tmp_path, launch, "galactic", "a.launch.py",
                {"nav.yaml": params.format(cls=layer)})
    assert found == [("a.launch.py", 6, "error")]
    assert run(tmp_path, launch, "humble", "a.launch.py",
               {"nav.yaml": params.format(cls=layer)}) == []


def test_an_include_of_nav2_bringup_reaches_amcl_through_its_params_file(tmp_path: Path
                                                                         ) -> None:
    params = "amcl:\n  ros__parameters:\n    robot_model_type: \"differential\"\n"
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch.actions import IncludeLaunchDescription\n"
              "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
              "from ament_index_python.packages import get_package_share_directory\n"
              "def generate_launch_description():\n"
              "    d = os.path.join(get_package_share_directory('nav2_bringup'), 'launch')\n"
              "    f = os.path.join(os.path.dirname(__file__), 'nav.yaml')\n"
              "    return LaunchDescription([IncludeLaunchDescription(\n"
              "        PythonLaunchDescriptionSource([d, '/bringup_launch.py']),\n"
              "        launch_arguments={{'params_file': f{more}}}.items())])\n")
    found = run(tmp_path, launch.format(more=""), "humble", "a.launch.py",
                {"nav.yaml": params})
    assert found == [("nav.yaml", 3, "error")]
    # With SLAM on, the file starts no AMCL.
    assert run(tmp_path, launch.format(more=", 'slam': 'True'"), "humble", "a.launch.py",
               {"nav.yaml": params}) == []


def test_a_renamed_controller_type(tmp_path: Path) -> None:
    params = ("controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
              "    jsb:\n      type: joint_state_controller/JointStateController\n")
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    f = os.path.join(os.path.dirname(__file__), 'c.yaml')\n"
              "    return LaunchDescription([Node(package='controller_manager',\n"
              "        executable='ros2_control_node', parameters=[f])])\n")
    assert [f[2] for f in run(tmp_path, launch, "humble", "a.launch.py",
                              {"c.yaml": params})] == ["error"]
    assert run(tmp_path, launch, "foxy", "a.launch.py", {"c.yaml": params}) == []


def test_the_file_nav2_bringup_reads_itself_is_not_a_missing_parameter_file(tmp_path: Path
                                                                           ) -> None:
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch.actions import IncludeLaunchDescription\n"
              "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
              "from ament_index_python.packages import get_package_share_directory\n"
              "def generate_launch_description():\n"
              "    d = os.path.join(get_package_share_directory('nav2_bringup'), 'launch')\n"
              "    f = os.path.join(os.path.dirname(__file__), 'gone.yaml')\n"
              "    return LaunchDescription([IncludeLaunchDescription(\n"
              "        PythonLaunchDescriptionSource([d, '/bringup_launch.py']),\n"
              "        launch_arguments={'params_file': f}.items())])\n")
    path = tmp_path / "a.launch.py"
    path.write_text(launch)
    options = LintOptions(package_paths=(), select=frozenset({"ros2_param_file_missing"}))
    assert not lint_paths([str(path)], options).diagnostics
