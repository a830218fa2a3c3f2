# SPDX-License-Identifier: MIT
# Included by CTest (TEST_INCLUDE_FILES, tests/CMakeLists.txt): one CTest entry per doctest case of
# ADMITGEN_CASES_EXE that ADMITGEN_CASES_FILTER selects (doctest options, e.g. --test-suite=statistical),
# run as doctest_discover_tests runs them (--test-case=<name>, commas escaped), with WORKING_DIRECTORY
# ADMITGEN_CASES_WORKING_DIRECTORY, LABELS ADMITGEN_CASES_LABELS and ENVIRONMENT ADMITGEN_CASES_ENVIRONMENT.
# An executable that is not built yet gives the failing entry <name>_NOT_BUILT (unless
# ADMITGEN_CASES_MISSING_REPORTED: another registration of the same executable gives it).
execute_process(COMMAND "${ADMITGEN_CASES_EXE}" --list-test-cases ${ADMITGEN_CASES_FILTER}
                OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  if(NOT ADMITGEN_CASES_MISSING_REPORTED)
    get_filename_component(exe_name "${ADMITGEN_CASES_EXE}" NAME)
    add_test("${exe_name}_NOT_BUILT" "${ADMITGEN_CASES_EXE}")
  endif()
  return()
endif()
string(REPLACE "\n" ";" lines "${out}")
foreach(line IN LISTS lines)
  if(line STREQUAL "" OR line MATCHES "^(\\[doctest\\]|====)")
    continue()
  endif()
  string(REPLACE "," "\\," filter "${line}")
  add_test("${line}" "${ADMITGEN_CASES_EXE}" "--test-case=${filter}")
  set_tests_properties("${line}" PROPERTIES WORKING_DIRECTORY "${ADMITGEN_CASES_WORKING_DIRECTORY}")
  if(ADMITGEN_CASES_LABELS)
    set_tests_properties("${line}" PROPERTIES LABELS "${ADMITGEN_CASES_LABELS}")
  endif()
  if(ADMITGEN_CASES_ENVIRONMENT)
    set_tests_properties("${line}" PROPERTIES ENVIRONMENT "${ADMITGEN_CASES_ENVIRONMENT}")
  endif()
endforeach()
