# Radiosity through the program: a bad radiosity block gets the precise parse error (exit status 1, no output
# file); a valid one renders at +Q9 (the default) and, as in POV-Ray, is left out below +Q9, so the +Q8 image is
# the one without the block and differs from the +Q9 one. Run from the scene's folder, as the sample-scene survey
# does.
# Usage: cmake -DPOVTRACE=<exe> -DWORK=<scratch folder> -P radiosity_check.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

function(expect_error scene text expected)
  file(WRITE "${WORK}/${scene}" "${text}")
  execute_process(COMMAND "${POVTRACE}" +W32 +H24 -D "+O${WORK}/out.png" "${scene}"
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 1)
    message(FATAL_ERROR "${scene}: exit status ${status}, expected 1\n${out}${err}")
  endif()
  string(FIND "${err}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${scene}: the error is not reported as expected:\n${err}\n--- expected ---\n${expected}")
  endif()
  if(EXISTS "${WORK}/out.png")
    message(FATAL_ERROR "${scene}: an image was written")
  endif()
endfunction()

expect_error(late_error.pov
  "#version 3.7;\nglobal_settings { radiosity { count 100 } }\nsphere { 0, 1 pigment { rgb 1 } }\nsphere { 0, Q }\n"
  "late_error.pov:4:13: error: ")
expect_error(bad_block.pov
  "#version 3.7;\nglobal_settings { radiosity { count 10, 5 } }\nsphere { 0, 1 pigment { rgb 1 } }\n"
  "bad_block.pov:2:41: error: Radiosity count can not be more than direction pool size (count 2nd value) (found 5); count is 10\nglobal_settings { radiosity { count 10, 5 } }\n                                        ^")
# +Q9 renders the radiosity (a white sphere lit only by a white sky: bright), +Q8 the scene without the block
# (no light, ambient 0: black), and the +Q8 image
# is the one of the scene written without the block.
set(lit "#version 3.7;\nglobal_settings { ambient_light 0 }\nsky_sphere { pigment { rgb 1 } }\ncamera { location <0, 0, -4> look_at 0 }\nsphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n")
file(WRITE "${WORK}/with.pov" "${lit}global_settings { radiosity { count 100 } }\n")
file(WRITE "${WORK}/without.pov" "${lit}")
foreach(run "with;9" "with;8" "without;8")
  list(GET run 0 name)
  list(GET run 1 q)
  execute_process(COMMAND "${POVTRACE}" +W32 +H24 -D +Q${q} "+O${WORK}/${name}_q${q}.png" ${name}.pov
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT EXISTS "${WORK}/${name}_q${q}.png")
    message(FATAL_ERROR "${name}.pov at +Q${q}: exit status ${status}, expected a render\n${out}${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/with_q8.png" "${WORK}/without_q8.png"
                RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "+Q8 with the radiosity block differs from the scene without it")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/with_q9.png" "${WORK}/with_q8.png"
                RESULT_VARIABLE same)
if(same EQUAL 0)
  message(FATAL_ERROR "+Q9 rendered the radiosity scene as +Q8 does: no radiosity computed")
endif()
# +QR (3.6's radiosity quality switch) is not a POV-Ray 3.7 option: povray fails to parse it; so does povtrace
# (its usage-error status 2), naming it, with no image.
execute_process(COMMAND "${POVTRACE}" +W32 +H24 -D +QR "+O${WORK}/qr.png" with.pov
                WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "\\+QR" OR EXISTS "${WORK}/qr.png")
  message(FATAL_ERROR "+QR: exit status ${status} (expected 2, an error naming +QR, no image)\n${out}${err}")
endif()
# +QR (3.6's radiosity quality switch) is not a POV-Ray 3.7 option: povray fails to parse it; so does povtrace
# (its usage-error status 2), naming it, with no image.
execute_process(COMMAND "${POVTRACE}" +W32 +H24 -D +QR "+O${WORK}/qr.png" with.pov
                WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "\\+QR" OR EXISTS "${WORK}/qr.png")
  message(FATAL_ERROR "+QR: exit status ${status} (expected 2, an error naming +QR, no image)\n${out}${err}")
endif()
file(REMOVE_RECURSE "${WORK}")
