# scene_switches(SCENE OUT): the extra switches a scene asks for in its "// switches: …" line (antialiasing,
# alpha), as reference/make_references.sh reads them, as a list in OUT (empty without such a line).
function(scene_switches scene out)
  file(STRINGS ${scene} switch_lines REGEX "^// switches:" LIMIT_COUNT 1)
  set(switches "")
  if(switch_lines)
    string(REGEX REPLACE "^// switches:[ ]*" "" switch_text "${switch_lines}")
    separate_arguments(switches UNIX_COMMAND "${switch_text}")
  endif()
  set(${out} "${switches}" PARENT_SCOPE)
endfunction()
