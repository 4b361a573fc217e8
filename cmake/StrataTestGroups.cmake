# strata_add_test_groups(TARGET LABELS label... TIMEOUT seconds GROUP_SIZE n)
#
# Registers a GoogleTest executable's tests with CTest a group at a time: each suite is one CTest
# test, a suite of more than GROUP_SIZE tests is cut into parts of at most that many. Every test
# still runs (its group names it in a --gtest_filter) and a failing group's output names the
# failing test; what is saved is a process a test, about 0.1 s each under the sanitizers (their
# start and the leak check at exit), for some 2,800 tests.
#
# As gtest_discover_tests does, the list is taken from the executable after each build, so a new
# test needs no edit here.
set(_strata_test_groups_script "${CMAKE_CURRENT_LIST_DIR}/StrataTestGroupsScript.cmake")

function(strata_add_test_groups target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TIMEOUT;GROUP_SIZE" "LABELS")
  if(NOT arg_GROUP_SIZE)
    set(arg_GROUP_SIZE 20)
  endif()
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 600)
  endif()
  set(base "${CMAKE_CURRENT_BINARY_DIR}/${target}_groups")
  set(tests_file "${base}_tests.cmake")
  set(include_file "${base}_include.cmake")
  string(REPLACE ";" "," labels "${arg_LABELS}")
  add_custom_command(
    TARGET ${target} POST_BUILD
    BYPRODUCTS "${tests_file}"
    COMMAND "${CMAKE_COMMAND}"
            -D "EXECUTABLE=$<TARGET_FILE:${target}>"
            -D "WORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}"
            -D "CTEST_FILE=${tests_file}"
            -D "LABELS=${labels}"
            -D "TIMEOUT=${arg_TIMEOUT}"
            -D "GROUP_SIZE=${arg_GROUP_SIZE}"
            -P "${_strata_test_groups_script}"
    VERBATIM)
  # A build that has not made the executable yet shows one failing test rather than none.
  file(WRITE "${include_file}"
       "if(EXISTS \"${tests_file}\")\n"
       "  include(\"${tests_file}\")\n"
       "else()\n"
       "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\n"
       "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
