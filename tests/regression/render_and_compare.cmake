# Renders one scene with povtrace and compares it with its POV-Ray reference (run with cmake -P).
# Inputs (-D): POVTRACE, POVDIFF, SCENE, SCENE_DIR, REFERENCE, OUTPUT, DIFF.
# Fails (FATAL_ERROR, non-zero exit) when povtrace fails, writes no image, or povdiff reports a mismatch.
foreach(var POVTRACE POVDIFF SCENE SCENE_DIR REFERENCE OUTPUT DIFF)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "render_and_compare.cmake: -D${var}=... is missing")
  endif()
endforeach()

# A stale image from an earlier run must not be compared if this render fails.
file(REMOVE ${OUTPUT} ${DIFF})

# Step 1: render, from the scenes folder as POV-Ray did for the reference, with the scene's own extra switches
# (a "// switches: …" line, as reference/make_references.sh reads it).
include(${CMAKE_CURRENT_LIST_DIR}/scene_switches.cmake)
scene_switches(${SCENE} extra_switches)
set(render_command ${POVTRACE} -D -A +W320 +H240 +FE ${extra_switches} +O${OUTPUT} ${SCENE})
execute_process(COMMAND ${render_command}
  WORKING_DIRECTORY ${SCENE_DIR}
  RESULT_VARIABLE render_result
  OUTPUT_VARIABLE render_stdout
  ERROR_VARIABLE render_stderr)
string(REPLACE ";" " " render_text "${render_command}")
if(NOT render_result EQUAL 0)
  message(FATAL_ERROR "povtrace failed (${render_result}): ${render_text}\n${render_stdout}${render_stderr}")
endif()
if(NOT EXISTS ${OUTPUT})
  message(FATAL_ERROR "povtrace exited 0 but wrote no image: ${render_text}\n${render_stdout}${render_stderr}")
endif()

# Step 2: compare with the reference; povdiff's last line is the verdict.
set(compare_command ${POVDIFF} ${OUTPUT} ${REFERENCE} --diff ${DIFF}
  --min-psnr 50 --threshold 1/255 --max-share 0.001)
execute_process(COMMAND ${compare_command}
  RESULT_VARIABLE compare_result
  OUTPUT_VARIABLE compare_stdout
  ERROR_VARIABLE compare_stderr)
string(REPLACE ";" " " compare_text "${compare_command}")
message("${compare_stdout}${compare_stderr}")
if(NOT compare_result EQUAL 0)
  message(FATAL_ERROR "image differs from reference (povdiff exit ${compare_result}): ${compare_text}\n"
    "difference map: ${DIFF}")
endif()
