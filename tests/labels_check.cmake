# Fails when a test of the build BUILD_DIR carries none of the labels LABELS (a regular expression
# ctest -LE takes): such a test would run in none of the loops the README offers.
execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N -LE "${LABELS}"
  OUTPUT_VARIABLE listed RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ctest -N failed (${status}):\n${listed}")
endif()
if(NOT listed MATCHES "Total Tests: ([0-9]+)")
  message(FATAL_ERROR "ctest -N printed no total:\n${listed}")
endif()
if(NOT CMAKE_MATCH_1 EQUAL 0)
  message(FATAL_ERROR "${CMAKE_MATCH_1} test(s) carry no label of ${LABELS} "
    "(tests/CMakeLists.txt says which fits):\n${listed}")
endif()
