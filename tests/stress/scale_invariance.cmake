# Scale invariance (issue 7): renders SCENE with S = 1 and with each of SCALES, and requires every scaled render to
# be within MIN_PSNR of the unit one. With --povray-tolerances (POV-Ray's absolute tolerances) the scale given as
# POVRAY_SCALE must instead fall below MIN_PSNR, as it does in POV-Ray itself, so that the switch is shown to
# reproduce the artefacts. Inputs (-D): POVTRACE, POVDIFF, SCENE, WORK_DIR, SCALES (comma-separated), MIN_PSNR, POVRAY_SCALE.
foreach(var POVTRACE POVDIFF SCENE WORK_DIR SCALES MIN_PSNR POVRAY_SCALE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "scale_invariance.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORK_DIR})

function(render scale output)
  execute_process(COMMAND ${POVTRACE} -D -A +W160 +H120 +FE Declare=S=${scale} ${ARGN} +O${output} ${SCENE}
    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0 OR NOT EXISTS ${output})
    message(FATAL_ERROR "povtrace failed at S = ${scale} (${result}):\n${out}${err}")
  endif()
endfunction()

include(${CMAKE_CURRENT_LIST_DIR}/../regression/povdiff_psnr.cmake)

math(EXPR min_h "${MIN_PSNR} * 100")
set(unit ${WORK_DIR}/scale_1.exr)
render(1 ${unit})
string(REPLACE "," ";" scale_list "${SCALES}")
foreach(scale ${scale_list})
  set(image ${WORK_DIR}/scale_${scale}.exr)
  render(${scale} ${image})
  povdiff_psnr(${POVDIFF} ${image} ${unit} p)
  message("S = ${scale}: ${p} hundredths of a dB against S = 1")
  if(p LESS min_h)
    message(FATAL_ERROR "S = ${scale} differs from its unit-scale twin: PSNR ${p}/100 dB < ${MIN_PSNR} dB")
  endif()
endforeach()

set(image ${WORK_DIR}/povray_tolerances_${POVRAY_SCALE}.exr)
render(${POVRAY_SCALE} ${image} --povray-tolerances)
povdiff_psnr(${POVDIFF} ${image} ${unit} p)
message("S = ${POVRAY_SCALE} with --povray-tolerances: ${p} hundredths of a dB against S = 1")
if(NOT p LESS min_h)
  message(FATAL_ERROR "--povray-tolerances did not reproduce POV-Ray's loss at S = ${POVRAY_SCALE}")
endif()
