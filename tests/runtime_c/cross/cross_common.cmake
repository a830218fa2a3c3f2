# SPDX-License-Identifier: MIT
# cross_common.cmake - building and running the C runtime on other architectures with Debian's cross
# toolchains and QEMU (docs/runtime.md, "Embedded targets"). Included by run_cross_test.cmake and
# cross_figures.cmake (cmake -P scripts). Targets:
#   aarch64       aarch64-linux-gnu-gcc, static, qemu-aarch64 (user mode); NEON kernels
#   armhf         arm-linux-gnueabihf-gcc (ARMv7-A Thumb-2, VFPv3-D16, no NEON), static, qemu-arm
#   cortex-m4     arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb, soft float (no FPU: q31/q15), bare metal on
#                 qemu-system-arm -M mps2-an386 with semihosting (cortex_m4_startup.S, cortex_m4.ld)
#   cortex-m4-fpu the same with -mfloat-abi=hard -mfpu=fpv4-sp-d16 (f32)

set(CROSS_DIR ${CMAKE_CURRENT_LIST_DIR})
# -ffunction-sections: cross_print_figures links with --gc-sections to measure the code a program really uses.
set(CROSS_STRICT -std=c99 -O2 -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wcast-qual -Wundef -Wshadow
                 -Werror -ffunction-sections -fdata-sections)

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

# Counts the guest instructions a program executes: QEMU translates one instruction per block (-singlestep) and
# logs every block it executes (-d exec,nochain; Debian's QEMU ships no TCG plugins) to a file whose lines are
# counted, then removed. (Not -D /dev/stdout piped to grep: in one run QEMU left a regular log file in place of
# the /dev/stdout link.)
function(cross_count_instructions prefix exe out_var)
  cross_run(${prefix} ${exe} out rc -singlestep -d exec,nochain -D ${exe}.log)
  execute_process(COMMAND grep -c "^Trace" ${exe}.log OUTPUT_VARIABLE n OUTPUT_STRIP_TRAILING_WHITESPACE)
  file(REMOVE ${exe}.log)
  if(NOT n MATCHES "^[1-9][0-9]*$")
    message(FATAL_ERROR "${exe}: counting under QEMU failed (exit status ${rc}, '${n}' instructions)")
  endif()
  set(${out_var} ${n} PARENT_SCOPE)
endfunction()

# Prints, per format of <formats> (f32, q31, q15), the figures of docs/runtime.md for one target: the .text
# bytes of the runtime functions a program of that format links (--gc-sections; libgcc helpers not included,
# the "calls" column names them), and the instructions per node-sample QEMU executes for 1 node (small-n path,
# 32 frames per call) and 64 nodes (block path, 1 frame per call). Two builds of rt_count.c differing only in
# the frame count cancel start-up, I/O and exit: (count(2F) - count(F)) / (F nodes). Printed, not asserted.
# Extra arguments: include flags for rt_count.c (the emitted headers and rt_golden.h).
function(cross_print_figures prefix target formats work objects)
  string(REGEX REPLACE "gcc$" "nm" nm ${${prefix}_CC})
  message("${target}: format  .text B  instructions per node-sample: 1 node / 64 nodes    external calls")
  foreach(name IN LISTS formats)
    set(all_formats f32 q31 q15)
    list(FIND all_formats ${name} idx)
    math(EXPR fmt "${idx} + 1")
    set(counts "")
    foreach(nodes 1 64)
      if(nodes EQUAL 1)
        set(frames 512)
      else()
        set(frames 32)
      endif()
      math(EXPR frames2 "2 * ${frames}")
      foreach(fr ${frames} ${frames2})
        set(exe ${work}/count_${name}_${nodes}_${fr})
        cross_link(${prefix} ${exe} ${CROSS_DIR}/rt_count.c "${objects}" ${ARGN} -DRT_FORMAT=${fmt} -DRT_NODES=${nodes}
                   -DRT_FRAMES=${fr} -Wl,--gc-sections)
        cross_count_instructions(${prefix} ${exe} n_${fr})
      endforeach()
      math(EXPR diff "${n_${frames2}} - ${n_${frames}}")
      math(EXPR per "${diff} / (${frames} * ${nodes})")
      math(EXPR frac "(${diff} * 10 / (${frames} * ${nodes})) % 10")
      list(APPEND counts "${per}.${frac}")
    endforeach()
    execute_process(COMMAND ${nm} -S --defined-only ${work}/count_${name}_64_32 OUTPUT_VARIABLE syms)
    string(REGEX MATCHALL "[0-9a-f]+ [0-9a-f]+ [tT] admitgen_rt[a-z0-9_]*" rt_syms "${syms}")
    set(text 0)
    foreach(sym IN LISTS rt_syms)
      string(REGEX MATCH "^[0-9a-f]+ ([0-9a-f]+)" _ "${sym}")
      math(EXPR text "${text} + 0x${CMAKE_MATCH_1}")
    endforeach()
    # undefined symbols of the runtime objects this format uses: only compiler support routines, no libm/heap
    set(fmt_objects ${objects})
    if(name STREQUAL "f32")
      list(FILTER fmt_objects EXCLUDE REGEX "_q31|_q15|_fixed")
    else()
      list(FILTER fmt_objects EXCLUDE REGEX "_f32|_avx2")
    endif()
    execute_process(COMMAND ${nm} -u ${fmt_objects} OUTPUT_VARIABLE undef)
    string(REGEX MATCHALL "U [A-Za-z0-9_]+" undef "${undef}")
    list(REMOVE_DUPLICATES undef)
    list(FILTER undef EXCLUDE REGEX "admitgen_rt")
    string(REPLACE "U " "" undef "${undef}")
    string(JOIN "," undef ${undef})
    list(GET counts 0 c1)
    list(GET counts 1 c64)
    message("${target}: ${name}     ${text}    ${c1} / ${c64}    ${undef}")
  endforeach()
endfunction()
