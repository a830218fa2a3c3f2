# SPDX-License-Identifier: MIT
# Builds the two Debian packages of the build tree with cpack, unpacks them into a scratch root (dpkg-deb
# -x, as dpkg would install them under /), then uses them the way a user of the packages would:
#   - samples/downstream configured with CMAKE_PREFIX_PATH=<root>/usr: find_package(admitgen),
#     admitgen_add_boundary() runs the packaged admitgen, the program links the packaged runtime, runs;
#   - the same program compiled by hand with `pkg-config --cflags --libs admitgen_rt` from the package;
#   - `man admitgen-fit` with MANPATH=<root>/usr/share/man; the packaged bash completion loads.
include(${CMAKE_CURRENT_LIST_DIR}/../script_support.cmake)
require_variables(SOURCE_DIR BINARY_DIR WORK_DIR CMAKE_GENERATOR CMAKE_MAKE_PROGRAM C_COMPILER)
file(REMOVE_RECURSE "${WORK_DIR}")

get_filename_component(cmake_bin "${CMAKE_COMMAND}" DIRECTORY)
run("${cmake_bin}/cpack" -G DEB --config "${BINARY_DIR}/CPackConfig.cmake" -B "${WORK_DIR}/packages")
file(GLOB debs "${WORK_DIR}/packages/*.deb")
list(LENGTH debs n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "expected two .deb files, cpack wrote: ${debs}")
endif()
set(root "${WORK_DIR}/root")
foreach(deb IN LISTS debs)
  run(dpkg-deb --field "${deb}" Package Version Depends)
  message(STATUS "${deb}:\n${out}")
  if(deb MATCHES "/admitgen_[^/]*\\.deb$" AND NOT out MATCHES "Depends: [^\n]*libadmitgen-rt-dev \\(= ")
    message(FATAL_ERROR "the generator package does not depend on libadmitgen-rt-dev:\n${out}")
  endif()
  run(dpkg-deb -x "${deb}" "${root}")
endforeach()
foreach(f usr/bin/admitgen usr/include/admitgen_rt.h usr/lib/pkgconfig/admitgen_rt.pc
          usr/share/man/man1/admitgen-fit.1 usr/share/bash-completion/completions/admitgen)
  if(NOT EXISTS "${root}/${f}")
    message(FATAL_ERROR "the packages do not install /${f}")
  endif()
endforeach()

# samples/downstream against the packages (the packaged admitgen generates the header at build time).
set(prefix "${root}/usr")
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/samples/downstream" -B "${WORK_DIR}/downstream" -G "${CMAKE_GENERATOR}"
    "-DCMAKE_MAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}" "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_PREFIX_PATH=${prefix}"
    -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS "${WORK_DIR}/downstream/CMakeCache.txt" dir_line REGEX "^admitgen_DIR:")
if(NOT dir_line MATCHES "${root}")
  message(FATAL_ERROR "samples/downstream found another admitgen: ${dir_line}")
endif()
run(${CMAKE_COMMAND} --build "${WORK_DIR}/downstream")
run("${WORK_DIR}/downstream/downstream")

# The same program by hand with pkg-config, against the header generated above.
run(${CMAKE_COMMAND} -E env "PKG_CONFIG_PATH=${prefix}/lib/pkgconfig" pkg-config --cflags --libs admitgen_rt)
string(STRIP "${out}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
if(NOT flags MATCHES "${root}")
  message(FATAL_ERROR "admitgen_rt.pc does not point into the package root: ${flags}")
endif()
run("${C_COMPILER}" -std=c99 "-I${WORK_DIR}/downstream/admitgen_boundary/wall" "${SOURCE_DIR}/samples/downstream/main.c"
    ${flags} -o "${WORK_DIR}/downstream_pkg_config")
run("${WORK_DIR}/downstream_pkg_config")

# man admitgen-fit from the package, and the packaged completion.
run(${CMAKE_COMMAND} -E env "MANPATH=${prefix}/share/man" MANWIDTH=100 man -P cat admitgen-fit)
if(NOT out MATCHES "admitgen-fit +- " OR NOT out MATCHES "--live")
  message(FATAL_ERROR "man admitgen-fit did not render the page:\n${out}")
endif()
run(bash --norc --noprofile -c "source '${prefix}/share/bash-completion/completions/admitgen' && complete -p admitgen")
message(STATUS "packages: downstream (CMake and pkg-config), man admitgen-fit and completion OK")
