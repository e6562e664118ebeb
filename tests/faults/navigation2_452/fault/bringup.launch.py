import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    here = os.path.dirname(__file__)
    return LaunchDescription([
        DeclareLaunchArgument('map'),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'turtlebot3_robot.launch.py'))),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'nav2_bringup_launch.py')),
            launch_arguments={'map': LaunchConfiguration('map')}.items()),
    ])
