# SPDX-License-Identifier: MIT
# cmake -DADMITGEN=<exe> -DARGS="emit;...;--out;@OUT@" [-DOUTNAME=<file name>] [-DEXPECTED=<file>] -DWORK=<dir>
#       -P expect_same_output.cmake
# Runs admitgen twice (@OUT@ = WORK/run1/OUTNAME, then WORK/run2/OUTNAME: same file name, since the
# header names itself) and requires byte-identical results, and, if EXPECTED is given, identical to that
# file (committed golden vectors, or the header the build generated).
if(NOT DEFINED OUTNAME)
  set(OUTNAME out)
endif()
foreach(i 1 2)
  file(MAKE_DIRECTORY "${WORK}/run${i}")
  string(REPLACE "@OUT@" "${WORK}/run${i}/${OUTNAME}" args "${ARGS}")
  execute_process(COMMAND ${ADMITGEN} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "admitgen ${args} failed (${rc}): ${out}${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/run1/${OUTNAME}" "${WORK}/run2/${OUTNAME}" RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "two runs of admitgen ${ARGS} differ")
endif()
if(DEFINED EXPECTED)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/run1/${OUTNAME}" "${EXPECTED}" RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "output differs from ${EXPECTED} (diff ${WORK}/run1/${OUTNAME} ${EXPECTED})")
  endif()
endif()
message(STATUS "byte-identical")
