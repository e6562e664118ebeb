import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config_file = os.path.join(
        get_package_share_directory('ros2_medkit_log_bridge'),
        'config',
        'log_bridge.yaml'
    )

    return LaunchDescription([
        Node(
            package='ros2_medkit_log_bridge',
            executable='log_bridge_node',
            name='log_bridge',
            output='screen',
            parameters=[config_file],
        ),
    ])
