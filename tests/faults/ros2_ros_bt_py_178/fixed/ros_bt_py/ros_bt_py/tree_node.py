import rclpy
from rclpy.executors import MultiThreadedExecutor
from rclpy.logging import get_logger
from rclpy.node import Node
from ros_bt_py.parameters import tree_node_parameters


class TreeNode(Node):
    """ROS node running a single behavior tree."""

    def load_default_tree(self, params: tree_node_parameters.Params):
        if params.default_tree.load_default_tree:
            self.get_logger().info(
                f"loading default tree: {params.default_tree.tree_path}"
            )


def main(argv=None):

    rclpy.init(args=argv)
    tree_node = TreeNode(node_name="BehaviorTreeNode")
    param_listener = tree_node_parameters.ParamListener(tree_node)
    params = param_listener.get_params()
    tree_node.load_default_tree(params=params)

    executor = MultiThreadedExecutor(num_threads=3)
    executor.add_node(tree_node)
    try:
        executor.spin()
    except KeyboardInterrupt:
        get_logger("tree_node").fatal("Shutting down rclpy!")


if __name__ == "__main__":
    import sys

    main(sys.argv)
