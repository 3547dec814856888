# cmake -DPREFIX=<install> -DWORK=<dir> -DBINDIR=<dir> -DSCENE=<scene file> -P plot.cmake
# The installed frictionlab runs a scene and draws its figures with the installed frictionlab.plot,
# which it finds from where it is installed, not from the build tree.
set(run ${WORK}/plot_run)
file(REMOVE_RECURSE ${run})
foreach(command "run;-q;${SCENE};-o;${run}" "plot;${run}")
  execute_process(COMMAND ${PREFIX}/${BINDIR}/frictionlab ${command}
    RESULT_VARIABLE result OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${command}")
    message(FATAL_ERROR "the installed frictionlab ${command} failed (${result}):\n${log}")
  endif()
endforeach()
foreach(figure loading_curve.png loading_curve.svg fronts.svg precursor_lengths.svg)
  if(NOT EXISTS ${run}/plots/${figure})
    message(FATAL_ERROR "the installed frictionlab plot drew no plots/${figure}:\n${log}")
  endif()
endforeach()
