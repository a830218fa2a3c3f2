# SPDX-License-Identifier: MIT
# run_cross_test.cmake - CTest driver: builds the runtime and tests/runtime_c/rt_bitexact.c (armhf: also rt_misuse.c) for one target
# with its Debian cross toolchain and runs it under QEMU (cross_common.cmake). Passes when the program exits 0
# and prints "PASS (0 failures)"; then prints the target's .text bytes and QEMU instruction counts per format. Without the toolchain or QEMU it prints ADMITGEN_CROSS_SKIPPED (CTest marks
# the test skipped) and names the packages; .ci/install-deps installs them.
#   cmake -DTARGET=<target> -DSRC_DIR=<repo> -DWORK=<dir> -DINCLUDES=<dir|dir|...> -DFORMATS=<fixed|f32|all>
#         -P run_cross_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cross_common.cmake)

cross_target(${TARGET} X)
if(X_MISSING)
  message("ADMITGEN_CROSS_SKIPPED: ${TARGET}: not installed: ${X_MISSING} (run .ci/install-deps: gcc-aarch64-linux-gnu "
          "gcc-arm-linux-gnueabihf gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-user qemu-system-arm)")
  return()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
cross_compile_runtime(X ${SRC_DIR} ${WORK} objects)
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(args "")
foreach(d IN LISTS include_dirs)
  list(APPEND args -I${d})
endforeach()
if(FORMATS STREQUAL "fixed" OR FORMATS STREQUAL "all")
  list(APPEND args -DRT_WITH_FIXED=1)
endif()
if(FORMATS STREQUAL "f32" OR FORMATS STREQUAL "all")
  list(APPEND args -DRT_WITH_F32=1)
endif()
cross_link(X ${WORK}/rt_bitexact ${SRC_DIR}/tests/runtime_c/rt_bitexact.c "${objects}" -I${SRC_DIR}/runtime/include
           -I${SRC_DIR}/runtime/src ${args})
cross_run(X ${WORK}/rt_bitexact out rc)
string(JOIN " " flags ${X_FLAGS})
message("${TARGET} (${X_CC} ${flags} -O2):\n${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "PASS \\(0 failures\\)")
  message(FATAL_ERROR "${TARGET}: the runtime proof failed (exit status ${rc})")
endif()
# The target's figures (docs/runtime.md, "Embedded targets"): .text bytes and QEMU instruction counts.
set(figure_formats f32 q31 q15)
if(FORMATS STREQUAL "fixed")
  set(figure_formats q31 q15)
elseif(FORMATS STREQUAL "f32")
  set(figure_formats f32)
endif()
cross_print_figures(X ${TARGET} "${figure_formats}" ${WORK} "${objects}" -I${SRC_DIR}/runtime/include ${args})
# Limits and misuse (tests/runtime_c/rt_misuse.c) where size_t has 32 bits: the state size of 64 pairs at
# ADMITGEN_RT_MAX_NODES nodes overflows it, and init must say ADMITGEN_RT_TOO_LARGE.
string(COMPARE EQUAL "${TARGET}" armhf is_armhf)  # (if(TARGET ...) would test for a CMake target)
if(is_armhf)
  cross_link(X ${WORK}/rt_misuse ${SRC_DIR}/tests/runtime_c/rt_misuse.c "${objects}" -I${SRC_DIR}/runtime/include
             -I${SRC_DIR}/runtime/src ${args})
  cross_run(X ${WORK}/rt_misuse out rc)
  message("${TARGET} rt_misuse:\n${out}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "PASS \\(0 failures\\)")
    message(FATAL_ERROR "${TARGET}: the limits-and-misuse test failed (exit status ${rc})")
  endif()
endif()
