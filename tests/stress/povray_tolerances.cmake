# --povray-tolerances against POV-Ray itself (issue 7): renders SCENE at scale SCALE with POV-Ray's absolute
# tolerances and compares it with POV-Ray's own render REFERENCE (reference/scale_twin/make_references.sh) at the
# regression thresholds. Where POV-Ray refuses the scene (ABORT_MESSAGE given: no reference exists), povtrace must
# refuse it the same way: exit status 1, that message, no image.
# Inputs (-D): POVTRACE, POVDIFF, SCENE, SCALE, OUTPUT, and REFERENCE or ABORT_MESSAGE.
foreach(var POVTRACE POVDIFF SCENE SCALE OUTPUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "povray_tolerances.cmake: -D${var}=... is missing")
  endif()
endforeach()
if(NOT DEFINED REFERENCE AND NOT DEFINED ABORT_MESSAGE)
  message(FATAL_ERROR "povray_tolerances.cmake: -DREFERENCE=... or -DABORT_MESSAGE=... is missing")
endif()

file(REMOVE ${OUTPUT})   # a stale image from an earlier run must not be compared
# The same switches as the reference (reference/scale_twin/README.md), plus --povray-tolerances.
set(render_command ${POVTRACE} --povray-tolerances -D -A +W160 +H120 +FE Declare=S=${SCALE} +O${OUTPUT} ${SCENE})
execute_process(COMMAND ${render_command}
  RESULT_VARIABLE render_result OUTPUT_VARIABLE render_stdout ERROR_VARIABLE render_stderr)
string(REPLACE ";" " " render_text "${render_command}")

if(DEFINED ABORT_MESSAGE)
  if(NOT render_result EQUAL 1)
    message(FATAL_ERROR "POV-Ray refuses S = ${SCALE}; povtrace exited ${render_result}: ${render_text}\n"
      "${render_stdout}${render_stderr}")
  endif()
  string(FIND "${render_stderr}" "${ABORT_MESSAGE}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "povtrace refused S = ${SCALE} without POV-Ray's \"${ABORT_MESSAGE}\":\n${render_stderr}")
  endif()
  if(EXISTS ${OUTPUT})
    message(FATAL_ERROR "povtrace refused S = ${SCALE} but wrote ${OUTPUT}")
  endif()
  message("S = ${SCALE}: refused as POV-Ray refuses it:\n${render_stderr}")
  return()
endif()

if(NOT render_result EQUAL 0 OR NOT EXISTS ${OUTPUT})
  message(FATAL_ERROR "povtrace failed (${render_result}): ${render_text}\n${render_stdout}${render_stderr}")
endif()
set(compare_command ${POVDIFF} ${OUTPUT} ${REFERENCE} --min-psnr 50 --threshold 1/255 --max-share 0.001)
execute_process(COMMAND ${compare_command}
  RESULT_VARIABLE compare_result OUTPUT_VARIABLE compare_stdout ERROR_VARIABLE compare_stderr)
message("S = ${SCALE}: ${compare_stdout}${compare_stderr}")
if(NOT compare_result EQUAL 0)
  string(REPLACE ";" " " compare_text "${compare_command}")
  message(FATAL_ERROR "--povray-tolerances differs from POV-Ray at S = ${SCALE} (povdiff exit ${compare_result}): "
    "${compare_text}")
endif()
