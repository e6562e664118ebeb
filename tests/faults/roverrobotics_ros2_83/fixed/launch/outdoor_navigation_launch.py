import os

from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, IncludeLaunchDescription,
                            SetEnvironmentVariable)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    # Get the launch directory
    rover_dir = os.path.join(os.path.dirname(__file__), '..')

    # Create the launch configuration variables
    use_sim_time = LaunchConfiguration('use_sim_time')
    slam_params_file = LaunchConfiguration('slam_params_file')
    map_file = LaunchConfiguration('map_file_name')

    stdout_linebuf_envvar = SetEnvironmentVariable(
        'RCUTILS_LOGGING_BUFFERED_STREAM', '1')

    declare_use_sim_time_cmd = DeclareLaunchArgument(
        'use_sim_time',
        default_value='false',
        description='Use simulation (Gazebo) clock if true')

    rl_launch_path = os.path.join(rover_dir, 'launch', 'robot_localizer_outdoor.launch.py')
    robot_localizer_launch = IncludeLaunchDescription(PythonLaunchDescriptionSource(rl_launch_path),
        launch_arguments={'use_sim_time': use_sim_time}.items())

    # Slam toolbox stuff
    declare_slam_params_file_cmd = DeclareLaunchArgument(
        'slam_params_file',
        default_value=os.path.join(rover_dir,
                                   'config/slam_configs', 'mapper_params_localization.yaml'),
        description='Full path to the ROS2 parameters file to use for the slam_toolbox node')

    declare_slam_map_file_cmd = DeclareLaunchArgument(
        'map_file_name',
        default_value='maze_map',
        description='Full path to the ROS2 parameters file to use for the slam_toolbox node')

    map_file_arg = PathJoinSubstitution([
        rover_dir, 'maps', map_file])

    start_async_slam_toolbox_node = Node(
        parameters=[
          slam_params_file,
          {'use_sim_time': use_sim_time},
          {'map_file_name': map_file_arg}
        ],
        package='slam_toolbox',
        executable='localization_slam_toolbox_node',
        name='slam_toolbox',
        output='screen')

    # Create the launch description and populate
    ld = LaunchDescription()

    # Add slam setup to launch description
    ld.add_action(declare_slam_params_file_cmd)
    ld.add_action(declare_slam_map_file_cmd)

    # Set environment variables
    ld.add_action(stdout_linebuf_envvar)

    # Declare the launch options
    ld.add_action(declare_use_sim_time_cmd)

    # Add the actions to launch all of the navigation nodes
    ld.add_action(robot_localizer_launch)
    ld.add_action(start_async_slam_toolbox_node)

    return ld
