import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config_husky_velocity_controller = os.path.join(os.path.dirname(__file__), 'control.yaml')

    node_controller_manager = Node(
        package="controller_manager",
        executable="ros2_control_node",
        parameters=[config_husky_velocity_controller],
        output={
            "stdout": "screen",
            "stderr": "screen",
        },
    )

    spawn_husky_velocity_controller = Node(
        package="controller_manager",
        executable="spawner",
        arguments=["husky_velocity_controller"],
        output="screen",
    )

    ld = LaunchDescription()
    ld.add_action(node_controller_manager)
    ld.add_action(spawn_husky_velocity_controller)

    return ld
