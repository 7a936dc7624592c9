# What `cmake --install` adds to the library, programs and plugins (each installed by its own folder,
# cmake/NavLinkInstall.cmake): the documentation, and a Debian package of the whole install (CPack).

# Debian's docs go in /usr/share/doc/<package>, and the package is navlink (GNUInstallDirs would say NavLink).
set(NAVLINK_INSTALL_DOCDIR ${CMAKE_INSTALL_DATAROOTDIR}/doc/navlink CACHE PATH "Where the docs are installed")
install(FILES README.md CHANGELOG.md LICENSE DESTINATION ${NAVLINK_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${NAVLINK_INSTALL_DOCDIR} FILES_MATCHING PATTERN "*.md" PATTERN "README.md" EXCLUDE)
# docs/README.md, the index of the docs, beside the project's README.md.
install(FILES docs/README.md DESTINATION ${NAVLINK_INSTALL_DOCDIR} RENAME docs.md)
install(FILES samples/README.md DESTINATION ${NAVLINK_INSTALL_DOCDIR} RENAME samples.md)

# `cpack -G DEB` in the build folder: one package (libnavlink.so and libnavlink.a, headers, CMake package,
# the .pc files, the navlink tool, the viewer, the plugin modules, the docs), its run-time dependencies
# read from what the binaries link (dpkg-shlibdeps). docs/shipping.md.
set(NAVLINK_PACKAGE_CONTACT "NavLink maintainers" CACHE STRING "The Debian package's Maintainer field")
set(CPACK_PACKAGE_NAME navlink)
set(CPACK_PACKAGE_VENDOR NavLink)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_CONTACT "${NAVLINK_PACKAGE_CONTACT}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Packages ship without debug info, whatever NAVLINK_INSTALL_STRIPPED says.
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR TGZ)
find_program(NAVLINK_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NAVLINK_DPKG_SHLIBDEPS)
  set(CPACK_GENERATOR DEB)
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libnavlink.so.0 is in the package itself: dpkg-shlibdeps finds it there for the programs.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# libnavlink.a is linked with what it links: their -dev packages (navlink-static.pc's Libs.private). Beside
# libnavlink.so only the hosts that link the archive need them; without the .so, every host does.
set(_navlink_static_dev_packages "libembree-dev, libtbb-dev, zlib1g-dev, librecast-dev")
if(NAVLINK_SHARED)
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "${_navlink_static_dev_packages}")
else()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${_navlink_static_dev_packages}")
endif()
include(CPack)
