# cmake -DPREFIX=<install> -DWORK=<dir> -DCHECK_SOURCE=<dir> -DGENERATOR=<g> -DMAKE_PROGRAM=<p>
#       -DCXX_COMPILER=<c> -DBINDIR=<dir> -DDATADIR=<dir> -DPLUGIN_SUBDIR=<dir> -P plugin_template.cmake
# Copies the installed template as a user would, builds it and the check program against the
# install, and runs the check on the plugin it produced.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${result}): ${command}")
  endif()
endfunction()

set(configure_options -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
if(MAKE_PROGRAM)
  list(APPEND configure_options -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
endif()

file(REMOVE_RECURSE ${WORK}/my_plugin ${WORK}/check ${WORK}/output)
file(COPY ${PREFIX}/${DATADIR}/frictionlab/plugin_template/ DESTINATION ${WORK}/my_plugin)
run(${CMAKE_COMMAND} -S ${WORK}/my_plugin -B ${WORK}/my_plugin/build ${configure_options})
run(${CMAKE_COMMAND} --build ${WORK}/my_plugin/build)
set(plugin ${WORK}/my_plugin/build/plugins/observer_max_speed_csv.so)
if(NOT EXISTS ${plugin})
  message(FATAL_ERROR "the template did not produce ${plugin}")
endif()

run(${CMAKE_COMMAND} -S ${CHECK_SOURCE} -B ${WORK}/check ${configure_options})
run(${CMAKE_COMMAND} --build ${WORK}/check)
file(MAKE_DIRECTORY ${WORK}/output)
run(${WORK}/check/check_template ${plugin} ${WORK}/output)

# The installed program finds the plugin through FRICTIONLAB_PLUGIN_PATH, and its shipped plugins
# next to itself in the install tree.
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env FRICTIONLAB_PLUGIN_PATH=${WORK}/my_plugin/build/plugins ${PREFIX}/${BINDIR}/frictionlab list
  RESULT_VARIABLE result OUTPUT_VARIABLE listing ERROR_VARIABLE listing)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "frictionlab list failed (${result}):\n${listing}")
endif()
foreach(expected "max_speed_csv" "${WORK}/my_plugin/build/plugins/observer_max_speed_csv.so"
                 "${PREFIX}/${PLUGIN_SUBDIR}/")
  string(FIND "${listing}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "frictionlab list does not show ${expected}:\n${listing}")
  endif()
endforeach()

# Through a scene, as a user would: the installed frictionlab runs a small lattice whose scene names
# the template's directory in plugin_paths (relative to the scene file) and its observer by type.
file(WRITE ${WORK}/scene/uses_template.yaml "output: out
plugin_paths: [../my_plugin/build/plugins]
bulk: {type: spring_lattice_2d, nx: 11, nz: 3, length: 0.025, height: 0.005}
loaders:
  - {type: rigid_base_contact}
  - {type: normal_load, total_force: 100, ramp_time: 1.0e-4}
integrator: {type: rk4, dt: 2.0e-7}
stages:
  - {name: settle, duration: 2.0e-4}
observers:
  - {type: max_speed_csv, every: 2.0e-5, file_name: max_speed.csv}
")
file(REMOVE_RECURSE ${WORK}/scene/out)
execute_process(
  COMMAND ${PREFIX}/${BINDIR}/frictionlab run -q uses_template.yaml
  WORKING_DIRECTORY ${WORK}/scene
  RESULT_VARIABLE result OUTPUT_VARIABLE run_log ERROR_VARIABLE run_log)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "frictionlab run of a scene using the template failed (${result}):\n${run_log}")
endif()
file(STRINGS ${WORK}/scene/out/max_speed.csv rows REGEX "^[0-9]")
list(LENGTH rows row_count)
if(NOT row_count EQUAL 11)
  message(FATAL_ERROR "max_speed.csv has ${row_count} rows, expected 11 (t = 0, 2e-5, ..., 2e-4)")
endif()
file(READ ${WORK}/scene/out/run.yaml record)
string(FIND "${record}" "observer_max_speed_csv" at)
if(at EQUAL -1)
  message(FATAL_ERROR "run.yaml does not record the template plugin:\n${record}")
endif()
