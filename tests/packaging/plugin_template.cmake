# cmake -DPREFIX=<dir> [-DBUILD_TREE=ON -DSOURCE_DIR=<src>] -DWORK=<dir> -DCHECK_SOURCE=<dir> -DGENERATOR=<g>
#       -DMAKE_PROGRAM=<p> -DCXX_COMPILER=<c> -DBINDIR=<dir> -DDATADIR=<dir> -DPLUGIN_SUBDIR=<dir> -P plugin_template.cmake
# Copies the plugin template as a user would, builds it and the check program against FrictionLab,
# and runs the check on the plugin it produced. PREFIX is an install (found through
# CMAKE_PREFIX_PATH, the template copied from its share/frictionlab), or with BUILD_TREE the build
# tree itself (found through FrictionLab_DIR, the template copied from the sources); both lay out
# bin/ and the shipped plugins alike.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${result}): ${command}")
  endif()
endfunction()

# Runs frictionlab on a scene written in ${WORK}/scene, into a fresh output folder.
function(run_scene scene output)
  file(REMOVE_RECURSE ${WORK}/scene/${output})
  execute_process(
    COMMAND ${PREFIX}/${BINDIR}/frictionlab run -q ${scene}
    WORKING_DIRECTORY ${WORK}/scene
    RESULT_VARIABLE result OUTPUT_VARIABLE run_log ERROR_VARIABLE run_log)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "frictionlab run of ${scene} failed (${result}):\n${run_log}")
  endif()
endfunction()

# Whether the run in ${WORK}/scene/<output> records the plugin library in its run.yaml.
function(expect_recorded output plugin)
  file(READ ${WORK}/scene/${output}/run.yaml record)
  string(FIND "${record}" "${plugin}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "run.yaml of ${output} does not record ${plugin}:\n${record}")
  endif()
endfunction()

if(BUILD_TREE)
  set(package -DFrictionLab_DIR=${PREFIX})
  set(template ${SOURCE_DIR}/share/plugin_template)
else()
  set(package -DCMAKE_PREFIX_PATH=${PREFIX})
  set(template ${PREFIX}/${DATADIR}/frictionlab/plugin_template)
endif()
set(configure_options -G ${GENERATOR} ${package} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
if(MAKE_PROGRAM)
  list(APPEND configure_options -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
endif()

file(REMOVE_RECURSE ${WORK}/my_plugin ${WORK}/check ${WORK}/output)
file(COPY ${template}/ DESTINATION ${WORK}/my_plugin)
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

# The program finds the plugin through FRICTIONLAB_PLUGIN_PATH, and its shipped plugins next to
# itself.
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

# Through a scene, as a user would: frictionlab runs a small lattice whose scene names
# the template's directory in plugin_paths (relative to the scene file) and its observer by type.
set(small_slider "plugin_paths: [../my_plugin/build/plugins]
bulk: {type: spring_lattice_2d, nx: 11, nz: 3, length: 0.025, height: 0.005}
integrator: {type: rk4, dt: 2.0e-7}
loaders:
  - {type: rigid_base_contact}
  - {type: normal_load, total_force: 100, ramp_time: 1.0e-4}
")
file(WRITE ${WORK}/scene/uses_template.yaml "output: out
${small_slider}
stages:
  - {name: settle, duration: 2.0e-4}
observers:
  - {type: max_speed_csv, every: 2.0e-5, file_name: max_speed.csv}
")
run_scene(uses_template.yaml out)
file(STRINGS ${WORK}/scene/out/max_speed.csv rows REGEX "^[0-9]")
list(LENGTH rows row_count)
if(NOT row_count EQUAL 11)
  message(FATAL_ERROR "max_speed.csv has ${row_count} rows, expected 11 (t = 0, 2e-5, ..., 2e-4)")
endif()
expect_recorded(out observer_max_speed_csv)

# The template's friction law, swapped into a scene by its `friction:` block: pulled at 0.05 m/s,
# far above its regularisation speed 5 mm/s, the slider slides steadily and the base's total
# friction is -mu F_N tanh(10) = -30 N (within 0.01 N), as the law states.
set(friction_plugin ${WORK}/my_plugin/build/plugins/friction_viscous_coulomb.so)
if(NOT EXISTS ${friction_plugin})
  message(FATAL_ERROR "the template did not produce ${friction_plugin}")
endif()
file(WRITE ${WORK}/scene/uses_template_law.yaml "output: out_law
${small_slider}  - {type: driving_spring, stages: [load], velocity: 0.05, height: 0.0025}
friction: {type: viscous_coulomb, mu: 0.3, regularisation_velocity: 5.0e-3}
stages:
  - {name: settle, duration: 2.0e-4, friction_events: false}
  - {name: load, duration: 0.01}
observers:
  - {type: loading_curve, every: 1.0e-4}
")
run_scene(uses_template_law.yaml out_law)
file(STRINGS ${WORK}/scene/out_law/loading_curve.csv rows)
list(GET rows 0 header)
string(REPLACE "," ";" header "${header}")
list(FIND header total_friction_force column)
list(GET rows -1 last)
string(REPLACE "," ";" last "${last}")
list(GET last ${column} total_friction)
if(NOT (total_friction GREATER -30.01 AND total_friction LESS -29.99))
  message(FATAL_ERROR "total friction ${total_friction} N, expected -mu F_N = -30 N")
endif()
expect_recorded(out_law friction_viscous_coulomb)
