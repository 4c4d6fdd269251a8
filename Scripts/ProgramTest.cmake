# Tests that run a program (a driver, talus-cg, a script) and check its exit status as well as its
# output. CTest ignores the exit status of a test with PASS_REGULAR_EXPRESSION, so a program that
# prints the expected line and then crashes, or that accepts bad input it should refuse, would
# pass. Every such test is therefore added with
#
#   talus_program_test(NAME name COMMAND program [args...] [WORKING_DIRECTORY dir] [EXIT status])
#
# (the signature of add_test plus EXIT; SelfTests' talus_self_test calls it). EXIT is the status
# the run must end with: 0, the default, for a run that must succeed; 1 for bad input that a
# driver (talus::Error, Simulation::solve) or talus-cg (cg::InputError) must refuse. The command
# runs under Scripts/expectExit.sh, which prints "TALUS-TEST: exit status S, expected E" when
# the status differs; that line, and a sanitizer's report, are the test's FAIL_REGULAR_EXPRESSION,
# which fails the test whatever the PASS_REGULAR_EXPRESSION says. So PASS_REGULAR_EXPRESSION
# keeps its meaning (set it as before, with set_tests_properties), and a command
# `sh -c "a && b"` must end with status EXIT as a whole. To add a fail pattern, append to
# FAIL_REGULAR_EXPRESSION (set_property(TEST name APPEND PROPERTY ...)); replacing it is refused.
# At the end of a directory that uses talus_program_test, every test of the directory must have
# been added by it (gtest_discover_tests' tests are not directory tests and are not concerned).
# No argument may hold a ';' (CMake cuts lists there): write `sh -c "a && b"`, not "a; b".
include_guard(GLOBAL)

# The lines that fail a test whatever else it printed: the exit-status check's, AddressSanitizer's
# and LeakSanitizer's report header, UndefinedBehaviorSanitizer's report.
set(TALUS_PROGRAM_TEST_FAIL "TALUS-TEST: exit status;==[0-9]+==ERROR: [A-Za-z]+Sanitizer;: runtime error: "
    CACHE INTERNAL "the fail patterns of every program test")

function(talus_program_test)
  cmake_parse_arguments(T "" "NAME;WORKING_DIRECTORY;EXIT" "COMMAND" ${ARGN})
  if(T_UNPARSED_ARGUMENTS OR NOT T_NAME OR NOT T_COMMAND)
    message(FATAL_ERROR "talus_program_test(NAME name COMMAND ... [WORKING_DIRECTORY dir] [EXIT status]): "
                        "unexpected ${T_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT DEFINED T_EXIT)
    set(T_EXIT 0)
  endif()
  if(NOT T_EXIT MATCHES "^[0-9]+$")
    message(FATAL_ERROR "talus_program_test ${T_NAME}: EXIT must be an exit status (0 to 255), "
                        "got '${T_EXIT}'")
  endif()
  # add_test runs an executable target named first by its file; behind the wrapper it must be named so.
  list(POP_FRONT T_COMMAND program)
  if(TARGET ${program})
    set(program $<TARGET_FILE:${program}>)
  endif()
  set(workingDirectory)
  if(T_WORKING_DIRECTORY)
    set(workingDirectory WORKING_DIRECTORY ${T_WORKING_DIRECTORY})
  endif()
  add_test(NAME ${T_NAME}
           COMMAND sh ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/expectExit.sh ${T_EXIT} ${program} ${T_COMMAND}
           ${workingDirectory})
  set_tests_properties(${T_NAME} PROPERTIES FAIL_REGULAR_EXPRESSION "${TALUS_PROGRAM_TEST_FAIL}")
  set_property(DIRECTORY APPEND PROPERTY TALUS_PROGRAM_TESTS ${T_NAME})
  get_property(checkScheduled DIRECTORY PROPERTY TALUS_PROGRAM_TESTS_CHECKED)
  if(NOT checkScheduled)
    set_property(DIRECTORY PROPERTY TALUS_PROGRAM_TESTS_CHECKED ON)
    cmake_language(DEFER CALL talus_check_program_tests)
  endif()
endfunction()

# Run at the end of a directory: a test added there by add_test, or whose fail patterns were
# replaced, would pass whatever its exit status.
function(talus_check_program_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  get_property(programTests DIRECTORY PROPERTY TALUS_PROGRAM_TESTS)
  foreach(test IN LISTS tests)
    if(NOT test IN_LIST programTests)
      message(FATAL_ERROR "test ${test} (${CMAKE_CURRENT_SOURCE_DIR}) was added by add_test, which "
                          "ignores its exit status under PASS_REGULAR_EXPRESSION: add it by "
                          "talus_program_test (Scripts/ProgramTest.cmake) or talus_self_test")
    endif()
    get_test_property(${test} FAIL_REGULAR_EXPRESSION failPatterns)
    foreach(pattern IN LISTS TALUS_PROGRAM_TEST_FAIL)
      if(NOT pattern IN_LIST failPatterns)
        message(FATAL_ERROR "test ${test} (${CMAKE_CURRENT_SOURCE_DIR}): its FAIL_REGULAR_EXPRESSION lost "
                            "'${pattern}': append to it (set_property(TEST ... APPEND ...))")
      endif()
    endforeach()
  endforeach()
endfunction()
