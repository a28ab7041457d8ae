# Draws a photo of PRESET's folds with MAKE_PHOTO into WORK_DIR, with the script that clicks
# them, and plays it: `foldlab render --play` must exit 0 (every expect held).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${MAKE_PHOTO} ${PRESET} ${WORK_DIR}/folds.png ${WORK_DIR}/script.json
  RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "make_fold_photo: exit status ${status}:\n${errors}")
endif()
execute_process(COMMAND ${FOLDLAB} render --play ${WORK_DIR}/script.json --preset ${PRESET}
  RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "exit status ${status}, expected 0:\n${errors}")
endif()
