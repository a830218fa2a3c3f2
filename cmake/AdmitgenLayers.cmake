# SPDX-License-Identifier: MIT
# The generator's layers, read from generator/layers.txt (the one declaration; docs/architecture.md).
# Used by the build (generator/CMakeLists.txt) and, in script mode, by tools/check-layers.
#
#   admitgen_read_layers(<table> <source-dir>)
#       Parses the table and checks it (known names, every arrow points to a layer declared above, no
#       layer twice). Sets in the caller: ADMITGEN_EXTERNAL_LAYERS (runtime), ADMITGEN_LAYERS (all,
#       lowest first), ADMITGEN_PRESENT_LAYERS
#       (those whose folder exists under <source-dir>), and for each layer L
#       ADMITGEN_LAYER_<L>_PUBLIC / ADMITGEN_LAYER_<L>_PRIVATE (lists of layers or "runtime").
#
#   admitgen_add_layer_libraries(<suffix> <include-root> [LAYER_OPTIMIZATION] [OPTIMIZATION <flag>...]
#                                [COMPILE_OPTIONS <flag>...] [LINK_OPTIONS <flag>...])
#       One library admitgen_layer_<L><suffix> per present layer, linked to the libraries of the
#       layers it may use, PUBLIC or PRIVATE as declared, and an INTERFACE aggregate
#       admitgen_core<suffix> over all of them. A layer's include directory is <include-root>/<L>, which
#       holds a single link <L> -> generator/<L>: `#include "L/x.hpp"` resolves only in a target that
#       links admitgen_layer_<L>, so an include of a layer that is not below fails to compile.
#       COMPILE_OPTIONS and LINK_OPTIONS are flags of the whole set and of everything that
#       links it (the sanitizers), carried by the INTERFACE target admitgen_flags<suffix>. OPTIMIZATION
#       flags are the layers' own, after the build type's: what links the set chooses its own level.
#       Per layer, the caller may set ADMITGEN_LAYER_<L>_EXTRA_SOURCES (generated sources),
#       ADMITGEN_LAYER_<L>_EXTRA_INCLUDES, ADMITGEN_LAYER_<L>_EXTRA_LIBS (PUBLIC),
#       ADMITGEN_LAYER_<L>_EXCLUDE (a regex of sources left out, e.g. an executable's main) and
#       ADMITGEN_LAYER_<L>_UNITY_BATCH (with ADMITGEN_UNITY_BUILD, a unity build of the layer, this many
#       sources per unit). With LAYER_OPTIMIZATION, ADMITGEN_LAYER_<L>_OPTIMIZATION (e.g. -O1) is the
#       layer's optimisation in a Release build, after the build type's -O3 so that it wins. The
#       libraries are EXCLUDE_FROM_ALL: a build compiles the layers that what it builds links (the
#       default build: the CLI's). Build cost: docs/building.md, "Where build time goes".
#
#   admitgen_link_as_layer_source(<target> <layer> <suffix>)   (build only)
#       Links <target> as if its sources were sources of <layer>: the layer's library, its private
#       layers and admitgen_layer_json (the tests' probes of tests/layers/).
#
#   admitgen_layer_json(<target> <layer>)   (build only)
#       nlohmann_json is the io layer's alone (docs/architecture.md, "JSON only in io"): a source of io
#       links it (PRIVATE), a source of any other layer finds cmake/json_outside_io/nlohmann/json.hpp first,
#       whose #error stops the compilation (the system's header, in a default include directory, would
#       otherwise resolve in any target). What links the aggregate (tests) gets neither.
include_guard(GLOBAL)

function(admitgen_read_layers table source_dir)
  set(ADMITGEN_EXTERNAL_LAYERS runtime)  # not folders of generator/: the C99 runtime
  set(ADMITGEN_EXTERNAL_LAYERS ${ADMITGEN_EXTERNAL_LAYERS} PARENT_SCOPE)
  file(STRINGS ${table} rows)
  set(layers "")
  set(present "")
  foreach(row IN LISTS rows)
    if(row MATCHES "^[ \t]*(#|$)")
      continue()
    endif()
    if(NOT row MATCHES "^[ \t]*([a-z_]+)[ \t]*\\|([a-z_ \t]*)\\|([a-z_ \t]*)$")
      message(FATAL_ERROR "${table}: cannot read the row '${row}' (expected: layer | public ... | private ...)")
    endif()
    set(layer ${CMAKE_MATCH_1})
    set(public_text "${CMAKE_MATCH_2}")
    set(private_text "${CMAKE_MATCH_3}")  # string(REGEX) below resets CMAKE_MATCH_<n>
    string(REGEX MATCHALL "[a-z_]+" public "${public_text}")
    string(REGEX MATCHALL "[a-z_]+" private "${private_text}")
    if(layer IN_LIST layers OR layer IN_LIST ADMITGEN_EXTERNAL_LAYERS)
      message(FATAL_ERROR "${table}: layer '${layer}' is declared twice")
    endif()
    foreach(dep IN LISTS public private)
      if(NOT dep IN_LIST layers AND NOT dep IN_LIST ADMITGEN_EXTERNAL_LAYERS)
        message(FATAL_ERROR "${table}: layer '${layer}' may use '${dep}', which is not a layer declared above it "
                            "(arrows point down the table only)")
      endif()
    endforeach()
    foreach(dep IN LISTS public)
      if(dep IN_LIST private)
        message(FATAL_ERROR "${table}: layer '${layer}' names '${dep}' both public and private")
      endif()
    endforeach()
    list(APPEND layers ${layer})
    if(IS_DIRECTORY ${source_dir}/${layer})
      list(APPEND present ${layer})
    endif()
    set(ADMITGEN_LAYER_${layer}_PUBLIC "${public}" PARENT_SCOPE)
    set(ADMITGEN_LAYER_${layer}_PRIVATE "${private}" PARENT_SCOPE)
  endforeach()
  # Every folder of generator/ holding sources is a declared layer.
  file(GLOB entries LIST_DIRECTORIES true RELATIVE ${source_dir} ${source_dir}/*)
  foreach(entry IN LISTS entries)
    if(IS_DIRECTORY ${source_dir}/${entry} AND NOT entry IN_LIST layers)
      file(GLOB_RECURSE sources ${source_dir}/${entry}/*.cpp ${source_dir}/${entry}/*.hpp)
      if(sources)
        message(FATAL_ERROR "generator/${entry}/ is not a declared layer: add a row for it to ${table}")
      endif()
    endif()
  endforeach()
  set(ADMITGEN_LAYERS "${layers}" PARENT_SCOPE)
  set(ADMITGEN_PRESENT_LAYERS "${present}" PARENT_SCOPE)
endfunction()

if(NOT CMAKE_SCRIPT_MODE_FILE)
  # The targets that provide the layers `deps` (layer names or "runtime"), for the layer set `suffix`.
  function(admitgen_layer_targets out suffix)
    set(targets "")
    foreach(dep IN LISTS ARGN)
      if(dep STREQUAL "runtime")
        list(APPEND targets admitgen_rt)
      elseif(dep IN_LIST ADMITGEN_PRESENT_LAYERS)
        list(APPEND targets admitgen_layer_${dep}${suffix})
      endif()
    endforeach()
    set(${out} ${targets} PARENT_SCOPE)
  endfunction()

  function(admitgen_add_layer_libraries suffix include_root)
    cmake_parse_arguments(ARG "LAYER_OPTIMIZATION" "" "OPTIMIZATION;COMPILE_OPTIONS;LINK_OPTIONS" ${ARGN})
    set(aggregate admitgen_core${suffix})
    add_library(${aggregate} INTERFACE)
    set(flags admitgen_flags${suffix})
    add_library(${flags} INTERFACE)
    target_compile_options(${flags} INTERFACE ${ARG_COMPILE_OPTIONS})
    target_link_options(${flags} INTERFACE ${ARG_LINK_OPTIONS})
    foreach(layer IN LISTS ADMITGEN_PRESENT_LAYERS)
      set(target admitgen_layer_${layer}${suffix})
      file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${layer}/*.cpp)
      if(ADMITGEN_LAYER_${layer}_EXCLUDE)
        list(FILTER sources EXCLUDE REGEX "${ADMITGEN_LAYER_${layer}_EXCLUDE}")
      endif()
      list(APPEND sources ${ADMITGEN_LAYER_${layer}_EXTRA_SOURCES})
      admitgen_layer_targets(public_targets "${suffix}" ${ADMITGEN_LAYER_${layer}_PUBLIC})
      admitgen_layer_targets(private_targets "${suffix}" ${ADMITGEN_LAYER_${layer}_PRIVATE})
      if(sources)
        add_library(${target} STATIC EXCLUDE_FROM_ALL ${sources})
        admitgen_warnings(${target})
        set(usage PUBLIC)
        target_link_libraries(${target} PRIVATE ${private_targets})
        target_compile_options(${target} PRIVATE ${ARG_OPTIMIZATION})
        if(ARG_LAYER_OPTIMIZATION AND ADMITGEN_LAYER_${layer}_OPTIMIZATION)
          target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:${ADMITGEN_LAYER_${layer}_OPTIMIZATION}>)
        endif()
        if(ADMITGEN_UNITY_BUILD AND ADMITGEN_LAYER_${layer}_UNITY_BATCH)
          set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                                UNITY_BUILD_BATCH_SIZE ${ADMITGEN_LAYER_${layer}_UNITY_BATCH})
        endif()
      else()  # headers only: nothing is private
        add_library(${target} INTERFACE)
        set(usage INTERFACE)
        list(APPEND public_targets ${private_targets})
      endif()
      target_include_directories(${target} ${usage} ${include_root}/${layer} ${ADMITGEN_LAYER_${layer}_EXTRA_INCLUDES})
      target_link_libraries(${target} ${usage} ${flags} ${public_targets} Eigen3::Eigen fmt::fmt
                                               OpenSSL::Crypto Threads::Threads ${ADMITGEN_LAYER_${layer}_EXTRA_LIBS})
      if(sources)
        admitgen_layer_json(${target} ${layer})
      endif()
      target_link_libraries(${aggregate} INTERFACE ${target})
    endforeach()
  endfunction()

  function(admitgen_link_as_layer_source target layer suffix)
    admitgen_layer_targets(private_targets "${suffix}" ${ADMITGEN_LAYER_${layer}_PRIVATE})
    target_link_libraries(${target} PRIVATE admitgen_layer_${layer}${suffix} ${private_targets})
    admitgen_layer_json(${target} ${layer})
  endfunction()

  function(admitgen_layer_json target layer)
    if(layer STREQUAL "io")
      target_link_libraries(${target} PRIVATE nlohmann_json::nlohmann_json)
    else()
      target_include_directories(${target} BEFORE PRIVATE ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/json_outside_io)
    endif()
  endfunction()
endif()
