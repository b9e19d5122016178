# CPack: a Debian package of what `cmake --install` puts in place
# (scripts/package.sh; tests/package/package_install.sh installs it into a
# temporary root and starts both programs from there).
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "mtc200-panel")
set(CPACK_PACKAGE_VENDOR "MTC200 panel simulator team")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Training and commissioning simulator of the Indramat/Rexroth MTC200 CNC operator panel")
set(CPACK_PACKAGE_DESCRIPTION
    "mtc200-panel reproduces the MTC200 operator panel (Qt 5) on an embedded CNC core with a\nsimulated mill and lathe; mtc200-cli is its headless twin for scripts and automated checks.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "MTC200 panel simulator team <maintainers@example.invalid>")
set(CPACK_DEBIAN_PACKAGE_SECTION "education")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# The run-time libraries (Qt 5, VTK 9, ...) from the binaries' own links.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
