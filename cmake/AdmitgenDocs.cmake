# SPDX-License-Identifier: MIT
# Man pages and bash completion for the admitgen CLI, built with it and installed by `cmake --install`
# (component generator).
#   man pages: generated from the CLI's own --help by help2man (Debian package help2man): admitgen(1)
#              and one page per subcommand, admitgen-fit(1), admitgen-emit(1), ... The subcommands are
#              read from `admitgen --help` at build time (packaging/man/generate_man_pages.cmake), so a
#              new subcommand gets its page without editing this file.
#   completion: packaging/bash-completion/admitgen, which asks the installed admitgen for its
#              subcommands and options (so it cannot drift from the CLI either).
set(ADMITGEN_COMPLETION_FILE ${PROJECT_SOURCE_DIR}/packaging/bash-completion/admitgen)
install(FILES ${ADMITGEN_COMPLETION_FILE} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        COMPONENT generator)

find_program(ADMITGEN_HELP2MAN help2man)
if(NOT ADMITGEN_HELP2MAN)
  message(WARNING "help2man not found: the man pages are not built (apt-get install help2man)")
  return()
endif()
set(ADMITGEN_MAN_DIR ${PROJECT_BINARY_DIR}/man)
add_custom_command(
  OUTPUT ${ADMITGEN_MAN_DIR}/man1/admitgen.1
  COMMAND ${CMAKE_COMMAND} -DADMITGEN_EXE=$<TARGET_FILE:admitgen> -DHELP2MAN=${ADMITGEN_HELP2MAN}
          -DVERSION=${PROJECT_VERSION} -DINCLUDE_FILE=${PROJECT_SOURCE_DIR}/packaging/man/admitgen.h2m
          -DCHANGELOG=${PROJECT_SOURCE_DIR}/CHANGELOG.md
          -DOUT_DIR=${ADMITGEN_MAN_DIR}/man1 -DWORK_DIR=${PROJECT_BINARY_DIR}/man_work -P ${PROJECT_SOURCE_DIR}/packaging/man/generate_man_pages.cmake
  DEPENDS admitgen ${PROJECT_SOURCE_DIR}/packaging/man/generate_man_pages.cmake
          ${PROJECT_SOURCE_DIR}/packaging/man/admitgen.h2m ${PROJECT_SOURCE_DIR}/CHANGELOG.md
  COMMENT "help2man: admitgen man pages"
  VERBATIM)
add_custom_target(admitgen_man_pages ALL DEPENDS ${ADMITGEN_MAN_DIR}/man1/admitgen.1)
install(DIRECTORY ${ADMITGEN_MAN_DIR}/ DESTINATION ${CMAKE_INSTALL_MANDIR} COMPONENT generator)
