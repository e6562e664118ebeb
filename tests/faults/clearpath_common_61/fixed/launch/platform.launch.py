import os

from launch import LaunchDescription
from launch.actions import (
    DeclareLaunchArgument,
    GroupAction,
    IncludeLaunchDescription,
)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (
    LaunchConfiguration,
    PathJoinSubstitution
)
from launch_ros.actions import PushRosNamespace


def generate_launch_description():

    # Packages
    here = os.path.dirname(__file__)

    # Launch Arguments
    arg_setup_path = DeclareLaunchArgument(
        'setup_path',
        default_value=os.path.join(here, '..') + '/'
    )

    arg_use_sim_time = DeclareLaunchArgument(
        'use_sim_time',
        choices=['true', 'false'],
        default_value='false',
        description='Use simulation time'
    )

    arg_namespace = DeclareLaunchArgument(
        'namespace',
        default_value='',
        description='Robot namespace'
    )

    # Launch Configurations
    setup_path = LaunchConfiguration('setup_path')
    use_sim_time = LaunchConfiguration('use_sim_time')
    namespace = LaunchConfiguration('namespace')

    # Launch files
    launch_file_platform_description = os.path.join(here, 'description.launch.py')

    launch_file_control = os.path.join(here, 'control.launch.py')

    launch_file_localization = os.path.join(here, 'localization.launch.py')

    group_platform_action = GroupAction(
        actions=[
            PushRosNamespace(namespace),

            IncludeLaunchDescription(
              PythonLaunchDescriptionSource(launch_file_platform_description),
              launch_arguments=[
                  ('setup_path', setup_path),
                  ('use_sim_time', use_sim_time),
                  ('namespace', namespace),
              ]
            ),

            # Launch clearpath_control/control.launch.py which is just robot_localization.
            IncludeLaunchDescription(
              PythonLaunchDescriptionSource(launch_file_control),
              launch_arguments=[
                  ('setup_path', setup_path),
                  ('use_sim_time', use_sim_time),
              ]
            ),

            # Launch localization (ekf node)
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(launch_file_localization),
                launch_arguments=[
                    ('setup_path', setup_path),
                    ('use_sim_time', use_sim_time)]
            ),
        ]
    )

    ld = LaunchDescription()
    ld.add_action(arg_setup_path)
    ld.add_action(arg_use_sim_time)
    ld.add_action(arg_namespace)
    ld.add_action(group_platform_action)
    return ld
