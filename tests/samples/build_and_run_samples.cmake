# SPDX-License-Identifier: MIT
# CTest driver: install admitgen into a scratch prefix, then configure, build and run the two sample
# integrations exactly as a downstream user would (find_package(admitgen) + admitgen_add_boundary).
# Invoked with -DSOURCE_DIR=... -DBINARY_DIR=... -DWORK_DIR=...
foreach(var SOURCE_DIR BINARY_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/install")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BINARY_DIR}" --prefix "${prefix}" COMMAND_ERROR_IS_FATAL ANY)
foreach(sample downstream engine_example)
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/samples/${sample}" -B "${WORK_DIR}/${sample}"
                          "-DCMAKE_PREFIX_PATH=${prefix}" COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK_DIR}/${sample}" COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND "${WORK_DIR}/${sample}/${sample}" COMMAND_ERROR_IS_FATAL ANY)
endforeach()
