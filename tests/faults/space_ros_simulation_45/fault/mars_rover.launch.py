import os

from launch import LaunchDescription
from launch.substitutions import Command
from launch_ros.actions import Node


def generate_launch_description():
    xacro_file = os.path.join(os.path.dirname(__file__), 'curiosity_mars_rover.xacro')
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': Command(['xacro ', xacro_file])}]),
    ])
