# Install rules: the library, its public headers, a CMake package
# (find_package(pogon) -> pogon::pogon) and a pkg-config file (pogon.pc).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(POGON_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/pogon"
    CACHE STRING "Where to install pogonConfig.cmake, relative to the prefix")
mark_as_advanced(POGON_INSTALL_CMAKEDIR)

# install(TARGETS) for a target made in another directory needs CMake 3.13.
install(TARGETS pogon
  EXPORT pogonTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
  INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/pogon"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
  FILES_MATCHING PATTERN "*.h")

install(EXPORT pogonTargets
  NAMESPACE pogon::
  FILE pogonTargets.cmake
  DESTINATION "${POGON_INSTALL_CMAKEDIR}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/pogonConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/pogonConfig.cmake"
  INSTALL_DESTINATION "${POGON_INSTALL_CMAKEDIR}")
# Before 1.0 a minor version may break the API, so only the same minor is compatible.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/pogonConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(FILES
  "${PROJECT_BINARY_DIR}/pogonConfig.cmake"
  "${PROJECT_BINARY_DIR}/pogonConfigVersion.cmake"
  DESTINATION "${POGON_INSTALL_CMAKEDIR}")

# pkg-config: relocatable (paths relative to ${pcfiledir}) unless the install
# directories were given as absolute paths.
set(_pogon_pc_dir "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(POGON_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(POGON_PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
  set(POGON_PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
else()
  file(RELATIVE_PATH _pogon_pc_up "/pogon-root/${_pogon_pc_dir}" "/pogon-root")
  set(POGON_PC_PREFIX "\${pcfiledir}/${_pogon_pc_up}")
  set(POGON_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(POGON_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
# A shared libpogon: the link line carries its run path, so a program built from
# `pkg-config --libs pogon` finds libpogon.so.0 without LD_LIBRARY_PATH (docs/install.md).
if(BUILD_SHARED_LIBS)
  set(POGON_PC_RPATH " -Wl,-rpath,\${libdir}")
else()
  set(POGON_PC_RPATH "")
endif()
configure_file("${CMAKE_CURRENT_LIST_DIR}/pogon.pc.in" "${PROJECT_BINARY_DIR}/pogon.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/pogon.pc" DESTINATION "${_pogon_pc_dir}")
