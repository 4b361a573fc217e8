# `cpack -G DEB` in a build folder: the Debian package strata_<version>_amd64.deb of what
# `cmake --install` installs under /usr. A release package comes from the `release` preset's
# build (README, "Installing"); the package test (tests/package/) packages the build it runs in.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME strata)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR strata)
set(CPACK_PACKAGE_CONTACT "strata maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "exact slicer of triangle meshes into layers of cells")
set(CPACK_PACKAGE_DESCRIPTION "strata slices triangle meshes (STL, OBJ, OFF, PLY, also \
gzip-compressed) into layers of cells for binder jetting and powder-bed printing: every cell of \
a regular grid is empty, interior or boundary shell, decided by exact predicates. It writes \
cells files, PNG and SVG stacks, CLI contours, a JSON report and a self-contained HTML view \
page, and serves a local web application. The package also holds the C++ library (static, with \
its headers and the CMake package: find_package(strata) gives strata::strata).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The executable's run-time libraries, found by dpkg-shlibdeps (dpkg-dev).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What find_package(strata) needs to link the static library (cmake/strataConfig.cmake.in):
# recommended, not required, so the command line installs alone with --no-install-recommends.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "cmake, pkg-config, libcgal-dev, libboost-dev, libgmp-dev, libmpfr-dev, libtbb-dev, \
zlib1g-dev, libfmt-dev, nlohmann-json3-dev, lib3mf-dev")
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
include(CPack)
