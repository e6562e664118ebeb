# ament_launch_linter([TESTNAME name] [FAIL_ON error|warning|info] [CONFIG file] [path ...])
#
# Adds a test that runs Launch-Linter on the given paths (default: the package's source
# folder) and writes xUnit results where colcon test-result finds them.
function(ament_launch_linter)
  cmake_parse_arguments(ARG "" "TESTNAME;FAIL_ON;CONFIG" "" ${ARGN})
  if(NOT ARG_TESTNAME)
    set(ARG_TESTNAME "launch_linter")
  endif()

  find_program(ament_launch_linter_BIN NAMES "ament_launch_linter")
  if(NOT ament_launch_linter_BIN)
    message(FATAL_ERROR "ament_launch_linter() could not find program 'ament_launch_linter'")
  endif()

  set(result_file "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/${ARG_TESTNAME}.xunit.xml")
  set(cmd "${ament_launch_linter_BIN}" "--xunit-file" "${result_file}")
  if(ARG_FAIL_ON)
    list(APPEND cmd "--fail-on" "${ARG_FAIL_ON}")
  endif()
  if(ARG_CONFIG)
    list(APPEND cmd "--config" "${ARG_CONFIG}")
  endif()
  list(APPEND cmd ${ARG_UNPARSED_ARGUMENTS})

  file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/ament_launch_linter")
  ament_add_test(
    "${ARG_TESTNAME}"
    COMMAND ${cmd}
    OUTPUT_FILE "${CMAKE_BINARY_DIR}/ament_launch_linter/${ARG_TESTNAME}.txt"
    RESULT_FILE "${result_file}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
  )
  set_tests_properties(
    "${ARG_TESTNAME}"
    PROPERTIES
    LABELS "launch_linter;linter"
  )
endfunction()
