# SPDX-License-Identifier: MIT
# Warning flags shared by every target: -Wall -Wextra -Wpedantic everywhere,
# -Wconversion in addition for the C99 runtime (see DEVELOPERS guide).
function(admitgen_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(ADMITGEN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

function(admitgen_strict_c_warnings target)
  admitgen_warnings(${target})
  target_compile_options(${target} PRIVATE -Wconversion -Wsign-conversion -Wcast-qual -Wundef -Wshadow)
endfunction()

# Sanitizer flags for the ASan+UBSan CTest configuration.
set(ADMITGEN_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
# The optimisation of the generator's sanitizer copy (after the build type's -O3, so it wins): -O1, as the
# sanitizers' documentation recommends; instrumented -O3 code took three to four times the plain compile time
# (docs/building.md, "Sanitizers"). The test sources over it are compiled at -O0: their run time is the
# generator's, and -O0 compiles them in less time than -O1.
set(ADMITGEN_SANITIZER_OPTIMIZATION -O1)
set(ADMITGEN_SANITIZER_TEST_OPTIMIZATION -O0)
