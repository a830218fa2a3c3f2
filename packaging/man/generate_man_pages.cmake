# SPDX-License-Identifier: MIT
# Writes admitgen.1 and admitgen-<subcommand>.1 into OUT_DIR with help2man, from the CLI's own --help.
# The subcommands are the lines of the Subcommands section of `admitgen --help` (CLI11's layout:
# two spaces, the name, the description). Invoked by cmake/AdmitgenDocs.cmake with
# -DADMITGEN_EXE=... -DHELP2MAN=... -DVERSION=... -DINCLUDE_FILE=... -DCHANGELOG=... -DOUT_DIR=... -DWORK_DIR=...
# (WORK_DIR: wrapper scripts and the assembled include file, kept out of the installed OUT_DIR).
# The pages carry the release date of VERSION from CHANGELOG.md ("## [VERSION] - YYYY-MM-DD"), not the
# build date, so equal sources give equal pages.
foreach(var ADMITGEN_EXE HELP2MAN VERSION INCLUDE_FILE CHANGELOG OUT_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()

execute_process(COMMAND "${ADMITGEN_EXE}" --help OUTPUT_VARIABLE help COMMAND_ERROR_IS_FATAL ANY)
string(REGEX MATCH "(SUBCOMMANDS|Subcommands):\n(  [a-z][^\n]*\n)+" section "${help}")
string(REGEX MATCHALL "\n  [a-z][a-z0-9-]*" names "${section}")
list(TRANSFORM names REPLACE "\n  " "")
if(NOT names)
  message(FATAL_ERROR "no SUBCOMMANDS section in `admitgen --help`:\n${help}")
endif()

file(READ "${CHANGELOG}" changelog)
string(REPLACE "." "\\." version_re "${VERSION}")
if(NOT changelog MATCHES "\n## \\[${version_re}\\] - ([0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9])")
  message(FATAL_ERROR "${CHANGELOG} has no entry \"## [${VERSION}] - YYYY-MM-DD\" for this version")
endif()
set(release_date "${CMAKE_MATCH_1}")

file(MAKE_DIRECTORY "${OUT_DIR}" "${WORK_DIR}")
# The include file: the fixed sections plus SEE ALSO listing every page.
set(see_also ".BR admitgen (1)")
foreach(name IN LISTS names)
  string(APPEND see_also ",\n.BR admitgen-${name} (1)")
endforeach()
file(READ "${INCLUDE_FILE}" sections)
set(include_file "${WORK_DIR}/admitgen.h2m")
file(WRITE "${include_file}" "${sections}\n[SEE ALSO]\n${see_also}\n")
# One page per program: help2man runs "PROGRAM --help", and names and titles the page after PROGRAM's
# file name, so each page is made through a wrapper script named admitgen or admitgen-NAME.
function(man_page page args description)
  set(wrapper "${WORK_DIR}/${page}")
  file(WRITE "${wrapper}" "#!/bin/sh\nexec '${ADMITGEN_EXE}' ${args} \"$@\"\n")
  file(CHMOD "${wrapper}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
  execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr --version-string=${VERSION}
                          --include=${include_file} --section=1 "--name=${description}"
                          --output=${OUT_DIR}/${page}.1 "${wrapper}" COMMAND_ERROR_IS_FATAL ANY)
  file(READ "${OUT_DIR}/${page}.1" text)
  string(REGEX REPLACE "\n(\\.TH [^ ]+ \"1\") \"[^\"]*\"" "\n\\1 \"${release_date}\"" text "${text}")
  file(WRITE "${OUT_DIR}/${page}.1" "${text}")
endfunction()

man_page(admitgen "" "multipole admittance fits and causal C boundary filters")
foreach(name IN LISTS names)
  execute_process(COMMAND "${ADMITGEN_EXE}" ${name} --help OUTPUT_VARIABLE sub_help COMMAND_ERROR_IS_FATAL ANY)
  string(REGEX MATCH "^[^\n]*" first_line "${sub_help}")  # CLI11 prints the description first
  man_page(admitgen-${name} ${name} "${first_line}")
endforeach()
