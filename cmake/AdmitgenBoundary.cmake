# SPDX-License-Identifier: MIT
# admitgen_add_boundary(<target>
#     FIT <fit.json> FS <hz> [<hz>...] FORMAT <f32|q31|q15>
#     [NAME <c-identifier>] [ORDER <QxSy>] [ESTIMATE passive|mean|max_likelihood] [FIR_TAPS <n>]
#     [BANDS_JSON <file>] [FIDELITY_TOLERANCE <x>] [ALLOW_UNSAFE] [NO_PASSIVITY_ENFORCEMENT])
#
# Runs `admitgen emit` at build time and creates an INTERFACE library <target> that provides the
# generated header <NAME>.h (NAME defaults to <target>) and links the C99 runtime (admitgen::runtime).
# The header is regenerated when the fit, the admitgen executable or the header template change.
# Sets the target property ADMITGEN_HEADER to the header's path. emit refuses a filter that fails
# `admitgen check` (the build then fails); ALLOW_UNSAFE passes --allow-unsafe (say why next to it).
# FIDELITY_TOLERANCE passes --fidelity-tolerance (the largest deviation of the filter from its model in band).
# NO_PASSIVITY_ENFORCEMENT passes --no-passivity-enforcement (emit the estimate exactly as fitted; for
# demonstrations of what a non-passive wall does).
#
# Works in the admitgen build tree (targets admitgen / admitgen_rt) and from an installed package
# (find_package(admitgen): imported targets admitgen::admitgen / admitgen::runtime).
include_guard(GLOBAL)

if(NOT DEFINED ADMITGEN_TEMPLATE_FILE)
  set(ADMITGEN_TEMPLATE_FILE "${CMAKE_CURRENT_LIST_DIR}/../templates/admitgen_boundary.h.in")
endif()
set(ADMITGEN_TEMPLATE_FILE "${ADMITGEN_TEMPLATE_FILE}" CACHE INTERNAL "admitgen header template")

function(admitgen_add_boundary target)
  cmake_parse_arguments(ARG "ALLOW_UNSAFE;NO_PASSIVITY_ENFORCEMENT" "FIT;FORMAT;NAME;ORDER;ESTIMATE;FIR_TAPS;BANDS_JSON;FIDELITY_TOLERANCE" "FS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "admitgen_add_boundary(${target}): unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_FIT OR NOT ARG_FS OR NOT ARG_FORMAT)
    message(FATAL_ERROR "admitgen_add_boundary(${target}): FIT, FS and FORMAT are required")
  endif()
  if(NOT ARG_NAME)
    set(ARG_NAME ${target})
  endif()
  get_filename_component(fit "${ARG_FIT}" ABSOLUTE)

  if(TARGET admitgen::admitgen)
    set(exe admitgen::admitgen)
  elseif(TARGET admitgen)
    set(exe admitgen)
  else()
    message(FATAL_ERROR "admitgen_add_boundary: no admitgen executable target (find_package(admitgen) first)")
  endif()
  if(TARGET admitgen::runtime)
    set(runtime admitgen::runtime)
  else()
    set(runtime admitgen_rt)
  endif()

  set(dir "${CMAKE_CURRENT_BINARY_DIR}/admitgen_boundary/${target}")
  set(header "${dir}/${ARG_NAME}.h")
  set(args emit "${fit}" --format ${ARG_FORMAT} --name ${ARG_NAME} --out "${header}" --quiet)
  foreach(fs IN LISTS ARG_FS)
    list(APPEND args --fs ${fs})
  endforeach()
  if(ARG_ORDER)
    list(APPEND args --order ${ARG_ORDER})
  endif()
  if(ARG_ESTIMATE)
    list(APPEND args --estimate ${ARG_ESTIMATE})
  endif()
  if(ARG_FIR_TAPS)
    list(APPEND args --fir-taps ${ARG_FIR_TAPS})
  endif()
  if(ARG_FIDELITY_TOLERANCE)
    list(APPEND args --fidelity-tolerance ${ARG_FIDELITY_TOLERANCE})
  endif()
  if(ARG_NO_PASSIVITY_ENFORCEMENT)
    list(APPEND args --no-passivity-enforcement)
  endif()
  if(ARG_ALLOW_UNSAFE)
    list(APPEND args --allow-unsafe)
  endif()
  set(outputs "${header}")
  if(ARG_BANDS_JSON)
    get_filename_component(bands "${ARG_BANDS_JSON}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    list(APPEND args --bands-json "${bands}")
    list(APPEND outputs "${bands}")
  endif()

  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${CMAKE_COMMAND} -E make_directory "${dir}"
    COMMAND ${exe} ${args}
    DEPENDS "${fit}" ${exe} "${ADMITGEN_TEMPLATE_FILE}"
    COMMENT "admitgen emit ${ARG_NAME}.h (${ARG_FORMAT}, fs ${ARG_FS})"
    VERBATIM)
  add_custom_target(${target}_generate DEPENDS ${outputs})
  add_library(${target} INTERFACE)
  target_sources(${target} INTERFACE "${header}")
  target_include_directories(${target} INTERFACE "${dir}")
  target_link_libraries(${target} INTERFACE ${runtime})
  add_dependencies(${target} ${target}_generate)
  set_target_properties(${target} PROPERTIES ADMITGEN_HEADER "${header}")
endfunction()
