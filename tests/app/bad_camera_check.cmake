# A camera whose location equals its look_at (issue 18): povtrace stops with exit status 1, prints the error with
# file:line:column, the line and a caret, and writes no output file (as POV-Ray: "Camera location and look_at point
# must be different.", no image).
# Usage: cmake -DPOVTRACE=<exe> -DWORK=<scratch folder> -P bad_camera_check.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/bad_camera.pov" "#version 3.7;\ncamera { location <0, 1, -5> look_at <0, 1, -5> }\nsphere { 0, 1 pigment { rgb 1 } }\n")
execute_process(COMMAND "${POVTRACE}" +W32 +H24 -D "+O${WORK}/bad_camera.png" "${WORK}/bad_camera.pov"
                WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, expected 1\n${out}${err}")
endif()
set(expected "bad_camera.pov:2:30: error: Camera location and look_at point must be different.\ncamera { location <0, 1, -5> look_at <0, 1, -5> }\n                             ^")
string(FIND "${err}" "${expected}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the error is not reported as expected:\n${err}\n--- expected ---\n${expected}")
endif()
file(GLOB left "${WORK}/*")
list(REMOVE_ITEM left "${WORK}/bad_camera.pov")
if(left)
  message(FATAL_ERROR "files written: ${left}")
endif()
file(REMOVE_RECURSE "${WORK}")
