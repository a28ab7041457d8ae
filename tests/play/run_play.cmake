# Runs `foldlab render --play SCRIPT` (ARGS: the rest of the command line, ;-separated) and checks
# its exit status against EXPECTED_EXIT and, when given, that stderr holds each of EXPECTED_TEXT.
execute_process(COMMAND ${FOLDLAB} render --play ${SCRIPT} ${ARGS}
  RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_QUIET)
if(NOT status EQUAL EXPECTED_EXIT)
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECTED_EXIT}:\n${errors}")
endif()
foreach(text IN LISTS EXPECTED_TEXT)
  string(FIND "${errors}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "stderr does not mention '${text}':\n${errors}")
  endif()
endforeach()
