# navlink_discover_tests(TARGET KIND abi|doctest [PREFIX P] [ARGS A...] [LABELS L...] [TIMEOUT S]
#                        [WORKING_DIRECTORY DIR] [SKIP_RETURN_CODE N])
#
# Registers each test case of the test program TARGET as a ctest test of its own, as doctest's
# doctest_discover_tests and CMake's gtest_discover_tests do: once TARGET is built, the build asks it
# for its cases and writes them into a file ctest reads (TEST_INCLUDE_FILES), so a case added to a
# source file shows up in ctest without touching CMake. Until TARGET is built, ctest shows one test,
# TARGET_NOT_BUILT, that fails.
#
#   KIND abi       navlink-abi-tests: listed with --list, run as PROGRAM --case NAME ARGS...
#   KIND doctest   a doctest program with tests/support/doctest_main.cpp: listed with --list-test-cases,
#                  run as PROGRAM --exact-test-case=NAME ARGS..., which runs exactly the case named NAME
#                  (doctest's own -tc filter reads ',' as a separator and '*' and '?' as wildcards) and
#                  fails unless that one case ran.
#
# Each test is named PREFIX + the case's name and gets the LABELS, TIMEOUT, WORKING_DIRECTORY
# (default: the current binary dir) and SKIP_RETURN_CODE given. The listing runs discover_tests.cmake,
# which refuses two cases of one name. doctest_discover_tests from Debian's doctest-dev (2.4.9) is not
# used: it splits a case's name at ';' (26 of the 121 core test cases have one), registering halves that
# run no case and pass, and it escapes only ','.
set(_NAVLINK_DISCOVER_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/discover_tests.cmake")

function(navlink_discover_tests TARGET)
  cmake_parse_arguments(PARSE_ARGV 1 _d "" "KIND;PREFIX;TIMEOUT;WORKING_DIRECTORY;SKIP_RETURN_CODE" "ARGS;LABELS")
  if(NOT _d_KIND MATCHES "^(abi|doctest)$")
    message(FATAL_ERROR "navlink_discover_tests(${TARGET}): KIND must be abi or doctest")
  endif()
  if(NOT _d_WORKING_DIRECTORY)
    set(_d_WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  endif()
  set(_tests_file "${CMAKE_CURRENT_BINARY_DIR}/${TARGET}_ctests.cmake")
  set(_include_file "${CMAKE_CURRENT_BINARY_DIR}/${TARGET}_ctests_include.cmake")
  # Lists go through -D as one argument each; '|' separates their items (';' would split the command).
  # The prefix ends with a '|' the script takes off: -D drops trailing spaces.
  string(REPLACE ";" "|" _args "${_d_ARGS}")
  string(REPLACE ";" "|" _labels "${_d_LABELS}")
  add_custom_command(
    OUTPUT "${_tests_file}"
    COMMAND "${CMAKE_COMMAND}"
            "-DTEST_EXECUTABLE=$<TARGET_FILE:${TARGET}>"
            "-DTEST_KIND=${_d_KIND}"
            "-DTEST_PREFIX=${_d_PREFIX}|"
            "-DTEST_ARGS=${_args}"
            "-DTEST_LABELS=${_labels}"
            "-DTEST_TIMEOUT=${_d_TIMEOUT}"
            "-DTEST_WORKING_DIRECTORY=${_d_WORKING_DIRECTORY}"
            "-DTEST_SKIP_RETURN_CODE=${_d_SKIP_RETURN_CODE}"
            "-DCTEST_FILE=${_tests_file}"
            -P "${_NAVLINK_DISCOVER_SCRIPT}"
    DEPENDS ${TARGET} "${_NAVLINK_DISCOVER_SCRIPT}"
    WORKING_DIRECTORY "${_d_WORKING_DIRECTORY}"
    COMMENT "Listing the test cases of ${TARGET} for ctest"
    VERBATIM)
  add_custom_target(${TARGET}-ctests ALL DEPENDS "${_tests_file}")
  file(WRITE "${_include_file}"
    "if(EXISTS \"${_tests_file}\")\n"
    "  include(\"${_tests_file}\")\n"
    "else()\n"
    "  add_test(${TARGET}_NOT_BUILT ${TARGET}_NOT_BUILT)\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${_include_file}")
endfunction()
