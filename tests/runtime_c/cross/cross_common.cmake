# SPDX-License-Identifier: MIT
# cross_common.cmake - building and running the C runtime on other architectures with Debian's cross
# toolchains and QEMU (docs/runtime.md, "Cross-architecture proof"). Included by run_cross_test.cmake and
# cross_figures.cmake (cmake -P scripts). Targets:
#   aarch64       aarch64-linux-gnu-gcc, static, qemu-aarch64 (user mode); NEON kernels
#   armhf         arm-linux-gnueabihf-gcc (ARMv7-A Thumb-2, VFPv3-D16, no NEON), static, qemu-arm
#   cortex-m4     arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb, soft float (no FPU: q31/q15), bare metal on
#                 qemu-system-arm -M mps2-an386 with semihosting (cortex_m4_startup.S, cortex_m4.ld)
#   cortex-m4-fpu the same with -mfloat-abi=hard -mfpu=fpv4-sp-d16 (f32)

set(CROSS_DIR ${CMAKE_CURRENT_LIST_DIR})
set(CROSS_STRICT -std=c99 -O2 -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wcast-qual -Wundef -Wshadow
                 -Werror)

# Sets <prefix>_CC, <prefix>_FLAGS (compile), <prefix>_LINK (extra link arguments), <prefix>_RUN (emulator
# command) and <prefix>_MISSING (names of absent tools, empty if all present) for a target.
function(cross_target target prefix)
  set(flags "")
  set(link "")
  if(target STREQUAL "aarch64")
    set(cc aarch64-linux-gnu-gcc)
    set(emu qemu-aarch64)
    set(link -static)
  elseif(target STREQUAL "armhf")
    set(cc arm-linux-gnueabihf-gcc)
    set(emu qemu-arm)
    set(link -static)
  elseif(target MATCHES "^cortex-m4")
    set(cc arm-none-eabi-gcc)
    set(emu qemu-system-arm)
    set(flags -mcpu=cortex-m4 -mthumb)
    if(target STREQUAL "cortex-m4-fpu")
      list(APPEND flags -mfloat-abi=hard -mfpu=fpv4-sp-d16)
    else()
      list(APPEND flags -mfloat-abi=soft)
    endif()
    set(link --specs=rdimon.specs -nostartfiles -T ${CROSS_DIR}/cortex_m4.ld ${CROSS_DIR}/cortex_m4_startup.S)
  else()
    message(FATAL_ERROR "unknown cross target '${target}' (aarch64, armhf, cortex-m4, cortex-m4-fpu)")
  endif()
  set(missing "")
  find_program(cc_path ${cc} NO_CACHE)
  find_program(emu_path ${emu} NO_CACHE)
  if(NOT cc_path)
    list(APPEND missing ${cc})
  endif()
  if(NOT emu_path)
    list(APPEND missing ${emu})
  endif()
  if(target MATCHES "^cortex-m4" AND cc_path)
    execute_process(COMMAND ${cc_path} ${flags} --specs=rdimon.specs -print-file-name=librdimon.a
                    OUTPUT_VARIABLE rdimon OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT IS_ABSOLUTE "${rdimon}")
      list(APPEND missing libnewlib-arm-none-eabi)
    endif()
  endif()
  if(target MATCHES "^cortex-m4")
    set(run ${emu_path} -M mps2-an386 -nographic -monitor none -serial none -semihosting-config enable=on,target=native
            -kernel)
  else()
    set(run ${emu_path})
  endif()
  set(${prefix}_CC ${cc_path} PARENT_SCOPE)
  set(${prefix}_FLAGS ${flags} PARENT_SCOPE)
  set(${prefix}_LINK ${link} PARENT_SCOPE)
  set(${prefix}_RUN ${run} PARENT_SCOPE)
  set(${prefix}_MISSING ${missing} PARENT_SCOPE)
endfunction()

# Compiles the runtime sources (strict warnings, -Werror) into objects under <work>/rt; sets <out_var> to the
# object list.
function(cross_compile_runtime prefix src_dir work out_var)
  file(GLOB sources ${src_dir}/runtime/src/*.c)
  file(MAKE_DIRECTORY ${work}/rt)
  set(objects "")
  foreach(s IN LISTS sources)
    get_filename_component(name ${s} NAME_WE)
    set(o ${work}/rt/${name}.o)
    execute_process(COMMAND ${${prefix}_CC} ${${prefix}_FLAGS} ${CROSS_STRICT} -I${src_dir}/runtime/include
                            -I${src_dir}/runtime/src -c ${s} -o ${o}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "compiling ${s} for the target failed:\n${out}")
    endif()
    list(APPEND objects ${o})
  endforeach()
  set(${out_var} ${objects} PARENT_SCOPE)
endfunction()

# Links a program from <sources> (C files) and the runtime objects; extra arguments: defines/includes.
function(cross_link prefix exe sources objects)
  execute_process(COMMAND ${${prefix}_CC} ${${prefix}_FLAGS} -std=c99 -O2 -Wall -Wextra -Werror ${ARGN} ${sources}
                          ${objects} ${${prefix}_LINK} -o ${exe}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "linking ${exe} failed:\n${out}")
  endif()
endfunction()

# Runs a program under the target's emulator (extra arguments are QEMU options); sets <out_var> to its output
# and <rc_var> to its exit status.
function(cross_run prefix exe out_var rc_var)
  if(${prefix}_RUN MATCHES "-kernel$")
    set(cmd ${${prefix}_RUN} ${exe} ${ARGN})
  else()
    set(cmd ${${prefix}_RUN} ${ARGN} ${exe})
  endif()
  execute_process(COMMAND ${cmd} TIMEOUT 240 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${rc_var} "${rc}" PARENT_SCOPE)
endfunction()
