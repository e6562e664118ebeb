from launch import LaunchDescription
import launch_ros.actions
import os


def generate_launch_description():
    return LaunchDescription([
        launch_ros.actions.Node(
            package='robot_localization',
            executable='ekf_node',
            name='ekf_node',
            output='screen',
            parameters=[os.path.join(os.path.dirname(__file__), 'localization.yaml')],
           ),
])
