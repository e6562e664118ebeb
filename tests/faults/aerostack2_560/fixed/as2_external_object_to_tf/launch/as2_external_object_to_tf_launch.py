from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='drone0'),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument(
            'config_file',
            description='Source data to TF config file. Example in node config folder'),
        Node(
            package='as2_external_object_to_tf',
            executable='as2_external_object_to_tf_node',
            name='external_object_to_tf',
            namespace=LaunchConfiguration('namespace'),
            parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')},
                        {'config_file': LaunchConfiguration('config_file')}],
            output='screen',
            emulate_tty=True
        )
    ])
