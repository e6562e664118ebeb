import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config_file = os.path.join(
        get_package_share_directory('ros2_medkit_action_status_bridge'),
        'config',
        'action_status_bridge.yaml'
    )

    return LaunchDescription([
        Node(
            package='ros2_medkit_action_status_bridge',
            executable='action_status_bridge_node',
            name='action_status_bridge',
            output='screen',
            parameters=[config_file],
        ),
    ])
