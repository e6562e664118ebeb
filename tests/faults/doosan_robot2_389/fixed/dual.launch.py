from launch import LaunchDescription
from launch_ros.actions import Node

ROBOT = ('<robot name="m0609"><link name="base_link"/><link name="link_1"/>'
         '<joint name="joint_1" type="fixed"><parent link="base_link"/><child link="link_1"/>'
         '</joint></robot>')


def generate_launch_description():
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             namespace='dsr03', parameters=[{'robot_description': ROBOT,
                                              'frame_prefix': 'dsr03/'}]),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             namespace='dsr04', parameters=[{'robot_description': ROBOT,
                                              'frame_prefix': 'dsr04/'}]),
    ])
