# cpack -G DEB in a build directory: the Debian package hydrocoef_VERSION_ARCH.deb of what
# cmake/install.cmake installs, under /usr, depending on the Debian runtime packages that
# dpkg-shlibdeps finds for its binaries.
set(CPACK_PACKAGE_NAME hydrocoef)
set(CPACK_PACKAGE_VENDOR "hydrocoef maintainers")
set(CPACK_PACKAGE_CONTACT "hydrocoef maintainers <maintainers@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The Python module (python/), when built, is in the package too; it needs numpy (which brings python3).
if(TARGET hydrocoef_python)
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS python3-numpy)
endif()
include(CPack)
