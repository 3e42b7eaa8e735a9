# One radiosity case of reference/radiosity/cases.txt (run with cmake -P): renders the scene with povtrace exactly as
# reference/make_radiosity_references.sh rendered it with POV-Ray (a scratch copy of the scene's folder, from that
# folder, -D -A +W160 +H120 +FE [case switches]) and requires povdiff's PSNR against POV-Ray's +WT1 render to be at
# least BAR, the lowest PSNR of POV-Ray's own +WT2 renders against that +WT1 render (reference/radiosity/bars.csv):
# povtrace must be as close to POV-Ray's reference as POV-Ray with two threads is. With -DORDER=povray the render
# uses --radiosity-povray-order (POV-Ray's +WT1 order, which should reproduce the reference) and the bar is at
# least 50 dB, the regression tests' usual one.
# Inputs (-D): POVTRACE, POVDIFF, SCENE (absolute path), SWITCHES (may be empty), REFERENCE, BAR (dB), WORK_DIR;
# ORDER (default | povray, optional).
# Optional -DCANDIDATE=IMAGE compares IMAGE instead of rendering (to check the comparison by hand, e.g. with one of
# POV-Ray's +WT2 renders).
foreach(var POVTRACE POVDIFF SCENE REFERENCE BAR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "radiosity_sample.cmake: -D${var}=... is missing")
  endif()
endforeach()

set(order_switches "")
if(ORDER STREQUAL "povray")
  set(order_switches --radiosity-povray-order)
  if(BAR LESS 50)
    set(BAR 50)
  endif()
endif()

# A fresh work folder, so no stale image or difference map counts.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
if(DEFINED CANDIDATE)
  set(output ${CANDIDATE})
else()
  # A copy of the scene's folder, so files the scene writes stay out of the sources.
  get_filename_component(scene_dir ${SCENE} DIRECTORY)
  get_filename_component(scene_file ${SCENE} NAME)
  file(COPY ${scene_dir}/ DESTINATION ${WORK_DIR}/scene)
  set(output ${WORK_DIR}/povtrace.exr)
  separate_arguments(switches UNIX_COMMAND "${SWITCHES}")
  set(render_command ${POVTRACE} -D -A +W160 +H120 +FE ${switches} ${order_switches} +O${output} ${scene_file})
  execute_process(COMMAND ${render_command}
    WORKING_DIRECTORY ${WORK_DIR}/scene
    RESULT_VARIABLE render_result
    OUTPUT_VARIABLE render_stdout
    ERROR_VARIABLE render_stderr)
  string(REPLACE ";" " " render_text "${render_command}")
  if(NOT render_result EQUAL 0)
    message(FATAL_ERROR "povtrace failed (${render_result}): ${render_text}\n${render_stdout}${render_stderr}")
  endif()
  if(NOT EXISTS ${output})
    message(FATAL_ERROR "povtrace exited 0 but wrote no image: ${render_text}\n${render_stdout}${render_stderr}")
  endif()
endif()

# PSNR only (--max-share 1 turns povdiff's share-of-pixels criterion off): radiosity noise moves many pixels a little
# in POV-Ray's own +WT2 renders too; the bar was measured with the same povdiff PSNR.
set(compare_command ${POVDIFF} ${output} ${REFERENCE} --diff ${WORK_DIR}/diff.png --min-psnr ${BAR} --max-share 1)
execute_process(COMMAND ${compare_command}
  RESULT_VARIABLE compare_result
  OUTPUT_VARIABLE compare_stdout
  ERROR_VARIABLE compare_stderr)
string(REPLACE ";" " " compare_text "${compare_command}")
message("${compare_stdout}${compare_stderr}")
if(NOT compare_result EQUAL 0 AND NOT compare_result EQUAL 1)
  message(FATAL_ERROR "povdiff could not compare (exit ${compare_result}): ${compare_text}")
endif()
if(compare_result EQUAL 1)
  message(FATAL_ERROR "further from POV-Ray's +WT1 render than the bar (PSNR ${BAR} dB: POV-Ray's worst +WT2 render, "
    "at least 50 dB in POV-Ray's order): "
    "${compare_text}")
endif()
message("within POV-Ray's spread: PSNR >= ${BAR} dB (worst +WT2 vs +WT1)")
