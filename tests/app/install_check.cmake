# Runs `cmake --install` of the build tree into a fresh prefix and checks the installed files
# (ctest: install_test). Arguments: -DBUILD_DIR=… -DPREFIX=…
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status}):\n${out}\n${err}")
endif()
include(GNUInstallDirs)
foreach(file "${CMAKE_INSTALL_BINDIR}/povtrace" "${CMAKE_INSTALL_BINDIR}/povdiff"
             "${CMAKE_INSTALL_MANDIR}/man1/povtrace.1")
  if(NOT EXISTS "${PREFIX}/${file}")
    message(FATAL_ERROR "not installed: ${PREFIX}/${file}")
  endif()
endforeach()
file(READ "${PREFIX}/${CMAKE_INSTALL_MANDIR}/man1/povtrace.1" man)
if(NOT man MATCHES "Include_Header" OR NOT man MATCHES "^\\.TH POVTRACE 1")
  message(FATAL_ERROR "the man page lacks the option table")
endif()
execute_process(COMMAND "${PREFIX}/${CMAKE_INSTALL_BINDIR}/povtrace" --version RESULT_VARIABLE status
                OUTPUT_VARIABLE version)
if(NOT status EQUAL 0 OR NOT version MATCHES "POV-Ray 3.7")
  message(FATAL_ERROR "installed povtrace --version: ${status} ${version}")
endif()
file(REMOVE_RECURSE "${PREFIX}")
