include_guard(GLOBAL)
include(GNUInstallDirs)

# frictionlab_add_plugin(<name> SOURCES <src>... [ENTRY <file>] [LIBRARIES <lib>...] [NO_INSTALL])
#
# Builds a plugin library: a MODULE named exactly <name>.so that exports one C symbol (see
# frictionlab/plugins/plugin.hpp). Used for the plugins shipped with FrictionLab and, after
# find_package(FrictionLab), for plugins built out of tree. In the FrictionLab tree the module goes
# to lib/frictionlab/plugins of the build tree; out of tree to <build>/plugins, the directory to
# name in a scene's plugin_paths or with --plugin-path.
#
# With ENTRY (the file that holds FRICTIONLAB_PLUGIN), SOURCES also form a static library
# <name>_code that unit tests link to reach the plugin's classes directly.
function(frictionlab_add_plugin name)
  cmake_parse_arguments(ARG "NO_INSTALL" "ENTRY" "SOURCES;LIBRARIES" ${ARGN})
  if(ARG_ENTRY)
    add_library(${name}_code STATIC ${ARG_SOURCES})
    target_link_libraries(${name}_code PUBLIC FrictionLab::frictionlab ${ARG_LIBRARIES})
    target_include_directories(${name}_code PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
    set_target_properties(${name}_code PROPERTIES POSITION_INDEPENDENT_CODE ON
      CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
    add_library(${name} MODULE ${ARG_ENTRY})
    target_link_libraries(${name} PRIVATE ${name}_code)
  else()
    add_library(${name} MODULE ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE FrictionLab::frictionlab ${ARG_LIBRARIES})
  endif()
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES
    PREFIX ""
    CXX_EXTENSIONS OFF
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  # Every symbol must resolve at link time, so a plugin never fails late inside dlopen.
  target_link_options(${name} PRIVATE "LINKER:-z,defs")
  set_property(GLOBAL APPEND PROPERTY FRICTIONLAB_PLUGIN_TARGETS ${name})
  if(FRICTIONLAB_PLUGIN_SUBDIR)
    # In the FrictionLab tree: lib/frictionlab/plugins, in the build and the install tree alike.
    set_target_properties(${name} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/${FRICTIONLAB_PLUGIN_SUBDIR})
    if(NOT ARG_NO_INSTALL)
      # Its libraries are found from the plugin directory, not from bin/ (CMAKE_INSTALL_RPATH).
      file(RELATIVE_PATH to_libdir /${FRICTIONLAB_PLUGIN_SUBDIR} /${CMAKE_INSTALL_LIBDIR})
      set_target_properties(${name} PROPERTIES INSTALL_RPATH "$ORIGIN/${to_libdir}")
      install(TARGETS ${name} LIBRARY DESTINATION ${FRICTIONLAB_PLUGIN_SUBDIR})
    endif()
  else()
    # Out of tree: a directory of plugins only, for a scene's plugin_paths or --plugin-path, since
    # every *.so in a searched directory must be a plugin. Installed into the same prefix as
    # FrictionLab, the plugin sits with the shipped ones and is found without naming its directory.
    set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/plugins)
    if(NOT ARG_NO_INSTALL)
      install(TARGETS ${name} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/frictionlab/plugins)
    endif()
    message(STATUS "FrictionLab plugin ${name}: ${PROJECT_BINARY_DIR}/plugins/${name}.so")
  endif()
endfunction()
