"""Launch the ublox gps node in a composable container with c94-m8p configuration."""

import os

import ament_index_python.packages

from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode

import yaml


def generate_launch_description():
    config_directory = os.path.join(
        os.path.join(os.path.dirname(__file__), '..'),
        'config')
    param_config = os.path.join(config_directory, 'c94_m8p_rover.yaml')
    with open(param_config, 'r') as f:
        params = yaml.safe_load(f)['ublox_gps_node']['ros__parameters']
    container = ComposableNodeContainer(
            node_name='ublox_gps_container',
            node_namespace='',
            package='rclcpp_components',
            node_executable='component_container',
            composable_node_descriptions=[
                ComposableNode(
                    package='ublox_gps',
                    node_plugin='ublox_node::UbloxNode',
                    node_name='ublox_gps_node',
                    parameters=[params]),
            ],
            output='both',
    )

    return LaunchDescription([container])
