# cmake --install: the core library and headers, the exported target FrictionLab::frictionlab with
# its package config (so out-of-tree plugins can find_package(FrictionLab)), and share/ as
# share/frictionlab. The CLI and the shipped plugins install themselves where they are defined.
# The build tree is a package too: its FrictionLabConfig.cmake finds the targets exported there and
# frictionlab_add_plugin() beside it (cmake -DFrictionLab_DIR=<build>).
include(CMakePackageConfigHelpers)

set(FRICTIONLAB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/FrictionLab)

install(TARGETS frictionlab EXPORT FrictionLabTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/frictionlab
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")
install(EXPORT FrictionLabTargets
  NAMESPACE FrictionLab::
  DESTINATION ${FRICTIONLAB_CMAKE_DIR})
# The same export set for the build tree (FrictionLab::campaign joins it in apps/campaign), its
# targets' include directories the sources' (their BUILD_INTERFACE).
export(EXPORT FrictionLabTargets
  NAMESPACE FrictionLab::
  FILE ${PROJECT_BINARY_DIR}/FrictionLabTargets.cmake)
configure_file(${CMAKE_CURRENT_LIST_DIR}/FrictionLabPlugin.cmake ${PROJECT_BINARY_DIR}/FrictionLabPlugin.cmake
  COPYONLY)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/FrictionLabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/FrictionLabConfig.cmake
  INSTALL_DESTINATION ${FRICTIONLAB_CMAKE_DIR})
# Before 1.0 a minor version may change the plugin ABI (plugin.hpp's framework_abi_version).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/FrictionLabConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/FrictionLabConfig.cmake
  ${PROJECT_BINARY_DIR}/FrictionLabConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FrictionLabPlugin.cmake
  DESTINATION ${FRICTIONLAB_CMAKE_DIR})

# Plugin template, docs, examples: whatever share/ holds.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/share/
  DESTINATION ${CMAKE_INSTALL_DATADIR}/frictionlab
  USE_SOURCE_PERMISSIONS)
