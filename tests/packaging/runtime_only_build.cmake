# SPDX-License-Identifier: MIT
# Configures, builds and installs the runtime alone (ADMITGEN_BUILD_GENERATOR=OFF) with a C compiler and
# nothing else visible to CMake: PATH holds only the C compiler and the assembler and linker it runs
# (no c++, g++, pkg-config, python), CMAKE_CXX_COMPILER names a file that
# does not exist, and every generator dependency is disabled (find_package of any of them would fail the
# configure). Then a C-only consumer finds the installed package with find_package(admitgen COMPONENTS
# runtime), links admitgen::runtime and runs; find_package(admitgen) without components must fail there,
# because the generator is not installed.
include(${CMAKE_CURRENT_LIST_DIR}/../script_support.cmake)
require_variables(SOURCE_DIR WORK_DIR CMAKE_GENERATOR CMAKE_MAKE_PROGRAM C_COMPILER)
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/bin")
get_filename_component(cc_name "${C_COMPILER}" NAME)
file(CREATE_LINK "${C_COMPILER}" "${WORK_DIR}/bin/${cc_name}" SYMBOLIC)
foreach(tool as ld)
  execute_process(COMMAND "${C_COMPILER}" -print-prog-name=${tool} OUTPUT_VARIABLE path OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT IS_ABSOLUTE "${path}")
    find_program(path_${tool} ${tool} REQUIRED)
    set(path "${path_${tool}}")
  endif()
  file(CREATE_LINK "${path}" "${WORK_DIR}/bin/${tool}" SYMBOLIC)
endforeach()
set(env ${CMAKE_COMMAND} -E env "PATH=${WORK_DIR}/bin" --unset=CXX --unset=CC
    --unset=CMAKE_C_COMPILER_LAUNCHER --unset=CMAKE_CXX_COMPILER_LAUNCHER)  # a launcher (ccache) is not on that PATH

set(disabled)
foreach(pkg Eigen3 CLI11 nlohmann_json fmt OpenSSL Threads doctest PkgConfig Python3)
  list(APPEND disabled -DCMAKE_DISABLE_FIND_PACKAGE_${pkg}=ON)
endforeach()

set(prefix "${WORK_DIR}/install")
run(${env} ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}/build" -G "${CMAKE_GENERATOR}"
    "-DCMAKE_MAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
    "-DCMAKE_CXX_COMPILER=${WORK_DIR}/no-such-c++-compiler" -DADMITGEN_BUILD_GENERATOR=OFF -DADMITGEN_WERROR=ON
    "-DCMAKE_INSTALL_PREFIX=${prefix}" ${disabled})
file(STRINGS "${WORK_DIR}/build/CMakeCache.txt" cxx_lines REGEX "^CMAKE_CXX_COMPILER_LOADED|Eigen3_DIR:")
file(GLOB cxx_files "${WORK_DIR}/build/CMakeFiles/*/CMakeCXXCompiler.cmake")
if(cxx_files)
  message(FATAL_ERROR "the runtime-only configure enabled C++: ${cxx_files}")
endif()
run(${env} ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run(${env} ${CMAKE_COMMAND} --install "${WORK_DIR}/build")
foreach(f include/admitgen_rt.h lib/libadmitgen_rt.a lib/pkgconfig/admitgen_rt.pc lib/cmake/admitgen/admitgenConfig.cmake)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "the runtime-only install lacks ${f}")
  endif()
endforeach()
if(EXISTS "${prefix}/bin/admitgen")
  message(FATAL_ERROR "the runtime-only install holds the generator")
endif()

set(consumer "${CMAKE_CURRENT_LIST_DIR}/runtime_consumer")
run(${env} ${CMAKE_COMMAND} -S "${consumer}" -B "${WORK_DIR}/consumer" -G "${CMAKE_GENERATOR}"
    "-DCMAKE_MAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}" "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_PREFIX_PATH=${prefix}")
run(${env} ${CMAKE_COMMAND} --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/runtime_consumer")

execute_process(COMMAND ${env} ${CMAKE_COMMAND} -S "${consumer}" -B "${WORK_DIR}/consumer_all" -G "${CMAKE_GENERATOR}"
                        "-DCMAKE_MAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
                        "-DCMAKE_PREFIX_PATH=${prefix}" -DREQUIRE_ALL_COMPONENTS=ON
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0 OR NOT out MATCHES "generator")
  message(FATAL_ERROR "find_package(admitgen) without the generator installed did not fail naming it:\n${out}")
endif()
message(STATUS "runtime-only build, install and C consumer: OK")
