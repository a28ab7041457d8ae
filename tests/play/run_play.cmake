# Runs `foldlab render --play SCRIPT` (ARGS: the rest of the command line, ;-separated) and checks
# its exit status against EXPECTED_EXIT and, when given, that stderr holds each of EXPECTED_TEXT.
# The run happens in a fresh temporary folder, which is also its config folder (user presets),
# so that nothing is written into the repository or $HOME; EXPECTED_FILES must appear in it.
string(RANDOM LENGTH 12 suffix)
if(DEFINED ENV{TMPDIR})
  set(temp_root $ENV{TMPDIR})
else()
  set(temp_root /tmp)
endif()
set(work_dir ${temp_root}/foldlab_play_${suffix})
file(MAKE_DIRECTORY ${work_dir})
execute_process(COMMAND ${CMAKE_COMMAND} -E env XDG_CONFIG_HOME=${work_dir}
    ${FOLDLAB} render --play ${SCRIPT} ${ARGS}
  WORKING_DIRECTORY ${work_dir}
  RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_QUIET)
set(missing "")
foreach(name IN LISTS EXPECTED_FILES)
  if(NOT EXISTS ${work_dir}/${name})
    list(APPEND missing ${name})
  endif()
endforeach()
file(REMOVE_RECURSE ${work_dir})
if(NOT status EQUAL EXPECTED_EXIT)
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECTED_EXIT}:\n${errors}")
endif()
foreach(text IN LISTS EXPECTED_TEXT)
  string(FIND "${errors}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "stderr does not mention '${text}':\n${errors}")
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "not written: ${missing}")
endif()
