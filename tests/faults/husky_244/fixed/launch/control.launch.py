import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()

    config_dir = os.path.join(os.path.dirname(__file__), '..', 'config')
    config_husky_ekf = os.path.join(config_dir, 'localization.yaml')

    node_ekf = Node(
        package='robot_localization',
        executable='ekf_node',
        name='ekf_node',
        output='screen',
        parameters=[config_husky_ekf],
        )
    ld.add_action(node_ekf)

    config_imu_filter = os.path.join(config_dir, 'imu_filter.yaml')
    node_imu_filter = Node(
        package='imu_filter_madgwick',
        executable='imu_filter_madgwick_node',
        name='imu_filter',
        output='screen',
        parameters=[config_imu_filter]
    )
    ld.add_action(node_imu_filter)

    return ld
