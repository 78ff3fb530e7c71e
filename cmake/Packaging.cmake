# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian package (CPack DEB): scripts/package.sh writes
# build/package/fivebar-studio_VERSION_ARCH.deb from the release build. Everything the install
# rules put under the prefix goes in; the dependencies are computed by dpkg-shlibdeps from the
# installed executables (Debian package dpkg-dev).
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "fivebar-studio")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "The FiveBar Studio developers")
set(CPACK_PACKAGE_CONTACT "${FIVEBAR_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
# The extended Description: one string of lines of at most 79 characters (CPack prefixes each
# with the space Debian's format wants). string(CONCAT), not set() with several strings: set()
# makes a list, and CMake joins a list with ';', which `apt show` then printed at the start of
# every line. tests/package/check_package.sh checks the field's lines.
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "FiveBar Studio makes a five-bar linkage robot (two motors on a base, two\n"
    "driving links, two floating links meeting at the pen) as easy to use as an\n"
    "x-y gantry: load an SVG, see it placed on the machine's real workspace with\n"
    "its singularities drawn, preview and simulate the job, and stream motor\n"
    "angles to a stock GRBL 1.1 board.\n"
    "\n"
    "Includes the command-line tool fivebar and the simulated GRBL machine\n"
    "fivebar-sim.")
set(CPACK_PACKAGE_HOMEPAGE_URL "https://github.com/fivebar/studio")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_PACKAGE_DIRECTORY "${CMAKE_SOURCE_DIR}/build/package")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_NAME "fivebar-studio")
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")  # NAME_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt loads its platform plugins at run time, so shlibdeps cannot see them (Qt Svg, whose
# icon engine the icons need, is a link dependency and found by shlibdeps). The Hershey fonts of
# `fivebar text` and the studio's text are data files read at run time (docs/text.md).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, hershey-fonts-data")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n")
include(CPack)
