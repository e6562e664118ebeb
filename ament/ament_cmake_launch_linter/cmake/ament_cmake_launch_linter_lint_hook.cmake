# ament_lint_auto's hook: a test when the package has launch, URDF or xacro files.
file(GLOB_RECURSE _launch_linter_files FOLLOW_SYMLINKS
  "*.launch" "*.launch.xml" "*_launch.xml" "*.launch.py" "*_launch.py"
  "*.launch.yaml" "*.launch.yml" "*_launch.yaml" "*.urdf" "*.xacro")
if(_launch_linter_files)
  message(STATUS "Added test 'launch_linter' to check launch files, URDF and xacro")
  ament_launch_linter()
endif()
