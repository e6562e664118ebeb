import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    here = os.path.dirname(__file__)
    with open(os.path.join(here, 'sam_bot_description.urdf')) as urdf:
        robot_description = urdf.read()
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': robot_description}]),
        Node(package='robot_localization', executable='ekf_node', name='ekf_filter_node',
             parameters=[{'world_frame': 'odom', 'base_link_frame': 'base_link',
                          'use_sim_time': True}]),
    ])
