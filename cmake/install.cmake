# What `cmake --install` puts under the prefix (included from CMakeLists.txt):
#   bin/hydrocoef                           the CLI (linked with the static library)
#   LIBDIR/libhydrocoef.so.0 (.so, .a)      the library, shared and static
#   include/hydrocoef/*.hpp                 the public headers (include/hydrocoef/ of the source tree and the
#                                           generated version.hpp and export.hpp, nothing else: src/ and importers/ are internal)
#   LIBDIR/cmake/hydrocoef/                 the CMake package: find_package(hydrocoef 0.1 CONFIG REQUIRED)
#   LIBDIR/pkgconfig/hydrocoef.pc           pkg-config --cflags --libs hydrocoef (the shared library)
#   share/hydrocoef/schema/*.sql            the database schema migrations (also compiled into the library)
#   share/doc/hydrocoef/                    README.md, the user guide (docs/*.md), the data's PROVENANCE.md
#   share/man/man1/hydrocoef*.1             a man page per command, made from its --help (optimized builds;
#                                           cmake/man_pages.cmake), and hydrocoef.1
#   lib/python3/dist-packages/hydrocoef/    the Python module, when it is built (python/CMakeLists.txt installs
#                                           it into HYDROCOEF_PYTHON_INSTALL_DIR)
# LIBDIR is lib/<multiarch triplet> (lib/x86_64-linux-gnu), Debian's layout, whatever the prefix.
#
# Exported targets (cmake/hydrocoefConfig.cmake.in):
#   hydrocoef::hydrocoef         the shared library (what a consumer links unless it asks otherwise)
#   hydrocoef::hydrocoef_static  the static library, with COMPONENTS static (which finds VTK, Ceres, ... too)
# In the build tree hydrocoef::hydrocoef stays the static library the CLI and the tests link.

# Debian's multiarch library directory for every prefix, not only /usr (GNUInstallDirs' rule).
if(NOT DEFINED CMAKE_INSTALL_LIBDIR AND CMAKE_LIBRARY_ARCHITECTURE)
  set(CMAKE_INSTALL_LIBDIR "lib/${CMAKE_LIBRARY_ARCHITECTURE}" CACHE PATH "Object code libraries (LIBDIR)")
endif()
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HYDROCOEF_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/hydrocoef" CACHE PATH
    "Where the CMake package files go (relative to the prefix)")
# The Python module's directory, relative to the prefix: Debian's directory for modules of every python3
# version. python/CMakeLists.txt, read before this file, sets the same default.
set(HYDROCOEF_PYTHON_INSTALL_DIR "lib/python3/dist-packages" CACHE PATH
    "Where the Python module goes (relative to the prefix)")

set_target_properties(hydrocoef_shared PROPERTIES EXPORT_NAME hydrocoef)
set_target_properties(hydrocoef PROPERTIES EXPORT_NAME hydrocoef_static)
install(TARGETS hydrocoef_shared EXPORT hydrocoefTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS hydrocoef EXPORT hydrocoefStaticTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS hydrocoef_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/hydrocoef DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/generated/include/hydrocoef/version.hpp
              ${PROJECT_BINARY_DIR}/generated/include/hydrocoef/export.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hydrocoef)
install(FILES ${HYDROCOEF_MIGRATIONS} DESTINATION ${CMAKE_INSTALL_DATADIR}/hydrocoef/schema)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/data/PROVENANCE.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
# The user guide beside the README, where the README's links (docs/NAME.md) find it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md" PATTERN "reference" EXCLUDE)

# Man pages: one per command from the built CLI's --help (cmake/man_pages.cmake), made at build time by the
# optimized builds; the sanitizer build is never installed and does not make them.
if(NOT HYDROCOEF_SANITIZE)
  set(HYDROCOEF_MAN_DIR ${PROJECT_BINARY_DIR}/man/man1)
  add_custom_command(
    OUTPUT ${HYDROCOEF_MAN_DIR}/hydrocoef.1
    COMMAND ${CMAKE_COMMAND} -DHYDROCOEF_CLI=$<TARGET_FILE:hydrocoef_cli> -DOUTPUT_DIR=${HYDROCOEF_MAN_DIR}
            -DVERSION=${PROJECT_VERSION} -P ${CMAKE_CURRENT_LIST_DIR}/man_pages.cmake
    DEPENDS hydrocoef_cli ${CMAKE_CURRENT_LIST_DIR}/man_pages.cmake
    COMMENT "Man pages from hydrocoef --help"
    VERBATIM)
  add_custom_target(hydrocoef_man_pages ALL DEPENDS ${HYDROCOEF_MAN_DIR}/hydrocoef.1)
  install(DIRECTORY ${HYDROCOEF_MAN_DIR}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 FILES_MATCHING PATTERN "*.1")
endif()

# The CMake package: the targets, the config that finds their dependencies, and the version file
# (0.x: a consumer asking for 0.1 accepts 0.1.y only).
install(EXPORT hydrocoefTargets NAMESPACE hydrocoef:: DESTINATION ${HYDROCOEF_INSTALL_CMAKEDIR})
install(EXPORT hydrocoefStaticTargets NAMESPACE hydrocoef:: DESTINATION ${HYDROCOEF_INSTALL_CMAKEDIR})
# The VTK modules the static library links, for the config's find_dependency(VTK COMPONENTS ...).
set(HYDROCOEF_VTK_COMPONENTS ${VTK_LIBRARIES})
list(TRANSFORM HYDROCOEF_VTK_COMPONENTS REPLACE "^VTK::" "")
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/hydrocoefConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/hydrocoefConfig.cmake INSTALL_DESTINATION ${HYDROCOEF_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/hydrocoefConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/hydrocoefConfig.cmake
              ${PROJECT_BINARY_DIR}/package/hydrocoefConfigVersion.cmake
        DESTINATION ${HYDROCOEF_INSTALL_CMAKEDIR})

# pkg-config: the shared library. Its prefix is the one the install runs with (cmake --install --prefix P,
# or /usr when cpack stages the package under DESTDIR), so the file is written at install time.
install(CODE "
  set(HYDROCOEF_PC_PREFIX \"\${CMAKE_INSTALL_PREFIX}\")
  set(CMAKE_INSTALL_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
  set(CMAKE_INSTALL_INCLUDEDIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
  set(PROJECT_DESCRIPTION \"${PROJECT_DESCRIPTION}\")
  set(PROJECT_VERSION \"${PROJECT_VERSION}\")
  configure_file(\"${CMAKE_CURRENT_LIST_DIR}/hydrocoef.pc.in\" \"${PROJECT_BINARY_DIR}/package/hydrocoef.pc\" @ONLY)
")
install(FILES ${PROJECT_BINARY_DIR}/package/hydrocoef.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
