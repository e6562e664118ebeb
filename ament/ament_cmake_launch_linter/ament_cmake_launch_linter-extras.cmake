# Loaded by find_package(ament_cmake_launch_linter): the ament_launch_linter() function, and
# the hook that ament_lint_auto_find_test_dependencies() runs for every package that lists
# ament_cmake_launch_linter among its test dependencies.

find_package(ament_cmake_test QUIET REQUIRED)

include("${ament_cmake_launch_linter_DIR}/ament_launch_linter.cmake")

ament_register_extension("ament_lint_auto" "ament_cmake_launch_linter"
  "ament_cmake_launch_linter_lint_hook.cmake")
