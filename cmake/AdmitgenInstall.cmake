# SPDX-License-Identifier: MIT
# Installation in two components, one Debian package each (cmake/AdmitgenPackaging.cmake):
#   runtime    the C99 runtime: static library, headers, pkg-config file admitgen_rt.pc, and the CMake
#              package admitgenConfig.cmake with admitgen::runtime           -> libadmitgen-rt-dev
#   generator  the admitgen executable, the header template, admitgen_add_boundary(), man pages and
#              bash completion                                              -> admitgen
# The CMake package is one: find_package(admitgen) requires both components, find_package(admitgen
# COMPONENTS runtime) only the runtime (cmake/admitgenConfig.cmake.in).
include(CMakePackageConfigHelpers)
set(ADMITGEN_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/admitgen)
set(ADMITGEN_INSTALL_TEMPLATEDIR ${CMAKE_INSTALL_DATADIR}/admitgen/templates)

# --- runtime
install(TARGETS admitgen_rt EXPORT admitgenRuntimeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY runtime/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT runtime
        FILES_MATCHING PATTERN "*.h")
install(EXPORT admitgenRuntimeTargets NAMESPACE admitgen:: DESTINATION ${ADMITGEN_INSTALL_CMAKEDIR}
        COMPONENT runtime)
configure_package_config_file(cmake/admitgenConfig.cmake.in ${PROJECT_BINARY_DIR}/admitgenConfig.cmake
                              INSTALL_DESTINATION ${ADMITGEN_INSTALL_CMAKEDIR}
                              PATH_VARS ADMITGEN_INSTALL_TEMPLATEDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/admitgenConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/admitgenConfig.cmake ${PROJECT_BINARY_DIR}/admitgenConfigVersion.cmake
        DESTINATION ${ADMITGEN_INSTALL_CMAKEDIR} COMPONENT runtime)

# admitgen_rt.pc is relocatable: its prefix is found from the file's own directory (${pcfiledir}), so the
# package works from any root (dpkg -x, a staging directory) as well as from the configured prefix.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(ADMITGEN_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH ADMITGEN_PC_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  set(ADMITGEN_PC_PREFIX "\${pcfiledir}/${ADMITGEN_PC_PREFIX}")
endif()
configure_file(packaging/admitgen_rt.pc.in ${PROJECT_BINARY_DIR}/admitgen_rt.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/admitgen_rt.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT runtime)
# Documentation in /usr/share/doc/<Debian package name>/ as Debian does it.
# (the licence also as "copyright", the name Debian looks for).
install(FILES LICENSE THIRD_PARTY_NOTICES.md CHANGELOG.md docs/versioning.md
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/libadmitgen-rt-dev COMPONENT runtime)
install(FILES LICENSE RENAME copyright DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/libadmitgen-rt-dev COMPONENT runtime)

# --- generator
if(ADMITGEN_BUILD_GENERATOR)
  install(TARGETS admitgen EXPORT admitgenGeneratorTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT generator)
  install(EXPORT admitgenGeneratorTargets NAMESPACE admitgen:: DESTINATION ${ADMITGEN_INSTALL_CMAKEDIR}
          COMPONENT generator)
  install(FILES templates/admitgen_boundary.h.in DESTINATION ${ADMITGEN_INSTALL_TEMPLATEDIR} COMPONENT generator)
  install(FILES cmake/AdmitgenBoundary.cmake DESTINATION ${ADMITGEN_INSTALL_CMAKEDIR} COMPONENT generator)
  install(FILES LICENSE THIRD_PARTY_NOTICES.md CHANGELOG.md docs/versioning.md
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/admitgen COMPONENT generator)
  install(FILES LICENSE RENAME copyright DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/admitgen COMPONENT generator)
endif()
