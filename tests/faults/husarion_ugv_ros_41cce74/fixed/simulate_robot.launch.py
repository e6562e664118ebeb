import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    namespace = LaunchConfiguration("namespace")
    declare_namespace_arg = DeclareLaunchArgument(
        "namespace",
        default_value="",
        description="Add namespace to all launched nodes.",
    )

    spawn_robot_launch = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            os.path.join(os.path.dirname(__file__), "spawn_robot.launch.py")
        ),
        launch_arguments={"namespace": namespace}.items(),
    )

    controller_launch = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            os.path.join(os.path.dirname(__file__), "controller.launch.py")
        ),
        launch_arguments={
            "namespace": namespace,
            "publish_robot_state": "False",
            "use_sim": "True",
        }.items(),
    )

    return LaunchDescription(
        [
            declare_namespace_arg,
            spawn_robot_launch,
            controller_launch,
        ]
    )
