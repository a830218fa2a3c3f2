# SPDX-License-Identifier: MIT
# cross_figures.cmake - the figures of docs/runtime.md for every cross target (cross_print_figures in
# cross_common.cmake): .text bytes per format and instructions per node-sample counted by QEMU. Each
# runtime_c.cross_* test prints its own target's; the bench target admitgen_rt_cross_figures runs this for all.
#   cmake -DSRC_DIR=<repo> -DWORK=<dir> -DINCLUDES=<dir|dir|...> -P cross_figures.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cross_common.cmake)
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(incs -I${SRC_DIR}/runtime/include)
foreach(d IN LISTS include_dirs)
  list(APPEND incs -I${d})
endforeach()

foreach(spec "aarch64:f32,q31,q15" "armhf:f32,q31,q15" "cortex-m4:q31,q15" "cortex-m4-fpu:f32")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 target)
  list(GET spec 1 formats)
  string(REPLACE "," ";" formats "${formats}")
  cross_target(${target} X)
  if(X_MISSING)
    message("${target}: skipped, not installed: ${X_MISSING}")
    continue()
  endif()
  set(work ${WORK}/${target})
  file(REMOVE_RECURSE ${work})
  cross_compile_runtime(X ${SRC_DIR} ${work} objects)
  cross_print_figures(X ${target} "${formats}" ${work} "${objects}" ${incs})
endforeach()
