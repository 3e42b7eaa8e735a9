# Proves that the image does not depend on how it was computed (run with cmake -P): one scene rendered with the
# paths specialised for what it holds (render_scene.hpp Specialisation, and the parser's expression programs) and
# with the general paths only (--no-specialise), and with 1, 2 and 4 threads; every render must be the same file,
# bit for bit (32-bit float EXR, so no rounding to half floats can hide a difference).
# Inputs (-D): POVTRACE, SCENE, SCENE_DIR, WORK_DIR.
foreach(var POVTRACE SCENE SCENE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "same_image.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORK_DIR})

# The scene's own extra switches (antialiasing, alpha), as the reference render uses them.
include(${CMAKE_CURRENT_LIST_DIR}/scene_switches.cmake)
scene_switches(${SCENE} extra_switches)

# name|switches
set(variants "specialised_1_thread|+WT1" "general_1_thread|+WT1 --no-specialise" "specialised_2_threads|+WT2"
  "specialised_4_threads|+WT4" "general_4_threads|+WT4 --no-specialise")
set(first "")
foreach(variant ${variants})
  string(REGEX REPLACE "\\|.*" "" name "${variant}")
  string(REGEX REPLACE "^[^|]*\\|" "" switch_text "${variant}")
  separate_arguments(switches UNIX_COMMAND "${switch_text}")
  set(output ${WORK_DIR}/${name}.exr)
  file(REMOVE ${output})
  set(command ${POVTRACE} -D -A +W96 +H72 ${extra_switches} ${switches} --format=exr32 +O${output} ${SCENE})
  execute_process(COMMAND ${command} WORKING_DIRECTORY ${SCENE_DIR}
    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " text "${command}")
  if(NOT result EQUAL 0 OR NOT EXISTS ${output})
    message(FATAL_ERROR "povtrace failed (${result}): ${text}\n${out}${err}")
  endif()
  if(first STREQUAL "")
    set(first ${output})
    set(first_name ${name})
  else()
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${first} ${output} RESULT_VARIABLE differs)
    if(NOT differs EQUAL 0)
      message(FATAL_ERROR "${name} differs from ${first_name}: ${output} against ${first}")
    endif()
  endif()
endforeach()
string(REPLACE ";" ", " listed "${variants}")
message("5 renders bit-identical: ${listed}")
