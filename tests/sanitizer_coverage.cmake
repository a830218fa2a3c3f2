# SPDX-License-Identifier: MIT
# CTest job sanitizers.asan_ubsan (tests/CMakeLists.txt): with ADMITGEN_SANITIZERS=ON every doctest case
# outside the suite "statistical" is its own CTest entry on the executable built with ASan + UBSan
# (SANITIZED), and the statistical cases run on the plain build (RELEASE), which is compiled only from the
# test sources that hold them (docs/building.md, "Sanitizers"). This job checks that arrangement: the
# sanitized executable is instrumented for both sanitizers, and the plain one holds every statistical case
# (a source that gained one since CMake last ran would otherwise lose it).
function(list_cases out exe)
  execute_process(COMMAND "${exe}" --list-test-cases ${ARGN} OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${exe} --list-test-cases ${ARGN} failed (${rc})")
  endif()
  string(REPLACE "\n" ";" lines "${text}")
  list(FILTER lines EXCLUDE REGEX "^(\\[doctest\\]|====|$)")
  list(SORT lines)
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

foreach(marker __asan_report_ __ubsan_handle_)
  file(STRINGS "${SANITIZED}" hits REGEX "${marker}" LIMIT_COUNT 1)
  if(NOT hits)
    message(FATAL_ERROR "${SANITIZED} is not instrumented (no ${marker} symbol)")
  endif()
endforeach()
list_cases(statistical_sanitized "${SANITIZED}" --test-suite=statistical)
list_cases(statistical_release "${RELEASE}" --test-suite=statistical)
list_cases(under_sanitizers "${SANITIZED}" --test-suite-exclude=statistical)
if(NOT statistical_sanitized STREQUAL statistical_release)
  message(FATAL_ERROR "The plain test executable does not hold every statistical case: re-run CMake\n"
                      "  expected: ${statistical_sanitized}\n  found:    ${statistical_release}")
endif()
list(LENGTH under_sanitizers n_sanitized)
list(LENGTH statistical_release n_statistical)
message(STATUS "${n_sanitized} test cases run under ASan + UBSan as their own CTest entries; "
               "${n_statistical} statistical cases run on the plain build")
