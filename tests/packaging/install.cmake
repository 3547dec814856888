# cmake -DBUILD_DIR=<build> -DSOURCE_DIR=<src> -DPREFIX=<dir> -D{BIN,LIB,INCLUDE,DATA}DIR=<dir> -DPLUGIN_SUBDIR=<dir>
#       -P install.cmake
# A fresh install of the build into PREFIX, which writes nothing into the source tree, and the files
# an out-of-tree plugin needs from it.

# The files and folders of the source tree, but the build tree (which may lie inside it), the
# repository and the caches Python writes beside the tests it runs.
function(source_tree_files out)
  file(GLOB_RECURSE files LIST_DIRECTORIES true RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*)
  file(RELATIVE_PATH build ${SOURCE_DIR} ${BUILD_DIR})
  set(kept)
  foreach(f IN LISTS files)
    if(NOT f MATCHES "(^|/)(\\.git|__pycache__)(/|$)" AND NOT (f STREQUAL build OR f MATCHES "^${build}/"))
      list(APPEND kept ${f})
    endif()
  endforeach()
  set(${out} ${kept} PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${PREFIX})
source_tree_files(before)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${result})")
endif()
source_tree_files(after)
list(REMOVE_ITEM after ${before})
if(after)
  message(FATAL_ERROR "cmake --install wrote into the source tree: ${after}")
endif()
foreach(file
    ${LIBDIR}/cmake/FrictionLab/FrictionLabConfig.cmake
    ${LIBDIR}/cmake/FrictionLab/FrictionLabConfigVersion.cmake
    ${LIBDIR}/cmake/FrictionLab/FrictionLabTargets.cmake
    ${LIBDIR}/cmake/FrictionLab/FrictionLabPlugin.cmake
    ${INCLUDEDIR}/frictionlab/plugins/plugin.hpp
    ${INCLUDEDIR}/frictionlab/plugins/registry.hpp
    ${INCLUDEDIR}/frictionlab/plugins/search.hpp
    ${INCLUDEDIR}/frictionlab/campaign/sweep.hpp
    ${DATADIR}/frictionlab/plugin_template/CMakeLists.txt
    ${DATADIR}/frictionlab/plugin_template/max_speed_csv.cpp
    ${DATADIR}/frictionlab/plugin_template/README.md
    ${BINDIR}/frictionlab)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
file(GLOB libraries ${PREFIX}/${LIBDIR}/libfrictionlab.so*)
file(GLOB plugins ${PREFIX}/${PLUGIN_SUBDIR}/*.so)
if(NOT libraries OR NOT plugins)
  message(FATAL_ERROR "not installed: ${LIBDIR}/libfrictionlab.so or the plugins in ${PLUGIN_SUBDIR}")
endif()
file(READ ${PREFIX}/${LIBDIR}/cmake/FrictionLab/FrictionLabTargets.cmake targets)
if(NOT targets MATCHES "FrictionLab::campaign")
  message(FATAL_ERROR "find_package(FrictionLab) gives no FrictionLab::campaign")
endif()
