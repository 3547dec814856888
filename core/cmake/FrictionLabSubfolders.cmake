# frictionlab_add_subfolders(): add_subdirectory() for every folder beside the calling CMakeLists.txt
# that has one of its own, so a new plugin or test folder is picked up without another line.
function(frictionlab_add_subfolders)
  file(GLOB entries LIST_DIRECTORIES true CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*)
  foreach(dir IN LISTS entries)
    if(IS_DIRECTORY ${dir} AND EXISTS ${dir}/CMakeLists.txt)
      add_subdirectory(${dir})
    endif()
  endforeach()
endfunction()
