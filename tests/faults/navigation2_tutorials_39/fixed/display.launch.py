import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    with open(os.path.join(os.path.dirname(__file__), 'sam_bot_description.urdf')) as urdf:
        robot_description = urdf.read()
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': robot_description}]),
    ])
