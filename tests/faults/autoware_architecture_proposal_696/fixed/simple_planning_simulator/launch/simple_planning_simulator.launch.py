import ament_index_python
import launch
import launch_ros.actions

from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from ament_index_python import get_package_share_directory

import os


def generate_launch_description():

    default_vehicle_characteristics_param = os.path.join(
        get_package_share_directory('simple_planning_simulator'),
        'param/vehicle_characteristics.param.yaml')

    vehicle_characteristics_param = DeclareLaunchArgument(
        'vehicle_characteristics_param_file',
        default_value=default_vehicle_characteristics_param,
        description='Path to config file for vehicle characteristics'
    )

    simple_planning_simulator_node = launch_ros.actions.Node(
        package='simple_planning_simulator',
        executable='simple_planning_simulator_exe',
        name='simple_planning_simulator',
        namespace='simulation',
        output='screen',
        parameters=[
            "{}/param/simple_planning_simulator_default.param.yaml".format(
                ament_index_python.get_package_share_directory(
                    "simple_planning_simulator"
                )
            ),
            LaunchConfiguration('vehicle_characteristics_param_file'),
        ],
        remappings=[
            ('input/vehicle_control_command', '/vehicle/vehicle_command'),
            ('input/ackermann_control_command', '/control/command/control_cmd'),
            ('input/gear_command', '/control/command/gear_cmd'),
            ('input/trajectory', '/planning/scenario_planning/trajectory'),
            ('output/twist', '/vehicle/status/velocity_status'),
            ('output/odometry', '/localization/kinematic_state'),
            ('output/steering', '/vehicle/status/steering_status'),
            ('output/gear_report', '/vehicle/status/gear_status'),
            ('output/control_mode_report', '/vehicle/status/control_mode'),
            ('/initialpose', '/initialpose'),
        ]
    )

    map_to_odom_tf_publisher = launch_ros.actions.Node(
        package='tf2_ros',
        executable='static_transform_publisher',
        name='static_map_to_odom_tf_publisher',
        output='screen',
        arguments=['0.0', '0.0', '0.0', '0', '0', '0', 'map', 'odom'])

    ld = launch.LaunchDescription([
        vehicle_characteristics_param,
        simple_planning_simulator_node,
        map_to_odom_tf_publisher
    ])
    return ld
