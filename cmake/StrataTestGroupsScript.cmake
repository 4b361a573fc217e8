# Run after a test executable is built (cmake/StrataTestGroups.cmake): lists its tests and
# writes CTEST_FILE, one add_test a suite or a part of a suite.
# Inputs (-D): EXECUTABLE, WORKING_DIRECTORY, CTEST_FILE, LABELS (comma-separated), TIMEOUT,
# GROUP_SIZE.
cmake_minimum_required(VERSION 3.21)

execute_process(
  COMMAND "${EXECUTABLE}" --gtest_list_tests
  WORKING_DIRECTORY "${WORKING_DIRECTORY}"
  TIMEOUT 120
  OUTPUT_VARIABLE listing
  ERROR_VARIABLE listing_errors
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${result}):\n"
                      "${listing}${listing_errors}")
endif()

string(REPLACE "," ";" labels "${LABELS}")
set(script "")

# Writes the add_test of each part of one suite. Parts are of near-equal size, so that a suite
# of 21 tests gives two of 11 and 10, not one of 20 and one of 1.
function(flush_suite)
  list(LENGTH suite_tests count)
  if(count EQUAL 0)
    return()
  endif()
  math(EXPR parts "(${count} + ${GROUP_SIZE} - 1) / ${GROUP_SIZE}")
  set(first 0)
  foreach(part RANGE 1 ${parts})
    math(EXPR last "(${count} * ${part}) / ${parts} - 1")
    if(parts EQUAL 1)
      set(name "${suite}")
      set(filter "${suite}.*")
    else()
      set(name "${suite}:${part}/${parts}")
      math(EXPR length "${last} - ${first} + 1")
      list(SUBLIST suite_tests ${first} ${length} chosen)
      list(TRANSFORM chosen PREPEND "${suite}.")
      list(JOIN chosen ":" filter)
    endif()
    string(APPEND script
      "add_test([==[${name}]==] [==[${EXECUTABLE}]==] [==[--gtest_filter=${filter}]==])\n"
      "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==]"
      " LABELS [==[${labels}]==] TIMEOUT ${TIMEOUT})\n")
    math(EXPR first "${last} + 1")
  endforeach()
  set(script "${script}" PARENT_SCOPE)
endfunction()

string(REPLACE "\n" ";" lines "${listing}")
set(suite "")
set(suite_tests "")
foreach(line IN LISTS lines)
  if(line MATCHES "^  +([^ ]+)")
    # A test; a parameterised one is followed by "  # GetParam() = ...", left out.
    list(APPEND suite_tests "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^([^ ]+)\\.( +#.*)?$")
    flush_suite()
    set(suite "${CMAKE_MATCH_1}")
    set(suite_tests "")
  endif()
  # Anything else (gtest_main's "Running main() from ...") is not a test.
endforeach()
flush_suite()

if(script STREQUAL "")
  message(FATAL_ERROR "${EXECUTABLE} lists no test")
endif()
file(WRITE "${CTEST_FILE}" "${script}")
