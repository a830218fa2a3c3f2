# SPDX-License-Identifier: MIT
# Debian packages with CPack: `cpack -G DEB` in the build tree writes
#   admitgen_<version>_<arch>.deb            the generator (component "generator"); depends on the next one,
#                                            since admitgen_add_boundary() links the runtime
#   libadmitgen-rt-dev_<version>_<arch>.deb  the C99 runtime for development (component "runtime")
# A runtime-only build (ADMITGEN_BUILD_GENERATOR=OFF) packages the runtime alone. The generator's
# shared-library dependencies (libfmt, libcrypto, libstdc++) come from dpkg-shlibdeps.
set(ADMITGEN_PACKAGE_CONTACT "admitgen maintainers <maintainers@users.noreply.h-seed-0d9a380f.example>"
    CACHE STRING "Maintainer field of the Debian packages")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME admitgen)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${ADMITGEN_PACKAGE_CONTACT}")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY "${PROJECT_BINARY_DIR}/packages")
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME libadmitgen-rt-dev)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION libdevel)
# CPackDeb puts the project description first (the short description); these texts follow it.
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
    "C99 runtime of the boundary filters, development files: recursive-convolution filters in float, Q31 and Q15 for the headers that admitgen emit writes: no heap, no libm, no dependency. Static library, header, pkg-config file admitgen_rt.pc and the CMake package admitgen (component runtime).")
if(ADMITGEN_BUILD_GENERATOR)
  set(CPACK_COMPONENTS_ALL runtime generator)
  set(CPACK_DEBIAN_GENERATOR_PACKAGE_NAME admitgen)
  set(CPACK_DEBIAN_GENERATOR_PACKAGE_SHLIBDEPS ON)
  set(CPACK_DEBIAN_GENERATOR_PACKAGE_DEPENDS "libadmitgen-rt-dev (= ${PROJECT_VERSION})")
  set(CPACK_COMPONENT_GENERATOR_DESCRIPTION
      "admitgen fits multipole admittance models to impedance-tube data, selects the order by Bayesian evidence (nested sampling), emits causal C99 boundary filters for wave solvers and audio engines, and proves them stable and passive.")
else()
  set(CPACK_COMPONENTS_ALL runtime)
endif()
include(CPack)
