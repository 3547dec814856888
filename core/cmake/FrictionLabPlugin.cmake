# frictionlab_add_plugin(<name> SOURCES <src>... [ENTRY <file>] [LIBRARIES <lib>...] [NO_INSTALL])
#
# Builds a plugin library: a MODULE named exactly <name>.so that exports one C symbol (see
# frictionlab/plugin.hpp). Used for the plugins shipped with FrictionLab and, after
# find_package(FrictionLab), for plugins built out of tree.
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
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  # Every symbol must resolve at link time, so a plugin never fails late inside dlopen.
  target_link_options(${name} PRIVATE "LINKER:-z,defs")
  if(FRICTIONLAB_PLUGIN_SUBDIR)
    # In the FrictionLab tree: lib/frictionlab/plugins, in the build and the install tree alike.
    set_target_properties(${name} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/${FRICTIONLAB_PLUGIN_SUBDIR})
    if(NOT ARG_NO_INSTALL)
      install(TARGETS ${name} LIBRARY DESTINATION ${FRICTIONLAB_PLUGIN_SUBDIR})
    endif()
  endif()
endfunction()
