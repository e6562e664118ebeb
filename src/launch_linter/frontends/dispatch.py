"""Pick the front-end for a launch file by its name and content.

``*.py`` files are ROS 2 Python launch files and ``*.yaml``/``*.yml`` files ROS 2 YAML
launch files. XML is ROS 1 unless it uses what only ROS 2 launch XML has
(:mod:`launch_linter.frontends.xml_dialect`). Both ROS versions use ``.launch`` and
``.launch.xml``, so the suffix does not decide (the engine lets the package's build type
decide for ``*.xml`` files).
"""

from __future__ import annotations

from launch_linter.frontends.robot.describe import attach_robot
from launch_linter.frontends.robot.standalone import load_description
from launch_linter.frontends.ros1 import LoadOptions, Ros1Loader, load_ros1
from launch_linter.frontends.xml_dialect import is_ros2_xml, reads_as_python
from launch_linter.knowledge import bundled
from launch_linter.model.diagnostic import Problem
from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import replace
from launch_linter.resolve.xml_safe import read_launch_bytes
from launch_linter.workspace.discovery import is_description_name

NEVER_LAUNCHED = "file_never_launched"
REFUSALS = frozenset({"ros2_schema", "roslaunch_error"})
"""The rules whose findings say that ``ros2 launch`` refuses the file."""


def front_end(path: str, data: bytes | None, ros_version: int | None = None) -> str:
    """``ros2`` or ``ros1``: which loader reads ``path`` (``data``: its bytes, if read).

    ``ros_version`` (from ``--ros`` or the package) decides for XML when given."""
    name = path.lower()
    if name.endswith((".py", ".yaml", ".yml")) or (data is not None
                                                   and reads_as_python(path, data)):
        return "ros2"
    if ros_version is not None:
        return "ros2" if ros_version == 2 else "ros1"
    return "ros2" if data is not None and is_ros2_xml(data) else "ros1"


def load_tree(path: str, options: LoadOptions, data: bytes | None = None) -> LaunchTree:
    """Read the launch tree rooted at ``path`` with the front-end its format needs."""
    if is_description_name(path):
        return load_description(path, options.args, options.packages, options.robots,
                                options.display_path, options.env, data)
    if data is None and not path.lower().endswith((".py", ".yaml", ".yml")):
        try:
            data = read_launch_bytes(path)
        except OSError:
            # The ROS 1 loader reports the file as unreadable.
            return load_ros1(path, options, None)
    if front_end(path, data, options.ros_version) == "ros2":
        # Imported when first needed: the ROS 2 front-ends are most of the start-up time
        # of a run over ROS 1 files only.
        from launch_linter.frontends.ros2_launch import Ros2Loader

        loader: Ros1Loader | Ros2Loader = Ros2Loader(options)
    else:
        loader = Ros1Loader(options)
    tree = loader.load(path, data)
    if not isinstance(loader, Ros1Loader) and any(
            p.rule in REFUSALS and p.path == tree.root for p in tree.problems):
        tree = _if_never_launched(tree, path, data, options)
    if tree.descriptions:
        tree = attach_robot(tree, options.packages, options.robots, options.display_path,
                            dict(options.env), loader.include_sites,
                            loader.tf_prefixes if isinstance(loader, Ros1Loader) else ())
    if not isinstance(loader, Ros1Loader) and any(n.params for n in tree.nodes):
        # Imported here: the install rules it reads cost start-up time a run without
        # such nodes need not pay.
        from launch_linter.frontends.declarations import attach_declarations

        tree = attach_declarations(tree, options.packages)
    return _with_built_here(tree, options)


def _with_built_here(tree: LaunchTree, options: LoadOptions) -> LaunchTree:
    """``tree`` with the packages of its nodes that the knowledge base has release facts
    for and whose source is under a linted root (``LaunchTree.built_here``): only those
    ask for the packages (the crawl is paid when a release fact could be wrong)."""
    knowledge = bundled() if options.knowledge is None else options.knowledge
    asked: dict[str, bool] = {}
    for node in tree.nodes:
        package = node.package
        if node.kind != "node" or not package or package in asked:
            continue
        asked[package] = any(
            knowledge.installed(package, node.ros, distro) is not None
            for distro in (*ROS1_DISTROS, *ROS2_DISTROS)
        ) and options.packages.in_source(package)
    built_here = tuple(package for package, here in asked.items() if here)
    return replace(tree, built_here=built_here) if built_here else tree


def _if_never_launched(tree: LaunchTree, path: str, data: bytes | None,
                       options: LoadOptions) -> LaunchTree:
    """``tree`` with a :data:`NEVER_LAUNCHED` problem when nothing runs its root file
    (:mod:`.launchable`): the rules then report its refusals at info."""
    # Imported here: only a root that ros2 launch refuses needs the install rules read.
    from launch_linter.frontends.launchable import why_never_launched

    reason = why_never_launched(path, data, options.packages)
    if reason is None:
        return tree
    problem = Problem(NEVER_LAUNCHED, tree.root, 1, 0,
                      f"{reason}; what ros2 launch would refuse in it is reported at info")
    return replace(tree, problems=(*tree.problems, problem))
