"""Front-ends: launch file syntax (ROS 1 XML, ROS 2 XML/YAML/Python) to the model."""
