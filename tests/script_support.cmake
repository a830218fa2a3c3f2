# SPDX-License-Identifier: MIT
# Helpers of the CTest driver scripts that run with `cmake -P`.

# Fails unless every named variable was passed with -D.
function(require_variables)
  foreach(var IN LISTS ARGN)
    if(NOT DEFINED ${var})
      message(FATAL_ERROR "${var} is not set")
    endif()
  endforeach()
endfunction()

# Runs a command. When it exits non-zero, the test fails and shows the command and its output.
# Otherwise the output (stdout and stderr together) is left in `out` in the caller's scope.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
