# The man page strata.1, made by help2man from `strata --help` and `strata --version` (so it
# never disagrees with the program) and man/strata.h2m, gzip-compressed as Debian installs man
# pages. Sets STRATA_MAN_PAGE, the file cmake/StrataInstall.cmake installs.
find_program(STRATA_HELP2MAN help2man)
if(NOT STRATA_HELP2MAN)
  message(FATAL_ERROR "strata's man page needs help2man: run `bash scripts/setup.sh` "
                      "(apt help2man) first")
endif()
set(STRATA_MAN_PAGE ${PROJECT_BINARY_DIR}/man/strata.1.gz)
add_custom_command(
  OUTPUT ${STRATA_MAN_PAGE}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
  COMMAND ${STRATA_HELP2MAN} --no-info --section=1
          "--name=slice triangle meshes into layers of cells"
          --include=${PROJECT_SOURCE_DIR}/man/strata.h2m
          --output=${PROJECT_BINARY_DIR}/man/strata.1 $<TARGET_FILE:strata_cli>
  COMMAND gzip -9nf ${PROJECT_BINARY_DIR}/man/strata.1
  DEPENDS strata_cli ${PROJECT_SOURCE_DIR}/man/strata.h2m
  COMMENT "Writing the man page strata.1 (help2man)"
  VERBATIM)
add_custom_target(strata_man ALL DEPENDS ${STRATA_MAN_PAGE})
