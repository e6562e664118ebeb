"""What reads the workspace as ROS finds it: packages, discovery, ignore files, configuration."""
