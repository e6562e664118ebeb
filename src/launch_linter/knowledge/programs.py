"""What ROS packages install and which programs give ROS 2 its ``/clock``, per release:
data read from the packages' sources, each fact citing the file, branch and commit it was
read from (docs/knowledge.md; checked by tests/knowledge/test_programs.py).

- :data:`INSTALLED`: the executables a package's release for a distribution installs
  (its build file's install rules): a node of that package with another ``type`` or
  ``executable`` cannot start on that distribution.
- :data:`CLOCK`: the programs and launch files that start Gazebo Sim without bridging
  its clock to ROS, those that publish or may bridge ``/clock``, and the programs known
  to publish no ``/clock``. ROS 2 nodes given ``use_sim_time`` true take their time from
  ``/clock`` alone (ros2/design, articles/130_ros_time.md: "the time will be zero until
  a message arrives on /clock"); Gazebo classic's ``gazebo_ros`` publishes it, Gazebo
  Sim publishes its clock on its own transport only, which ``ros_gz_bridge`` bridges.

Standard library only: the core reads it.
"""

from __future__ import annotations

from launch_linter.knowledge import Source
from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS


class Installed:
    """A package's executables in the releases of ``distros`` (ROS ``ros``)."""

    __slots__ = ("package", "ros", "distros", "executables", "sources")

    def __init__(self, package: str, ros: int, distros: tuple[str, ...],
                 executables: tuple[str, ...], sources: tuple[Source, ...]) -> None:
        self.package = package
        self.ros = ros
        self.distros = distros
        self.executables = executables
        self.sources = sources


class ClockFact:
    """A program (``package``, ``executable``: a node, ``*`` any of the package's) or a
    launch file (``package``, ``launch``: its path in the package's share folder) and
    what it does with ``/clock``: ``publishes`` (Gazebo classic), ``may_bridge`` (a
    bridge whose configuration may include /clock), ``gz_sim`` (starts or feeds Gazebo
    Sim and bridges nothing) or ``none`` (publishes no clock)."""

    __slots__ = ("package", "executable", "launch", "does", "sources")

    def __init__(self, package: str, does: str, sources: tuple[Source, ...],
                 executable: str | None = None, launch: str | None = None) -> None:
        self.package = package
        self.does = does
        self.sources = sources
        self.executable = executable
        self.launch = launch


CLOCK_ROLES = ("publishes", "may_bridge", "gz_sim", "none")

_RSP = "ros/robot_state_publisher"
_RSP_1_13 = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "kinetic-devel",
                   "d8600f658aa09c3cb68f034feec357dc1d24bb72", "32-37, 72")
_RSP_1_14 = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "melodic-devel",
                   "cd1c43cae1c9cbcdc0591bdb8a6a0a4c3a944299", "51-56, 98")
_RSP_1_15 = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "1.15.0",
                   "2bb8b4a5189f8c33ee025f8b5f9425f639f9cae0", "51, 97")
_RSP_NOETIC = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "noetic-devel",
                     "9afecc81119decb3535bb461d234193e796e68ff", "44, 85")
_RSP_FOXY = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "foxy",
                   "a1346e963b04b2c452eccdcbf69c7b8f81db314d", "44-46")
_RSP_HUMBLE = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "humble",
                     "8b5af4f31e0f754c7c262eb487ccd3956cb788cc", "48-50")
_RSP_ROLLING = Source(_RSP, "robot_state_publisher", "CMakeLists.txt", "rolling",
                      "e0f77e62457ae01f8dbf3b5c4cc62d15fa36dfad", "50-52")

INSTALLED: tuple[Installed, ...] = (
    # Until Melodic (1.13, 1.14) the deprecated ``state_publisher`` was built from the
    # same source; 1.15.0, Noetic's release, installs robot_state_publisher alone.
    Installed("robot_state_publisher", 1, ("kinetic", "lunar", "melodic"),
              ("robot_state_publisher", "state_publisher"), (_RSP_1_13, _RSP_1_14)),
    Installed("robot_state_publisher", 1, ("noetic",), ("robot_state_publisher",),
              (_RSP_1_15, _RSP_NOETIC)),
    Installed("robot_state_publisher", 2, ROS2_DISTROS[ROS2_DISTROS.index("foxy"):],
              ("robot_state_publisher",), (_RSP_FOXY, _RSP_HUMBLE, _RSP_ROLLING)),
)

_GZ = "gazebosim/ros_gz"
_GZ_SIM_HUMBLE = Source(_GZ, "ros_gz_sim", "ros_gz_sim/launch/gz_sim.launch.py.in", "humble",
                        "5cc92f804739b8b72f71aa2551a4be893d74efc0", "142-149")
_GZ_SIM_IRON = Source(_GZ, "ros_gz_sim", "ros_gz_sim/launch/gz_sim.launch.py.in", "iron",
                      "14e4465305ac96beb4c93c506552783fbf6a46a0", "142-149")
_GZ_SIM_JAZZY = Source(_GZ, "ros_gz_sim", "ros_gz_sim/launch/gz_sim.launch.py.in", "jazzy",
                       "739cb42a5846cd12a526b97ba051a2d8cdbe034b", "129-136")
_IGN_GAZEBO = Source(_GZ, "ros_ign_gazebo", "ros_ign_gazebo/launch/ign_gazebo.launch.py.in",
                     "galactic", "6ffa8271e9db31ce8bdae4c491c23bb4271737cd", "40-63")
_CREATE = Source(_GZ, "ros_gz_sim", "ros_gz_sim/src/create.cpp", "humble",
                 "5cc92f804739b8b72f71aa2551a4be893d74efc0", "37 (no publisher)")
_BRIDGE = Source(_GZ, "ros_gz_bridge", "ros_gz_bridge/src/parameter_bridge.cpp", "rolling",
                 "a4d00a90a1a5f753a0d0fbfe8e1e142540aebadd", "31-61")
_GZ_SIM_LAUNCH = Source(_GZ, "ros_gz_sim", "ros_gz_sim/launch/ros_gz_sim.launch.py", "rolling",
                        "a4d00a90a1a5f753a0d0fbfe8e1e142540aebadd", "86-108")
_GZ_SERVER = Source(_GZ, "ros_gz_sim", "ros_gz_sim/launch/gz_server.launch.py", "rolling",
                    "a4d00a90a1a5f753a0d0fbfe8e1e142540aebadd", "43-95")
_GAZEBO_ROS_INIT = Source("ros-simulation/gazebo_ros_pkgs", "gazebo_ros",
                          "gazebo_ros/src/gazebo_ros_init.cpp", "ros2",
                          "d52f7c471d1d2fd9425bf8621290bc4831be8dea", "161-165")

CLOCK: tuple[ClockFact, ...] = (
    # gz_sim.launch.py runs ``gz sim`` (ExecuteProcess) and nothing else, in every branch.
    ClockFact("ros_gz_sim", "gz_sim", (_GZ_SIM_HUMBLE, _GZ_SIM_IRON, _GZ_SIM_JAZZY),
              launch="launch/gz_sim.launch.py"),
    ClockFact("ros_ign_gazebo", "gz_sim", (_IGN_GAZEBO,), launch="launch/ign_gazebo.launch.py"),
    ClockFact("ros_gz_sim", "gz_sim", (_CREATE,), executable="create"),
    ClockFact("ros_ign_gazebo", "gz_sim", (_CREATE,), executable="create"),
    ClockFact("ros_gz_sim", "gz_sim", (_GZ_SERVER,), executable="gzserver"),
    ClockFact("ros_gz_sim", "gz_sim", (_GZ_SERVER,), launch="launch/gz_server.launch.py"),
    # parameter_bridge bridges the topics its arguments or configuration file name.
    ClockFact("ros_gz_bridge", "may_bridge", (_BRIDGE,), executable="*"),
    ClockFact("ros_ign_bridge", "may_bridge", (_BRIDGE,), executable="*"),
    ClockFact("ros_gz_sim", "may_bridge", (_GZ_SIM_LAUNCH,), launch="launch/ros_gz_sim.launch.py"),
    ClockFact("gazebo_ros", "publishes", (_GAZEBO_ROS_INIT,), executable="*"),
    ClockFact("gazebo_ros", "publishes", (_GAZEBO_ROS_INIT,), launch="*"),
)

DISTROS = ROS1_DISTROS + ROS2_DISTROS


def installed(package: str, ros: int | None, distro: str | None) -> Installed | None:
    """What ``package`` installs in ``distro`` (None: not known)."""
    for fact in INSTALLED:
        if fact.package == package and fact.ros == ros and distro in fact.distros:
            return fact
    return None


def clock_program(package: str, executable: str) -> ClockFact | None:
    """What a node's program does with /clock, None when not known here."""
    for fact in CLOCK:
        if fact.package == package and fact.executable in (executable, "*"):
            return fact
    return None


def clock_launch(package: str, launch: str) -> ClockFact | None:
    """What a package's launch file (its path in the share folder) does with /clock."""
    for fact in CLOCK:
        if fact.package == package and fact.launch in (launch, "*"):
            return fact
    return None
