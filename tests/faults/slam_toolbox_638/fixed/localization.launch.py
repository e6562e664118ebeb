from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='robot_localization', executable='ekf_node', name='local_ekf',
             parameters=[{'world_frame': 'odom', 'odom0': 'wheel/odom'}]),
        Node(package='robot_localization', executable='ekf_node', name='global_ekf',
             parameters=[{'world_frame': 'map', 'pose0': 'slam_pose'}]),
        Node(package='slam_toolbox', executable='async_slam_toolbox_node', name='slam_toolbox',
             parameters=[{'mode': 'mapping', 'transform_publish_period': 0.0}]),
    ])
