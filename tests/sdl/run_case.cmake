# Runs one SDL case with povtrace and compares its #debug text with POV-Ray's (run with cmake -P).
# Inputs (-D): POVTRACE, NAME, CASES_DIR (tests/sdl/cases), EXPECTED (expected/NAME.txt), PENDING (pending.txt),
#              WORK_DIR (scratch folder for this case; emptied first).
#
# The case runs in a fresh copy of CASES_DIR (file I/O cases write next to the scene) as
#   povtrace -D +W8 +H8 -F NAME.pov
# povtrace prints #debug text to stderr a complete line at a time (as POV-Ray: text after the last line end is
# dropped); it also prints there, and has no switch to silence,
#   - lines starting with "povtrace: " (the closing summary, renderer warnings), and
#   - parser warnings and #warning text: "FILE:LINE:COL: warning: ..." followed by the source line, a
#     caret line and, inside macros and include files, "  in macro M called from ..." / "  included
#     from ..." lines,
# which are removed here (POV-Ray's captures leave out its warning stream the same way). What remains must
# equal EXPECTED exactly.
#
# A case named in PENDING (a feature povtrace does not have yet) that does not match prints
# "SDL_PENDING: ..." with the reason, which the test's SKIP_REGULAR_EXPRESSION turns into a skip; a pending
# case that matches fails, so that it gets removed from the list.
cmake_minimum_required(VERSION 3.16)
foreach(var POVTRACE NAME CASES_DIR EXPECTED PENDING WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_case.cmake: -D${var}=... is missing")
  endif()
endforeach()

# CMake lists split at ';' and treat '[' ']' specially: protect them while working line by line.
macro(protect text_var)
  string(REPLACE ";" "<sdl-semicolon>" ${text_var} "${${text_var}}")
  string(REPLACE "[" "<sdl-open>" ${text_var} "${${text_var}}")
  string(REPLACE "]" "<sdl-close>" ${text_var} "${${text_var}}")
endmacro()
macro(unprotect text_var)
  string(REPLACE "<sdl-semicolon>" ";" ${text_var} "${${text_var}}")
  string(REPLACE "<sdl-open>" "[" ${text_var} "${${text_var}}")
  string(REPLACE "<sdl-close>" "]" ${text_var} "${${text_var}}")
endmacro()

# Is this case pending, and why?
set(pending_reason "")
if(EXISTS ${PENDING})
  file(STRINGS ${PENDING} pending_lines)
  foreach(line IN LISTS pending_lines)
    if(line MATCHES "^${NAME}([ \t]+(.*))?$")
      set(pending_reason "${CMAKE_MATCH_2}")
      if(pending_reason STREQUAL "")
        set(pending_reason "(no reason given)")
      endif()
    endif()
  endforeach()
endif()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(COPY ${CASES_DIR}/ DESTINATION ${WORK_DIR})

set(command ${POVTRACE} -D +W8 +H8 -F ${NAME}.pov)
execute_process(COMMAND ${command}
  WORKING_DIRECTORY ${WORK_DIR}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE stdout_text
  ERROR_VARIABLE stderr_text)
string(REPLACE ";" " " command_text "${command}")

# Filter stderr line by line.
protect(stderr_text)
string(REPLACE "\n" ";" lines "${stderr_text}")
set(got "")
set(skip 0)
set(in_warning 0)
list(LENGTH lines count)
math(EXPR last "${count} - 1")
foreach(i RANGE 0 ${last})
  if(count EQUAL 0)
    break()   # no stderr at all (RANGE 0 -1 would still visit 0 and -1)
  endif()
  list(GET lines ${i} line)
  if(skip GREATER 0)
    math(EXPR skip "${skip} - 1")
    continue()
  endif()
  if(line MATCHES "^povtrace: ")
    continue()
  endif()
  if(line MATCHES "^.+:[0-9]+:[0-9]+: warning: ")
    set(in_warning 1)
    math(EXPR caret "${i} + 2")
    if(caret LESS count)
      list(GET lines ${caret} caret_line)
      if(caret_line MATCHES "^[ \t]*\\^$")
        set(skip 2)
      endif()
    endif()
    continue()
  endif()
  if(in_warning AND line MATCHES "^  (in macro .* called from |included from |\\.\\.\\. [0-9]+ more levels)")
    continue()
  endif()
  set(in_warning 0)
  if(i EQUAL last)
    string(APPEND got "${line}")       # after the last "\n": an unterminated line, or nothing
  else()
    string(APPEND got "${line}\n")
  endif()
endforeach()
unprotect(got)

file(READ ${EXPECTED} expected_text)
get_filename_component(got_file ${WORK_DIR}/../${NAME}.got.txt ABSOLUTE)
file(WRITE ${got_file} "${got}")

if(status EQUAL 0 AND got STREQUAL expected_text)
  if(NOT pending_reason STREQUAL "")
    message(FATAL_ERROR "sdl.${NAME} now matches POV-Ray but tests/sdl/pending.txt still lists it "
      "(${pending_reason}): remove its line from pending.txt.")
  endif()
  message("sdl.${NAME}: povtrace's #debug output matches POV-Ray 3.7's (${EXPECTED})")
  return()
endif()

# Mismatch: build the report. First differing line, then a line-by-line listing.
set(expected_lines "${expected_text}")
set(got_lines "${got}")
protect(expected_lines)
protect(got_lines)
string(REPLACE "\n" ";" expected_lines "${expected_lines}")
string(REPLACE "\n" ";" got_lines "${got_lines}")
list(LENGTH expected_lines n_expected)
list(LENGTH got_lines n_got)
set(first_difference "")
set(n ${n_expected})
if(n_got GREATER n)
  set(n ${n_got})
endif()
math(EXPR n_last "${n} - 1")
set(listing "")
foreach(i RANGE 0 ${n_last})
  if(n EQUAL 0)
    break()
  endif()
  set(e "<no line>")
  set(g "<no line>")
  if(i LESS n_expected)
    list(GET expected_lines ${i} e)
  endif()
  if(i LESS n_got)
    list(GET got_lines ${i} g)
  endif()
  math(EXPR line_number "${i} + 1")
  if(e STREQUAL g)
    string(APPEND listing "  ${e}\n")
  else()
    unprotect(e)
    unprotect(g)
    if(first_difference STREQUAL "")
      set(first_difference "line ${line_number}:\n  expected: ${e}\n  got:      ${g}\n")
    endif()
    string(APPEND listing "- ${e}\n+ ${g}\n")
  endif()
endforeach()
unprotect(listing)
if(first_difference STREQUAL "" AND NOT status EQUAL 0)
  set(first_difference "(the text matches, but povtrace failed)\n")
endif()

set(diff_text "")
find_program(DIFF_PROGRAM diff)
if(DIFF_PROGRAM)
  execute_process(COMMAND ${DIFF_PROGRAM} -u --label expected/${NAME}.txt --label povtrace ${EXPECTED} ${got_file}
    OUTPUT_VARIABLE diff_text)
else()
  set(diff_text "--- expected/${NAME}.txt\n+++ povtrace\n${listing}")
endif()

string(CONCAT report "povtrace's #debug output differs from POV-Ray 3.7's for ${NAME}.pov\n"
  "command (in ${WORK_DIR}): ${command_text}\n"
  "povtrace exit status: ${status}\n"
  "first difference at ${first_difference}"
  "${diff_text}")
if(NOT status EQUAL 0)
  unprotect(stderr_text)
  string(APPEND report "povtrace's stderr:\n${stderr_text}${stdout_text}\n")
endif()

# message() without a mode prints the text as it is (FATAL_ERROR would re-wrap it).
if(NOT pending_reason STREQUAL "")
  message("SDL_PENDING: ${NAME} is listed in tests/sdl/pending.txt: ${pending_reason}\n"
    "(skipped; the current difference follows)\n${report}")
  return()
endif()
message("${report}")
message(FATAL_ERROR "sdl.${NAME}: povtrace differs from POV-Ray (report above)")
