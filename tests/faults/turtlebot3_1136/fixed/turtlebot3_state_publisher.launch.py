from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node

ROBOT = ('<robot name="turtlebot3_waffle"><link name="base_footprint"/><link name="base_link"/>'
         '<joint name="base_joint" type="fixed"><parent link="base_footprint"/>'
         '<child link="base_link"/></joint></robot>')


def generate_launch_description():
    namespace = LaunchConfiguration('namespace', default='')
    use_sim_time = LaunchConfiguration('use_sim_time', default='false')

    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        Node(
            package='robot_state_publisher',
            executable='robot_state_publisher',
            output='screen',
            parameters=[
                {'robot_description': ROBOT},
                {'use_sim_time': use_sim_time},
                {'frame_prefix': PythonExpression(
                    ['"', namespace, '/" if "', namespace, '" else ""'])}]),
        Node(package='slam_toolbox', executable='async_slam_toolbox_node', name='slam_toolbox',
             parameters=[{'base_frame': 'base_footprint'}]),
    ])
