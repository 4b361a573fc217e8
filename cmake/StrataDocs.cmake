# The API documentation: `cmake --build <build> --target strata_docs` runs Doxygen over the public
# headers (include/strata/) with docs/library.md as the main page, into <build>/docs/html/.
# Not part of the default build; Debian's doxygen is installed by `scripts/setup.sh docs`.
find_package(Doxygen)
if(NOT DOXYGEN_FOUND)
  add_custom_target(strata_docs
    COMMAND ${CMAKE_COMMAND} -E echo "strata_docs needs doxygen: run 'bash scripts/setup.sh docs'"
    COMMAND ${CMAKE_COMMAND} -E false
    VERBATIM)
  return()
endif()
set(DOXYGEN_PROJECT_NAME strata)
set(DOXYGEN_PROJECT_BRIEF "exact slicing of triangle meshes into layers of cells")
set(DOXYGEN_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/docs)
set(DOXYGEN_USE_MDFILE_AS_MAINPAGE ${PROJECT_SOURCE_DIR}/docs/library.md)
set(DOXYGEN_STRIP_FROM_PATH ${PROJECT_SOURCE_DIR}/include ${PROJECT_SOURCE_DIR}/docs)
set(DOXYGEN_STRIP_FROM_INC_PATH ${PROJECT_SOURCE_DIR}/include)
set(DOXYGEN_EXCLUDE_SYMBOLS detail)
# Every member is listed, the plain data members whose names say what they hold too; the rest
# carry a /// comment (one @{ ... @} group shares one comment).
set(DOXYGEN_EXTRACT_ALL YES)
set(DOXYGEN_DISTRIBUTE_GROUP_DOC YES)
set(DOXYGEN_WARN_IF_INCOMPLETE_DOC NO)
set(DOXYGEN_GENERATE_TREEVIEW YES)
set(DOXYGEN_SORT_MEMBER_DOCS NO)
set(DOXYGEN_MACRO_EXPANSION YES)
set(DOXYGEN_QUIET YES)
doxygen_add_docs(strata_docs
  ${PROJECT_SOURCE_DIR}/include/strata ${PROJECT_SOURCE_DIR}/docs/library.md
  ${PROJECT_SOURCE_DIR}/docs/namespaces.dox
  COMMENT "Writing the API documentation (Doxygen) into ${PROJECT_BINARY_DIR}/docs/html")
