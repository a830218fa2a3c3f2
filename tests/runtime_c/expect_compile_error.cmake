# SPDX-License-Identifier: MIT
# cmake -DCC=<c compiler> -DINCLUDES="<dir>;<dir>" -DHEADER=<generated header> -DDEFINE=<macro=value>
#       -DMUTATE_FROM=<text> -DMUTATE_TO=<text> -DEXPECT=<regex> -DWORK=<dir> -P expect_compile_error.cmake
# Compiles a one-line C file including HEADER (optionally a copy with MUTATE_FROM replaced by MUTATE_TO,
# simulating a header from another generator) and succeeds only if compilation FAILS with output
# matching EXPECT: proves that a mismatched sample rate or ABI cannot slip through.
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(name "${HEADER}" NAME)
file(READ "${HEADER}" text)
if(DEFINED MUTATE_FROM)
  string(FIND "${text}" "${MUTATE_FROM}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "'${MUTATE_FROM}' not found in ${HEADER}")
  endif()
  string(REPLACE "${MUTATE_FROM}" "${MUTATE_TO}" text "${text}")
endif()
file(WRITE "${WORK}/${name}" "${text}")
file(WRITE "${WORK}/use.c" "#include \"${name}\"\nint main(void) { return 0; }\n")
set(flags -std=c99 -fsyntax-only -I${WORK})
foreach(dir IN LISTS INCLUDES)
  list(APPEND flags -I${dir})
endforeach()
if(DEFINED DEFINE)
  list(APPEND flags -D${DEFINE})
endif()
execute_process(COMMAND ${CC} ${flags} ${WORK}/use.c RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "compilation succeeded but must fail (${DEFINE} ${MUTATE_TO})")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "compilation failed without the expected message '${EXPECT}':\n${out}${err}")
endif()
message(STATUS "failed as expected: ${EXPECT}")
