# Media whose sampling draws random numbers (method 1, jitter, extra samples) are random in POV-Ray with more than
# one thread; povtrace's random numbers come from each ray segment, so its image is the same for any thread count.
# The test renders SCENE with povtrace with 1 and 3 threads (the images must be identical) and requires its PSNR
# against REFERENCE, POV-Ray's +WT1 render, to be at least POV-Ray's own: the worst PSNR of its +WT2 renders WT2
# (a ;-list) against the same reference, less their run-to-run spread (the largest minus the smallest), since three
# runs only sample how far POV-Ray itself lands.
# Inputs (-D): POVTRACE, POVDIFF, SCENE, SCENE_DIR, REFERENCE, WT2, WORK_DIR.
foreach(var POVTRACE POVDIFF SCENE SCENE_DIR REFERENCE WT2 WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "media_random.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/povdiff_psnr.cmake)

foreach(threads 1 3)
  set(image ${WORK_DIR}/wt${threads}.exr)
  file(REMOVE ${image})
  execute_process(COMMAND ${POVTRACE} -D -A +W320 +H240 +FE +WT${threads} +O${image} ${SCENE}
    WORKING_DIRECTORY ${SCENE_DIR} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0 OR NOT EXISTS ${image})
    message(FATAL_ERROR "povtrace failed with ${threads} thread(s) (${result}):\n${out}${err}")
  endif()
endforeach()
povdiff_psnr(${POVDIFF} ${WORK_DIR}/wt1.exr ${WORK_DIR}/wt3.exr same)
if(NOT same EQUAL 100000)
  message(FATAL_ERROR "the image depends on the thread count (1 vs 3 threads: ${same} hundredths of a dB)")
endif()

set(worst 100000)
set(best -100000)
foreach(render ${WT2})
  povdiff_psnr(${POVDIFF} ${render} ${REFERENCE} p)
  if(p LESS worst)
    set(worst ${p})
  endif()
  if(p GREATER best)
    set(best ${p})
  endif()
endforeach()
math(EXPR bar "${worst} - (${best} - ${worst})")
povdiff_psnr(${POVDIFF} ${WORK_DIR}/wt1.exr ${REFERENCE} ours)
message("povtrace vs POV-Ray +WT1: ${ours}; POV-Ray +WT2 vs +WT1: ${worst} to ${best}; bar ${bar} (hundredths of a dB)")
if(ours LESS bar)
  message(FATAL_ERROR "povtrace is further from POV-Ray's +WT1 render than POV-Ray's own +WT2 renders are")
endif()
